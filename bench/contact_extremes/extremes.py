#!/usr/bin/python3
"""Contact at the extremes (issue 4, "Speed against accuracy, and the extremes"): each case is run
by the inpact executable and checked against its analytic answer, then classified as

  right          converged, and the answer is right (the error is given)
  stopped        stopped with a diagnostic (exit code and message; read it: is it clear?)
  wrong, warned  converged to a wrong answer, and a warning of the run says why (ν = 0.4999 locking)
  WRONG          converged to a wrong answer silently, or wrote NaN — must never happen

Cases (two-block patch test of blocks.py unless said otherwise; p = applied load / area exactly):
  penalty   STIFFNESS SCALE FACTOR 1e-6 … 1e8 for linear penalty, augmented Lagrange and nonlinear
            penalty, under load (pressure) and displacement control; a given stiffness of 1e20
  modulus   E_slave / E_master 1e-6 … 1e6 (stiff slave on soft master and the reverse)
  size      element size 1e3 times smaller on one side of the interface than on the other
  nu        ν = 0.4999: the patch test (uniaxial strain: no locking possible), and Hertz line contact
            (decks/contact_verification, level 1) with CPE4 (locks), CPE4R and CPE4I
  gap       initial gaps 0 and 1e-12 of the model size, overclosures 1e-12 and 1e-6 of it
  units     the same decks in mm/N/MPa and in m/N/Pa: every result must scale exactly
  start     bodies held only by contact: the Hertz cylinder resting on its block at one node and
            pushed by a force (hertz_2d_force.inp, every method), and the patch's upper block
            0.001 above the lower one under its pressure, with *CONTACT STABILIZATION or
            *STATIC, STABILIZE (free until the contact closes; unstabilised it stops, see gap)

Right means: every interface node's CPRESS within 1e-3 of p (general contact: both surfaces), the top's displacement within 1e-3 of
the analytic one (augmented Lagrange: the analytic one plus the penetration it reports, which
must be under its tolerance), no NaN anywhere in the results file. Hertz: the peak pressure within
3 % of p0 (Johnson §4.2) for the load carried (the ν = 0.3 error of the same mesh is 0.7 % with
node to surface, 0.8 … 2.1 % with surface to surface).

    extremes.py --inpact BUILD/apps/inpact [--groups penalty modulus ...]
                [--discretization "NODE TO SURFACE" | "SURFACE TO SURFACE" | GENERAL] [--compare OLD.json]

--discretization GENERAL replaces the pair by general contact (*CONTACT INCLUSIONS, ALL EXTERIOR);
its Hertz cases are not run. --compare adds a section of what changed against an earlier run.
Writes bench/results/contact_extremes[_surface_to_surface|_general].md and .json, prints the table.
"""
import argparse
import json
import math
import os
import re
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
import blocks  # noqa: E402
import figures  # noqa: E402
import gen_contact_verification as gcv  # noqa: E402

TOL = 1e-3          # relative error of a right answer in the patch test
APPROX = "approx (coarse slave)"
UNITS_TOL = 1e-9    # m against mm, relative (raised to 10 k ε L / p for a stiff penalty: roundoff_pressure)
HERTZ_TOL = 0.03    # relative error of the Hertz peak pressure (level 1, h = a/4: node to surface is
                    # within 0.7 % at ν = 0.3, surface to surface within 0.8 … 2.1 %; locking: +50 … +110 %)
METHODS = {"direct": "DIRECT", "penalty": "PENALTY", "augmented": "AUGMENTED LAGRANGE",
           "nonlinear": "PENALTY=NONLINEAR"}


# --------------------------------------------------------------------------- running one deck

