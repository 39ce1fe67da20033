#!/usr/bin/python3
"""inpact against CalculiX on the elastic–plastic indentation (issue 15's contact scene).

decks/contact_verification/gen_indentation.py's deck (a rigid-like cylinder pressed 0.1 into a
Mises block, plane strain) at mesh levels 1, 2, 3, extruded into one-element-thick C3D8 slabs with
U3 = 0 (bench/contact_ccx/slab.py: the same mesh and DOF count for both solvers), small strain and
NLGEOM, automatic incrementation from ten increments (0.1 at most). Contact as CalculiX has it: node to surface, the
block the slave, linear penalty K = 10 k_e (k_e as inpact computes it), σ∞ = 1e-4 of 3000, c0 = 1e-3.
Each deck is run by ccx and by inpact (inpact reads CalculiX's pressure-overclosure form); inpact
also runs its own Abaqus form with direct (hard) contact, its default.

Per run: the indenter's reaction (per unit thickness) at every increment, its largest difference to
ccx's over the increment ends both have (relative to the final force), Newton iterations and CPU
time (user + system, medians of RUNS runs).

    indentation.py --inpact BUILD/apps/inpact [--levels 1 2 3] [--runs 1] [--work DIR]

Writes bench/results/plastic_indentation.md and .json and prints the table.
"""
import argparse
import os
import re
import statistics
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "bench", "contact_ccx"))
sys.path.insert(0, os.path.join(ROOT, "decks", "contact_verification"))
import ccx_bench  # noqa: E402
import results  # noqa: E402
import gen_indentation  # noqa: E402
import slab  # noqa: E402

LOAD_SET, SLAVE, MASTER = "INDENTER_TOP", "BLOCK_S", "INDENTER_S"
REFERENCE_PRESSURE = 3000.0


