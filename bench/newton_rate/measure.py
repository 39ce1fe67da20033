#!/usr/bin/env python3
"""Newton's rate on the smoothed and frictional contact decks: iterations per increment and the
residual sequence of the longest increment, per deck and method (`inpact run -v`).

  bench/newton_rate/measure.py INPACT [OUT.csv]

Columns: deck, method, status, increments, iterations, iterations per increment, the residuals
(relative to the average force) of the increment with the most iterations, and the last ratios
log(r_{k+1})/log(r_k) (2 = quadratic)."""
import csv, math, os, re, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DECKS = os.path.join(HERE, "..", "..", "decks")
SMOOTHED = ["contact_verification/interference_2d_smoothed", "contact_verification/oring_axi_smoothed",
            "contact_verification/spherical_seat_axi_smoothed", "contact_verification/spherical_seat_3d_smoothed",
            "pin_in_hole"]
FRICTION = ["contact/friction_slide_2d_direct", "contact/friction_slide_2d_lagrange", "contact/friction_slide_2d_penalty",
            "contact/friction_slide_3d_direct", "contact/friction_stick_2d_direct", "contact/friction_stick_2d_lagrange",
            "contact/friction_stick_3d_penalty", "contact/patch_2d_general_friction"]
METHODS = {"direct": "DIRECT", "penalty": "PENALTY", "augmented": "AUGMENTED LAGRANGE"}
ITER = re.compile(r"inc (\d+) att (\d+) iter (\d+)\s+max residual \S+ \((\S+) of the average force\)")
DONE = re.compile(r"step (\d+) inc (\d+) att (\d+)\s+iterations (\d+)")


def run(exe, deck, method):
    args = [exe, "run", "-v", os.path.join(DECKS, deck + ".inp"), "-o", tempfile.mkdtemp(prefix="nr")]
    if method:
        args += ["-P", f"method={METHODS[method]}"]
    p = subprocess.run(args, capture_output=True, text=True, timeout=900)
    seqs, current, incs, iters = [], [], 0, 0
    for line in p.stdout.splitlines():
        m = ITER.search(line)
        if m:
            if int(m.group(3)) == 0 and current:
                seqs.append(current)
                current = []
            current.append(float(m.group(4)))
            continue
        m = DONE.search(line)
        if m:
            incs += 1
            iters += int(m.group(4))
    if current:
        seqs.append(current)
    worst = max(seqs, key=len) if seqs else []
    rates = [math.log(b) / math.log(a) for a, b in zip(worst[1:], worst[2:]) if 0 < a < 1 and 0 < b < 1]
    return dict(status=p.returncode, increments=incs, iterations=iters,
                per_increment=iters / incs if incs else float("nan"),
                residuals=" ".join(f"{r:.2e}" for r in worst),
                rates=" ".join(f"{r:.2f}" for r in rates[-3:]))


def main():
    exe = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else None
    rows = []
    cases = [(d, m) for d in SMOOTHED for m in METHODS] + [(d, None) for d in FRICTION]
    for deck, method in cases:
        r = run(exe, deck, method)
        r.update(deck=os.path.basename(deck), method=method or "(deck)")
        rows.append(r)
        print(f"{r['deck']:32s} {r['method']:10s} rc={r['status']} inc={r['increments']:3d} it={r['iterations']:4d} "
              f"it/inc={r['per_increment']:.2f}  [{r['residuals']}]  rates {r['rates']}", flush=True)
    if out:
        with open(out, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=["deck", "method", "status", "increments", "iterations", "per_increment",
                                              "residuals", "rates"])
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