def run(inpact, deck_path, work, job, params=()):
    cmd = [inpact, "run", deck_path, "-o", work, "-j", job]
    for k, v in params:
        cmd += ["-P", f"{k}={v}"]
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        rc, out = p.returncode, (p.stdout or "") + (p.stderr or "")
    except subprocess.TimeoutExpired as e:
        rc, out = -1, f"TIMEOUT after 600 s {e}"
    wall = time.perf_counter() - t0
    text = [ln for ln in out.splitlines() if ln.strip()]
    msg = text[-1] if text else ""
    if rc != 0:
        # the error lines, not the progress lines; keep the reason, not the path
        errs = [ln for ln in text if "error:" in ln or "stopped" in ln] or text[-1:]
        msg = " / ".join(errs)
        for cut in ("the analysis stopped: ", "error: "):
            msg = re.sub(r"\S+\.inp(:\d+:\d+)?: " + cut, "", msg)
        msg = re.sub(r"\S+\.inp: ", "", msg)
    warnings = [ln.split("warning:", 1)[1].strip() for ln in text if "warning:" in ln]
    info = {}
    for key, pat in (("k", r"\bk = ([-+.\deE]+)"), ("kf", r"K_f = ([-+.\deE]+)"), ("ke", r"k_e = ([-+.\deE]+)")):
        found = [float(x.rstrip(",;.")) for x in re.findall(pat, out)]
        if found:
            info[key] = found[0]
            info[key + "_all"] = found
    # how the pair's law is enforced, from the pair line inpact prints at the step's start
    if "Lagrange multipliers (slope >" in out:
        info["enforcement"] = "multipliers"
    elif "direct hard contact" in out:
        info["enforcement"] = "direct"
    elif "augmented Lagrange" in out:
        info["enforcement"] = "augmented"
    elif "penalty" in out:
        info["enforcement"] = "penalty"
    return dict(rc=rc, msg=msg, wall=wall, warnings=warnings, printed=info, output=out)


def read_h5(path):
    """Last frame's fields, the status table, NaN anywhere."""
    r = {}
    with h5py.File(path, "r") as f:
        r["status_attr"] = f.attrs.get("status")
        if isinstance(r["status_attr"], bytes):
            r["status_attr"] = r["status_attr"].decode()
        nan = []
        for sname, step in f["steps"].items():
            for key, g in step["fieldOutputs"].items():
                d = g["data"][:]
                bad = ~np.isfinite(d)
                if key == "COPEN" and "CPRESS" in step["fieldOutputs"]:
                    # documented (solver/contact_results.hpp): COPEN is NaN where no master face is
                    # in range; such a node must be open (CPRESS 0)
                    cp = step["fieldOutputs"]["CPRESS"]["data"][:]
                    bad &= ~((cp == 0) & np.isnan(d))
                if d.size and bad.any():
                    nan.append(f"{sname}/{key}")
        r["nan"] = nan
        step = list(f["steps"].values())[-1]
        fo = step["fieldOutputs"]
        for key in ("CPRESS", "COPEN", "CNAREA", "U", "RF"):
            if key in fo and fo[key]["data"].shape[0]:
                r[key] = fo[key]["data"][-1]
                r[key + "_rows"] = fo[key]["nodes"][:]
        r["sets"] = {k: v[:] for k, v in f["model/sets/nsets"].items()}
        st = f["status"][:]
        r["newton"] = int(st["total_iters"].sum())
        r["augmentations"] = int(st["augmentations"].sum())
        r["cutbacks"] = int(st["cut_back"].sum())
        r["increments"] = int((st["cut_back"] == 0).sum())
    return r


def nodal(r, key, nset, comp):
    rows = r[key + "_rows"]
    idx = np.searchsorted(rows, r["sets"][nset])
    return r[key][idx, comp]


# --------------------------------------------------------------------------- the patch test

def check_patch(r, exp, method):
    """Errors of one patch-test run against blocks.expectation. Only the interface's nodes (set
    IFACE) count: general contact reports CPRESS on every exterior node of both bodies."""
    up = exp["dim"] - 1
    sel = np.isin(r["CPRESS_rows"], r["sets"]["IFACE"]) if "IFACE" in r["sets"] else slice(None)
    cp = r["CPRESS"][sel, 0]
    pen = -r["COPEN"][sel, 0]
    p = exp["p"]
    out = {"cp_err": float(np.abs(cp - p).max() / p) if p > 0 else float(np.abs(cp).max()),
           "penetration": float(np.nanmax(pen)), "p_ref": p, "cp_range": (float(cp.min()), float(cp.max()))}
    ca = r["CNAREA"][sel, 0] if "CNAREA" in r else None
    u = float(nodal(r, "U", "TOP", up).mean())
    u_ref = exp["u_top"]
    if method == "AUGMENTED LAGRANGE":
        # its penetration is whatever it stopped at (under the tolerance): the exact answer for it
        h = max(out["penetration"], 0.0)
        out["pen_ok"] = h <= exp["tol_pen"] * (1 + 1e-9)
        if exp["load"] == "pressure":
            u_ref -= h
        else:
            p = max(exp["d"] - exp["gap"] - h, 0.0) / exp["compliance"]
            out["p_ref"] = p
            out["cp_err"] = float(np.abs(cp - p).max() / p) if p > 0 else float(np.abs(cp).max())
    out["u_err"] = abs(u - u_ref) / abs(u_ref) if u_ref else abs(u)
    if exp["penetration"] > 0:
        out["pen_err"] = abs(out["penetration"] - exp["penetration"]) / exp["penetration"]
    force = out["p_ref"] * exp["force"] / exp["p"] if exp["p"] else 0.0
    out["rf_err"] = abs(float(nodal(r, "RF", "BOTTOM", up).sum()) - force) / force if force else 0.0
    if ca is not None and force:
        # the force the reported pressures carry, Σ CPRESS·CNAREA over the interface (balanced
        # general contact: both surfaces, each row's areas halved, so the sum is the force once)
        out["pa_err"] = abs(float((cp * ca).sum()) - force) / force
    return out


