#!/usr/bin/python3
"""compare_solvers.py: `inpact run --solver petsc` against `--solver direct` on every contact
verification deck (decks/contact_verification, each enforcement method its <method> parameter
takes: direct multipliers, penalty, augmented Lagrange) and the friction decks of decks/contact.

A case passes when both runs completed and every field of every frame agrees to 1e-6 of the
field's largest value over the step (max |petsc − direct| <= 1e-6 · max |direct|). A case
over it is rerun with Newton converged to R_n = 1e-9 on both paths: when the direct run differs
itself by more than 1e-6 from its own tightened run, Newton's criterion leaves more open than
1e-6 in any correct answer, and the case is judged on the tightened runs (saying so), provided
the petsc run's default answer is no more than 10 times as far from the converged one.

  /usr/bin/python3 bench/petsc_solver/compare_solvers.py --inpact build/apps/inpact [--out DIR] [--only NAME...]
                                                         [--ranks N]
writes DIR/compare.md (a table) and prints it. With --ranks N the PETSc runs are distributed:
`mpirun -np N inpact run ...` (the solver then is PETSc without asking).
"""
import argparse, glob, math, os, re, subprocess, sys, time
import h5py, numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
LENGTHS = ("COPEN", "CSLIP1", "CSLIP2")
ROUND_OFF = 1e-12  # inpact compare's default absolute atol (io/compare.hpp)
METHODS = {"direct": "DIRECT", "penalty": "PENALTY", "auglag": "AUGMENTED LAGRANGE"}


def cases(extra=()):
    out = [(os.path.basename(deck)[:-4], os.path.abspath(deck), {}) for deck in extra]
    for deck in sorted(glob.glob(os.path.join(ROOT, "decks/contact_verification/*.inp"))):
        name = os.path.basename(deck)[:-4]
        if "<method>" in open(deck).read():
            out += [(f"{name}-{m}", deck, {"method": v}) for m, v in METHODS.items()]
        else:
            out.append((name, deck, {}))
    for deck in sorted(glob.glob(os.path.join(ROOT, "decks/contact/*friction*.inp"))):
        out.append((os.path.basename(deck)[:-4], deck, {}))
    return out


def mpirun(ranks, unbound=False):
    """The launcher's words for `ranks` processes on this machine (as root too, in CI);
    `unbound`: no rank bound to a core (a rank's element threads may use them all)."""
    if ranks <= 1:
        return []
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    return ["mpirun", "-np", str(ranks), "--oversubscribe"] + (["--bind-to", "none"] if unbound else [])


def run(inpact, deck, job, params, solver, out, reuse=False, ranks=1):
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, job + ".timings")
    if reuse and os.path.exists(os.path.join(out, job + ".h5")) and os.path.exists(path):
        timings = dict((k, float(v)) for k, _, v in (l.strip().partition("=") for l in open(path)))
        with h5py.File(os.path.join(out, job + ".h5")) as f:
            rc = 0 if f.attrs["status"] == "COMPLETED" else 4
        return rc, timings.get("total_s", 0.0), timings, [] if rc == 0 else ["(reused: the run stopped)"]
    cmd = mpirun(ranks) + [inpact, "run", deck, "-j", job, "-o", out, "-q", "--solver", solver,
           "--timings", os.path.join(out, job + ".timings")]
    for k, v in params.items():
        cmd += ["-P", f"{k}={v}"]
    t0 = time.time()
    rc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seconds = time.time() - t0
    timings = {}
    path = os.path.join(out, job + ".timings")
    if os.path.exists(path):
        for line in open(path):
            k, _, v = line.strip().partition("=")
            timings[k] = float(v)
    return rc.returncode, seconds, timings, rc.stderr.strip().splitlines()[-1:] if rc.returncode else []


