#!/usr/bin/python3
"""inpact against CalculiX and Hill's closed form on the elastic–perfectly plastic thick cylinder
(issue 15): decks/verification/gen_verification.py's plastic_cylinder (plane strain, CPE8R,
a = 10, b = 20, the plastic zone to c = 15, pressure in ten DIRECT increments) at three meshes.

Each deck is run as it is by inpact and, with *NODE PRINT of the bore instead of field output,
by ccx (CalculiX expands CPE8R into C3D20R itself). Per mesh: the bore's mean radial displacement
against Hill's u(a) = 3 k c²/(2 E a) (ν = 0.4999: corrections O(1 − 2ν)), Newton iterations, CPU
time (user + system, medians of RUNS runs), and inpact's residual sequence in the increment with
the most iterations (from `inpact run -v`), which shows Newton's rate.

    thick_cylinder.py --inpact BUILD/apps/inpact [--runs 1] [--work DIR]

Writes bench/results/plastic_cylinder.md and .json and prints the table.
"""
import argparse
import math
import os
import re
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "bench", "contact_ccx"))
sys.path.insert(0, os.path.join(ROOT, "decks", "verification"))
import ccx_bench  # noqa: E402
import results  # noqa: E402
import gen_verification as gv  # noqa: E402

MESHES = [(12, 4), (24, 8), (48, 16)]


def bore_nodes(lines, a):
    nodes, kw = [], None
    for ln in lines:
        if ln.startswith("*"):
            kw = ln.split(",")[0].upper()
            continue
        if kw == "*NODE":
            n, x, y = (float(v) for v in ln.split(",")[:3])
            if abs(math.hypot(x, y) - a) < 1e-6:
                nodes.append(int(n))
    return nodes


def write_decks(nr, nt, work):
    lines = gv.plastic_cylinder("CPE8R", nr, nt).lines
    bore = bore_nodes(lines, gv.CYL["a"])
    nset = ["*NSET, NSET=BORE_N"] + [", ".join(map(str, bore[i:i + 16])) for i in range(0, len(bore), 16)]
    at_step = lines.index("*STEP, NAME=PRESSURIZE")
    native = lines[:at_step] + nset + lines[at_step:]
    out = native.index("*OUTPUT, FIELD")
    ccx = native[:out] + ["*NODE PRINT, NSET=BORE_N", "U", "*END STEP"]
    ccx[ccx.index("*STEP, NAME=PRESSURIZE")] = "*STEP"
    # CalculiX has no symmetry type names in *BOUNDARY
    ccx = [{"ON_X, YSYMM": "ON_X, 2, 2", "ON_Y, XSYMM": "ON_Y, 1, 1"}.get(ln, ln) for ln in ccx]
    name = f"plastic_cylinder_{nr}x{nt}"
    paths = {}
    for kind, text in (("inpact", native), ("ccx", ccx)):
        paths[kind] = os.path.join(work, f"{name}_{kind}.inp")
        with open(paths[kind], "w") as f:
            f.write("\n".join(text) + "\n")
    return paths, bore


def ccx_bore(job, bore):
    text = open(job + ".dat").read()
    blocks = text.split("displacements (vx,vy,vz)")
    u = {}
    for ln in blocks[-1].splitlines()[1:]:
        p = ln.split()
        if len(p) >= 3 and p[0].isdigit():
            u[int(p[0])] = (float(p[1]), float(p[2]))
    ur = [u[n][0] * x + u[n][1] * y for n, (x, y) in bore.items() if n in u]
    newton = sum(1 for ln in open(job + ".cvg") if re.match(r"\s+\d+\s+\d+\s+\d+\s+\d+", ln))
    return float(np.mean(ur)), newton


