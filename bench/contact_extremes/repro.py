#!/usr/bin/python3
"""Minimal decks for the problems bench/contact_extremes found (helper report, issue 4), each a
two-block patch test of blocks.py whose exact answer is CPRESS = p at every interface node:

  touch_gap        2-D, linear penalty, pressure load, initial gap +2e-12 (1e-12 of the model):
                   stops ("diverging"); right before the vertex snap was removed (883ce7b)
  sts_touch_3d     3-D surface to surface, penalty, gap 0: the first iteration overshoots 10×
                   (residual 1e2 × the average force); with an overclosure of 2e-15 it does not
  sts_c3d8r        3-D surface to surface, penalty, C3D8R, ν = 0.4999: completed with CPRESS 0
                   everywhere, open gaps and the top moving up — residual 251 N for a 40 N load
                   (q̃ inflated by a first-iteration spike; right since ee58956, kept as a check)
  general_split    general contact (ALL EXTERIOR), penalty: CPRESS 6.67 on one body, 13.3 on the
                   other, for p = 10 (Σ CPRESS·CNAREA = the load)
  general_stiff    general contact, given penalty stiffness 1e20 (multipliers): CPRESS −4929 … 4703

    repro.py [--inpact build/apps/inpact] [--out DIR] [NAME ...]

Writes DIR/NAME.inp, runs `inpact run`, prints the exit code and CPRESS / COPEN of the interface
nodes and the top's displacement against the exact ones.
"""
import argparse
import os
import subprocess
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import blocks  # noqa: E402

CASES = {
    "touch_gap": dict(method="PENALTY", gap=2e-12),
    "sts_touch_3d": dict(dim=3, method="PENALTY", discretization="SURFACE TO SURFACE"),
    "sts_c3d8r": dict(dim=3, elem="C3D8R", nus=0.4999, num=0.4999, method="PENALTY",
                      discretization="SURFACE TO SURFACE"),
    "general_split": dict(method="PENALTY", discretization=blocks.GENERAL),
    "general_stiff": dict(method="PENALTY", stiffness=1e20, discretization=blocks.GENERAL),
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inpact", default=os.path.join(HERE, "..", "..", "build", "apps", "inpact"))
    ap.add_argument("--out", default="repro")
    ap.add_argument("names", nargs="*", help="some of " + ", ".join(CASES) + " (default: all)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name in args.names or list(CASES):
        text, exp = blocks.deck(**CASES[name])
        path = os.path.join(args.out, name + ".inp")
        with open(path, "w") as f:
            f.write(text)
        p = subprocess.run([args.inpact, "run", path, "-o", args.out, "-j", name, "-v"], capture_output=True, text=True)
        iters = [ln.strip() for ln in p.stdout.splitlines() if " iter 1 " in ln][:1]
        print(f"== {name}: inpact run {path} -v  → exit {p.returncode}")
        if iters:
            print("   first iteration:", iters[0])
        if p.returncode != 0:
            print("  ", (p.stderr or p.stdout).strip().splitlines()[-1][:300])
            continue
        with h5py.File(os.path.join(args.out, name + ".h5"), "r") as f:
            fo = list(f["steps"].values())[-1]["fieldOutputs"]
            iface = f["model/sets/nsets/IFACE"][:]
            rows = fo["CPRESS/nodes"][:]
            sel = np.isin(rows, iface)
            cp, co = fo["CPRESS/data"][-1][sel, 0], fo["COPEN/data"][-1][sel, 0]
            u_rows, u = fo["U/nodes"][:], fo["U/data"][-1]
            top = u[np.searchsorted(u_rows, f["model/sets/nsets/TOP"][:]), exp["dim"] - 1].mean()
        print(f"   CPRESS {cp.min():.4g} … {cp.max():.4g} (exact {exp['p']:g}); COPEN {np.nanmin(co):.3g} … "
              f"{np.nanmax(co):.3g} (exact {-exp['penetration']:.3g}); top U {top:.4g} (exact {exp['u_top']:.4g})")


if __name__ == "__main__":
    main()