def roundoff_pressure(exp):
    """The pressure a penalty law makes of the round-off of a gap measured from coordinates of the
    model's size: k ε L (relative to p). Two runs of the same deck in other units differ by it."""
    if not exp.get("k") or not exp["p"]:
        return 0.0
    L = exp["W"] + abs(exp["u_top"]) + exp["compliance"] * exp["p"]  # ≈ the interface's coordinates
    return exp["k"] * np.finfo(float).eps * L / exp["p"]


def classify(row, errors_ok, detail, exact=True, warned=False):
    """warned: a wrong answer a warning of the run explains (not silent) → 'wrong, warned'."""
    if row["rc"] != 0:
        row["class"] = "stopped"
        row["what"] = f"exit {row['rc']}: {row['msg']}"
        return
    if row.get("nan"):
        row["class"] = "WRONG"
        row["what"] = "NaN in " + ", ".join(row["nan"])
        return
    if row.get("status_attr") != "COMPLETED":
        row["class"] = "WRONG"
        row["what"] = f"exit 0 but results status {row.get('status_attr')}"
        return
    row["class"] = "right" if errors_ok else ("WRONG" if exact and not warned else
                                              "wrong, warned" if warned else APPROX)
    row["what"] = detail


def patch_case(args, group, label, exact=True, **kw):
    """exact=False: a mesh on which node-to-surface is known not to pass the patch test (a coarse
    slave on a finer master whose nodes are not under slave nodes): an error is APPROX. Surface to
    surface integrates segment by segment between the master facets' edges
    (contact/mortar_segments.hpp) and passes it: exact=True there."""
    kw.setdefault("discretization", args.discretization)
    text, exp = blocks.deck(**kw)
    job = f"{group}_{label}".replace(" ", "_").replace("=", "").replace("/", "_")
    path = os.path.join(args.work, job + ".inp")
    with open(path, "w") as f:
        f.write(text)
    row = dict(group=group, case=label, job=job, exp={k: v for k, v in exp.items() if v is not None})
    row.update(run(args.inpact, path, args.work, job))
    row["enforcement"] = row["printed"].get("enforcement", "")
    if row["rc"] == 0:
        r = read_h5(os.path.join(args.work, job + ".h5"))
        row.update({k: r[k] for k in ("status_attr", "nan", "newton", "augmentations", "cutbacks", "increments")})
        if not r["nan"] and "CPRESS" in r:
            e = check_patch(r, exp, kw.get("method", "DIRECT"))
            row.update(e)
            ok = e["cp_err"] <= TOL and e["u_err"] <= TOL and e["rf_err"] <= TOL and e.get("pen_ok", True)
            detail = f"CPRESS {e['cp_err']:.1e}, U {e['u_err']:.1e}"
            if e["cp_err"] > TOL:
                detail += f" (CPRESS {e['cp_range'][0]:.4g} … {e['cp_range'][1]:.4g}, p = {e['p_ref']:.4g})"
            if e["rf_err"] > TOL:
                detail += f", RF {e['rf_err']:.1e}"
            if "pa_err" in e and (exp["general"] or e["pa_err"] > TOL):
                detail += f", ΣCPRESS·CNAREA {e['pa_err']:.1e}"
            if "pen_err" in e:
                if exp["penetration"] < 100 * np.finfo(float).eps * (exp["W"] + abs(exp["u_top"])):
                    detail += f", pen {e['penetration']:.1e} (p/k {exp['penetration']:.1e}: at round-off)"
                else:
                    detail += f", pen {e['pen_err']:.1e}"
            if "pen_ok" in e:
                detail += f", pen {e['penetration']:.2g} {'≤' if e['pen_ok'] else '>'} tol {exp['tol_pen']:.2g}"
            if "ke_all" in row["printed"]:
                # the distinct values: general contact's two rows print the same (averaged) k_e,
                # and a stiff law (multipliers) keeps one row of the two
                distinct = lambda v: [x for i, x in enumerate(sorted(v)) if i == 0 or abs(x - sorted(v)[i - 1]) > 1e-3 * x]
                want = distinct(exp["kes"])
                got = distinct(row["printed"]["ke_all"])
                if len(got) != len(want) or any(abs(a - b) > 1e-3 * b for a, b in zip(got, want)):
                    detail += f"; k_e printed {', '.join(f'{x:.4g}' for x in got)} ≠ {', '.join(f'{x:.4g}' for x in want)}"
            # a stabilised run that ends with damping left in says so (ALLSD against ALLSE), and a
            # penetration deeper than the search can trust too (ContactProblem::deep_penetration_warning)
            warned = any("stabiliz" in w or "penetrates its master" in w for w in row.get("warnings", []))
            classify(row, ok, detail, exact, warned=warned and not ok)
        else:
            classify(row, False, "no contact output")
    else:
        classify(row, False, "")
    row["fields"] = r if row["rc"] == 0 else None
    report(row)
    return row