def fields(path):
    """{(step, field, frame): data} of a results file, and the Newton iterations of its .sta table."""
    out = {}
    with h5py.File(path) as f:
        for step, g in f["steps"].items():
            for key, fo in g.get("fieldOutputs", {}).items():
                data = fo["data"][()]
                for i in range(data.shape[0]):
                    out[(step, key, i)] = data[i]
        iters = int(np.sum(f["status"]["total_iters"])) if "status" in f else -1
    return out, iters


def worst_difference(a, b):
    """Largest max|a−b| / max|a| over the fields of a, with its field and frame. max|a| is the
    field's largest value over the step's frames; for the lengths COPEN and CSLIP at least the
    step's largest |U|: a closed contact's COPEN is round-off of the coordinates (1e-16), and
    is measured in the units of the motion instead, and the moment RM and section force SF of a
    symmetric load in those of the forces RF (inpact compare's frame-max rule, io/compare.hpp).
    Differences within ROUND_OFF are none (compare's absolute atol): a field that is zero in
    exact arithmetic (the stress of a rigid rotation) has no scale of its own."""
    if set(a) != set(b):
        return float("inf"), "structure: " + str(sorted(set(a) ^ set(b))[:3])
    scale = {}
    for (step, key, _), x in a.items():
        if x.size:
            scale[(step, key)] = max(scale.get((step, key), 0.0), float(np.nanmax(np.abs(x))))
    worst, where = 0.0, ""
    for k, x in a.items():
        y = b[k]
        if x.shape != y.shape or not np.array_equal(np.isnan(x), np.isnan(y)):
            return float("inf"), f"{k}: shape or NaN"
        if not x.size:
            continue
        s = scale[(k[0], k[1])]
        if k[1] in LENGTHS:
            s = max(s, scale.get((k[0], "U"), 0.0))
        if k[1] in ("RM", "SF"):
            s = max(s, scale.get((k[0], "RF"), 0.0))
        diff = float(np.nanmax(np.abs(x - y)))
        if diff <= ROUND_OFF:
            continue
        rel = diff / s if s > 0 else (0.0 if diff == 0 else float("inf"))
        if rel > worst:
            worst, where = rel, f"{k[1]} step {k[0]} frame {k[2]}"
    return worst, where


TIGHT_R_N = 1e-9  # Newton's R_n and C_n of the rerun of a case that differs (newton_tolerance_verdict)


STATIC_LINE = re.compile(r"\s*\*\s*STATIC\b", re.I)
OWN_CONTROLS = re.compile(r"^\s*\*\s*(CONTROLS|INCLUDE)\b|\bINPUT\s*=", re.I | re.M)


def tightened_deck(deck, out):
    """A copy of `deck` in `out` whose every *STATIC step converges Newton to TIGHT_R_N (a
    *CONTROLS before its *STATIC line); None when the deck sets its own *CONTROLS (which would
    rule) or reads other files (their paths are relative to it)."""
    text = open(deck).read()
    if OWN_CONTROLS.search(text):
        return None
    controls = f"*CONTROLS, PARAMETERS=FIELD\n{TIGHT_R_N:g}, {TIGHT_R_N:g}\n"
    lines = text.splitlines(keepends=True)
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, os.path.basename(deck)[:-4] + "_tight.inp")
    with open(path, "w") as f:
        f.write("".join((controls if STATIC_LINE.match(l) else "") + l for l in lines))
    return path


