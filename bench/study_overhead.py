#!/usr/bin/env python3
"""Overhead per case of `inpact study` against the solve time of a case (goal: < 5%).

A study of 64 cases of a contact deck of a few thousand elements (study_overhead_deck.py) runs
with -j 2, both cores busy, as a user's study would. Everything is measured inside that study:
each case writes cases/ID/timings.txt (`inpact run --timings`: wall seconds of its phases) and
the study records each case's wall time from fork to exit (results.csv). Per case:
  solve     the analysis minus the output it asked for (analysis_s - output_s)
  read      deck read, parameter substitution, validation, the deck's SHA-256
  create    the results file's model and view geometry, the .sta and .dat
  output    computing and writing the frames (and printed tables)
  finish    closing the results file and renaming it .h5
  process   handing the case to its worker and back (fork and exit with --inpact EXE): the
            case's wall time minus its timed phases
  dispatch  what the study adds between cases (handing the next case over, collecting the
            values, case.result): 2 x (T - M) / N, where T runs from the first case's start to
            the last one's end (case.result: started, wall_time) and M is what T would be had
            each worker started its next case the moment the last one ended (the cases' walls
            scheduled in manifest order on 2 workers)
overhead = everything but the solve. Not per case, and shown apart: the study's own start and
end (manifest, workers, the table: study wall - T), and the end of the cases, when one worker
has nothing left to run while the other finishes (2 M - the sum of the case walls).
The same study also runs with `--inpact EXE`, each case an exec of the executable as before
the fork workers. Each variant runs REPEAT times, alternating; the table gives medians.
Writes bench/results/study_overhead.md (or study_overhead_<elements>_<type>.md for another deck).

Usage: bench/study_overhead.py [BUILD_DIR (default build-study)] [N_CASES (64)] [NX NY [NZ]] [--repeat N (3)]
NX NY: the lower block's elements of the plane (CPE4) deck (default 36 30: 3,240 elements in all);
NX NY NZ: a solid (C3D8) deck instead (10 10 6: 3,000 elements).
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
cli = argparse.ArgumentParser(description="Overhead per case of `inpact study` against the solve time of a case.")
cli.add_argument("build", nargs="?", default=os.path.join(ROOT, "build-study"), help="build folder (build-study)")
cli.add_argument("n_cases", nargs="?", type=int, default=64, help="cases of the study (64)")
cli.add_argument("size", nargs="*", help="NX NY (plane CPE4 deck, default 36 30) or NX NY NZ (solid C3D8 deck)")
cli.add_argument("--repeat", type=int, default=3, help="runs of each variant (3)")
args = cli.parse_args()
if len(args.size) not in (0, 2, 3):
    cli.error("the deck size is NX NY or NX NY NZ")
build, n_cases, deck_size, repeat = os.path.abspath(args.build), args.n_cases, args.size, args.repeat
inpact = os.path.join(build, "apps", "inpact")
work = os.path.join(build, "bench-study")
os.makedirs(work, exist_ok=True)

deck = os.path.join(work, "contact.inp")
made = subprocess.run([sys.executable, os.path.join(ROOT, "bench", "study_overhead_deck.py"), deck] + deck_size,
                      check=True, capture_output=True, text=True).stdout
print(made, end="")
n_elem, elem_type = made.split(": ")[1].split()[:2]  # "OUT: 3240 CPE4 elements, 3410 nodes"
n_elem = int(n_elem)
reaction = "RF3" if elem_type == "C3D8" else "RF2"  # the bottom's reaction in the stacking direction


def own_cpu(pid):
    """CPU seconds of process pid itself (not its children), from /proc/pid/stat."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def run_study(name, extra):
    """Runs the study; returns its wall time, the study process's own CPU and the per-case rows
    (results.csv joined with each case's timings.txt)."""
    study_dir = os.path.join(work, name)
    subprocess.run(["rm", "-rf", study_dir], check=True)
    loads = ",".join(f"{5 + 0.25 * i:g}" for i in range(n_cases))
    t0 = time.perf_counter()
    study = subprocess.Popen([inpact, "study", deck, "--grid", f"load={loads}", "-j", "2", "-o", study_dir, "-q",
                              "--collect", "max:CPRESS", "--collect", "max:-COPEN", "--collect", f"sum:{reaction}@BOTTOM"]
                             + extra)
    cpu = 0.0
    while study.poll() is None:
        try:
            cpu = own_cpu(study.pid)
        except OSError:
            pass
        time.sleep(0.02)
    wall = time.perf_counter() - t0
    if study.returncode != 0:
        sys.exit(f"the study {name} failed (exit {study.returncode})")
    rows = list(csv.DictReader(open(os.path.join(study_dir, "results.csv"))))
    for r in rows:
        if r["status"] != "completed":
            sys.exit(f"case {r['id']} of {name}: {r['status']} {r['message']}")
        case = os.path.join(study_dir, "cases", r["id"])
        t = dict(line.strip().split("=") for line in open(os.path.join(case, "timings.txt")))
        r.update({k: float(v) for k, v in t.items()})
        outcome = dict(line.rstrip("\n").split("=", 1) for line in open(os.path.join(case, "case.result")))
        r["wall"] = float(outcome["wall_time"])
        r["started"] = float(outcome["started"])
    return wall, cpu, rows