def write_decks(level, nlgeom, work):
    lines = gen_indentation.indentation_2d(level)
    t = 1.0 / 2 ** (level + 1)
    d0 = slab.parse_2d(lines)
    K = float(f"{10.0 * ccx_bench.element_stiffness(d0, SLAVE):.4g}")
    sigma_inf = float(f"{1e-4 * REFERENCE_PRESSURE:.3g}")
    ccx_contact = ["*SURFACE INTERACTION, NAME=SI", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
                   f"{K:g}, {sigma_inf:g}, 0.001", "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE",
                   f"{SLAVE}, {MASTER}"]
    prints = [f"*NODE PRINT, NSET={LOAD_SET}, TOTALS=ONLY", "RF"]
    native = ["*SURFACE INTERACTION, NAME=SI", "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE", f"{SLAVE}, {MASTER}"]
    out = ["*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "PEEQ"]
    name = f"indentation_l{level}_{'nlgeom' if nlgeom else 'small'}"
    decks = {}
    for kind, contact, step_out, ccx in (("ccx", ccx_contact, prints, True), ("ccx_form", ccx_contact, out, False),
                                         ("direct", native, out, False)):
        text, _, _ = slab.slab_deck(lines, t, contact, step_out, ccx=ccx, nlgeom=nlgeom)
        decks[kind] = os.path.join(work, f"{name}_{kind}.inp")
        with open(decks[kind], "w") as f:
            f.write(text)
    return decks, t, K


def ccx_forces(job):
    forces = []
    with open(job + ".dat") as f:
        text = f.read()
    for m in re.finditer(r"total force \(fx,fy,fz\) for set \S+ and time\s+(\S+)\s*\n\s*\n\s*(\S+)\s+(\S+)", text):
        forces.append((float(m.group(1)), float(m.group(3))))
    newton = sum(1 for ln in open(job + ".cvg") if re.match(r"\s+\d+\s+\d+\s+\d+\s+\d+", ln))
    return forces, newton


def inpact_forces(h5):
    with h5py.File(h5, "r") as f:
        step = list(f["steps"].values())[-1]["fieldOutputs"]
        rows = f[f"model/sets/nsets/{LOAD_SET}"][:]
        rf_rows = step["RF/nodes"][:]
        data = step["RF/data"][:]
        idx = np.searchsorted(rf_rows, rows)
        st = f["status"][:]
        times = st["step_time"][st["cut_back"] == 0]
        forces = [(float(tm), float(data[k][idx, 1].sum())) for k, tm in enumerate(times)]
        peeq = float(step["PEEQ/data"][-1].max()) if "PEEQ" in step else 0.0
        return forces, int(st["total_iters"].sum()), peeq


def run_case(args, level, nlgeom):
    decks, t, K = write_decks(level, nlgeom, args.work)
    row = dict(level=level, nlgeom=nlgeom, h=t, K=K)
    job = os.path.splitext(os.path.basename(decks["ccx"]))[0]
    rc, _, cpu, _ = ccx_bench.repeat(["ccx", job], args.work, args.runs)
    row["ccx"] = dict(rc=rc, cpu=cpu)
    if rc == 0:
        row["ccx"]["forces"], row["ccx"]["newton"] = ccx_forces(os.path.join(args.work, job))
    for kind in ("ccx_form", "direct"):
        j = os.path.splitext(os.path.basename(decks[kind]))[0]
        rc, _, cpu, out = ccx_bench.repeat([args.inpact, "run", decks[kind], "-o", args.work, "-j", j, "--quiet"],
                                          args.work, args.runs)
        row[kind] = dict(rc=rc, cpu=cpu)
        if rc == 0:
            row[kind]["forces"], row[kind]["newton"], row[kind]["peeq"] = inpact_forces(os.path.join(args.work, j + ".h5"))
    return row


def difference(a, b):
    """Largest |F_a − F_b| over the common increments, relative to b's final force."""
    fb = dict((round(t, 9), v) for t, v in b)
    common = [(v, fb[round(t, 9)]) for t, v in a if round(t, 9) in fb]
    if not common:
        return float("nan")
    return max(abs(x - y) for x, y in common) / abs(b[-1][1])


def table(rows):
    out = ["| level | h | NLGEOM | F ccx | F inpact (ccx form) | diff | F inpact direct | diff | PEEQ max | "
           "Newton ccx / inpact / direct | CPU s ccx / inpact / direct |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        c, i, d = r["ccx"], r["ccx_form"], r["direct"]
        if c["rc"] or i["rc"] or d["rc"]:
            out.append(f"| {r['level']} | {r['h']:g} | {r['nlgeom']} | rc {c['rc']} / {i['rc']} / {d['rc']} | | | | | | | |")
            continue
        per_t = 1.0 / r["h"]
        out.append(f"| {r['level']} | {r['h']:g} | {'yes' if r['nlgeom'] else 'no'} | {c['forces'][-1][1] * per_t:.1f} | "
                   f"{i['forces'][-1][1] * per_t:.1f} | {difference(i['forces'], c['forces']):+.2%} | "
                   f"{d['forces'][-1][1] * per_t:.1f} | {difference(d['forces'], c['forces']):+.2%} | {i['peeq']:.3f} | "
                   f"{c['newton']} / {i['newton']} / {d['newton']} | {c['cpu']:.2f} / {i['cpu']:.2f} / {d['cpu']:.2f} |")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--levels", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "plastic_ccx"))
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    rows = [run_case(args, level, nlgeom) for level in args.levels for nlgeom in (False, True)]
    text = ("# Elastic–plastic indentation: inpact against CalculiX (bench/plastic_ccx/indentation.py)\n\n"
            "Forces per unit thickness at the full depth 0.1; diff: the largest difference over the "
            "increment ends both solvers have, relative to ccx's final force. Load average at the start: "
            f"{os.getloadavg()[0]:.1f}.\n\n" + table(rows) + "\n")
    results.write("plastic_indentation", text, rows)

if __name__ == "__main__":
    main()
