#!/usr/bin/env python3
"""A rubber O-ring squeezed between two flat steel plates (axisymmetric, CAX4H): the deck
oring_rubber_cax4h.inp and, with --element, the same model with other elements (CalculiX has no
hybrid axisymmetric elements: its reference runs CAX8R).

  python3 gen_oring_rubber.py --out .
  python3 gen_oring_rubber.py --out DIR --element CAX4 --name oring_rubber_cax4.inp
  python3 gen_oring_rubber.py --out . --smoothing --name oring_rubber_cax4h_smoothed.inp

The ring: cross-section radius a = 1 centred at r = R0 = 5, z = 0; half model z >= 0 (the
mid-plane z = 0 a symmetry plane: the lower plate is the mirror of the upper one). Neo-Hooke
C10 = 0.5, D1 = 0.02 (mu0 = 1, K0 = 100). The plate: steel-like and 2000 times stiffer than the rubber (E = 2000, nu = 0.3: stiffer plates leave their reactions at the round-off of their own large internal forces), r from 3 to 7,
z from a to 1.5 a, its top face moved down by 0.15 a in 10 increments (the ring squeezed by 15 %
of its diameter). Contact: node to surface, frictionless, PRESSURE-OVERCLOSURE=LINEAR with
k = 1000 (p = k h; the same law in CalculiX). Reported: the plate's reaction force (the whole
ring), against CalculiX on the CAX8R deck.

--smoothing: the ring's surface corrected toward the torus it was meshed from ([AX] 38.1.3;
*SURFACE SMOOTHING RING_S, TOROIDAL about the y axis, arc centre at R = R0, tube radius a from the
nodes). Geometric correction is for surface-to-surface pairs, so the pair becomes SURFACE TO
SURFACE, still with the ring the slave: there the slave's integration points are moved onto its
idealised surface (the faceted chord lies up to a (1 - cos(pi/48)) = 0.0021 inside the circle
between its nodes); the plate stays faceted (it is flat: a correction would be zero). Node to
surface could not use it: its slave points are the ring's nodes, already on the circle. The
correction is the reference torus's, carried by each facet's rotation while the ring flattens.
(The ring as the corrected master, the plate the slave, gives about the same force, 14.13 against
14.17, but takes 122 Newton iterations against 37.)"""
import argparse
import math
import os

A, R0 = 1.0, 5.0
SQUEEZE = 0.15


class Nodes:
    def __init__(self):
        self.ids, self.xy = {}, []

    def at(self, x, y):
        key = (round(x, 9), round(y, 9))
        if key not in self.ids:
            self.ids[key] = len(self.xy) + 1
            self.xy.append((x, y))
        return self.ids[key]


def ccw(nodes, quad):
    (x1, y1), (x2, y2), (x3, y3) = (nodes.xy[quad[k] - 1] for k in range(3))
    area = (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1)
    return quad if area > 0 else [quad[0], quad[3], quad[2], quad[1]]


def grid(nodes, point, ni, nj):
    """Quads of the map point(s, t), s, t in [0, 1], ni × nj elements; returns (elements, edge t=1)."""
    ids = [[nodes.at(*point(i / ni, j / nj)) for j in range(nj + 1)] for i in range(ni + 1)]
    quads = [ccw(nodes, [ids[i][j], ids[i + 1][j], ids[i + 1][j + 1], ids[i][j + 1]])
             for i in range(ni) for j in range(nj)]
    outer = [(quads[i * nj + nj - 1], ids[i][nj], ids[i + 1][nj]) for i in range(ni)]
    return quads, outer