def report(row):
    short = {k: row.get(k) for k in ("group", "case", "class", "what", "newton", "augmentations", "cutbacks")}
    short["wall"] = round(row["wall"], 2)
    print(json.dumps(short, ensure_ascii=False), flush=True)


# --------------------------------------------------------------------------- groups

SF = [1e-6, 1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6, 1e8]


def group_penalty(args):
    rows = []
    base = blocks.deck()[1]
    # displacement control: the top moved by the approach that gives p = 10 with direct contact
    d = -base["u_top"]
    for name in ("penalty", "augmented", "nonlinear"):
        for sf in SF:
            for load in ("pressure", "displacement"):
                rows.append(patch_case(args, "penalty", f"{name} sf={sf:g} {load}", method=METHODS[name], sf=sf,
                                       load=load, d=d))
    rows.append(patch_case(args, "penalty", "penalty sf=200 pressure", method="PENALTY", sf=200.0))
    rows.append(patch_case(args, "penalty", "penalty k=1e20 given pressure", method="PENALTY", stiffness=1e20))
    rows.append(patch_case(args, "penalty", "penalty k=1e-20 given pressure", method="PENALTY", stiffness=1e-20))
    return rows


def group_modulus(args):
    rows = []
    E = 210000.0
    for r in (1e-6, 1e-4, 1e-2, 1e2, 1e4, 1e6):
        es, em = E * r, E
        p = 1e-4 * min(es, em)  # strains ≤ 1e-4 in the softer block
        for name in ("direct", "penalty", "augmented"):
            rows.append(patch_case(args, "modulus", f"Es/Em={r:g} {name}", Es=es, Em=em, p=p, method=METHODS[name]))
    return rows


def group_size(args):
    rows = []
    W = 2.0
    cases = {  # label: slave n, rows, height; master n, rows, height
        "slave h/1000 (1000 on 1)": dict(ns=1000, nms=1, Hs=W / 1000, nm=1, nmm=1, Hm=W),
        "master h/1000 (1 on 1000)": dict(ns=1, nms=1, Hs=W, nm=1000, nmm=1, Hm=W / 1000),
        "slave h/1000 non-nested (1000 on 3)": dict(ns=1000, nms=1, Hs=W / 1000, nm=3, nmm=3, Hm=W),
        "master h/1000 non-nested (3 on 1000)": dict(ns=3, nms=3, Hs=W, nm=1000, nmm=1, Hm=W / 1000),
    }
    for label, geo in cases.items():
        # a coarse slave on a fine master: node to surface lets master nodes between slave nodes
        # penetrate the slave face (APPROX); surface to surface (pairs and general contact)
        # integrates segment by segment (contact/mortar_segments.hpp) and must pass exactly
        exact = geo["ns"] >= geo["nm"] or args.discretization != "NODE TO SURFACE"
        for name in ("direct", "penalty", "augmented"):
            rows.append(patch_case(args, "size", f"{label} {name}", exact=exact, method=METHODS[name], **geo))
    return rows