def parts(wall, cpu, rows):
    """Mean seconds per case of each part, and the study's figures."""
    mean = lambda key: statistics.mean(r[key] for r in rows)
    slots = [0.0, 0.0]  # the cases back to back on 2 workers, in manifest order
    for r in rows:
        k = slots.index(min(slots))
        slots[k] += r["wall"]
    makespan = max(slots)
    first = min(r["started"] for r in rows)
    last = max(r["started"] + r["wall"] for r in rows)
    p = {
        "solve": statistics.mean(r["analysis_s"] - r["output_s"] for r in rows),
        "read": mean("read_s"),
        "create": mean("create_s"),
        "output": mean("output_s"),
        "finish": mean("finish_s"),
        "process": statistics.mean(r["wall"] - r["total_s"] for r in rows),
        "dispatch": max(0.0, 2 * ((last - first) - makespan) / len(rows)),
    }
    p["overhead"] = sum(v for k, v in p.items() if k != "solve")
    p["percent"] = 100 * p["overhead"] / p["solve"]
    p["tail"] = 2 * makespan - sum(r["wall"] for r in rows)
    p["ends"] = wall - (last - first)  # the study before its first case and after its last
    p["study_cpu"] = cpu / len(rows)
    p["wall"] = wall
    p["case_wall"] = mean("wall")
    return p


def median_parts(runs):
    return {k: statistics.median(r[k] for r in runs) for k in runs[0]}


load_before = os.getloadavg()[0]
fork_runs, exec_runs = [], []
for i in range(repeat):
    fork_runs.append(parts(*run_study("S", [])))
    exec_runs.append(parts(*run_study("S_exec", ["--inpact", inpact])))
fork, exec_ = median_parts(fork_runs), median_parts(exec_runs)
h5_size = os.path.getsize(os.path.join(work, "S", "cases", "c0001", "c0001.h5"))

names = [("read", "deck read + validation + SHA-256"), ("create", "results file created (model, view geometry)"),
         ("output", "frames computed and written"), ("finish", "results file closed and renamed"),
         ("process", "to the worker and back (exec: fork, exec, exit)"), ("dispatch", "study dispatch (between cases)")]
lines = [
    "# `inpact study` overhead per case",
    "",
    f"Deck: bench/study_overhead_deck.py {' '.join(deck_size or ['36', '30'])} ({n_elem} {elem_type} elements,"
    " penalty contact, one step in 4 increments);",
    f"{n_cases} cases (the pressure varied) with `-j 2` on 2 cores; results {h5_size / 1e6:.1f} MB per case.",
    "Measured inside the study: each case's phases from its `--timings` file, its wall time (handed to a worker",
    "to ended) and start from its case.result; mean milliseconds per case; `bench/study_overhead.py` writes this file.",
    f"Columns: the study as it runs (forked workers) and with `--inpact EXE` (each case an exec, as before);",
    f"medians of {repeat} runs of each, alternating.",
    "",
    "| part | fork: ms | % of solve | exec: ms | % of solve |",
    "|---|---|---|---|---|",
]


def row(label, key, bold=False):
    b = "**" if bold else ""
    cells = [f"{b}{p[key] * 1e3:.2f}{b} | {b}{100 * p[key] / p['solve']:.1f}{b}" for p in (fork, exec_)]
    return f"| {b}{label}{b} | " + " | ".join(cells) + " |"


for key, label in names:
    lines.append(row(label, key))
lines += [
    row("overhead", "overhead", True),
    row("solve (analysis − output)", "solve"),
    "",
    "",
    "Overhead of each run, % of its solve: fork " + ", ".join(f"{r['percent']:.1f}" for r in fork_runs)
    + "; exec " + ", ".join(f"{r['percent']:.1f}" for r in exec_runs) + ".",
    f"Study wall {fork['wall']:.2f} s forked, {exec_['wall']:.2f} s with exec; mean case wall "
    f"{fork['case_wall'] * 1e3:.1f} / {exec_['case_wall'] * 1e3:.1f} ms. Once per study, not per case: its start and end "
    f"{fork['ends'] * 1e3:.0f} / {exec_['ends'] * 1e3:.0f} ms; one worker idle at the end of the cases "
    f"{fork['tail'] * 1e3:.0f} / {exec_['tail'] * 1e3:.0f} ms.",
    f"The study process's own CPU per case (inside dispatch): {fork['study_cpu'] * 1e3:.2f} / "
    f"{exec_['study_cpu'] * 1e3:.2f} ms (the exec'd cases' values are read back from their results files).",
    f"Load average {load_before:.1f} at the start, {os.getloadavg()[0]:.1f} at the end, on {os.cpu_count()} cores "
    "(other jobs make every part noisy).",
]
os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
out = os.path.join(ROOT, "bench", "results", f"study_overhead_{n_elem}_{elem_type}.md" if deck_size else "study_overhead.md")
open(out, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
