#!/usr/bin/python3
"""inpact against CalculiX (issue 4, "Against CalculiX"): the Hertz line contact and the
thick-cylinder interference fit of decks/contact_verification/, extruded into one-element-thick
C3D8 slabs with U3 = 0 (slab.py: the same mesh and DOF count for both solvers), written in
CalculiX's dialect with linear penalty contact

    *SURFACE INTERACTION / *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR / K, σ∞, c0
    *CONTACT PAIR, INTERACTION=SI, TYPE=<discretisation>

K = 10 k_e (inpact's and Abaqus's default linear penalty; k_e as inpact computes it, M/h of the
slave elements, median), σ∞ = 1e-4 of the reference pressure (CalculiX's law is
p = K d (1/2 + atan(d/ε)/π), ε = π σ∞/K: it tends to K d − σ∞), c0 = 1e-3 (CalculiX's default).
Each deck is run by ccx and by inpact; inpact also runs its own Abaqus-form deck with direct hard
contact (its default) and with default linear penalty. Per run: the error of the peak pressure
(Hertz: the symmetry node's pressure against p0 of Johnson §4.2 for the load carried) or of the
mean pressure (interference: Σ p A / Σ A over the slave nodes against Lamé), Newton iterations
(ccx: the rows of its .cvg; inpact: the .sta's total), wall and CPU time (user + system of the
process, medians of RUNS runs; the machine is shared, so CPU time is the steadier figure).

The cost of an inpact Newton iteration: (CPU of the contact run − CPU of the same mesh without
contact) / (their difference in iterations), against one assembly + factorisation + solve of the
same system from bench/solver_floor (CHOLMOD, as inpact drives it).

    ccx_bench.py --inpact BUILD/apps/inpact --floor BUILD/bench/solver_floor [--runs 3] [--levels 1 2]
                 [--problems hertz interference] [--discretization "NODE TO SURFACE" "SURFACE TO SURFACE"]
                 [--ccx-discretization ...]   (which of them ccx runs too; default all)

Writes bench/results/contact_ccx.md and .json and prints them.
"""
import argparse
import json
import math
import os
import re
import statistics
import subprocess
import sys
import time

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "bench", "contact_trade"))
sys.path.insert(0, os.path.join(ROOT, "decks", "contact_verification"))
import figures  # noqa: E402
import gen_contact_verification as gcv  # noqa: E402
import slab  # noqa: E402

M_STEEL = gcv.E * (1 - gcv.NU) / ((1 + gcv.NU) * (1 - 2 * gcv.NU))


def thickness(problem, level):
    if problem == "hertz":
        return 1.0 / 2 ** (level + 1)          # the element size at the contact
    return gcv.RING_B * math.pi / 2 / (34 * 2 ** (level - 1))


PROBLEMS = {  # 2-D generator, slave, master, set whose reaction is the load (or None)
    "hertz": (gcv.hertz_2d, "INDENTER_S", "BLOCK_S", "INDENTER_TOP"),
    "interference": (gcv.interference_2d, "OUTER_S", "INNER_S", None),
}


