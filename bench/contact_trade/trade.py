#!/usr/bin/python3
"""The contact speed/accuracy trade (issue 4, "Speed against accuracy"): the Hertz line contact and
interference-fit decks of decks/contact_verification/ at three mesh levels, for every enforcement
method and its main parameter, through the inpact executable with -P parameters:

  direct                      method=DIRECT
  penalty × 0.01 … 100        method=PENALTY, sf = *CONTACT CONTROLS, STIFFNESS SCALE FACTOR
  nonlinear penalty           method=PENALTY=NONLINEAR
  augmented Lagrange 1e-2 …   method=AUGMENTED LAGRANGE, *CONTACT CONTROLS, RELATIVE PENETRATION
                              TOLERANCE = tol (× the characteristic length)

Per run: error of the peak pressure (Hertz: CPRESS at the symmetry node against p0 of Johnson
§4.2 for the load carried) or of the mean pressure (interference: Σ CPRESS·CNAREA / Σ CNAREA
against Lamé), the largest penetration, Newton iterations, augmentations and the wall time
(median of RUNS runs of the whole process). Writes bench/results/contact_trade.md and
contact_trade.png and prints the table.

    trade.py --inpact BUILD/apps/inpact [--runs 3] [--levels 1 2 3]
"""
import argparse
import json
import os
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


def run_one(inpact, deck, params, work, job, runs):
    cmd = [inpact, "run", deck, "-o", work, "-j", job, "-q"]
    for k, v in params.items():
        cmd += ["-P", f"{k}={v}"]
    times, rc, err = [], 0, ""
    for _ in range(runs):
        t0 = time.perf_counter()
        p = subprocess.run(cmd, capture_output=True, text=True)
        times.append(time.perf_counter() - t0)
        rc, err = p.returncode, (p.stderr or p.stdout).strip().splitlines()
        if rc != 0:
            break
    msg = err[-1] if err else ""
    for cut in ("the analysis stopped: ", "error: "):  # keep the reason, not the path
        if cut in msg:
            msg = msg.split(cut, 1)[1]
    return rc, statistics.median(times), msg


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--levels", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--work", default=None)
    args = ap.parse_args()
    work = args.work or os.path.join(os.path.dirname(os.path.abspath(args.inpact)), "..", "contact_trade")
    work = os.path.abspath(work)
    os.makedirs(work, exist_ok=True)
    gen = os.path.join(ROOT, "decks", "contact_verification", "gen_contact_verification.py")
    for level in args.levels:
        subprocess.run([sys.executable, gen, "--out", work, "--level", str(level), *DECKS], check=True)

    rows = []
    for name in DECKS:
        for level in args.levels:
            for family, label, params in VARIANTS:
                job = f"{name}_l{level}_{label.replace(' ', '_').replace('×', 'x')}"
                rc, wall, msg = run_one(args.inpact, deck_path(work, name, level), params, work, job, args.runs)
                row = {"deck": name, "level": level, "family": family, "variant": label, "rc": rc, "wall": wall}
                if rc == 0:
                    fg = figures.figures(os.path.join(work, job + ".h5"), name)
                    row.update(fg)
                    row["error"] = abs(fg["err_p0"] if name == "hertz_2d" else fg["err_mean"])
                else:
                    row["message"] = msg
                rows.append(row)
                print(json.dumps({k: row[k] for k in ("deck", "level", "variant", "rc", "wall")} |
                                 ({"error": round(row["error"], 5)} if rc == 0 else {"message": msg})), flush=True)

    results = os.path.join(ROOT, "bench", "results")
    os.makedirs(results, exist_ok=True)
    with open(os.path.join(work, "contact_trade.json"), "w") as f:
        json.dump(rows, f, indent=1)
    md = [f"# Contact speed/accuracy trade ({time.strftime('%Y-%m-%d %H:%M', time.gmtime())} UTC, "
          f"{os.cpu_count()} cores, median of {args.runs} runs)", "",
          "Written by bench/contact_trade/run.sh. Decks: decks/contact_verification/ (level L: Hertz h = a/2^(L+1) "
          "at the contact; interference 24·2^(L−1)/34·2^(L−1) elements per quarter). Error: Hertz — CPRESS at the "
          "symmetry node against p0 (Johnson §4.2) for the load carried; interference — mean CPRESS "
          "(Σ CPRESS·CNAREA / Σ CNAREA) against Lamé. Penetration: the largest −COPEN of a closed node; scatter: "
          "(max − min CPRESS)/p_Lamé. Iterations: Newton iterations of the step (severe ones included).", ""]
    md += ["| deck | level | variant | error | max penetration | scatter / half-width | Newton | augm. | wall s |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["rc"] != 0:
            md.append(f"| {r['deck']} | {r['level']} | {r['variant']} | exit {r['rc']}: {r['message'][:160]} | | | | | "
                      f"{r['wall']:.2f} |")
            continue
        extra = (f"{r['scatter']:.2f}" if r["deck"] == "interference_2d"
                 else f"a {r['a_fe']:.3f} (ref {r['a_ref']:.3f})")
        md.append(f"| {r['deck']} | {r['level']} | {r['variant']} | {r['error']:.2e} | {r['max_penetration']:.2e} | "
                  f"{extra} | {r['newton']} | {r['augmentations']} | {r['wall']:.2f} |")
    text = "\n".join(md) + "\n"
    with open(os.path.join(results, "contact_trade.md"), "w") as f:
        f.write(text)
    print(text)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    markers = {"direct": "o", "penalty": "s", "nonlinear penalty": "^", "augmented Lagrange": "D"}
    for ax, name in zip(axes, DECKS):
        for family, marker in markers.items():
            pts = [(r["wall"], max(r["error"], 1e-6)) for r in rows
                   if r["deck"] == name and r["family"] == family and r["rc"] == 0]
            if pts:
                ax.scatter(*zip(*pts), marker=marker, label=family)
        for r in rows:
            if r["deck"] == name and r["rc"] == 0:
                ax.annotate(f"L{r['level']}", (r["wall"], max(r["error"], 1e-6)), fontsize=6)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time of inpact run [s] (median)")
        ax.set_ylabel("peak pressure error" if name == "hertz_2d" else "mean pressure error")
        ax.set_title(name)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(results, "contact_trade.png"), dpi=120)
    print(f"wrote {results}/contact_trade.md and contact_trade.png")


if __name__ == "__main__":
    main()