def ring(nodes, m, k):
    """The half disk: a core [-b, b] × [0, b] and three blocks out to the arc (an O-grid)."""
    b = 0.45 * A
    quads, _ = grid(nodes, lambda s, t: (R0 - b + 2 * b * s, b * t), 2 * m, m)
    arc = lambda th: (R0 + A * math.cos(th), A * math.sin(th))
    blocks = [  # inner edge point (s), outer arc angle (s)
        (lambda s: (R0 + b, b * s), lambda s: math.pi / 4 * s, m),
        (lambda s: (R0 + b - 2 * b * s, b), lambda s: math.pi / 4 + math.pi / 2 * s, 2 * m),
        (lambda s: (R0 - b, b - b * s), lambda s: 3 * math.pi / 4 + math.pi / 4 * s, m),
    ]
    outer = []
    for inner, angle, n in blocks:
        def point(s, t, inner=inner, angle=angle):
            (xi, yi), (xo, yo) = inner(s), arc(angle(s))
            return xi + (xo - xi) * t, yi + (yo - yi) * t
        q, o = grid(nodes, point, n, k)
        quads += q
        outer += o
    return quads, outer


def with_midsides(nodes, quads):
    """Quad8 connectivity: the midside nodes at the edge midpoints (straight edges)."""
    out = []
    for q in quads:
        mids = []
        for f in range(4):
            (x1, y1), (x2, y2) = nodes.xy[q[f] - 1], nodes.xy[q[(f + 1) % 4] - 1]
            mids.append(nodes.at((x1 + x2) / 2, (y1 + y2) / 2))
        out.append(q + mids)
    return out


def face_of(quad, n1, n2):
    """The Abaqus face number (S1..S4) of the edge n1-n2 of a quad."""
    for f in range(4):
        if {quad[f], quad[(f + 1) % 4]} == {n1, n2}:
            return f + 1
    raise ValueError("edge not in element")


def build(quadratic):
    """Ring and plate, each on its own nodes (the plate's bottom touches the ring's top at
    (R0, a)): the node coordinates, connectivities, the ring's outer edges and the plate's
    bottom elements (0-based into the plate's list)."""
    ring_nodes, plate_nodes = Nodes(), Nodes()
    ring_q, ring_outer = ring(ring_nodes, 6, 8)
    plate_q, _ = grid(plate_nodes, lambda s, t: (R0 - 2 * A + 4 * A * s, A + 0.5 * A * t), 40, 4)
    bottom = [e for e, q in enumerate(plate_q) if all(abs(plate_nodes.xy[n - 1][1] - A) < 1e-9 for n in q[:2])]
    ring_conn = with_midsides(ring_nodes, ring_q) if quadratic else ring_q
    plate_conn = with_midsides(plate_nodes, plate_q) if quadratic else plate_q
    offset = len(ring_nodes.xy)
    plate_conn = [[n + offset for n in q] for q in plate_conn]
    return ring_nodes.xy, plate_nodes.xy, ring_conn, plate_conn, ring_q, ring_outer, bottom


def id_lines(ids):
    return [", ".join(map(str, ids[i:i + 12])) for i in range(0, len(ids), 12)]


