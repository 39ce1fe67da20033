#!/usr/bin/env python3
"""The cost of surface-to-surface contact in one Newton iteration (issue 14, "Speed"): per deck,
the contact time of an iteration against one element assembly + one factorisation of the same
system, from `inpact run --timings` (solver/iteration_seconds.hpp):

    contact per iteration = (contact_update + contact_begin + contact_assembly) / contact_updates
    floor                 = element_assembly / element_assemblies + factorization / factorizations
    ratio                 = contact per iteration / floor                (the goal: ≤ 1.5)

Each deck runs RUNS times per executable, the executables alternating (A B A B ...); the table
gives medians. With --base, the base executable is run too and the table shows both (before and
after a change). Every deck runs with TYPE=SURFACE TO SURFACE (-P type=...). --decks may name
pin_in_hole_l2 and pin_in_hole_l3 too, the default job's finer meshes (generated, not run by
default): on 2026-12-06 the default job's ratio was 1.91 (level 1), 1.53 (level 2), 0.97 (level 3),
against 2.33, 1.70 and 1.13 for the build before 222b5a7 (a 6 x 6 plain rule on faces, every point
searched at every update) in the same run. Later that day (the tabulated projection start grid,
the kept ray Jacobian, hints and memos kept across point layouts, cheaper correction
derivatives: a5c056a..df2382b), 9 runs against 42d276b in the same run: contact per iteration
12.89 -> 12.23 ms at level 1 (ratio 1.96 -> 1.92), 27.57 -> 26.23 ms at level 2 (1.53 -> 1.53),
55.80 -> 54.90 ms at level 3 (0.99 -> 0.98); with --threads 2, 1.51 -> 1.46 at level 1 (the
floor itself grows with 2 threads on so small a system). On 2026-12-07 (the elements' pattern
kept when contact's couplings change, contact blocks scattered column by column, the face
projection's last Newton step predicted), 7 runs against e14b43a in the same run: ratio 1.93 ->
1.80 at level 1, 1.52 -> 1.33 at level 2, 0.96 -> 0.84 at level 3, sphere_3d 0.14 -> 0.09; with
--threads 2, 1.41 -> 1.32 and 1.25 -> 1.09. Later that day (symmetric triangle rules in the
mortar cells' fans, 3 x 3 plain rules on linear faces: 27 points a slave facet instead of 33;
projections and patterns not redone), 9 runs against 2dfb4eb in the same run: 1.74 -> 1.45 at
level 1 (1.78 -> 1.47 in a run of 15), 1.25 -> 1.09 at level 2, 0.78 -> 0.72 at level 3; with
--threads 2, 1.37 -> 1.09 and 1.22 -> 1.02. This machine's floor moves by 20 % between runs:
compare ratios within one run only.

    contact_iteration.py --inpact BUILD/apps/inpact [--base OTHER/inpact] [--runs 5] [--threads 1]
                         [--decks hertz_2d ...] [--out bench/results/contact_iteration.md]
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECKS = {
    "hertz_2d": "decks/contact_verification/hertz_2d.inp",
    "interference_2d_smoothed": "decks/contact_verification/interference_2d_smoothed.inp",
    "sphere_3d": "decks/contact_verification/sphere_3d.inp",
    "spherical_seat_3d_smoothed": "decks/contact_verification/spherical_seat_3d_smoothed.inp",
    "pin_in_hole": "decks/pin_in_hole.inp",
}
# The default job's finer meshes (decks/gen_pin_in_hole.py --level N), written into the run's
# work folder: how the ratio goes as the model grows (the floor grows faster than the contact).
GENERATED = {"pin_in_hole_l2": 2, "pin_in_hole_l3": 3}
# Decks whose contact is a *PARAMETER `type` (the others are surface to surface already, or
# general contact, which is).
TYPE_PARAMETER = {"hertz_2d", "interference_2d_smoothed", "sphere_3d", "spherical_seat_3d_smoothed"}


def deck_path(name, work):
    """The deck's path; a GENERATED one is written into `work` first."""
    if name not in GENERATED:
        return os.path.join(ROOT, DECKS[name])
    path = os.path.join(work, name + ".inp")
    if not os.path.exists(path):
        subprocess.run([sys.executable, os.path.join(ROOT, "decks", "gen_pin_in_hole.py"), "--out", work,
                        "--level", str(GENERATED[name])], check=True, stdout=subprocess.DEVNULL)
    return path


def run_once(exe, name, work, threads):
    timings = os.path.join(work, name + ".timings")
    cmd = [exe, "run", deck_path(name, work), "-j", name, "-o", work, "--quiet", "--timings", timings,
           "--threads", str(threads)]
    if name in TYPE_PARAMETER:
        cmd += ["-P", "type=SURFACE TO SURFACE"]
    rc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
    if rc != 0:
        sys.exit(f"{' '.join(cmd)}: exit {rc}")
    t = dict(line.strip().split("=") for line in open(timings))
    t = {k: float(v) for k, v in t.items()}
    contact = (t["contact_update_s"] + t["contact_begin_s"] + t["contact_assembly_s"]) / t["contact_updates"]
    floor = t["element_assembly_s"] / t["element_assemblies"] + t["factorization_s"] / t["factorizations"]
    return {"contact": contact, "floor": floor, "ratio": contact / floor, "total": t["total_s"],
            "iterations": int(t["contact_updates"])}


def medians(samples):
    return {k: statistics.median(s[k] for s in samples) for k in samples[0]}


def main():
    cli = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    cli.add_argument("--inpact", required=True)
    cli.add_argument("--base", help="a second executable (the state before a change)")
    cli.add_argument("--runs", type=int, default=5)
    cli.add_argument("--threads", type=int, default=1)
    cli.add_argument("--decks", nargs="+", default=list(DECKS), choices=list(DECKS) + list(GENERATED))
    cli.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "contact_iteration.md"))
    args = cli.parse_args()
    exes = [("base", args.base)] if args.base else []
    exes.append(("new", args.inpact))
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name in args.decks:
            samples = {key: [] for key, _ in exes}
            for _ in range(args.runs):
                for key, exe in exes:
                    samples[key].append(run_once(exe, name, work, args.threads))
            m = {key: medians(s) for key, s in samples.items()}
            rows.append((name, m))
            print(name, "  ".join(f"{k}: contact {v['contact'] * 1e3:.2f} ms, floor {v['floor'] * 1e3:.2f} ms, "
                                  f"ratio {v['ratio']:.2f}, run {v['total']:.3f} s" for k, v in m.items()), flush=True)
    write_table(args, exes, rows)
    return 0


def write_table(args, exes, rows):
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w") as f:
        f.write("# Contact time per Newton iteration against one element assembly + factorisation\n\n")
        f.write(f"Medians of {args.runs} runs, --threads {args.threads}; surface to surface on every deck. ")
        f.write(" ".join(f"{k} = `{e}`." for k, e in exes) + "\n\n")
        head = "| deck | iterations |" + "".join(f" {k}: contact (ms) | {k}: floor (ms) | {k}: ratio | {k}: run (s) |"
                                                   for k, _ in exes)
        f.write(head + "\n|" + "---|" * (head.count("|") - 1) + "\n")
        for name, m in rows:
            first = next(iter(m.values()))
            f.write(f"| {name} | {first['iterations']} |" +
                    "".join(f" {v['contact'] * 1e3:.2f} | {v['floor'] * 1e3:.2f} | {v['ratio']:.2f} | {v['total']:.3f} |"
                            for v in m.values()) + "\n")
    print("wrote", args.out)


if __name__ == "__main__":
    sys.exit(main())
