#!/usr/bin/env python3
"""Overhead per case of `inpact study` against the solve time of a case (goal: < 5%).

A study of 64 cases of a contact deck of a few thousand elements (study_overhead_deck.py) runs
with -j 2, both cores busy. Each case's overhead beyond the analysis is measured separately,
as medians of repeated runs:
  start      `inpact --version`: exec, dynamic libraries, CLI set-up
  read       `inpact check DECK` minus start: deck read + validation (+ the model summary)
  write      `inpact run DECK` minus the same run with its field output switched off
             (*OUTPUT, FIELD, FREQUENCY=0): computing and writing the frames. (A deck with no
             *OUTPUT at all is no baseline: it gets Abaqus's preselected output, more fields.)
  dispatch   the study's wall time per case over what the cases take (fork/exec, waitpid,
             case.result, the table): 2 × study wall / 64 − mean case wall
solve = run − start − read − write. Writes bench/results/study_overhead.md.

Usage: bench/study_overhead.py [BUILD_DIR (default build-study)] [N_CASES (64)] [NX NY]
NX NY: the lower block's elements (default 36 30: 3,240 elements in all); another size writes
bench/results/study_overhead_<elements>.md instead.
"""
import csv
import os
import resource
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(ROOT, "build-study")
n_cases = int(sys.argv[2]) if len(sys.argv) > 2 else 64
deck_size = sys.argv[3:5]
inpact = os.path.join(build, "apps", "inpact")
work = os.path.join(build, "bench-study")
os.makedirs(work, exist_ok=True)

deck = os.path.join(work, "contact.inp")
subprocess.run([sys.executable, os.path.join(ROOT, "bench", "study_overhead_deck.py"), deck] + deck_size, check=True)
text = open(deck).read()
noout = os.path.join(work, "contact_noout.inp")
open(noout, "w").write(text[:text.index("*OUTPUT, FIELD")] + "*OUTPUT, FIELD, FREQUENCY=0\n*NODE OUTPUT\nU\n*END STEP\n")


# The environment of a study's case (apps/study_runner.cpp): one BLAS and OpenMP thread.
case_env = dict(os.environ)
case_env.setdefault("OPENBLAS_NUM_THREADS", "1")
case_env.setdefault("OMP_NUM_THREADS", "1")


def once(args):
    """Wall and CPU seconds (user + system) of one run."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(args, cwd=work, env=case_env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)


def medians(samples):
    return tuple(statistics.median(s[k] for s in samples) for k in range(2))


def paired(a, b, repeat):
    """Medians (wall, CPU) of a and of a − b, a and b run alternately: a difference of a few
    milliseconds survives the load of other jobs better than two separate medians."""
    ta, diff = [], []
    for _ in range(repeat):
        x, y = once(a), once(b)
        ta.append(x)
        diff.append((x[0] - y[0], x[1] - y[1]))
    return medians(ta), medians(diff)


def own_cpu(pid):
    """CPU seconds of process pid itself (not its children), from /proc/pid/stat."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


# The study first: both cores busy, as the cases of a real study. Its own CPU time (without
# the cases') is polled from /proc until it ends.
load_before = os.getloadavg()[0]
study_dir = os.path.join(work, "S")
subprocess.run(["rm", "-rf", study_dir], check=True)
loads = ",".join(f"{5 + 0.25 * i:g}" for i in range(n_cases))
t0 = time.perf_counter()
study = subprocess.Popen([inpact, "study", deck, "--grid", f"load={loads}", "-j", "2", "-o", study_dir, "-q",
                          "--collect", "max:CPRESS", "--collect", "max:-COPEN", "--collect", "sum:RF2@BOTTOM"])
study_cpu = 0.0
while study.poll() is None:
    try:
        study_cpu = own_cpu(study.pid)
    except OSError:
        pass
    time.sleep(0.02)
study_wall = time.perf_counter() - t0
if study.returncode != 0:
    sys.exit(f"the study failed (exit {study.returncode})")
rows = list(csv.DictReader(open(os.path.join(study_dir, "results.csv"))))
walls = [float(r["wall_time_s"]) for r in rows if r["status"] == "completed"]
mean_case = statistics.mean(walls)
dispatch = (max(0.0, 2 * study_wall / n_cases - mean_case), study_cpu / n_cases)

# The parts of one case, run alone in the environment of a case (medians).
start = medians([once([inpact, "--version"]) for _ in range(41)])
check, read = paired([inpact, "check", deck], [inpact, "--version"], 31)
run, write = paired([inpact, "run", deck, "-q", "-j", "full"], [inpact, "run", noout, "-q", "-j", "noout"], 15)
read = tuple(max(0.0, x) for x in read)
write = tuple(max(0.0, x) for x in write)
solve = tuple(run[k] - start[k] - read[k] - write[k] for k in range(2))
overhead = tuple(start[k] + read[k] + write[k] + dispatch[k] for k in range(2))
h5_size = os.path.getsize(os.path.join(work, "full.h5"))

n_elem = sum(1 for line in text.splitlines() if line[:1].isdigit() and line.count(",") == 4)
lines = [
    "# `inpact study` overhead per case",
    "",
    f"Deck: bench/study_overhead_deck.py ({n_elem} CPE4 elements, penalty contact, one step in 4 increments);",
    f"{n_cases} cases (the pressure varied) with `-j 2` on 2 cores; results {h5_size / 1e6:.1f} MB per case.",
    "Medians of repeated runs (read and write: medians of paired differences); `bench/study_overhead.py` writes this file.",
    "CPU is user + system time; the study dispatch's CPU is the study process's own, per case.",
    "",
    "| part | wall s per case | % of solve | CPU s per case | % of solve |",
    "|---|---|---|---|---|",
]


def row(name, t, bold=False):
    b = "**" if bold else ""
    return (f"| {b}{name}{b} | {b}{t[0]:.4f}{b} | {b}{100 * t[0] / solve[0]:.1f}{b} "
            f"| {b}{t[1]:.4f}{b} | {b}{100 * t[1] / solve[1]:.1f}{b} |")


for name, t in [("process start (`inpact --version`)", start), ("deck read + validation (`check` − start)", read),
                ("results write (run − run with FREQUENCY=0)", write), ("study dispatch (2·wall/N − mean case)", dispatch)]:
    lines.append(row(name, t))
lines += [
    row("overhead", overhead, True),
    row("solve (run − start − read − write)", solve),
    "",
    f"Study: {len(walls)}/{n_cases} completed in {study_wall:.2f} s wall; mean case wall {mean_case:.3f} s "
    f"(both cores busy) against {run[0]:.3f} s for one run alone.",
    f"Load average {load_before:.1f} at the start, {os.getloadavg()[0]:.1f} at the end, on {os.cpu_count()} cores "
    "(other jobs make every part noisy).",
]
os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
out = os.path.join(ROOT, "bench", "results", f"study_overhead_{n_elem}.md" if deck_size else "study_overhead.md")
open(out, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
