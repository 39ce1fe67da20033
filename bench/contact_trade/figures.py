#!/usr/bin/env python3
"""Figures of one contact verification run (decks/contact_verification/), read from its JOB.h5:

    figures.py JOB.h5 {hertz_2d|sphere_3d|interference_2d}   # prints one JSON line

Hertz (Johnson, Contact Mechanics, 1985, §4.2), from the load P the run carried (its reaction):
  line contact:  a = sqrt(4PR/(πE*)), p0 = sqrt(PE*/(πR))        P = 2 × the half model's
  sphere:        a = (3PR/(4E*))^(1/3), p0 = 3P/(2πa²)            P = 4 × the quarter model's
Interference fit (Lamé, same material, plane strain): p = E'δ(c²−b²)(b²−a²)/(2b³(c²−a²)).
The same formulas are in tests/contact_verification/contact_verification.hpp (C++)."""
import json
import math
import sys

import h5py
import numpy as np

E, NU = 210000.0, 0.3
E_STAR = E / (2.0 * (1.0 - NU * NU))
R_HERTZ, R_SPHERE = 20.0, 20.0
RING_A, RING_B, RING_C, DELTA = 0.5, 1.0, 2.0, 0.01


def lame_pressure():
    ep = E / (1.0 - NU * NU)
    a, b, c = RING_A, RING_B + 0.5 * DELTA, RING_C
    return ep * DELTA * (c * c - b * b) * (b * b - a * a) / (2.0 * b ** 3 * (c * c - a * a))


def last(f, step, key):
    g = f[f"steps/{step}/fieldOutputs/{key}"]
    return g["data"][-1], g["nodes"][:]


def figures(path, problem):
    with h5py.File(path, "r") as f:
        step = list(f["steps"].keys())[0]
        xyz = f["model/nodes/coordinates"][:]
        cp, rows = last(f, step, "CPRESS")
        co, _ = last(f, step, "COPEN")
        ca, _ = last(f, step, "CNAREA")
        cp, co, ca = cp[:, 0], co[:, 0], ca[:, 0]
        status = f["status"][:]
        out = {"newton": int(status["total_iters"].sum()), "augmentations": int(status["augmentations"].sum()),
               "severe": int(status["severe_discon_iters"].sum()), "increments": int((status["cut_back"] == 0).sum()),
               "cutbacks": int(status["cut_back"].sum())}
        closed = cp > 0
        out["max_penetration"] = float(max(0.0, (-co[closed]).max())) if closed.any() else 0.0
        if problem == "interference_2d":
            p_ref = lame_pressure()
            mean = float((cp * ca).sum() / ca.sum())
            out.update(p_ref=p_ref, p_mean=mean, p_max=float(cp.max()), p_min=float(cp.min()),
                       err_mean=(mean - p_ref) / p_ref, scatter=float((cp.max() - cp.min()) / p_ref),
                       n_closed=int(closed.sum()), n_slave=int(len(cp)))
            # the overclosure is resolved in the first increment: pressure of the first frame
            cp0 = f[f"steps/{step}/fieldOutputs/CPRESS/data"][0][:, 0]
            out["first_frame_mean"] = float((cp0 * ca).sum() / ca.sum())
            return out
        rf, rf_rows = last(f, step, "RF")
        top = f["model/sets/nsets/INDENTER_TOP"][:]
        idx = np.searchsorted(rf_rows, top)
        dim = 2 if problem == "hertz_2d" else 3
        p_model = -float(rf[idx, dim - 1].sum())  # the indenter is pushed down: RF up is the load
        x = xyz[rows]
        r = np.abs(x[:, 0]) if dim == 2 else np.hypot(x[:, 0], x[:, 1])
        if dim == 2:
            p_load = 2.0 * p_model
            a_ref = math.sqrt(4.0 * p_load * R_HERTZ / (math.pi * E_STAR))
            p0_ref = math.sqrt(p_load * E_STAR / (math.pi * R_HERTZ))
        else:
            p_load = 4.0 * p_model
            a_ref = (3.0 * p_load * R_SPHERE / (4.0 * E_STAR)) ** (1.0 / 3.0)
            p0_ref = 3.0 * p_load / (2.0 * math.pi * a_ref ** 2)
        centre = int(np.argmin(r))
        p0 = float(cp[centre])
        r_closed = float(r[closed].max()) if closed.any() else 0.0
        r_open = float(r[~closed & (r > r_closed)].min()) if (~closed & (r > r_closed)).any() else float("nan")
        # contact size estimate: halfway between the last closed and the first open node
        a_fe = 0.5 * (r_closed + r_open)
        out.update(P=p_load, a_ref=a_ref, p0_ref=p0_ref, p0=p0, p_max=float(cp.max()), a_closed=r_closed,
                   a_open=r_open, a_fe=a_fe, err_p0=(p0 - p0_ref) / p0_ref, err_a=(a_fe - a_ref) / a_ref,
                   h=float(np.sort(np.unique(np.round(r, 12)))[1]))
        return out


if __name__ == "__main__":
    print(json.dumps(figures(sys.argv[1], sys.argv[2])))