def mesh_lines(element, quadratic):
    ring_xy, plate_xy, ring_conn, plate_conn, ring_q, ring_outer, bottom = build(quadratic)
    xy = ring_xy + plate_xy
    lines = ["*NODE, NSET=ALL"] + [f"{i + 1}, {x:.12g}, {y:.12g}" for i, (x, y) in enumerate(xy)]
    lines.append(f"*ELEMENT, TYPE={element}, ELSET=RING")
    lines += [f"{e + 1}, " + ", ".join(map(str, q)) for e, q in enumerate(ring_conn)]
    lines.append(f"*ELEMENT, TYPE={'CAX8' if quadratic else 'CAX4'}, ELSET=PLATE")
    lines += [f"{len(ring_q) + e + 1}, " + ", ".join(map(str, q)) for e, q in enumerate(plate_conn)]
    by_face = {}
    for quad, n1, n2 in ring_outer:
        by_face.setdefault(face_of(quad, n1, n2), []).append(ring_q.index(quad) + 1)
    surface = ["*SURFACE, NAME=RING_S"]
    for f, els in sorted(by_face.items()):
        lines += [f"*ELSET, ELSET=RING_S{f}"] + id_lines(els)
        surface.append(f"RING_S{f}, S{f}")
    lines += surface
    # The plate's bottom row of elements, face S1 (their first edge runs along z = a).
    lines += ["*ELSET, ELSET=PLATE_BOTTOM"] + id_lines([len(ring_q) + e + 1 for e in bottom])
    lines += ["*SURFACE, NAME=PLATE_S", "PLATE_BOTTOM, S1"]
    sym = [i + 1 for i, (x, y) in enumerate(ring_xy) if abs(y) < 1e-9]
    top = [i + 1 for i, (x, y) in enumerate(xy) if abs(y - 1.5 * A) < 1e-9]
    return lines + ["*NSET, NSET=SYM"] + id_lines(sym) + ["*NSET, NSET=PLATE_TOP"] + id_lines(top)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--element", default="CAX4H")
    ap.add_argument("--name", default="oring_rubber_cax4h.inp")
    ap.add_argument("--smoothing", action="store_true",
                    help="the ring's surface smoothed (TOROIDAL, R = R0); the pair surface to surface")
    a = ap.parse_args()
    pair_type = "SURFACE TO SURFACE" if a.smoothing else "NODE TO SURFACE"
    lines = ["*HEADING"]
    if a.smoothing:
        lines.append(f"** Smoothed: the ring's surface corrected toward the torus about the y axis, R = {R0:g} "
                     "([AX] 38.1.3).")
    lines += [f" Rubber O-ring squeezed between flat plates, {a.element}: a = {A}, R0 = {R0}, squeeze {SQUEEZE} a "
              "(15 % of the diameter)",
              f"** Neo-Hooke C10 = 0.5, D1 = 0.02 (mu0 = 1, K0 = 100); plate E = 2000; {pair_type.lower()},",
              "** PRESSURE-OVERCLOSURE=LINEAR k = 1000, frictionless. Reference: CalculiX 2.20 on the CAX8R form.",
              "** Generated by decks/contact_verification/gen_oring_rubber.py."]
    lines += mesh_lines(a.element, a.element.startswith("CAX8"))
    lines += ["*SOLID SECTION, ELSET=RING, MATERIAL=RUBBER", "*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL",
              "*MATERIAL, NAME=RUBBER", "*HYPERELASTIC, NEO HOOKE", "0.5, 0.02",
              "*MATERIAL, NAME=STEEL", "*ELASTIC", "2000., 0.3"]
    if a.smoothing:  # the torus about the y axis (a = (0, 0, 0), b = (0, 1, 0)), arc centres at R0
        lines += ["*SURFACE SMOOTHING, NAME=RING_TORUS", f"RING_S, TOROIDAL, 0., 0., 0., 0., 1., 0., {R0:g}"]
    pair = f"*CONTACT PAIR, INTERACTION=RUBBER_STEEL, TYPE={pair_type}"
    if a.smoothing:
        pair += ", GEOMETRIC CORRECTION=RING_TORUS"
    lines += ["*SURFACE INTERACTION, NAME=RUBBER_STEEL", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", "1000.",
              pair, "RING_S, PLATE_S",
              "*BOUNDARY", "SYM, 2, 2", "PLATE_TOP, 1, 1",
              "*STEP, NLGEOM, INC=200", "*STATIC", "0.1, 1.", "*BOUNDARY", f"PLATE_TOP, 2, 2, {-SQUEEZE * A:.12g}",
              "*NODE PRINT, NSET=PLATE_TOP, TOTALS=ONLY", "RF", "*NODE FILE", "U, RF",
              "*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S", "*CONTACT OUTPUT",
              "CPRESS, COPEN, CSTATUS", "*END STEP"]
    with open(os.path.join(a.out, a.name), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
