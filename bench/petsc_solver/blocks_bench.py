#!/usr/bin/python3
"""blocks_bench.py: a contact model from 100k to 1M DOF with the direct solver, PETSc on one
process and PETSc on N MPI ranks: two stacked C3D8 blocks in node-to-surface penalty contact
under a uniform pressure of 10 (bench/study_overhead_deck.py NX NX NX: the upper block twice
as fine in the plane, its bottom the slave surface), whole `inpact run` processes under
/usr/bin/time -v (cube_bench.py's one_run).

  /usr/bin/python3 bench/petsc_solver/blocks_bench.py --inpact build/apps/inpact --sizes 18 27 40 \\
      [--solvers direct petsc petsc:2] [--direct-max-n 27] [--runs 1] [--work DIR]

The contact pressure is the load, 10, at every slave node (a patch test): its range says each
run solved the model. Writes WORK/blocks.md and prints it. Never commit WORK.
"""
import argparse, os, statistics, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import cube_bench  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(HERE))


def deck(n, work):
    path = os.path.join(work, f"blocks{n}.inp")
    if not os.path.exists(path):
        subprocess.run([sys.executable, os.path.join(ROOT, "bench/study_overhead_deck.py"), path, str(n), str(n), str(n)],
                       check=True, stdout=subprocess.DEVNULL)
    return path


def dofs(n):
    return 3 * ((n + 1) ** 3 + (2 * n + 1) ** 2 * (n + 1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--sizes", type=int, nargs="+", default=[18, 27, 40])
    ap.add_argument("--solvers", nargs="+", default=["direct", "petsc", "petsc:2"])
    ap.add_argument("--direct-max-n", type=int, default=27, help="larger models: PETSc only")
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--work", default="blocks_bench.out")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    med = lambda rs, k: statistics.median(r[k] for r in rs)
    rows = ["| N | DOF | solver | wall s | CPU s | linear solve s | contact s | peak RSS GB (largest rank) | Newton | Krylov | "
            "CPRESS min-max | load |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for n in a.sizes:
        path = deck(n, a.work)
        for solver in a.solvers:
            if solver == "direct" and n > a.direct_max_n:
                continue
            runs = [cube_bench.one_run(a.inpact, path, solver, a.work, a.threads) for _ in range(a.runs)]
            ok = [r for r in runs if "failed" not in r]
            if not ok:
                rows.append(f"| {n} | {dofs(n):,} | {solver} | failed: {runs[0]['failed']} |||||||||")
            else:
                contact = med(ok, "contact_update_s") + med(ok, "contact_assembly_s")
                p = ok[0].get("cpress", (0.0, 0.0))
                rows.append(f"| {n} | {dofs(n):,} | {solver} | {med(ok, 'wall'):.1f} | {med(ok, 'cpu'):.1f} | "
                            f"{med(ok, 'factorization_s') + med(ok, 'back_solve_s'):.1f} | {contact:.1f} | "
                            f"{med(ok, 'rss_gb'):.2f} | {ok[0]['newton']} | {int(ok[0].get('krylov_iterations', 0))} | "
                            f"{p[0]:.6g}-{p[1]:.6g} | {med(ok, 'load'):.1f} |")
            print(rows[-1], flush=True)
    text = "\n".join(rows) + "\n"
    with open(os.path.join(a.work, "blocks.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
