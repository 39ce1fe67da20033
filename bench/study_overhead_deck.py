#!/usr/bin/env python3
"""Writes the deck of bench/study_overhead.py: two stacked blocks in penalty contact, a few
thousand elements, the top pressure a *PARAMETER <load>. The upper block is twice as fine in
the plane (nested meshes: every master node under a slave node, so it converges like the patch
test); the sides are on rollers, the bottom fixed in the stacking direction.
  2D (plane strain CPE4): NX NY, the lower block's elements (upper: 2 NX x NY)
  3D (C3D8):              NX NY NZ (upper: 2 NX x 2 NY x NZ)
Usage: study_overhead_deck.py OUT.inp [NX NY [NZ]]  (default 36 30: 3,240 CPE4 elements)."""
import sys

out = sys.argv[1]
nx = int(sys.argv[2]) if len(sys.argv) > 2 else 36
ny = int(sys.argv[3]) if len(sys.argv) > 3 else 30
nz = int(sys.argv[4]) if len(sys.argv) > 4 else 0
solid = nz > 0
U0 = 1_000_000  # first label of the upper block


def grid2(first, nx_, ny_, y0, y1):
    nodes, elems = [], []
    for j in range(ny_ + 1):
        for i in range(nx_ + 1):
            nodes.append((first + j * (nx_ + 1) + i, (2.0 * i / nx_, y0 + (y1 - y0) * j / ny_)))
    for j in range(ny_):
        for i in range(nx_):
            a = first + j * (nx_ + 1) + i
            elems.append((first + j * nx_ + i, a, a + 1, a + nx_ + 2, a + nx_ + 1))
    return nodes, elems


def grid3(first, nx_, ny_, nz_, z0, z1):
    """A brick of C3D8: layers of nz_ in z between z0 and z1; node order as Abaqus (bottom face
    counter-clockwise seen from above, then the top face), so S1 faces down and S2 up."""
    nodes, elems = [], []
    px, pxy = nx_ + 1, (nx_ + 1) * (ny_ + 1)
    for k in range(nz_ + 1):
        for j in range(ny_ + 1):
            for i in range(nx_ + 1):
                nodes.append((first + k * pxy + j * px + i, (2.0 * i / nx_, 2.0 * j / ny_, z0 + (z1 - z0) * k / nz_)))
    for k in range(nz_):
        for j in range(ny_):
            for i in range(nx_):
                a = first + k * pxy + j * px + i
                bottom = [a, a + 1, a + px + 1, a + px]
                elems.append((first + (k * ny_ + j) * nx_ + i, *bottom, *[n + pxy for n in bottom]))
    return nodes, elems


def lines(items, per=12):
    items = [str(i) for i in items]
    return "\n".join(", ".join(items[k:k + per]) for k in range(0, len(items), per)) + "\n"


if solid:
    ln, le = grid3(1, nx, ny, nz, 0.0, 1.0)
    un, ue = grid3(U0 + 1, 2 * nx, 2 * ny, nz, 1.0, 2.0)
    layer, layer_u = nx * ny, 4 * nx * ny  # elements of one layer
    etype, down, up, stack = "C3D8", "S1", "S2", 3
else:
    ln, le = grid2(1, nx, ny, 0.0, 1.0)
    un, ue = grid2(U0 + 1, 2 * nx, ny, 1.0, 2.0)
    layer, layer_u = nx, 2 * nx
    etype, down, up, stack = "CPE4", "S1", "S3", 2
fmt = lambda x: f"{x:.12g}"
s = "*HEADING\n Study overhead bench: two blocks in penalty contact under a pressure LOAD\n"
s += "*PARAMETER\nload = 10\n"
s += "*NODE, NSET=ALL\n" + "".join(f"{n}, " + ", ".join(map(fmt, x)) + "\n" for n, x in ln + un)
s += f"*ELEMENT, TYPE={etype}, ELSET=LOWER\n" + "".join(", ".join(map(str, e)) + "\n" for e in le)
s += f"*ELEMENT, TYPE={etype}, ELSET=UPPER\n" + "".join(", ".join(map(str, e)) + "\n" for e in ue)
s += "*ELSET, ELSET=LOWER_TOP\n" + lines([e[0] for e in le[-layer:]])
s += "*ELSET, ELSET=UPPER_BOTTOM\n" + lines([e[0] for e in ue[:layer_u]])
s += "*ELSET, ELSET=UPPER_TOP\n" + lines([e[0] for e in ue[-layer_u:]])
s += f"*SURFACE, NAME=MASTER_S\nLOWER_TOP, {up}\n*SURFACE, NAME=SLAVE_S\nUPPER_BOTTOM, {down}\n"
s += f"*SURFACE, NAME=TOP_S\nUPPER_TOP, {up}\n"
s += "*SOLID SECTION, ELSET=LOWER, MATERIAL=SOFT\n*SOLID SECTION, ELSET=UPPER, MATERIAL=SOFT\n"
s += "*MATERIAL, NAME=SOFT\n*ELASTIC\n1000, 0.3\n"
s += "*SURFACE INTERACTION, NAME=SMOOTH\n*SURFACE BEHAVIOR, PENALTY\n"
s += "*CONTACT PAIR, INTERACTION=SMOOTH, TYPE=NODE TO SURFACE\nSLAVE_S, MASTER_S\n"
s += "*NSET, NSET=BOTTOM\n" + lines([n for n, x in ln if x[stack - 1] == 0.0])
s += "*NSET, NSET=SIDES\n" + lines([n for n, x in ln + un if x[0] in (0.0, 2.0)])
if solid:
    s += "*NSET, NSET=FRONT_BACK\n" + lines([n for n, x in ln + un if x[1] in (0.0, 2.0)])
s += f"*BOUNDARY\nBOTTOM, {stack}\nSIDES, 1\n" + ("FRONT_BACK, 2\n" if solid else "")
s += "*STEP, NAME=PRESS\n*STATIC\n0.25, 1.0\n*DSLOAD\nTOP_S, P, <load>\n"
s += "*OUTPUT, FIELD\n*NODE OUTPUT\nU, RF\n*ELEMENT OUTPUT\nS\n*CONTACT OUTPUT\nCPRESS, COPEN, CSTATUS\n*END STEP\n"
open(out, "w").write(s)
print(f"{out}: {len(le) + len(ue)} {etype} elements, {len(ln) + len(un)} nodes")