def hertz_case(args, group, label, nu, elem, params, unit="mm"):
    if args.discretization == blocks.GENERAL:
        # figures.py reads the peak at the symmetry node of the slave; general contact reports
        # both bodies (and its balanced rows each their own k g): not comparable, not run
        row = dict(group=group, case=label, job="", rc=None, wall=0.0, warnings=[], printed={}, fields=None,
                   **{"class": "not run", "what": "Hertz deck with general contact: not run (figures.py reads one slave surface)"})
        report(row)
        return row
    old = gcv.NU
    gcv.NU = nu
    try:
        text = "\n".join(gcv.hertz_2d(1)) + "\n"
    finally:
        gcv.NU = old
    # the deck's discretisation is its *PARAMETER type (TYPE=<type> on the pair)
    assert 'type = "NODE TO SURFACE"' in text
    text = text.replace("TYPE=CPE4,", f"TYPE={elem},").replace('type = "NODE TO SURFACE"',
                                                                  f'type = "{args.discretization}"')
    if unit == "m":
        text = blocks.to_metres(text)
    job = f"{group}_{label}".replace(" ", "_").replace("=", "").replace("/", "_").replace(".", "p")
    path = os.path.join(args.work, job + ".inp")
    with open(path, "w") as f:
        f.write(text)
    row = dict(group=group, case=label, job=job)
    row.update(run(args.inpact, path, args.work, job, params))
    row["enforcement"] = row["printed"].get("enforcement", "")
    row["fields"] = None
    if row["rc"] == 0:
        r = read_h5(os.path.join(args.work, job + ".h5"))
        row["fields"] = r
        row.update({k: r[k] for k in ("status_attr", "nan", "newton", "augmentations", "cutbacks", "increments")})
        if unit == "mm" and not r["nan"]:
            figures.E_STAR = gcv.E / (2.0 * (1.0 - nu * nu))
            fg = figures.figures(os.path.join(args.work, job + ".h5"), "hertz_2d")
            row["err_p0"] = fg["err_p0"]
            detail = (f"p0 {fg['err_p0']:+.1e} (p0 {fg['p0']:.4g}, ref {fg['p0_ref']:.4g}), a {fg['a_fe']:.3g} "
                      f"(ref {fg['a_ref']:.3g}), load {fg['P']:.4g}")
            locking = [w for w in row["warnings"] if "lock" in w]
            if abs(fg["err_p0"]) > HERTZ_TOL and nu > 0.49 and elem in ("CPE4", "C3D8"):
                detail += (" — volumetric locking of the fully integrated element, " +
                           ("the run warns of it" if locking else "no warning printed"))
            classify(row, abs(fg["err_p0"]) <= HERTZ_TOL, detail, warned=bool(locking))
        else:
            classify(row, not r["nan"], "(compared with mm below)")
    else:
        classify(row, False, "")
    report(row)
    return row


def group_nu(args):
    rows = []
    for elem2, elem3 in (("CPE4", "C3D8"), ("CPE4R", "C3D8R"), ("CPE4I", "C3D8I")):
        for name in ("direct", "penalty"):
            rows.append(patch_case(args, "nu", f"patch 2D {elem2} nu=0.4999 {name}", elem=elem2, nus=0.4999,
                                   num=0.4999, method=METHODS[name]))
            rows.append(patch_case(args, "nu", f"patch 3D {elem3} nu=0.4999 {name}", dim=3, elem=elem3, nus=0.4999,
                                   num=0.4999, method=METHODS[name]))
    for nu in (0.3, 0.4999):
        for elem in ("CPE4", "CPE4R", "CPE4I"):
            for name in ("direct", "penalty"):
                rows.append(hertz_case(args, "nu", f"Hertz {elem} nu={nu:g} {name}", nu, elem,
                                       [("method", METHODS[name])]))
    return rows


