#!/usr/bin/env python3
"""Writes the deck of bench/study_overhead.py: two stacked 2D plane-strain blocks (CPE4) in
penalty contact, a few thousand elements, the top pressure a *PARAMETER <load>.
Usage: study_overhead_deck.py OUT.inp [NX_LOWER NY_LOWER]  (upper block: 2 NX, NY)."""
import sys

out = sys.argv[1]
nx = int(sys.argv[2]) if len(sys.argv) > 2 else 36
ny = int(sys.argv[3]) if len(sys.argv) > 3 else 30
nxu = 2 * nx  # nested meshes: every master node under a slave node (converges like the patch test)


def grid(first, nx_, ny_, y0, y1):
    nodes, elems = [], []
    for j in range(ny_ + 1):
        for i in range(nx_ + 1):
            nodes.append((first + j * (nx_ + 1) + i, 2.0 * i / nx_, y0 + (y1 - y0) * j / ny_))
    for j in range(ny_):
        for i in range(nx_):
            a = first + j * (nx_ + 1) + i
            elems.append((first + j * nx_ + i, a, a + 1, a + nx_ + 2, a + nx_ + 1))
    return nodes, elems


def lines(items, per=12):
    items = [str(i) for i in items]
    return "\n".join(", ".join(items[k:k + per]) for k in range(0, len(items), per)) + "\n"


U0 = 1_000_000
ln, le = grid(1, nx, ny, 0.0, 1.0)
un, ue = grid(U0 + 1, nxu, ny, 1.0, 2.0)
s = "*HEADING\n Study overhead bench: two blocks in penalty contact under a pressure LOAD\n"
s += "*PARAMETER\nload = 10\n"
s += "*NODE, NSET=ALL\n" + "".join(f"{n}, {x:.12g}, {y:.12g}\n" for n, x, y in ln + un)
s += "*ELEMENT, TYPE=CPE4, ELSET=LOWER\n" + "".join(", ".join(map(str, e)) + "\n" for e in le)
s += "*ELEMENT, TYPE=CPE4, ELSET=UPPER\n" + "".join(", ".join(map(str, e)) + "\n" for e in ue)
s += "*ELSET, ELSET=LOWER_TOP\n" + lines([e[0] for e in le[-nx:]])
s += "*ELSET, ELSET=UPPER_BOTTOM\n" + lines([e[0] for e in ue[:nxu]])
s += "*ELSET, ELSET=UPPER_TOP\n" + lines([e[0] for e in ue[-nxu:]])
s += "*SURFACE, NAME=MASTER_S\nLOWER_TOP, S3\n*SURFACE, NAME=SLAVE_S\nUPPER_BOTTOM, S1\n*SURFACE, NAME=TOP_S\nUPPER_TOP, S3\n"
s += "*SOLID SECTION, ELSET=LOWER, MATERIAL=SOFT\n*SOLID SECTION, ELSET=UPPER, MATERIAL=SOFT\n"
s += "*MATERIAL, NAME=SOFT\n*ELASTIC\n1000, 0.3\n"
s += "*SURFACE INTERACTION, NAME=SMOOTH\n*SURFACE BEHAVIOR, PENALTY\n"
s += "*CONTACT PAIR, INTERACTION=SMOOTH, TYPE=NODE TO SURFACE\nSLAVE_S, MASTER_S\n"
s += "*NSET, NSET=BOTTOM\n" + lines([n for n, x, y in ln[:nx + 1]])
sides = [n for n, x, y in ln + un if x in (0.0, 2.0)]
s += "*NSET, NSET=SIDES\n" + lines(sides)
s += "*BOUNDARY\nBOTTOM, 2\nSIDES, 1\n"
s += "*STEP, NAME=PRESS\n*STATIC\n0.25, 1.0\n*DSLOAD\nTOP_S, P, <load>\n"
s += "*OUTPUT, FIELD\n*NODE OUTPUT\nU, RF\n*ELEMENT OUTPUT\nS\n*CONTACT OUTPUT\nCPRESS, COPEN, CSTATUS\n*END STEP\n"
open(out, "w").write(s)
print(f"{out}: {len(le) + len(ue)} elements, {len(ln) + len(un)} nodes")