def inpact_bore(h5, bore):
    with h5py.File(h5, "r") as f:
        labels = list(f["model/nodes/labels"][:])
        step = list(f["steps"].values())[-1]["fieldOutputs"]
        rows, data = list(step["U/nodes"][:]), step["U/data"][-1]
        index = {int(labels[r]): i for i, r in enumerate(rows)}
        ur = [data[index[n], 0] * x + data[index[n], 1] * y for n, (x, y) in bore.items()]
        return float(np.mean(ur)), int(f["status"][:]["total_iters"].sum())


def residual_sequence(verbose_output):
    """The relative residuals of the increment with the most iterations."""
    incs, cur = [], []
    for ln in verbose_output.splitlines():
        m = re.search(r"iter (\d+)\s+max residual \S+ \((\S+) of the average force\)", ln)
        if m:
            if m.group(1) == "0" and cur:
                incs.append(cur)
                cur = []
            cur.append(float(m.group(2)))
    if cur:
        incs.append(cur)
    return max(incs, key=len) if incs else []


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "plastic_ccx"))
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    a, c, E, sy = (gv.CYL[k] for k in ("a", "c", "E", "sy"))
    u_hill = 3 * sy / math.sqrt(3) * c * c / (2 * E * a)
    rows = []
    for nr, nt in MESHES:
        paths, labels = write_decks(nr, nt, args.work)
        coords = {}
        for ln in open(paths["inpact"]):
            p = ln.split(",")
            if len(p) == 3 and p[0].strip().isdigit() and int(p[0]) in labels:
                x, y = float(p[1]), float(p[2])
                coords[int(p[0])] = (x / a, y / a)
        row = dict(mesh=f"{nr}x{nt}")
        job = os.path.splitext(os.path.basename(paths["ccx"]))[0]
        rc, _, cpu, _ = ccx_bench.repeat(["ccx", job], args.work, args.runs)
        row["ccx"] = dict(rc=rc, cpu=cpu)
        if rc == 0:
            row["ccx"]["u"], row["ccx"]["newton"] = ccx_bore(os.path.join(args.work, job), coords)
        j = os.path.splitext(os.path.basename(paths["inpact"]))[0]
        rc, _, cpu, out = ccx_bench.repeat([args.inpact, "run", paths["inpact"], "-o", args.work, "-j", j, "-v"],
                                          args.work, args.runs)
        row["inpact"] = dict(rc=rc, cpu=cpu, residuals=residual_sequence(out))
        if rc == 0:
            row["inpact"]["u"], row["inpact"]["newton"] = inpact_bore(os.path.join(args.work, j + ".h5"), coords)
        rows.append(row)
    lines = ["# Thick cylinder, elastic–perfectly plastic: inpact, CalculiX and Hill (bench/plastic_ccx/thick_cylinder.py)",
             "", f"u(a) of Hill = {u_hill:.9g}; load average at the start {os.getloadavg()[0]:.1f}.", "",
             "| mesh | u(a) inpact | vs Hill | u(a) ccx | vs Hill | inpact vs ccx | Newton inpact / ccx | CPU s inpact / ccx |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        i, c2 = r["inpact"], r["ccx"]
        if i["rc"] or c2["rc"]:
            lines.append(f"| {r['mesh']} | rc {i['rc']} | | rc {c2['rc']} | | | | |")
            continue
        lines.append(f"| {r['mesh']} | {i['u']:.7g} | {i['u'] / u_hill - 1:+.2e} | {c2['u']:.7g} | {c2['u'] / u_hill - 1:+.2e} | "
                     f"{i['u'] / c2['u'] - 1:+.2e} | {i['newton']} / {c2['newton']} | {i['cpu']:.2f} / {c2['cpu']:.2f} |")
    lines += ["", "inpact's residuals (relative to the average force) in its longest increment, per mesh:", ""]
    for r in rows:
        lines.append(f"- {r['mesh']}: " + ", ".join(f"{v:.2e}" for v in r["inpact"].get("residuals", [])))
    text = "\n".join(lines) + "\n"
    results.write("plastic_cylinder", text, rows)

if __name__ == "__main__":
    main()
