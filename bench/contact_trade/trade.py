#!/usr/bin/python3
"""The contact speed/accuracy trade (issue 4, "Speed against accuracy"): the Hertz line contact and
interference-fit decks of decks/contact_verification/ at three mesh levels, for every enforcement
method and its main parameter, through the inpact executable with -P parameters:

  direct                      method=DIRECT
  penalty × 0.01 … 100        method=PENALTY, sf = *CONTACT CONTROLS, STIFFNESS SCALE FACTOR
  nonlinear penalty           method=PENALTY=NONLINEAR
  augmented Lagrange 1e-2 …   method=AUGMENTED LAGRANGE, *CONTACT CONTROLS, RELATIVE PENETRATION
                              TOLERANCE = tol (× the characteristic length)

each with the pair's discretisation node to surface (NTS) and surface to surface (STS), -P type=.

Per run: error of the peak pressure (Hertz: CPRESS at the symmetry node against p0 of Johnson
§4.2 for the load carried) or of the mean pressure (interference: Σ CPRESS·CNAREA / Σ CNAREA
against Lamé), the largest penetration, Newton iterations, augmentations, the wall time and the
CPU time (user + system) of the whole process (medians of RUNS runs; the machine is shared, CPU
time is the steadier figure). Writes bench/results/contact_trade.md and contact_trade.png (error
against CPU time per method and discretisation) and prints the table.

    trade.py --inpact BUILD/apps/inpact [--runs 3] [--levels 1 2 3] [--discretizations NTS STS]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import figures  # noqa: E402

VARIANTS = ([("direct", "direct", {"method": "DIRECT"})] +
            [("penalty", f"penalty ×{sf:g}", {"method": "PENALTY", "sf": f"{sf:g}"}) for sf in (0.01, 0.1, 1, 10, 100)] +
            [("nonlinear penalty", "nonlinear penalty", {"method": "PENALTY=NONLINEAR"})] +
            [("augmented Lagrange", f"augmented tol {tol:g}", {"method": "AUGMENTED LAGRANGE", "tol": f"{tol:g}"})
             for tol in (1e-2, 1e-3, 1e-4, 1e-5)])
DECKS = ("hertz_2d", "interference_2d")


def deck_path(work, name, level):
    return os.path.join(work, f"{name}.inp" if level == 1 else f"{name}_l{level}.inp")


DISCRETIZATIONS = {"NTS": "NODE TO SURFACE", "STS": "SURFACE TO SURFACE"}


def run_one(inpact, deck, params, work, job, runs):
    """Return code, median wall and CPU (user + system) time of the process, last message."""
    cmd = [inpact, "run", deck, "-o", work, "-j", job, "-q", "--threads", "1"]
    for k, v in params.items():
        cmd += ["-P", f"{k}={v}"]
    walls, cpus, rc, err = [], [], 0, ""
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    for _ in range(runs):
        t0 = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env)
        out = p.stdout.read().decode(errors="replace")
        _, status, ru = os.wait4(p.pid, 0)
        walls.append(time.perf_counter() - t0)
        cpus.append(ru.ru_utime + ru.ru_stime)
        rc, err = os.waitstatus_to_exitcode(status), out.strip().splitlines()
        if rc != 0:
            break
    msg = err[-1] if err else ""
    for cut in ("the analysis stopped: ", "error: "):  # keep the reason, not the path
        if cut in msg:
            msg = msg.split(cut, 1)[1]
    return rc, statistics.median(walls), statistics.median(cpus), msg


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--levels", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--work", default=None)
    ap.add_argument("--discretizations", nargs="+", default=list(DISCRETIZATIONS), choices=list(DISCRETIZATIONS))
    ap.add_argument("--decks", nargs="+", default=list(DECKS), choices=list(DECKS))
    args = ap.parse_args()
    work = args.work or os.path.join(os.path.dirname(os.path.abspath(args.inpact)), "..", "contact_trade")
    work = os.path.abspath(work)
    os.makedirs(work, exist_ok=True)
    gen = os.path.join(ROOT, "decks", "contact_verification", "gen_contact_verification.py")
    for level in args.levels:
        subprocess.run([sys.executable, gen, "--out", work, "--level", str(level), *DECKS], check=True)

    rows = []
    for name in args.decks:
        for level in args.levels:
            for disc in args.discretizations:
                for family, label, params in VARIANTS:
                    job = f"{name}_l{level}_{disc}_{label.replace(' ', '_').replace('×', 'x')}"
                    params = dict(params, type=DISCRETIZATIONS[disc])
                    rc, wall, cpu, msg = run_one(args.inpact, deck_path(work, name, level), params, work, job, args.runs)
                    row = {"deck": name, "level": level, "disc": disc, "family": family, "variant": label, "rc": rc,
                           "wall": wall, "cpu": cpu}
                    if rc == 0:
                        fg = figures.figures(os.path.join(work, job + ".h5"), name)
                        row.update(fg)
                        row["error"] = abs(fg["err_p0"] if name == "hertz_2d" else fg["err_mean"])
                    else:
                        row["message"] = msg
                    rows.append(row)
                    print(json.dumps({k: row[k] for k in ("deck", "level", "disc", "variant", "rc", "wall", "cpu")} |
                                     ({"error": round(row["error"], 5)} if rc == 0 else {"message": msg})), flush=True)

    # the characteristic length (augmented Lagrange's tolerance is relative to it), from inpact check
    lchar = {}
    for name in args.decks:
        for level in args.levels:
            for disc in args.discretizations:
                lchar[(name, level, disc)] = characteristic_length(args.inpact, deck_path(work, name, level), disc)
    for r in rows:
        if r["rc"] == 0 and r["family"] == "augmented Lagrange" and lchar.get((r["deck"], r["level"], r["disc"])):
            tol = float(r["variant"].split()[-1]) * lchar[(r["deck"], r["level"], r["disc"])]
            r["tol_abs"] = tol
            r["tol_met"] = r["max_penetration"] <= tol * (1 + 1e-9)

    results = os.path.join(ROOT, "bench", "results")
    os.makedirs(results, exist_ok=True)
    with open(os.path.join(work, "contact_trade.json"), "w") as f:
        json.dump(rows, f, indent=1)
    md = [f"# Contact speed/accuracy trade ({time.strftime('%Y-%m-%d %H:%M', time.gmtime())} UTC, "
          f"{os.cpu_count()} cores shared, median of {args.runs} run(s), 1 thread; load average "
          f"{os.getloadavg()[0]:.1f} at the end)", "",
          "Written by bench/contact_trade/run.sh. Decks: decks/contact_verification/ (level L: Hertz h = a/2^(L+1) "
          "at the contact; interference 24·2^(L−1)/34·2^(L−1) elements per quarter), run with -P type= (NTS node to "
          "surface, STS surface to surface) and -P method/sf/tol. Error: Hertz — CPRESS at the "
          "symmetry node against p0 (Johnson §4.2) for the load carried; interference — mean CPRESS "
          "(Σ CPRESS·CNAREA / Σ CNAREA) against Lamé. Penetration: the largest −COPEN of a closed node (augmented "
          "Lagrange: ✓ under its tolerance × the characteristic length of inpact check, ✗ over it); scatter: "
          "(max − min CPRESS)/p_Lamé. Newton: iterations of the step (severe ones included); cb: cutbacks. "
          "CPU = user + system time of the process.", ""]
    md += ["| deck | L | disc. | variant | error | max penetration | scatter / half-width | Newton | augm. | cb | CPU s | "
           "wall s |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["rc"] != 0:
            md.append(f"| {r['deck']} | {r['level']} | {r['disc']} | {r['variant']} | exit {r['rc']}: "
                      f"{r['message'][:160]} | | | | | | {r['cpu']:.2f} | {r['wall']:.2f} |")
            continue
        extra = (f"{r['scatter']:.2f}" if r["deck"] == "interference_2d"
                 else f"a {r['a_fe']:.3f} (ref {r['a_ref']:.3f})")
        pen = f"{r['max_penetration']:.2e}"
        if "tol_met" in r:
            pen += f" {'✓' if r['tol_met'] else '✗'} {r['tol_abs']:.1e}"
        md.append(f"| {r['deck']} | {r['level']} | {r['disc']} | {r['variant']} | {r['error']:.2e} | {pen} | {extra} | "
                  f"{r['newton']} | {r['augmentations']} | {r['cutbacks']} | {r['cpu']:.2f} | {r['wall']:.2f} |")
    text = "\n".join(md) + "\n"
    with open(os.path.join(results, "contact_trade.md"), "w") as f:
        f.write(text)
    print(text)
    plot(rows, args.decks, os.path.join(results, "contact_trade.png"))
    print(f"wrote {results}/contact_trade.md and contact_trade.png")


def characteristic_length(inpact, deck, disc):
    """The pair's characteristic length from `inpact check` (its augmented Lagrange line:
    'penetration tolerance X % of the characteristic length = Y')."""
    p = subprocess.run([inpact, "check", deck, "-P", "method=AUGMENTED LAGRANGE", "-P", f"type={DISCRETIZATIONS[disc]}"],
                       capture_output=True, text=True)
    m = re.search(r"penetration tolerance ([\d.eE+-]+) % of the characteristic length = ([\d.eE+-]+)", p.stdout)
    return float(m.group(2)) / (float(m.group(1)) / 100.0) if m else None


def plot(rows, decks, path):
    """Error against CPU time: one panel per deck, colour per method, marker per discretisation
    (filled: node to surface, open: surface to surface); a line joins the levels of one variant."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(decks), figsize=(7 * len(decks), 6), squeeze=False)
    colours = {"direct": "tab:blue", "penalty": "tab:orange", "nonlinear penalty": "tab:green",
               "augmented Lagrange": "tab:red"}
    markers = {"NTS": "o", "STS": "s"}
    for ax, name in zip(axes[0], decks):
        for disc, marker in markers.items():
            for family, colour in colours.items():
                pts = [r for r in rows if r["deck"] == name and r["family"] == family and r["disc"] == disc
                       and r["rc"] == 0]
                if not pts:
                    continue
                ax.scatter([r["cpu"] for r in pts], [max(r["error"], 1e-6) for r in pts], marker=marker,
                           facecolors=colour if disc == "NTS" else "none", edgecolors=colour,
                           label=f"{family} ({disc})", s=28)
                for variant in sorted({r["variant"] for r in pts}):
                    line = sorted((r for r in pts if r["variant"] == variant), key=lambda r: r["level"])
                    if len(line) > 1:
                        ax.plot([r["cpu"] for r in line], [max(r["error"], 1e-6) for r in line], color=colour,
                                alpha=0.25, linewidth=0.8, linestyle="-" if disc == "NTS" else "--")
                for r in pts:
                    ax.annotate(f"L{r['level']}", (r["cpu"], max(r["error"], 1e-6)), fontsize=5, alpha=0.7)
        failed = [r for r in rows if r["deck"] == name and r["rc"] != 0]
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("CPU time of the inpact run [s] (user + system, 1 thread)")
        ax.set_ylabel("peak pressure error |p0 − p0_Hertz| / p0_Hertz" if name == "hertz_2d"
                      else "mean pressure error |p − p_Lamé| / p_Lamé")
        ax.set_title(f"{name}" + (f" ({len(failed)} runs stopped, not shown)" if failed else ""))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