def group_gap(args):
    rows = []
    L = 2.0  # model size: width and total height
    base = blocks.deck()[1]
    d = -base["u_top"]
    gaps = (("0", 0.0), ("+1e-12 L", 1e-12 * L), ("-1e-12 L", -1e-12 * L), ("-1e-6 L", -1e-6 * L),
            ("+1e-6 L", 1e-6 * L))
    for dim in (2, 3):
        for glabel, g in gaps:
            if dim == 3 and glabel in ("-1e-6 L", "+1e-6 L"):
                continue
            for name in ("direct", "penalty", "augmented", "nonlinear"):
                for load in ("pressure", "displacement"):
                    rows.append(patch_case(args, "gap", f"{dim}D gap {glabel} {name} {load}", dim=dim, gap=g,
                                           method=METHODS[name], load=load, d=d))
    return rows


def group_start(args):
    """Bodies held only by contact. Force-driven: the cylinder of decks/contact_verification/
    hertz_2d_force.inp resting on its block at one node and pushed by a force (Hertz p0 within
    HERTZ_TOL of the load the block's base carries). Stabilised: the patch test's upper block
    0.001 above the lower one under its pressure, free until the contact closes, with
    *CONTACT STABILIZATION or *STATIC, STABILIZE (the exact answer of the closed contact)."""
    rows = []
    for name in ("direct", "penalty", "augmented"):
        rows.append(force_hertz_case(args, f"Hertz under a force {name}", [("method", METHODS[name])]))
    for dim in (2, 3):
        for how in ("contact", "static"):
            for name in ("direct", "penalty", "augmented"):
                rows.append(patch_case(args, "start", f"{dim}D gap 0.001 {how} stabilized {name}", dim=dim, gap=0.001,
                                       method=METHODS[name], stabilize=how))
    return rows


def force_hertz_case(args, label, params):
    path = os.path.join(ROOT, "decks", "contact_verification", "hertz_2d_force.inp")
    job = f"start_{label}".replace(" ", "_")
    disc = "SURFACE TO SURFACE" if args.discretization == blocks.GENERAL else args.discretization
    row = dict(group="start", case=label, job=job)
    row.update(run(args.inpact, path, args.work, job, list(params) + [("type", disc)]))
    row["enforcement"] = row["printed"].get("enforcement", "")
    row["fields"] = None
    if row["rc"] != 0:
        classify(row, False, "")
        report(row)
        return row
    h5 = os.path.join(args.work, job + ".h5")
    r = read_h5(h5)
    row.update({k: r[k] for k in ("status_attr", "nan", "newton", "augmentations", "cutbacks", "increments")})
    with h5py.File(h5, "r") as f:
        x = f["model/nodes/coordinates"][:]
    bottom = np.isin(r["RF_rows"], r["sets"]["BLOCK_BOTTOM"])
    load = 2.0 * float(r["RF"][bottom, 1].sum())  # both halves, per unit length
    e_star = gcv.E / (2.0 * (1.0 - gcv.NU ** 2))
    p0_ref = math.sqrt(load * e_star / (math.pi * gcv.R_HERTZ))
    rows = r["CPRESS_rows"]
    axis = rows[np.argmin(np.abs(x[rows, 0]) + np.abs(x[rows, 1]))]  # the slave node touching at the start
    p0 = float(r["CPRESS"][np.searchsorted(r["CPRESS_rows"], axis), 0])
    err = p0 / p0_ref - 1.0
    detail = f"p0 {err:+.1e} (p0 {p0:.4g}, ref {p0_ref:.4g}), load {load:.5g}, {disc.lower()}"
    classify(row, not r["nan"] and abs(err) <= HERTZ_TOL, detail)
    report(row)
    return row


def compare_scaled(a, b, dim, length):
    """Largest relative difference between run a (mm) and run b (m) scaled back to mm. COPEN:
    differences up to 100 ε × length (the model size in mm: the round-off of a gap measured from
    coordinates) are ignored, and the rest is relative to at least Newton's contact compatibility
    tolerance, 1e-3 of the largest displacement (direct contact's COPEN is that noise)."""
    worst = {}
    for key, s in (("CPRESS", 1e6), ("COPEN", 1e-3), ("CNAREA", 1e-3 ** (dim - 1)), ("U", 1e-3),
                   ("RF", blocks.force_scale(dim))):
        if key not in a or key not in b:
            continue
        x, y = a[key], b[key] / s
        both = np.isnan(x) & np.isnan(y)  # COPEN of a node with no master in range, in both
        x, y = np.where(both, 0.0, x), np.where(both, 0.0, y)
        ref = np.abs(x).max()
        diff = np.abs(x - y)
        if np.isnan(diff).any():
            worst[key] = float("inf")
            continue
        if key == "COPEN":
            # a gap is measured from coordinates: its round-off (100 ε L) is no unit dependence;
            # direct contact closes to Newton's compatibility tolerance (1e-3 of the increment's
            # displacement, solver/newton.cpp), not to zero: that much of COPEN is noise
            ref = max(ref, 1e-3 * float(np.abs(a["U"]).max()))
            diff = np.maximum(diff - 100 * np.finfo(float).eps * length, 0.0)
        worst[key] = float(diff.max() / ref) if ref > 0 else float(np.abs(y).max())
    return worst