def element_stiffness(d, surface):
    """k_e as inpact computes it (contact/normal_behavior.cpp): median over the slave facets of
    M / (element area / edge length) — the same for the slab, whose faces are edge × t."""
    xy = {n: (x, y) for n, x, y in d["nodes"]}
    elems = {}
    for _, rows in d["elements"].values():
        for e, *nodes in rows:
            elems[e] = nodes
    edge = {"S1": (0, 1), "S2": (1, 2), "S3": (2, 3), "S4": (3, 0)}
    ks = []
    for es, face in d["surfaces"][surface]:
        for e in d["elsets"][es]:
            p = [xy[n] for n in elems[e]]
            area = 0.5 * abs(sum(p[i][0] * p[(i + 1) % 4][1] - p[(i + 1) % 4][0] * p[i][1] for i in range(4)))
            i, j = edge[face]
            ks.append(M_STEEL / (area / math.dist(p[i], p[j])))
    ks.sort()
    n = len(ks)
    return ks[n // 2] if n % 2 else 0.5 * (ks[n // 2 - 1] + ks[n // 2])


def reference_pressure(problem):
    return 3200.0 if problem == "hertz" else figures.lame_pressure()


def tag(disc):
    return "nts" if disc == "NODE TO SURFACE" else "sts" if disc == "SURFACE TO SURFACE" else disc.lower().replace(" ", "_")


def build(problem, level, disc, work):
    """Write the decks of one problem/level and discretisation; returns their paths and the
    geometry. Surface to surface: ccx prints its contact stress per integration point without
    coordinates, so its deck also asks for *CONTACT FILE, CSTR (nodal CPRESS in the .frd); inpact's
    "direct" deck says DIRECT (the default of finite-sliding surface to surface is penalty)."""
    gen, slave, master, load_set = PROBLEMS[problem]
    lines = gen(level)
    t = thickness(problem, level)
    d0 = slab.parse_2d(lines)
    ke = element_stiffness(d0, slave)
    K = float(f"{10.0 * ke:.4g}")
    sigma_inf = float(f"{1e-4 * reference_pressure(problem):.3g}")
    prints = ([f"*NODE PRINT, NSET={load_set}, TOTALS=ONLY", "RF"] if load_set else []) + ["*CONTACT PRINT", "CSTR, CDIS"]
    if problem == "interference":
        prints += ["*NODE FILE", "U"]          # ccx: the displacement (r = c) cross-check
    if disc != "NODE TO SURFACE":
        prints += ["*CONTACT FILE", "CSTR"]
    ccx_contact = ["*SURFACE INTERACTION, NAME=SI", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
                   f"{K:g}, {sigma_inf:g}, 0.001", f"*CONTACT PAIR, INTERACTION=SI, TYPE={disc}", f"{slave}, {master}"]
    native_out = ["*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*CONTACT OUTPUT", "CPRESS, COPEN, CNAREA"]
    decks = {}
    name = f"{problem}_l{level}_{tag(disc)}"
    text, d, off = slab.slab_deck(lines, t, ccx_contact, prints, ccx=True)
    decks["ccx"] = os.path.join(work, f"{name}_ccx.inp")
    # inpact runs the ccx deck without ccx's .frd requests (*NODE FILE / *CONTACT FILE): inpact
    # takes them for field output requests, and does not map CalculiX's CSTR (so a deck with
    # *CONTACT FILE, CSTR gets no field output at all)
    decks["ccx_for_inpact"] = os.path.join(work, f"{name}_ccx_for_inpact.inp")
    with open(decks["ccx_for_inpact"], "w") as f:
        f.write(strip_file_requests(text))
    direct = [] if disc == "NODE TO SURFACE" else ["*SURFACE BEHAVIOR, DIRECT"]
    for method, behavior in (("direct", direct), ("penalty", ["*SURFACE BEHAVIOR, PENALTY"])):
        contact = (["*SURFACE INTERACTION, NAME=SI"] + behavior +
                   [f"*CONTACT PAIR, INTERACTION=SI, TYPE={disc}", f"{slave}, {master}"])
        text_n, _, _ = slab.slab_deck(lines, t, contact, native_out, ccx=False)
        decks[method] = os.path.join(work, f"{name}_{method}.inp")
        with open(decks[method], "w") as f:
            f.write(text_n)
    text_nc, _, _ = slab.slab_deck(lines, t, [], native_out, no_contact=True, ccx=False)
    decks["nocontact"] = os.path.join(work, f"{problem}_l{level}_nocontact.inp")
    with open(decks["ccx"], "w") as f:
        f.write(text)
    with open(decks["nocontact"], "w") as f:
        f.write(text_nc)
    # the outer ring's free surface r = c (both layers), for the pressure its displacement implies
    outer = {}
    if problem == "interference":
        for n, x, y in d["nodes"]:
            if abs(math.hypot(x, y) - gcv.RING_C) < 1e-9:
                outer[n] = outer[n + off] = (x / gcv.RING_C, y / gcv.RING_C)
    geo = dict(t=t, off=off, K=K, ke=ke, sigma_inf=sigma_inf, load_set=load_set,
               slave=slab.slave_geometry(d, off, slave, t), n_nodes=2 * len(d["nodes"]), outer=outer)
    return decks, geo


def strip_file_requests(text):
    """The deck without *NODE FILE and *CONTACT FILE (and their data lines)."""
    out, skip = [], False
    for ln in text.splitlines():
        if ln.startswith("*") and not ln.startswith("**"):
            skip = ln.split(",")[0].strip().upper() in ("*NODE FILE", "*CONTACT FILE")
        if not skip:
            out.append(ln)
    return "\n".join(out) + "\n"


def timed(cmd, cwd, env=None):
    """Wall and CPU (user + system) of one process."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env)
    out = p.stdout.read().decode(errors="replace")
    _, status, ru = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    return p.returncode, time.perf_counter() - t0, ru.ru_utime + ru.ru_stime, out


def repeat(cmd, cwd, runs, env=None):
    walls, cpus, rc, out = [], [], 0, ""
    for _ in range(runs):
        rc, wall, cpu, out = timed(cmd, cwd, env)
        walls.append(wall)
        cpus.append(cpu)
        if rc != 0:
            break
    return rc, statistics.median(walls), statistics.median(cpus), out


# --------------------------------------------------------------------------- results

def inpact_results(h5, geo):
    with h5py.File(h5, "r") as f:
        labels = f["model/nodes/labels"][:]
        step = list(f["steps"].values())[-1]["fieldOutputs"]
        p = {}
        if "CPRESS" in step:
            cp = step["CPRESS/data"][-1][:, 0]
            p = {int(labels[r]): float(c) for r, c in zip(step["CPRESS/nodes"][:], cp)}
        force = None
        if geo["load_set"]:
            rows = f[f"model/sets/nsets/{geo['load_set']}"][:]
            rf_rows = step["RF/nodes"][:]
            force = float(step["RF/data"][-1][np.searchsorted(rf_rows, rows), 1].sum())
        ur = None
        if geo.get("outer") and "U" in step:
            u_rows, u = step["U/nodes"][:], step["U/data"][-1]
            index = {int(labels[r]): i for i, r in enumerate(u_rows)}
            ur = float(np.mean([u[index[n], 0] * cx + u[index[n], 1] * cy for n, (cx, cy) in geo["outer"].items()]))
        st = f["status"][:]
        return dict(p=p, force=force, ur=ur, newton=int(st["total_iters"].sum()), cutbacks=int(st["cut_back"].sum()))


def frd_last_block(path, name, column):
    """{node: value} of one column of the last `name` block (CONTACT, DISP) of a CalculiX .frd
    (fixed columns: ' -1', the node in 10 characters, then 12-character values)."""
    res, block = {}, None
    with open(path) as f:
        for ln in f:
            if ln.startswith(" -4"):
                block = {} if ln.split()[1] == name else None
            elif block is not None and ln.startswith(" -1"):
                block[int(ln[3:13])] = float(ln[13 + 12 * column:25 + 12 * column])
            elif block is not None and ln.startswith(" -3"):
                res, block = block, None
    return res


def frd_contact_pressure(path):
    """CPRESS per node of the last CONTACT block (COPEN CSLIP1 CSLIP2 CPRESS CSHEAR1 CSHEAR2)."""
    return frd_last_block(path, "CONTACT", 3)


def ccx_results(job, geo, disc):
    with open(job + ".dat") as f:
        text = f.read()
    blocks = re.split(r"\n\s*(?=contact stress|relative contact|total force|forces)", text)
    p, force, ips = {}, None, []
    for b in blocks:
        head, _, body = b.strip().partition("\n")
        rows = [ln.split() for ln in body.strip().splitlines() if ln.strip()]
        if head.startswith("contact stress"):
            if "element+face" in head:
                ips = [float(r[2]) for r in rows]
            else:
                p = {int(r[0]): float(r[1]) for r in rows}  # the last block (time 1) wins
        elif head.startswith("total force"):
            force = float(rows[0][1])
    newton = 0
    with open(job + ".cvg") as f:
        for ln in f:
            if re.match(r"\s+\d+\s+\d+\s+\d+\s+\d+", ln):
                newton += 1
    done = False
    with open(job + ".sta") as f:
        for ln in f:
            m = re.match(r"\s+\d+\s+\d+\s+\d+\s+\d+\s+(\S+)", ln)
            if m:
                done = abs(float(m.group(1).replace("D", "E")) - 1.0) < 1e-9
    ur = None
    if os.path.exists(job + ".frd"):
        if not p:  # surface to surface: nodal CPRESS from the .frd
            p = {n: v for n, v in frd_contact_pressure(job + ".frd").items() if n in geo["slave"]}
        if geo.get("outer"):
            ux, uy = frd_last_block(job + ".frd", "DISP", 0), frd_last_block(job + ".frd", "DISP", 1)
            if ux:
                ur = float(np.mean([ux[n] * cx + uy[n] * cy for n, (cx, cy) in geo["outer"].items()]))
    return dict(p=p, ips=ips, force=force, ur=ur, newton=newton, completed=done)


def errors(problem, res, geo):
    """Peak (Hertz) or mean (interference) pressure error."""
    p = res["p"]
    if problem == "hertz":
        P = 2.0 * abs(res["force"]) / geo["t"]     # per unit length, both halves
        e_star = gcv.E / (2.0 * (1.0 - gcv.NU ** 2))
        p0_ref = math.sqrt(P * e_star / (math.pi * gcv.R_HERTZ))
        if p:
            peak = 0.5 * (p.get(1, 0.0) + p.get(1 + geo["off"], 0.0))
        else:  # surface-to-surface in ccx: integration points, no coordinates: the largest
            peak = max(res.get("ips") or [0.0])
        return dict(error=(peak - p0_ref) / p0_ref, value=peak, ref=p0_ref, load=P)
    ref = figures.lame_pressure()
    if p:
        area = sum(a for a, _, _ in geo["slave"].values())
        mean = sum(p.get(n, 0.0) * a for n, (a, _, _) in geo["slave"].items()) / area
        spread = (max(p.values()) - min(p.get(n, 0.0) for n in geo["slave"])) / ref
    else:
        ips = res.get("ips") or [0.0]
        mean, spread = sum(ips) / len(ips), (max(ips) - min(ips)) / ref
    out = dict(error=(mean - ref) / ref, value=mean, ref=ref, spread=spread)
    if res.get("ur") is not None:
        # the mean pressure the outer ring's displacement at r = c implies (Lamé, plane strain:
        # u(c) = 2 (1 − ν²) p b² c / (E (c² − b²)) with b its inner radius)
        b, c = gcv.RING_B, gcv.RING_C
        u_ref = 2.0 * (1.0 - gcv.NU ** 2) * ref * b * b * c / (gcv.E * (c * c - b * b))
        out["error_ur"] = res["ur"] / u_ref - 1.0
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--floor", required=True, help="bench/solver_floor executable")
    ap.add_argument("--ccx", default="ccx")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--levels", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--problems", nargs="+", default=list(PROBLEMS), choices=list(PROBLEMS))
    ap.add_argument("--discretization", nargs="+", default=["NODE TO SURFACE", "SURFACE TO SURFACE"],
                    help="the pair's TYPE= in every deck (one run each)")
    ap.add_argument("--ccx-discretization", nargs="*", default=None,
                    help="the discretisations ccx runs too (default: all of --discretization)")
    ap.add_argument("--work", required=True)
    args = ap.parse_args()
    if args.ccx_discretization is None:
        args.ccx_discretization = args.discretization
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    env1 = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1", CCX_NPROC_STIFFNESS="1",
                CCX_NPROC_RESULTS="1", OPENBLAS_NUM_THREADS="1")
    inpact = os.path.abspath(args.inpact)
    rows, iters = [], []
    for problem in args.problems:
        for level in args.levels:
            inpact_rows = []
            for disc in args.discretization:
                decks, geo = build(problem, level, disc, work)
                base = dict(problem=problem, level=level, dof=3 * geo["n_nodes"], K=geo["K"], disc=tag(disc).upper())
                # ccx on its deck
                job = os.path.splitext(os.path.basename(decks["ccx"]))[0]
                if disc in args.ccx_discretization:
                    rc, wall, cpu, out = repeat([args.ccx, "-i", job], work, args.runs, env1)
                    row = dict(base, solver="ccx", variant=f"LINEAR K={geo['K']:.4g}", rc=rc, wall=wall, cpu=cpu)
                    try:
                        res = ccx_results(os.path.join(work, job), geo, disc)
                        row.update(newton=res["newton"], completed=res["completed"])
                        if res["completed"]:
                            row.update(errors(problem, res, geo))
                        else:
                            row["message"] = "did not reach the step end: " + " ".join(
                                ln.strip() for ln in out.splitlines() if "ERROR" in ln or "error" in ln)[:200]
                    except (OSError, ValueError, IndexError, KeyError) as e:
                        row["message"] = f"no results ({e}); " + out.strip().splitlines()[-1][:200] if out.strip() else ""
                    rows.append(row)
                    print(json.dumps(row), flush=True)
                # inpact on the same deck, and on its own decks
                for variant, deck in (("ccx deck (LINEAR)", decks["ccx_for_inpact"]),
                                      ("direct (default)" if disc == "NODE TO SURFACE" else "direct", decks["direct"]),
                                      ("penalty 10 k_e", decks["penalty"])):
                    jobname = os.path.splitext(os.path.basename(deck))[0] + "_inpact"
                    rc, wall, cpu, out = repeat([inpact, "run", deck, "-o", work, "-j", jobname, "-q", "--threads", "1"],
                                                work, args.runs, env1)
                    row = dict(base, solver="inpact", variant=variant, rc=rc, wall=wall, cpu=cpu)
                    if rc == 0:
                        res = inpact_results(os.path.join(work, jobname + ".h5"), geo)
                        row.update(newton=res["newton"], cutbacks=res["cutbacks"], completed=True)
                        row.update(errors(problem, res, geo))
                    else:
                        row["message"] = out.strip().splitlines()[-1][:200] if out.strip() else f"exit {rc}"
                    rows.append(row)
                    inpact_rows.append(row)
                    print(json.dumps(row), flush=True)
            # the cost of one Newton iteration against the floor
            jobname = f"{problem}_l{level}_nocontact_inpact"
            rc, wall_nc, cpu_nc, out = repeat([inpact, "run", decks["nocontact"], "-o", work, "-j", jobname, "-q",
                                               "--threads", "1"], work, args.runs, env1)
            n_nc = inpact_results(os.path.join(work, jobname + ".h5"), dict(geo, load_set=None))["newton"] if rc == 0 else 0
            floors = []
            for _ in range(args.runs):
                p = subprocess.run([args.floor, decks["nocontact"], "1"], capture_output=True, text=True, env=env1)
                floors.append(dict(kv.split("=") for kv in p.stdout.split()))
            pick = lambda k: statistics.median(float(f[k]) for f in floors)
            floor = dict(assembly=pick("assembly"), analyse=pick("analyse"), factor=pick("factor"), solve=pick("solve"),
                         residual=pick("residual"))
            one = floor["assembly"] + floor["factor"] + floor["solve"]
            for r in inpact_rows:
                if r.get("rc") != 0 or r["newton"] <= n_nc:
                    continue
                t_iter = (r["cpu"] - cpu_nc) / (r["newton"] - n_nc)
                iters.append(dict(problem=problem, level=level, dof=r["dof"], disc=r["disc"], variant=r["variant"],
                                  newton=r["newton"], cpu=r["cpu"], cpu_nc=cpu_nc, newton_nc=n_nc, t_iter=t_iter,
                                  floor=one, floor_analyse=floor["analyse"], residual=floor["residual"], ratio=t_iter / one))
                print(json.dumps(iters[-1]), flush=True)

    results = os.path.join(ROOT, "bench", "results")
    os.makedirs(results, exist_ok=True)
    discs = [tag(d) for d in args.discretization]
    suffix = "" if "nts" in discs else "_" + "_".join(discs)
    with open(os.path.join(results, f"contact_ccx{suffix}.json"), "w") as f:
        json.dump(dict(rows=rows, iterations=iters), f, indent=1)
    md = [f"# inpact against CalculiX ({', '.join(d.lower() for d in args.discretization)}; "
          f"{time.strftime('%Y-%m-%d %H:%M', time.gmtime())} UTC, median of {args.runs} runs, 1 thread each; "
          f"load average {os.getloadavg()[0]:.1f} at the end)", "",
          "Written by bench/contact_ccx/run.sh (ccx_bench.py). Plane-strain decks of decks/contact_verification/ extruded "
          "into one-element-thick C3D8 slabs (same mesh for both solvers). ccx deck: PRESSURE-OVERCLOSURE=LINEAR with "
          "K = 10 k_e (the default linear penalty), σ∞ = 1e-4 p_ref, c0 = 1e-3; inpact runs it too, and its own Abaqus "
          "deck with direct hard contact and with default linear penalty. disc.: the pair's TYPE (NTS node to surface, "
          "STS surface to surface) in all three decks. Error: Hertz — the symmetry node's pressure "
          "against p0 (Johnson §4.2) for the load carried; interference — Σ p A / Σ A over the slave nodes against "
          "Lamé. ccx surface to surface prints its contact stress per integration point without coordinates; its nodal "
          "CPRESS (extrapolated by ccx to the slave nodes, *CONTACT FILE → .frd) is used instead. error (u_r): "
          "interference only, the mean pressure the outer ring's radial displacement at r = c implies (Lamé, plane "
          "strain) against Lamé — a cross-check of the pressure output by the displacement field (ccx: *NODE FILE, U). "
          "inpact runs the ccx deck without its *NODE FILE / *CONTACT FILE lines. CPU = user + system "
          "time of the process (the machine is shared: wall times are noisy).", "",
          "| problem | level | DOF | disc. | solver | variant | error | error (u_r) | Newton | wall s | CPU s | note |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        err = f"{r['error']:+.2e}" if "error" in r else "—"
        note = r.get("message", "")
        if "spread" in r:
            note = (note + " " if note else "") + f"spread {r['spread']:.2f}"
        if r.get("cutbacks"):
            note = (note + " " if note else "") + f"{r['cutbacks']} cutbacks"
        if "error_ur" in r and abs(r["error"] - r["error_ur"]) > 0.1:
            note = (note + "; " if note else "") + "its CPRESS output is not the pressure its displacement implies"
        err_ur = f"{r['error_ur']:+.2e}" if "error_ur" in r else "—"
        md.append(f"| {r['problem']} | {r['level']} | {r['dof']} | {r['disc']} | {r['solver']} | {r['variant']} | {err} | "
                  f"{err_ur} | {r.get('newton', '—')} | {r['wall']:.2f} | {r['cpu']:.2f} | {note} |")
    md += ["", "## Time per inpact Newton iteration against one assembly + factorisation + solve", "",
           "t_iter = (CPU of the contact run − CPU of the same mesh without contact) / (difference in Newton iterations); "
           "floor = assembly + factor + solve of the no-contact system by bench/solver_floor (CHOLMOD, 1 thread; the "
           "symbolic analysis, reused across iterations, is shown apart). Goal: t_iter ≤ 1.5 × floor.", "",
           "| problem | level | DOF | disc. | variant | Newton | CPU s | no-contact CPU s (iters) | t_iter ms | floor ms "
           "(analyse) | residual-only assembly ms | t_iter / floor |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for it in iters:
        md.append(f"| {it['problem']} | {it['level']} | {it['dof']} | {it['disc']} | {it['variant']} | {it['newton']} | "
                  f"{it['cpu']:.2f} | {it['cpu_nc']:.2f} ({it['newton_nc']}) | {1e3 * it['t_iter']:.1f} | "
                  f"{1e3 * it['floor']:.1f} ({1e3 * it['floor_analyse']:.1f}) | {1e3 * it['residual']:.1f} | "
                  f"{it['ratio']:.2f} |")
    text = "\n".join(md) + "\n"
    with open(os.path.join(results, f"contact_ccx{suffix}.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
