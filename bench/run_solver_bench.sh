#!/usr/bin/env bash
# Solver benchmark: a clamped C3D8 cube under pressure at N³ elements (default 30 50 70), one
# linear static step. Per size, in the same run and on the same machine:
#   floor        bench/solver_floor: one assembly + CHOLMOD analyse/factor/solve (1 and 2 threads)
#   inpact       `inpact run --threads 1` and `--threads 2`, whole process (/usr/bin/time -v)
#   ccx          CalculiX (Debian calculix-ccx) on the same problem in its dialect, 1 thread
# medians of RUNS runs (default 3; RUNS_LARGE, default 1, for sizes >= LARGE_FROM = 70, whose
# runs take many minutes), the min-max spread, and the tip displacement of both codes (the
# same problem must give the same answer). Writes bench/results/solver.md and solver.png.
#
#   bash bench/run_solver_bench.sh [N ...]
#   env: BUILD (default build-bench2), RUNS, RUNS_LARGE, LARGE_FROM, SKIP_CCX=1, CCX_MAX_N (default 70),
#        KEEP_RAW=1 (add to the last run's measurements instead of starting afresh)
#
# The machine is shared: other work adds noise. Medians and spreads are reported, never limits.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build-bench2}
runs=${RUNS:-3}
runs_large=${RUNS_LARGE:-1}
large_from=${LARGE_FROM:-70}
ccx_max=${CCX_MAX_N:-70}
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(30 50 70)
work=$build/solver_bench
results=$root/bench/results
mkdir -p "$work" "$results"

source "$root/bench/bench_setup.sh"
bench_build "$root" "$build" apps/inpact bench/solver_floor
# Tools the benchmark needs, installed when missing (never added to .ci).
command -v ccx >/dev/null || [ "${SKIP_CCX:-0}" = 1 ] || bench_need calculix-ccx
bench_need_python matplotlib
[ -x /usr/bin/time ] || bench_need time
bench_install_needed

raw=$work/raw.txt
# KEEP_RAW=1 adds to the previous measurements (e.g. a large size run on its own later); the
# tables cover every size in raw.txt.
[ "${KEEP_RAW:-0}" = 1 ] || : >"$raw"
# timed NAME CMD...: runs CMD under /usr/bin/time -v, appends "NAME wall_s peak_mb" to $raw.
timed() {
  local name=$1; shift
  /usr/bin/time -v -o "$work/time.txt" "$@" >"$work/$name.out" 2>&1 || { echo "FAILED: $*" >&2; tail -5 "$work/$name.out" >&2; exit 1; }
  local wall mb
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n=split($2,t,":"); s=0; for(i=1;i<=n;i++) s=s*60+t[i]; print s}' "$work/time.txt")
  mb=$(awk -F': ' '/Maximum resident set size/ {printf "%.0f", $2/1024}' "$work/time.txt")
  echo "$name $wall $mb" >>"$raw"
}

for n in "${sizes[@]}"; do
  deck=$work/cube$n.inp
  ccx_job=cube${n}_ccx
  [ -f "$deck" ] || /usr/bin/python3 "$root/bench/solver_gen_cube.py" "$n" "$deck" "$work/$ccx_job.inp"
  r=$runs; [ "$n" -lt "$large_from" ] || r=$runs_large
  echo "== $n^3 elements: $r run(s) each" >&2
  for ((i = 1; i <= r; i++)); do
    # Interleaved, so that a noisy minute hits every contender alike.
    for t in 1 2; do
      "$build/bench/solver_floor" "$deck" $t | sed "s/^/floor$t n=$n /" >>"$raw"
      (cd "$work" && timed "inpact$t-$n" "$build/apps/inpact" run "$deck" -j "cube$n-t$t" --threads $t --quiet)
    done
    if [ "${SKIP_CCX:-0}" != 1 ] && [ "$n" -le "$ccx_max" ]; then
      (cd "$work" && OMP_NUM_THREADS=1 CCX_NPROC_STIFFNESS=1 CCX_NPROC_EQUATION_SOLVER=1 \
         timed "ccx-$n" ccx -i "$ccx_job")
    fi
    tail -n 4 "$raw" >&2
  done
  # Tip displacement (node (1,1,1)): the U3 column of each code's .dat.
  awk -v n=$n 'f && NF == 4 && $1 ~ /^[0-9]+$/ {print "tip-inpact-" n, $4; exit} /NODE FOOT-/ {f=1}' "$work/cube$n-t1.dat" >>"$raw"
  if [ -f "$work/$ccx_job.dat" ]; then
    awk -v n=$n 'NF == 4 && $1 ~ /^[0-9]+$/ {v=$4} END {if (v != "") print "tip-ccx-" n, v}' "$work/$ccx_job.dat" >>"$raw"
  fi