def newton_tolerance_verdict(a, job, deck, params, direct_fields, petsc_fields):
    """A case over the tolerance, rerun with Newton converged to TIGHT_R_N on both paths. When
    the direct run itself is farther than the tolerance from its own tightened run, Newton's
    criterion leaves more open than the tolerance asks of the solvers, and they are compared
    where it does not. It passes when the tightened runs agree and the petsc run's default
    answer is as close to the converged one as the direct run's, within a factor of 10 (the two
    default paths stop at different points of the same tolerance; a wrong answer is farther by
    orders). Returns (tightened runs' worst difference, direct's distance, petsc's) or None."""
    tight = tightened_deck(deck, os.path.join(a.out, "tight"))
    if tight is None:
        return None
    rc_d, _, _, _ = run(a.inpact, tight, job, params, "direct", os.path.join(a.out, "tight", "direct"), a.reuse)
    rc_p, _, _, _ = run(a.inpact, tight, job, params, "petsc", os.path.join(a.out, "tight", "petsc"), a.reuse, a.ranks)
    if rc_d != 0 or rc_p != 0:
        return None
    td, _ = fields(os.path.join(a.out, "tight", "direct", job + ".h5"))
    tp, _ = fields(os.path.join(a.out, "tight", "petsc", job + ".h5"))
    tight_worst, _ = worst_difference(td, tp)
    direct_off, _ = worst_difference(td, direct_fields)  # (inf when the frames differ)
    petsc_off, _ = worst_difference(td, petsc_fields)
    converged_apart = math.isfinite(direct_off) and direct_off > a.tolerance
    if converged_apart and tight_worst <= a.tolerance and petsc_off <= 10 * direct_off:
        return tight_worst, direct_off, petsc_off
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--out", default="compare_solvers.out")
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--tolerance", type=float, default=1e-6)
    ap.add_argument("--ranks", type=int, default=1, help="MPI ranks of the PETSc runs (mpirun -np N)")
    ap.add_argument("--extra", nargs="*", default=[], help="more decks, each a case named by its file")
    ap.add_argument("--reuse", action="store_true",
                    help="compare the results already in --out (times: the runs' total_s) instead of running")
    a = ap.parse_args()
    rows = [f"| case | direct s | petsc{f' ({a.ranks} ranks)' if a.ranks > 1 else ''} s | Newton direct / petsc | Krylov its | worst rel. diff | where | pass |",
            "|---|---|---|---|---|---|---|---|"]
    failed = 0
    for job, deck, params in cases(a.extra):
        if a.only and not any(o in job for o in a.only):
            continue
        rc_d, s_d, _, err_d = run(a.inpact, deck, job, params, "direct", os.path.join(a.out, "direct"), a.reuse)
        rc_p, s_p, t_p, err_p = run(a.inpact, deck, job, params, "petsc", os.path.join(a.out, "petsc"), a.reuse,
                                    a.ranks)
        if rc_d != 0 or rc_p != 0:
            same = rc_d == rc_p
            rows.append(f"| {job} | {s_d:.1f} | {s_p:.1f} | exit {rc_d} / {rc_p} | | | {' '.join(err_d + err_p)[:120]} | "
                        f"{'both stop alike' if same else 'NO'} |")
            failed += not same
            print(rows[-1], flush=True)
            continue
        fd, it_d = fields(os.path.join(a.out, "direct", job + ".h5"))
        fp, it_p = fields(os.path.join(a.out, "petsc", job + ".h5"))
        worst, where = worst_difference(fd, fp)
        ok = worst <= a.tolerance
        verdict = "yes" if ok else "NO"
        if not ok:
            newton = newton_tolerance_verdict(a, job, deck, params, fd, fp)
            if newton:
                ok = True
                verdict = (f"at R_n {TIGHT_R_N:g}: {newton[0]:.1e} (from the default R_n to it direct moves "
                           f"{newton[1]:.1e}, petsc {newton[2]:.1e})")
        failed += not ok
        rows.append(f"| {job} | {s_d:.1f} | {s_p:.1f} | {it_d} / {it_p} | {int(t_p.get('krylov_iterations', 0))} | "
                    f"{worst:.2e} | {where} | {verdict} |")
        print(rows[-1], flush=True)
    text = "\n".join(rows) + "\n"
    os.makedirs(a.out, exist_ok=True)  # (no case may have run)
    with open(os.path.join(a.out, "compare.md"), "w") as f:
        f.write(text)
    print(text)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
