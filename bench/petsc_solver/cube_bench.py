#!/usr/bin/python3
"""cube_bench.py: CHOLMOD (`--solver direct`) against PETSc (`--solver petsc`: CG + GAMG) on the
solver benchmark cube (bench/solver_gen_cube.py: N³ C3D8, clamped bottom, pressure on top, one
linear static step), or with --dim 2 its plane-strain square (bench/solver_gen_square.py: N²
CPE4), or with --dim shell a clamped plate of N² S4 shells (bench/solver_gen_plate.py), whole
`inpact run` processes under /usr/bin/time -v.

  /usr/bin/python3 bench/petsc_solver/cube_bench.py --inpact build/apps/inpact --sizes 31 45 \
      [--dim 3|2|shell] [--runs 3] [--direct-max-n 45] [--work DIR] [--threads 1] [--solvers direct petsc petsc:2]

A solver `petsc:N` is a distributed run, `mpirun -np N inpact run ...`; its peak RSS is that
of the largest rank (what /usr/bin/time reports for the process tree), its CPU time that of
all ranks together.

Per size and solver: the median (and min-max) of RUNS runs of the wall time, the CPU time
(user + system: what the process itself spent, steadier than the wall time on a loaded machine), the peak RSS,
the analysis and linear-solve seconds (--timings), Newton and Krylov iterations, the tip's U3
(both must solve the same problem) and the 1-minute load average before each run (the machine
is shared). DOF is the model DOF `--solver auto` decides by (the .dat's "auto: 3D, NNN DOF"):
3 (N+1)³ for the cube, 2 (N+1)² for the square, 6 (N+1)² for the plate (its shell nodes and the
nodes added for their rotations, 3 each). Writes WORK/cube.md (square.md, plate.md) and prints it. Never commit WORK (decks of 100+ MB).
"""
import argparse, os, re, statistics, subprocess, sys
import h5py, numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import compare_solvers  # noqa: E402  (its mpirun launcher)


NAMES = {3: "cube", 2: "square", "shell": "plate"}


def model_dof(n, dim=3):
    """The model DOF inpact reports (auto's rule): nodes x 3 in 3D (shell rotation nodes counted), x 2 in 2D."""
    return 6 * (n + 1) ** 2 if dim == "shell" else dim * (n + 1) ** dim


def deck(n, work, dim=3):
    path = os.path.join(work, f"{NAMES[dim]}{n}.inp")
    if not os.path.exists(path):
        if dim == "shell":
            subprocess.run([sys.executable, os.path.join(ROOT, "bench/solver_gen_plate.py"), str(n), path], check=True)
        elif dim == 3:
            subprocess.run([sys.executable, os.path.join(ROOT, "bench/solver_gen_cube.py"), str(n), path,
                            os.path.join(work, f"cube{n}_ccx.inp")], check=True)
        else:
            subprocess.run([sys.executable, os.path.join(ROOT, "bench/solver_gen_square.py"), str(n), path], check=True)
    return path