done

/usr/bin/python3 - "$raw" "$results" <<'EOF'
import statistics, sys, platform, subprocess
raw, out_dir = sys.argv[1], sys.argv[2]
whole, floor, tip = {}, {}, {}
for line in open(raw):
    f = line.split()
    if f[0].startswith("floor"):
        t = int(f[0][5:]); kv = dict(x.split("=") for x in f[1:])
        floor.setdefault((int(kv["n"]), t), []).append({k: float(v) for k, v in kv.items()})
    elif f[0].startswith("tip-"):
        _, code, n = f[0].split("-"); tip[(code, int(n))] = float(f[1])
    else:
        name, n = f[0].rsplit("-", 1)
        whole.setdefault((name, int(n)), []).append((float(f[1]), float(f[2])))

sizes = sorted({n for n, _ in floor})
def med(v): return statistics.median(v)
def spread(v): return "%.3g–%.3g" % (min(v), max(v)) if len(v) > 1 else "1 run"
def fmt(x): return "–" if x is None else ("%.3g" % x if x < 100 else "%.0f" % x)

rows, plot = [], {"dof": [], "inpact": [], "inpact2": [], "floor": [], "ccx": []}
for n in sizes:
    f1 = floor.get((n, 1)); f2 = floor.get((n, 2))
    if not f1: continue
    fm = lambda k, fl=f1: med([x[k] for x in fl])
    i1 = whole.get(("inpact1", n), []); i2 = whole.get(("inpact2", n), []); cx = whole.get(("ccx", n), [])
    w1 = med([w for w, _ in i1]) if i1 else None
    w2 = med([w for w, _ in i2]) if i2 else None
    wc = med([w for w, _ in cx]) if cx else None
    fl1, fl2 = fm("floor"), (med([x["floor"] for x in f2]) if f2 else None)
    mem1 = max(m for _, m in i1) if i1 else None
    memc = max(m for _, m in cx) if cx else None
    ti, tc = tip.get(("inpact", n)), tip.get(("ccx", n))
    rows.append(dict(n=n, dof=int(f1[0]["dof"]), eq=int(f1[0]["equations"]), runs=len(i1), asm=fm("assembly"),
                     res=fm("residual"), ana=fm("analyse"), fac=fm("factor"), sol=fm("solve"), gflop=fm("gflop"),
                     fpeak=max(x["peak_mb"] for x in f1), ipeak=mem1, cpeak=memc, w1=w1, w2=w2, fl1=fl1, fl2=fl2,
                     wc=wc, s1=spread([w for w, _ in i1]), s2=spread([w for w, _ in i2]) if i2 else "–",
                     sf=spread([x["floor"] for x in f1]), sc=spread([w for w, _ in cx]) if cx else "–",
                     ccx_runs=len(cx), ti=ti, tc=tc))
    plot["dof"].append(rows[-1]["dof"]); plot["inpact"].append(w1); plot["inpact2"].append(w2)
    plot["floor"].append(fl1); plot["ccx"].append(wc)

blas = subprocess.run(["sh", "-c", "readlink -f /etc/alternatives/libblas.so.3-x86_64-linux-gnu"],
                      capture_output=True, text=True).stdout.strip()