def group_units(args):
    rows = []
    for dim in (2, 3):
        for name in ("direct", "penalty", "augmented", "nonlinear"):
            pair = [patch_case(args, "units", f"{dim}D patch {name} {unit}", dim=dim, unit=unit, method=METHODS[name])
                    for unit in ("mm", "m")]
            rows += scale_pair(pair, dim)
    for name in ("direct", "penalty", "augmented", "nonlinear"):
        pair = [hertz_case(args, "units", f"Hertz {name} {unit}", 0.3, "CPE4", [("method", METHODS[name])], unit)
                for unit in ("mm", "m")]
        rows += scale_pair(pair, 2)
    return rows


def scale_pair(pair, dim):
    a, b = pair
    if a["rc"] == 0 and b["rc"] == 0 and a["fields"] and b["fields"]:
        worst = compare_scaled(a["fields"], b["fields"], dim, 2 * a["exp"]["W"] if "exp" in a
                               else gcv.HERTZ_W + gcv.HERTZ_H)
        w = max(worst.values()) if worst else float("nan")
        same_iters = (a["newton"], a["augmentations"]) == (b["newton"], b["augmentations"])
        b["scale_diff"] = worst
        # m and mm coordinates round differently: a penalty law turns the gap's round-off ε L
        # into k ε L of pressure (1000 k_e: ~2e-8 of p); anything above 10 × that, or 1e-9, is a
        # unit dependence
        limit = max(UNITS_TOL, 10.0 * roundoff_pressure(a["exp"])) if "exp" in a else UNITS_TOL
        b["units_limit"] = limit
        # Iterations: the same deck in other units should take the same path; a different path
        # to the same answer (round-off deciding a contact status) is noted, not failed.
        ok = w <= limit and b["class"] != "WRONG"
        iters = "" if same_iters else f"; iterations (Newton/augm.) {a['newton']}/{a['augmentations']} (mm) vs " \
                                      f"{b['newton']}/{b['augmentations']} (m): another path"
        b["class"] = "right" if ok else "WRONG"
        prefix = b["what"] + "; " if b["what"] and "compared" not in b["what"] else ""
        b["what"] = prefix + f"m vs mm: max rel. diff {w:.1e} {'≤' if w <= limit else '>'} {limit:.0e} " + \
            f"({', '.join(f'{k} {v:.0e}' for k, v in worst.items())}){iters}"
    elif (a["rc"] == 0) != (b["rc"] == 0):
        b["class"] = "WRONG"
        b["what"] = f"mm exit {a['rc']}, m exit {b['rc']}: {b['what'] or a['what']}"
    report(b)
    return [a, b]