def one_run(inpact, path, solver, work, threads, tip=None):
    """tip: the tip node's row in U (the plate: its corner node (1, 1)); default the largest |U| along the load."""
    solver, _, ranks = solver.partition(":")
    job = f"{os.path.basename(path)[:-4]}_{solver}{ranks}"
    timings = os.path.join(work, job + ".timings")
    load = os.getloadavg()[0]
    launcher = compare_solvers.mpirun(int(ranks or 1), unbound=True)
    cmd = ["/usr/bin/time", "-v"] + launcher + [inpact, "run", path, "-j", job, "-o", work, "-q", "--solver", solver,
           "--threads", str(threads), "--timings", timings]
    p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        return {"failed": p.stderr.strip().splitlines()[-3:]}
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", p.stderr)
    h, m, s = wall.groups()
    r = {"wall": int(h or 0) * 3600 + int(m) * 60 + float(s),
         "rss_gb": int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr).group(1)) / 1024 ** 2,
         "load": load,
         "cpu": sum(float(re.search(rf"{k} time \(seconds\): ([\d.]+)", p.stderr).group(1)) for k in ("User", "System"))}
    for line in open(timings):
        k, _, v = line.strip().partition("=")
        r[k] = float(v)
    with h5py.File(os.path.join(work, job + ".h5")) as f:
        r["newton"] = int(np.sum(f["status"]["total_iters"]))
        u = f["steps"]["Step-1" if "Step-1" in f["steps"] else list(f["steps"])[0]]["fieldOutputs"]["U"]["data"][-1]
        c = 2 if u.shape[1] > 2 else 1  # the load's direction: z in the cube, y in the square
        r["tip_u3"] = float(u[np.argmax(np.abs(u[:, c])) if tip is None else tip, c])
        fields = f["steps"][list(f["steps"])[-1]]["fieldOutputs"]
        if "CPRESS" in fields:  # contact decks (blocks_bench.py): the pressure's range
            p = fields["CPRESS"]["data"][-1]
            p = p[np.isfinite(p) & (p > 0)]
            r["cpress"] = (float(p.min()), float(p.max())) if p.size else (0.0, 0.0)
    os.remove(os.path.join(work, job + ".h5"))
    return r


def median_spread(values, fmt):
    return f"{fmt.format(statistics.median(values))} ({fmt.format(min(values))}-{fmt.format(max(values))})"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inpact", required=True)
    ap.add_argument("--sizes", type=int, nargs="+", default=[31, 45])
    ap.add_argument("--dim", choices=["2", "3", "shell"], default="3",
                    help="2: the CPE4 square instead of the cube; shell: the S4 plate")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--direct-max-n", type=int, default=45, help="larger cubes: petsc only (CHOLMOD's memory)")
    ap.add_argument("--solvers", nargs="+", default=["direct", "petsc"])
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--work", default="cube_bench.out")
    a = ap.parse_args()
    a.dim = a.dim if a.dim == "shell" else int(a.dim)
    os.makedirs(a.work, exist_ok=True)
    rows = ["| N | DOF | solver | runs | wall s | CPU s | analysis s | linear solve s | peak RSS GB | Newton | Krylov | tip U3 | load |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for n in a.sizes:
        path = deck(n, a.work, a.dim)
        dof = model_dof(n, a.dim)
        tip = (n + 1) ** 2 - 1 if a.dim == "shell" else None  # the corner (1, 1), the deck's last shell node
        for solver in a.solvers:
            if solver == "direct" and n > a.direct_max_n:
                continue
            runs = [one_run(a.inpact, path, solver, a.work, a.threads, tip) for _ in range(a.runs)]
            ok = [r for r in runs if "failed" not in r]
            if not ok:
                rows.append(f"| {n} | {dof} | {solver} | 0 | failed: {runs[0]['failed']} |||||||")
                print(rows[-1], flush=True)
                continue
            solve = [r["factorization_s"] + r["back_solve_s"] for r in ok]
            rows.append(f"| {n} | {dof} | {solver} | {len(ok)} | {median_spread([r['wall'] for r in ok], '{:.1f}')} | "
                        f"{median_spread([r['cpu'] for r in ok], '{:.1f}')} | "
                        f"{median_spread([r['analysis_s'] for r in ok], '{:.1f}')} | {median_spread(solve, '{:.1f}')} | "
                        f"{median_spread([r['rss_gb'] for r in ok], '{:.2f}')} | {ok[0]['newton']} | "
                        f"{int(ok[0].get('krylov_iterations', 0))} | {ok[0]['tip_u3']:.6e} | "
                        f"{median_spread([r['load'] for r in ok], '{:.1f}')} |")
            print(rows[-1], flush=True)
    text = "\n".join(rows) + "\n"
    with open(os.path.join(a.work, NAMES[a.dim] + ".md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