L = []
L.append("# Solver benchmark: clamped C3D8 cube under pressure, one linear static step\n")
L.append("Machine: %s, %s cores (shared: other work adds noise), BLAS %s. Medians of the runs; "
         "spread min–max. Generated by `bench/run_solver_bench.sh`.\n" % (platform.processor() or platform.machine(),
         subprocess.run(["nproc"], capture_output=True, text=True).stdout.strip(), blas or "?"))
L.append("| N³ | DOF (equations) | runs | assembly s | residual-only s | CHOLMOD analyse / factor / solve s | factor GFlop |"
         " floor peak MB | inpact peak MB | ccx peak MB |")
L.append("|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    L.append("| %d³ | %d (%d) | %d | %s | %s | %s / %s / %s | %.0f | %.0f | %s | %s |" % (
        r["n"], r["dof"], r["eq"], r["runs"], fmt(r["asm"]), fmt(r["res"]), fmt(r["ana"]), fmt(r["fac"]),
        fmt(r["sol"]), r["gflop"], r["fpeak"], fmt(r["ipeak"]), fmt(r["cpeak"])))
L.append("")
L.append("| N³ | inpact 1 thr s (spread) | inpact 2 thr s (spread) | floor 1 thr s (spread) | floor 2 thr s |"
         " ratio whole/floor 1 thr | ratio 2 thr | ccx s (runs, spread) | inpact/ccx | tip U3 inpact | tip U3 ccx | rel. diff |")
L.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    ratio = lambda a, b: "%.2f" % (a / b) if a and b else "–"
    rel = "%.1e" % (abs(r["ti"] - r["tc"]) / abs(r["tc"])) if r["ti"] is not None and r["tc"] else "–"
    L.append("| %d³ | %s (%s) | %s (%s) | %s (%s) | %s | %s | %s | %s (%d, %s) | %s | %s | %s | %s |" % (
        r["n"], fmt(r["w1"]), r["s1"], fmt(r["w2"]), r["s2"], fmt(r["fl1"]), r["sf"], fmt(r["fl2"]),
        ratio(r["w1"], r["fl1"]), ratio(r["w2"], r["fl2"]), fmt(r["wc"]), r["ccx_runs"], r["sc"],
        ratio(r["w1"], r["wc"]), "%.6e" % r["ti"] if r["ti"] is not None else "–",
        "%.6e" % r["tc"] if r["tc"] is not None else "–", rel))
L.append("")
L.append("floor = one assembly + CHOLMOD analyse + factor + solve of the same matrix (bench/solver_floor). "
         "ccx: CalculiX %s, its default solver for this deck, OMP_NUM_THREADS=1. "
         "Whole runs include reading the deck and writing results (.h5, .frd). inpact prints the tip "
         "displacement with 5 digits (.dat), so a relative difference below ~1e-4 is agreement." %
         subprocess.run(["sh", "-c", "dpkg-query -W -f='${Version}' calculix-ccx 2>/dev/null"],
                        capture_output=True, text=True).stdout.strip())
text = "\n".join(L) + "\n"
open(out_dir + "/solver.md", "w").write(text)
print(text)

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
fig, ax = plt.subplots(figsize=(6.4, 4.4))
for key, label, style in [("inpact", "inpact run, 1 thread", "o-"), ("inpact2", "inpact run, 2 threads", "s--"),
                          ("floor", "floor (assembly + CHOLMOD), 1 thread", "^-"), ("ccx", "CalculiX ccx, 1 thread", "d-")]:
    pts = [(d, v) for d, v in zip(plot["dof"], plot[key]) if v]
    if pts: ax.plot(*zip(*pts), style, label=label)
ax.set_xscale("log"); ax.set_yscale("log")
ax.set_xlabel("DOF"); ax.set_ylabel("wall time [s] (median)")
ax.set_title("Clamped C3D8 cube, linear static")
ax.grid(True, which="both", alpha=0.3); ax.legend()
fig.tight_layout(); fig.savefig(out_dir + "/solver.png", dpi=120)
print("wrote %s/solver.md and %s/solver.png" % (out_dir, out_dir))
EOF
