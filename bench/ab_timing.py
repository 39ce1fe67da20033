#!/usr/bin/env python3
"""Whole-run wall time of two inpact executables on the same decks: a change against its base.

Each deck runs with A and B alternately (A B A B ...), REPEAT times each, one process at a time,
so both see the same machine state; the table gives each one's median and the ratio B / A.
Writes bench/results/ab_timing.md (or --out FILE). Typical use, the base built from another
worktree (`git worktree add ../base HEAD~1` and a Release build there):

  bench/ab_timing.py ../base/build/apps/inpact build/apps/inpact decks/pin_in_hole.inp ...

Usage: bench/ab_timing.py A_EXE B_EXE DECK... [--repeat N (5)] [--out FILE]
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_once(exe, deck, out_dir):
    start = time.perf_counter()
    rc = subprocess.run([exe, "run", deck, "-o", out_dir, "--quiet"], stdout=subprocess.DEVNULL,
                        stderr=subprocess.DEVNULL).returncode
    return time.perf_counter() - start, rc


def main():
    cli = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    cli.add_argument("a")
    cli.add_argument("b")
    cli.add_argument("decks", nargs="+")
    cli.add_argument("--repeat", type=int, default=5)
    cli.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "ab_timing.md"))
    args = cli.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for deck in args.decks:
            times = {"a": [], "b": []}
            codes = set()
            for _ in range(args.repeat):
                for key in ("a", "b"):
                    t, rc = run_once(getattr(args, key), deck, os.path.join(tmp, key))
                    times[key].append(t)
                    codes.add((key, rc))
            ta, tb = statistics.median(times["a"]), statistics.median(times["b"])
            rows.append((os.path.relpath(deck, ROOT), ta, tb, tb / ta, sorted(codes)))
            print(f"{rows[-1][0]}: A {ta:.3f} s, B {tb:.3f} s, B/A {tb / ta:.3f}", flush=True)
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w") as f:
        f.write(f"# Whole-run wall time, A = `{args.a}`, B = `{args.b}`\n\n")
        f.write(f"Medians of {args.repeat} runs each, alternating A and B, one process at a time.\n\n")
        f.write("| deck | A (s) | B (s) | B / A | exit codes |\n|---|---|---|---|---|\n")
        for deck, ta, tb, ratio, codes in rows:
            f.write(f"| {deck} | {ta:.3f} | {tb:.3f} | {ratio:.3f} | {codes} |\n")
    print("wrote", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
