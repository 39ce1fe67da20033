#!/usr/bin/python3
"""Smoothing against mesh density (issue 5, "The trade"): how coarse a mesh can be with geometric
correction for the accuracy of a finer faceted one, and what that saves in time and memory.

Cases (each through the inpact executable, `/usr/bin/time -v`):
  interference   decks/contact_verification/gen_contact_verification.py --level L, the decks
                 interference_2d (faceted) and interference_2d_smoothed (*SURFACE SMOOTHING of both
                 rings), surface to surface (-P type="SURFACE TO SURFACE"), direct and penalty
                 (-P method=...). Error per slave node: CPRESS / p_Lame - 1, p_Lame the exact
                 small-strain answer of the two radii (lame_2d()).
  pin_in_hole    decks/gen_pin_in_hole.py --level L [--faceted]: general contact, penalty, mu 0.1.
                 The exact answer is axisymmetric but not known in closed form (short press fit):
                   circumferential error: per ring of slave nodes (one pass, one axial position) whose
                     mean pressure is at least a tenth of the largest ring mean, CPRESS / ring mean - 1;
                   N error: N = sum CPRESS CNAREA (both passes) against the finest smoothed level's.

Per case: max and mean |error| over the nodes, Newton iterations (all attempts), increments, CPU
(user + sys) and wall seconds (medians of --runs runs; the expensive pin levels run --runs-big
times), peak RSS (median), and the 1-minute load average before each case. Writes
bench/results/smoothing_trade.md and smoothing_trade.png and prints the table.

    trade.py --inpact BUILD/apps/inpact [--runs 3] [--runs-big 1] [--levels-2d 1 2 3] [--levels-pin 1 2 3]
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

E, NU = 210000.0, 0.3
RING_A, RING_B, RING_C, DELTA = 0.5, 1.0, 2.0, 0.01  # gen_contact_verification.py
PIN_B, PIN_DELTA, PIN_C = 5.0, 0.025, 10.0           # gen_pin_in_hole.py
BIG_SECONDS = 20.0  # a case whose first run takes longer is not repeated beyond --runs-big


def lame_2d():
    """The exact small-strain answer of the deck's geometry: the outer ring's bore b and the inner
    ring's outer radius b + δ each take their own Lamé compliance (plane strain, E' = E/(1−ν²),
    ν' = ν/(1−ν)): δ = p/E' [b ((c²+b²)/(c²−b²) + ν') + b1 ((b1²+a²)/(b1²−a²) − ν')]. 0.66 % above
    the one-radius formula of tests/contact_verification/ (b at the middle of the overlap)."""
    ep, nup = E / (1 - NU * NU), NU / (1 - NU)
    a, b, b1, c = RING_A, RING_B, RING_B + DELTA, RING_C
    return ep * DELTA / (b * ((c * c + b * b) / (c * c - b * b) + nup) + b1 * ((b1 * b1 + a * a) / (b1 * b1 - a * a) - nup))


def lame_2d_mid():
    ep = E / (1 - NU * NU)
    a, b, c = RING_A, RING_B + 0.5 * DELTA, RING_C
    return ep * DELTA * (c * c - b * b) * (b * b - a * a) / (2 * b ** 3 * (c * c - a * a))


def lame_pin():
    return E * PIN_DELTA * (PIN_C ** 2 - PIN_B ** 2) / (2 * PIN_B * PIN_C ** 2)


def last_frame(h5):
    step = h5["steps"][list(h5["steps"].keys())[-1]]
    return step["fieldOutputs"], -1


def contact_fields(path):
    with h5py.File(path, "r") as h5:
        fo, fr = last_frame(h5)
        out = {k: fo[k]["data"][fr, :, 0] for k in ("CPRESS", "CNAREA")}
        out["nodes"] = fo["CPRESS"]["nodes"][:]
        out["pair"] = fo["CPRESS"]["pair"][:]
        out["X"] = h5["model/nodes/coordinates"][:]
        status = h5["status"][:]
        out["iterations"] = int(status["total_iters"].sum())
        out["increments"] = int(len(h5["steps"][list(h5["steps"].keys())[-1]]["frames/step_time"]))
        out["cutbacks"] = int(status["cut_back"].sum())
    return out


def interference_errors(path):
    c = contact_fields(path)
    e = c["CPRESS"] / lame_2d() - 1.0
    return {"max_err": float(np.max(np.abs(e))), "mean_err": float(np.mean(np.abs(e))),
            "min_p": float(c["CPRESS"].min() / lame_2d()), "max_p": float(c["CPRESS"].max() / lame_2d()),
            "iterations": c["iterations"], "increments": c["increments"], "cutbacks": c["cutbacks"]}


def pin_errors(path):
    c = contact_fields(path)
    p, a = c["CPRESS"], c["CNAREA"]
    axial = np.round(c["X"][c["nodes"], 0], 6)
    rings = {}
    for i in range(len(p)):
        rings.setdefault((int(c["pair"][i]), float(axial[i])), []).append(p[i])
    means = {k: float(np.mean(v)) for k, v in rings.items()}
    top = max(means.values()) if means else 0.0
    devs = []
    for k, v in rings.items():
        if top > 0 and means[k] >= 0.1 * top:
            devs += list(np.abs(np.array(v) / means[k] - 1.0))
    return {"N": float(np.sum(p * a)), "closed": int(np.sum(p > 0)),
            "max_err": float(max(devs)) if devs else float("nan"),
            "mean_err": float(np.mean(devs)) if devs else float("nan"),
            "rings": sum(1 for k in rings if top > 0 and means[k] >= 0.1 * top),
            "iterations": c["iterations"], "increments": c["increments"], "cutbacks": c["cutbacks"]}


def timed(cmd, runs, log):
    """Runs cmd `runs` times under /usr/bin/time -v; medians of CPU, wall and peak RSS."""
    cpu, wall, rss, rc, msg = [], [], [], 0, ""
    for k in range(runs):
        load = os.getloadavg()[0]
        p = subprocess.run(["/usr/bin/time", "-v", "-o", log] + cmd, capture_output=True, text=True)
        rc = p.returncode
        if rc != 0:
            msg = ((p.stderr or p.stdout).strip().splitlines() or [""])[-1]
            break
        t = {}
        with open(log) as f:
            for line in f:
                key, _, val = line.strip().rpartition(": ")
                t[key] = val
        cpu.append(float(t["User time (seconds)"]) + float(t["System time (seconds)"]))
        h, _, rest = t["Elapsed (wall clock) time (h:mm:ss or m:ss)"].rpartition(":")
        wall.append(float(rest) + 60.0 * sum(float(x) * 60 ** i for i, x in enumerate(reversed(h.split(":"))) if x))
        rss.append(float(t["Maximum resident set size (kbytes)"]) / 1024.0)
        if k == 0 and wall[0] > BIG_SECONDS:
            runs = min(runs, 1)
        if k + 1 >= runs:
            break
    if rc != 0:
        return {"rc": rc, "message": msg, "load": load}
    return {"rc": 0, "cpu": statistics.median(cpu), "wall": statistics.median(wall), "rss": statistics.median(rss),
            "runs": len(cpu), "load": load}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--runs-big", type=int, default=1, help="runs of a case that takes over 20 s")
    ap.add_argument("--levels-2d", type=int, nargs="*", default=[1, 2, 3])
    ap.add_argument("--levels-pin", type=int, nargs="*", default=[1, 2, 3])
    ap.add_argument("--work", default=None)
    ap.add_argument("--report-only", action="store_true",
                    help="rewrite the table and the plot from WORK/smoothing_trade.json without running")
    args = ap.parse_args()
    work = os.path.abspath(args.work or tempfile.mkdtemp(prefix="smoothing_trade-"))
    if args.report_only:
        with open(os.path.join(work, "smoothing_trade.json")) as f:
            saved = json.load(f)
        report(saved["rows"], saved["load0"], saved["load1"], saved["runs"], saved["runs_big"], work, saved["when"])
        return
    os.makedirs(work, exist_ok=True)
    gen2d = os.path.join(ROOT, "decks", "contact_verification", "gen_contact_verification.py")
    genpin = os.path.join(ROOT, "decks", "gen_pin_in_hole.py")
    for level in args.levels_2d:
        subprocess.run([sys.executable, gen2d, "--out", work, "--level", str(level), "interference_2d",
                        "interference_2d_smoothed"], check=True)
    for level in args.levels_pin:
        for extra in ([], ["--faceted"]):
            subprocess.run([sys.executable, genpin, "--out", work, "--level", str(level), *extra], check=True)
    log = os.path.join(work, "time.log")
    load0 = os.getloadavg()
    when = time.strftime("%Y-%m-%d %H:%M", time.gmtime())
    rows = []

    def case(kind, level, smoothed, method, deck, params, runs):
        job = os.path.splitext(os.path.basename(deck))[0] + "_" + method.lower()
        cmd = [args.inpact, "run", deck, "-o", work, "-j", job, "-q"]
        for k, v in params.items():
            cmd += ["-P", f"{k}={v}"]
        row = {"case": kind, "level": level, "smoothed": smoothed, "method": method}
        row.update(timed(cmd, runs, log))
        if row["rc"] == 0:
            h5 = os.path.join(work, job + ".h5")
            row.update(interference_errors(h5) if kind == "interference" else pin_errors(h5))
        rows.append(row)
        print(json.dumps({k: (round(v, 5) if isinstance(v, float) else v) for k, v in row.items()}), flush=True)

    sfx = lambda level: "" if level == 1 else f"_l{level}"
    for level in args.levels_2d:
        for smoothed in (False, True):
            deck = os.path.join(work, ("interference_2d_smoothed" if smoothed else "interference_2d") + sfx(level) + ".inp")
            for method in ("DIRECT", "PENALTY"):
                case("interference", level, smoothed, method, deck, {"type": "SURFACE TO SURFACE", "method": method},
                     args.runs)
    for level in args.levels_pin:
        for smoothed in (True, False):
            deck = os.path.join(work, ("pin_in_hole" if smoothed else "pin_in_hole_faceted") + sfx(level) + ".inp")
            case("pin_in_hole", level, smoothed, "PENALTY", deck, {}, args.runs if level == 1 else args.runs_big)
    load1 = os.getloadavg()
    with open(os.path.join(work, "smoothing_trade.json"), "w") as f:
        json.dump({"rows": rows, "load0": load0, "load1": load1, "runs": args.runs, "runs_big": args.runs_big,
                   "when": when}, f, indent=1)
    report(rows, load0, load1, args.runs, args.runs_big, work, when)


def report(rows, load0, load1, runs, runs_big, work, when):
    # The pin's reference: N of the finest smoothed level.
    pins = [r for r in rows if r["case"] == "pin_in_hole" and r["rc"] == 0]
    ref = max((r for r in pins if r["smoothed"]), key=lambda r: r["level"], default=None)
    for r in pins:
        r["N_err"] = abs(r["N"] / ref["N"] - 1.0) if ref and ref["N"] > 0 else float("nan")

    mesh_2d = {lv: f"{24 * 2 ** (lv - 1)}/{34 * 2 ** (lv - 1)}" for lv in (1, 2, 3, 4)}
    mesh_pin = {1: "4/6, 1.0", 2: "6/8, 0.75", 3: "8/11, 0.5"}
    md = [f"# Smoothing against mesh density ({when} UTC, "
          f"{os.cpu_count()} cores shared, load average {load0[0]:.2f} at the start, {load1[0]:.2f} at the end)", "",
          "Written by `bench/smoothing_trade/run.sh`. CPU = user + sys of the whole `inpact run` process, median of "
          f"{runs} runs ({runs_big} for cases over {BIG_SECONDS:g} s; column *runs*); RSS = peak resident set "
          "(`/usr/bin/time -v`), median; load = 1-minute load average before the case (other engineers share the "
          "2 cores: prefer CPU to wall).", "",
          "**Interference fit** (decks/contact_verification, plane strain, quarter rings, elements around the inner/"
          "outer ring; surface to surface): error = CPRESS/p_Lamé − 1 at every slave node, p_Lamé = "
          f"{lame_2d():.2f}, the exact small-strain answer with each ring's own radius at the interface (the one-radius "
          f"formula of tests/contact_verification/, b at the middle of the overlap, gives {lame_2d_mid():.2f}, "
          f"{100 * (1 - lame_2d_mid() / lame_2d()):.2f} % less). **Pin in hole** (decks/gen_pin_in_hole.py; pin/hole facets per quarter, axial element "
          "length in mm; general contact, penalty, μ = 0.1, pushed 3.25 mm): the answer is axisymmetric but has "
          "no closed form (a short press fit: N is 1.7 × the open-ended Lamé estimate), so the error is "
          "CPRESS/(its ring's mean) − 1 over the rings carrying at least a tenth of the largest ring mean, and "
          "N = Σ CPRESS·CNAREA against the finest smoothed level's.", ""]
    md += ["| case | level | mesh | smoothing | method | max err | mean err | N err | Newton (cutbacks) | incr. | CPU s | "
           "wall s | RSS MB | runs | load |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        mesh = mesh_2d[r["level"]] if r["case"] == "interference" else mesh_pin.get(r["level"], "?")
        head = f"| {r['case']} | {r['level']} | {mesh} | {'yes' if r['smoothed'] else 'no'} | {r['method'].lower()} |"
        if r["rc"] != 0:
            md.append(head + f" exit {r['rc']}: {r['message'][:120]} | | | | | | | | | {r['load']:.1f} |")
            continue
        nerr = f"{r['N_err']:.3f}" if r["case"] == "pin_in_hole" else ""
        err = (f" {r['max_err']:.3f} | {r['mean_err']:.3f} |" if not math.isnan(r["max_err"])
               else " no contact | no contact |")
        md.append(head + err + f" {nerr} | {r['iterations']} ({r['cutbacks']}) | {r['increments']} | {r['cpu']:.2f} | "
                  f"{r['wall']:.2f} | {r['rss']:.0f} | {r['runs']} | {r['load']:.1f} |")

    # The trade: the coarsest smoothed mesh as accurate as the finest faceted one.
    md += ["", "## The trade", ""]
    for kind, method, key in (("interference", "DIRECT", "max_err"), ("interference", "PENALTY", "max_err"),
                              ("pin_in_hole", "PENALTY", "max_err"), ("pin_in_hole", "PENALTY", "N_err")):
        ok = [r for r in rows if r["case"] == kind and r["method"] == method and r["rc"] == 0
              and not math.isnan(r.get(key, float("nan")))]
        fac = [r for r in ok if not r["smoothed"]]
        smo = [r for r in ok if r["smoothed"]]
        if not fac or not smo:
            continue
        best = min(fac, key=lambda r: r[key])
        good = [r for r in smo if r[key] <= best[key]]
        if not good:
            md.append(f"- {kind} ({method.lower()}, {key}): no smoothed level reaches the faceted best "
                      f"{best[key]:.3f} (level {best['level']}).")
            continue
        c = min(good, key=lambda r: r["level"])
        md.append(f"- {kind} ({method.lower()}, {key.replace('_', ' ')}): smoothed level {c['level']} "
                  f"({c[key]:.3f}, {c['cpu']:.2f} s CPU, {c['rss']:.0f} MB) against the best faceted, level "
                  f"{best['level']} ({best[key]:.3f}, {best['cpu']:.2f} s, {best['rss']:.0f} MB): "
                  f"{best['cpu'] / max(c['cpu'], 1e-9):.1f} × less CPU, {best['rss'] / c['rss']:.2f} × less memory.")
    results = os.path.join(ROOT, "bench", "results")
    os.makedirs(results, exist_ok=True)
    text = "\n".join(md) + "\n"
    with open(os.path.join(results, "smoothing_trade.md"), "w") as f:
        f.write(text)
    print(text)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    fig, axes = plt.subplots(1, 3, figsize=(16, 5))
    panels = (("interference", "max_err", "interference fit: max |CPRESS/p_Lamé − 1|"),
              ("pin_in_hole", "max_err", "pin in hole: max |CPRESS/ring mean − 1|"),
              ("pin_in_hole", "N_err", "pin in hole: |N/N_finest smoothed − 1| (the finest is the reference)"))
    style = {(True, "DIRECT"): ("o", "tab:blue"), (True, "PENALTY"): ("s", "tab:blue"),
             (False, "DIRECT"): ("o", "tab:red"), (False, "PENALTY"): ("s", "tab:red")}
    for ax, (kind, key, title) in zip(axes, panels):
        for (smoothed, method), (marker, color) in style.items():
            pts = sorted((r["cpu"], r[key], r["level"]) for r in rows
                         if r["case"] == kind and r["smoothed"] == smoothed and r["method"] == method
                         and r["rc"] == 0 and not math.isnan(r.get(key, float("nan"))) and r[key] > 0)
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker, color=color,
                    linestyle="-" if method == "DIRECT" else "--",
                    label=f"{'smoothed' if smoothed else 'faceted'}, {method.lower()}")
            for x, y, lv in pts:
                ax.annotate(f"L{lv}", (x, y), fontsize=7, xytext=(3, 3), textcoords="offset points")
        lost = [r for r in rows if r["case"] == kind and not r["smoothed"] and r["rc"] == 0
                and math.isnan(r.get("max_err", 0.0))]
        for r in lost:
            ax.annotate(f"L{r['level']} faceted: no contact", (0.02, 0.85 - 0.05 * r["level"]),
                        xycoords="axes fraction", fontsize=7, color="tab:red")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("CPU time of inpact run [s] (median)")
        ax.set_ylabel("error")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="center left" if kind == "interference" else "center right")
    fig.tight_layout()
    fig.savefig(os.path.join(results, "smoothing_trade.png"), dpi=110)
    print(f"wrote {results}/smoothing_trade.md and smoothing_trade.png (work files in {work})")


if __name__ == "__main__":
    main()