GROUPS = {"penalty": group_penalty, "modulus": group_modulus, "size": group_size, "nu": group_nu, "gap": group_gap,
          "units": group_units, "start": group_start}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--groups", nargs="+", default=list(GROUPS), choices=list(GROUPS))
    ap.add_argument("--discretization", default="NODE TO SURFACE",
                    help='TYPE= of *CONTACT PAIR ("SURFACE TO SURFACE"), or GENERAL: *CONTACT, ALL EXTERIOR')
    ap.add_argument("--compare", help="an earlier run's contact_extremes*.json: a section of what changed")
    args = ap.parse_args()
    args.work = os.path.abspath(args.work)
    os.makedirs(args.work, exist_ok=True)
    rows = []
    for g in args.groups:
        rows += GROUPS[g](args)
    for r in rows:
        r.pop("fields", None)
        r.pop("output", None)

    results = os.path.join(ROOT, "bench", "results")
    os.makedirs(results, exist_ok=True)
    suffix = "" if args.discretization == "NODE TO SURFACE" else "_" + args.discretization.lower().replace(" ", "_")
    with open(os.path.join(results, f"contact_extremes{suffix}.json"), "w") as f:
        json.dump(rows, f, indent=1, default=str)
    title = "general contact, ALL EXTERIOR" if args.discretization == blocks.GENERAL else args.discretization.lower()
    md = [f"# Contact at the extremes ({title}; {time.strftime('%Y-%m-%d %H:%M', time.gmtime())} UTC, "
          f"load average {os.getloadavg()[0]:.1f} at the end)", "",
          "Written by bench/contact_extremes/run.sh (extremes.py; decks by blocks.py). "
          "right = converged and within the tolerance of the analytic answer (patch test: CPRESS of every "
          f"interface node and the top's displacement within {TOL:g}; Hertz: peak pressure within {HERTZ_TOL:g} of p0; "
          f"units: m and mm results equal within {UNITS_TOL:g} after scaling — or 10 k ε L / p, the round-off a penalty "
          "law k makes of a gap measured from coordinates of size L; a different iteration count is noted); "
          f"{APPROX} = converged on a mesh where node to surface is known not to pass the patch test (a coarse slave on "
          "a fine master; node to surface only: surface to surface integrates segment by segment and must pass), error given; stopped = exit code and message; wrong, warned = a wrong answer the run warns of; "
          "WRONG = a wrong answer or NaN, silently. Errors are relative; pen = penetration against p/k (penalty) or the "
          "nonlinear law (\"at round-off\": p/k below 100 ε L, the coordinates' round-off); ΣCPRESS·CNAREA = the force "
          "the reported pressures carry, against the load. enf. = how the law was enforced, from the pair line "
          "inpact prints (multipliers: a penalty-type law stiffer than 1000 k_e, table 38.1.21). "
          "Newton = all iterations of the step (severe ones and cut-back attempts included).", "",
          "Totals: " + totals(rows) + ".", ""]
    if args.compare:
        md += compare_section(rows, args.compare)
    md += ["| group | case | result | enf. | error / message | Newton | augm. | cutbacks | wall s |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        what = (r.get("what") or "").replace("|", "/")
        if r.get("warnings"):
            what += " [warning: " + "; ".join(r["warnings"])[:200] + "]"
        md.append(f"| {r['group']} | {r['case']} | {r['class']} | {r.get('enforcement', '')} | {what[:400]} | "
                  f"{r.get('newton', '')} | {r.get('augmentations', '')} | {r.get('cutbacks', '')} | {r['wall']:.2f} |")
    text = "\n".join(md) + "\n"
    with open(os.path.join(results, f"contact_extremes{suffix}.md"), "w") as f:
        f.write(text)
    print(text)


CLASSES = ("right", APPROX, "stopped", "wrong, warned", "WRONG", "not run")
OLD_NAMES = {"approx (NTS)": APPROX}  # class names of earlier runs


def totals(rows):
    counts = {c: sum(r["class"] == c for r in rows) for c in CLASSES}
    return ", ".join(f"{n} {c}" for c, n in counts.items() if n or c in ("right", "stopped", "WRONG"))


def compare_section(rows, path):
    """What changed against an earlier run's .json (same discretisation): class transitions and
    the cases that changed class."""
    with open(path) as f:
        old = {(r["group"], r["case"]): dict(r, **{"class": OLD_NAMES.get(r["class"], r["class"])}) for r in json.load(f)}
    md = [f"## Against {os.path.basename(path)} ({totals(list(old.values()))})", ""]
    moves = {}
    for r in rows:
        o = old.get((r["group"], r["case"]))
        key = (o["class"] if o else "new case", r["class"])
        moves.setdefault(key, []).append((r, o))
    md += ["| before → now | cases |", "|---|---|"]
    for (a, b), items in sorted(moves.items(), key=lambda kv: -len(kv[1])):
        md.append(f"| {a} → {b} | {len(items)} |")
    md += ["", "| group | case | before | now | before: error / message |", "|---|---|---|---|---|"]
    for (a, b), items in moves.items():
        if a == b:
            continue
        for r, o in items:
            was = ((o or {}).get("what") or "").replace("|", "/")[:160]
            md.append(f"| {r['group']} | {r['case']} | {a} | {b} | {was} |")
    gone = [k for k in old if k not in {(r["group"], r["case"]) for r in rows}]
    if gone:
        md += ["", "Cases of the earlier run not run now: " + "; ".join(f"{g} {c}" for g, c in gone)]
    return md + [""]


if __name__ == "__main__":
    main()
