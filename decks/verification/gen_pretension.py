#!/usr/bin/env python3
"""Generator of the *PRE-TENSION SECTION verification decks (decks/verification/pretension_*.inp):

    gen_pretension.py --out DIR

  pretension_bar.inp              a C3D8 bar 10 x 10 x 40 (2x2x8, E = 210000, nu = 0.3) along z, both
                                  ends held in z (x = 0 / y = 0 symmetry planes, lateral contraction
                                  free), cut at z = 20 by a pre-tension section. Step 1: F = 1000 on the
                                  pre-tension node: S33 = F/A = 10 everywhere, tightening u = FL/EA.
                                  Step 2: the node FIXED, the top end moved up by 0.01: the bolt force
                                  grows by EA 0.01 / L = 5250.
  pretension_joint.inp            a quarter of a bolted joint (x = 0, y = 0 symmetry): plates A (z 0..10)
                                  and B (z 10..20), 24 x 24, with a square hole; a solid bolt (8 x 8 shank
                                  through the hole, 12 x 12 head and nut, 6 thick) whose head and nut are
                                  tied to the plates' outer faces; frictionless contact between the plates.
                                  Step 1: bolt force 1000 (quarter: 250) on the pre-tension node; step 2:
                                  the node FIXED, the plates pulled apart by P (pressure on the plates'
                                  outer faces around the head and nut, quarter total 100).
  pretension_joint_bolt.inp       the bolt alone, its section held (u = 0), pulled by pressure on the head's
                                  and the nut's clamping faces: k_b = F / (change of their distance);
  pretension_joint_plates.inp     the plates alone, pressed together on the same faces: k_c.
  pretension_beam.inp             the same with a B31 bolt (CIRC of area 1, its lower end's rotations held).
  pretension_truss.inp            a T3D2 bolt (A = 1) along the axis of a C3D8 column 1 x 1 x 4, from
                                  its base centre to its top centre, cut by ELEMENT=. Step 1: F = 1000 on
                                  the pre-tension node: the truss carries 1000, base reactions sum to 0;
                                  step 2: the node FIXED, the top face pulled up by 400 in all.

Pure standard-library Python.
"""
import argparse
import math
import os

E, NU = 210000.0, 0.3


class Mesh:
    """Nodes on a tensor grid per body (labels from `first`), C3D8 cells where a predicate holds."""

    def __init__(self):
        self.coords = {}
        self.elements = {}  # label -> (body, conn, (i, j, k))
        self.next_node = 1
        self.next_elem = 1

    def body(self, name, xs, ys, zs, keep, region=None):
        """region(i, j, k): the element set of a cell (default: the body's name)."""
        lab = {}

        def node(i, j, k):
            if (i, j, k) not in lab:
                lab[i, j, k] = self.next_node
                self.coords[self.next_node] = (xs[i], ys[j], zs[k])
                self.next_node += 1
            return lab[i, j, k]

        for k in range(len(zs) - 1):
            for j in range(len(ys) - 1):
                for i in range(len(xs) - 1):
                    if not keep(i, j, k):
                        continue
                    c = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                         node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
                    self.elements[self.next_elem] = (name, c, (i, j, k), region(i, j, k) if region else name)
                    self.next_elem += 1

    def elems(self, body, pred=lambda i, j, k: True):
        return [e for e, (b, _, ijk, _) in self.elements.items() if b == body and pred(*ijk)]

    def nodes_where(self, pred, body=None):
        out = set()
        for e, (b, conn, _, _) in self.elements.items():
            if body is None or b == body:
                out.update(n for n in conn if pred(*self.coords[n]))
        return sorted(out)


def lines_of(labels, per_line=8):
    return [", ".join(str(v) for v in labels[i:i + per_line]) for i in range(0, len(labels), per_line)]


def write_mesh(out, m, regions):
    """regions: element set -> material (STEEL, or RIGID: steel's E times 1e4, a head or nut that
    moves as a rigid plate, as the joint diagram's springs assume)."""
    out += ["*NODE, NSET=ALL"] + [f"{n}, {x:.10g}, {y:.10g}, {z:.10g}" for n, (x, y, z) in m.coords.items()]
    for r, material in regions.items():
        out.append(f"*ELEMENT, TYPE=C3D8, ELSET={r}")
        out += [f"{e}, " + ", ".join(map(str, conn)) for e, (_, conn, _, rr) in m.elements.items() if rr == r]
        out += [f"*SOLID SECTION, ELSET={r}, MATERIAL={material}", ""]
    out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]
    if "RIGID" in regions.values():
        out += ["*MATERIAL, NAME=RIGID", "*ELASTIC", f"{E * 1e4:g}, {NU:g}"]


def nset(out, name, labels):
    out.append(f"*NSET, NSET={name}")
    out += lines_of(labels)


def surface(out, name, elems, face):
    out.append(f"*ELSET, ELSET={name}_E")
    out += lines_of(elems)
    out += [f"*SURFACE, NAME={name}, TYPE=ELEMENT", f"{name}_E, {face}"]


def bar():
    m = Mesh()
    zs = [5.0 * k for k in range(9)]
    m.body("BAR", [0.0, 5.0, 10.0], [0.0, 5.0, 10.0], zs, lambda i, j, k: True)
    out = ["*HEADING", " Pre-tension section in a bar (tests/verification/test_pretension.cpp)"]
    write_mesh(out, m, {"BAR": "STEEL"})
    nset(out, "BOTTOM", m.nodes_where(lambda x, y, z: abs(z) < 1e-9))
    nset(out, "TOP", m.nodes_where(lambda x, y, z: abs(z - 40) < 1e-9))
    nset(out, "X0", m.nodes_where(lambda x, y, z: abs(x) < 1e-9))
    nset(out, "Y0", m.nodes_where(lambda x, y, z: abs(y) < 1e-9))
    surface(out, "CUT", m.elems("BAR", lambda i, j, k: k == 3), "S2")
    out += ["*NODE, NSET=PT", "9001, 5., 5., 20.",
            "*PRE-TENSION SECTION, SURFACE=CUT, NODE=PT",
            "*BOUNDARY", "BOTTOM, 3, 3", "TOP, 3, 3", "X0, 1, 1", "Y0, 2, 2"]
    out += ["*STEP, NAME=TIGHTEN", "*STATIC", "1., 1.", "*CLOAD", "PT, 1, 1000.",
            "*NODE PRINT, NSET=PT", "U, RF", "*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S",
            "*END STEP"]
    out += ["*STEP, NAME=LOCKED", "*STATIC", "1., 1.", "*BOUNDARY, FIXED", "PT, 1, 1", "*BOUNDARY", "TOP, 3, 3, 0.01",
            "*NODE PRINT, NSET=PT", "U, RF", "*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S",
            "*END STEP"]
    return out


# The joint's grid (a quarter: x, y >= 0). Shank: cells i, j < 2 (x, y < 4); head and nut: i, j < 3
# (x, y < 6); plates: every cell but the shank's, out to 24. The load P acts on the plates' ring
# 6 < x or y, x and y < 10 (cells i, j < 4 outside the head).
XS = [0.0, 2.0, 4.0, 6.0, 10.0, 15.0, 24.0]
ZA, ZB = [0.0, 5.0, 10.0], [10.0, 15.0, 20.0]
Z_BOLT = [-6.0, -3.0, 0.0, 5.0, 10.0, 15.0, 20.0, 23.0, 26.0]  # nut k 0-1, shank 2-5, head 6-7


def shank(i, j):
    return i < 2 and j < 2


def under_head(i, j):
    return i < 3 and j < 3 and not shank(i, j)


def load_ring(i, j):
    return i < 4 and j < 4 and not (i < 3 and j < 3)


def bolt_cell(i, j, k):
    return shank(i, j) or ((k < 2 or k > 5) and i < 3 and j < 3)


def joint_mesh(with_bolt, with_plates):
    m = Mesh()
    if with_plates:
        m.body("PLATE_A", XS, XS, ZA, lambda i, j, k: not shank(i, j))
        m.body("PLATE_B", XS, XS, ZB, lambda i, j, k: not shank(i, j))
    if with_bolt:
        m.body("BOLT", XS[:4], XS[:4], Z_BOLT, bolt_cell, lambda i, j, k: "SHANK" if 1 < k < 6 else "HEAD_NUT")
    return m


def joint_common(out, m, with_bolt, with_plates):
    nset(out, "X0", m.nodes_where(lambda x, y, z: abs(x) < 1e-9))
    nset(out, "Y0", m.nodes_where(lambda x, y, z: abs(y) < 1e-9))
    if with_bolt:
        surface(out, "HEAD_CLAMP", m.elems("BOLT", lambda i, j, k: k == 6 and under_head(i, j)), "S1")
        surface(out, "NUT_CLAMP", m.elems("BOLT", lambda i, j, k: k == 1 and under_head(i, j)), "S2")
        surface(out, "CUT", m.elems("BOLT", lambda i, j, k: k == 3), "S2")
        surface(out, "HEAD_TOP", m.elems("BOLT", lambda i, j, k: k == 7), "S2")
        surface(out, "NUT_BOTTOM", m.elems("BOLT", lambda i, j, k: k == 0), "S1")
        nset(out, "HEAD_RING", m.nodes_where(lambda x, y, z: abs(z - 20) < 1e-9 and (x > 4 - 1e-9 or y > 4 - 1e-9), "BOLT"))
        nset(out, "NUT_RING", m.nodes_where(lambda x, y, z: abs(z) < 1e-9 and (x > 4 - 1e-9 or y > 4 - 1e-9), "BOLT"))
    if with_plates:
        surface(out, "B_TOP", m.elems("PLATE_B", lambda i, j, k: k == 1 and under_head(i, j)), "S2")
        surface(out, "A_BOTTOM", m.elems("PLATE_A", lambda i, j, k: k == 0 and under_head(i, j)), "S1")
        surface(out, "B_LOAD", m.elems("PLATE_B", lambda i, j, k: k == 1 and load_ring(i, j)), "S2")
        surface(out, "A_LOAD", m.elems("PLATE_A", lambda i, j, k: k == 0 and load_ring(i, j)), "S1")
        surface(out, "B_BOTTOM", m.elems("PLATE_B", lambda i, j, k: k == 0), "S1")
        surface(out, "A_TOP", m.elems("PLATE_A", lambda i, j, k: k == 1), "S2")
        nset(out, "B_RING", m.nodes_where(lambda x, y, z: abs(z - 20) < 1e-9 and x < 6 + 1e-9 and y < 6 + 1e-9, "PLATE_B"))
        nset(out, "A_RING", m.nodes_where(lambda x, y, z: abs(z) < 1e-9 and x < 6 + 1e-9 and y < 6 + 1e-9, "PLATE_A"))
        # The plates (and the bolt tied to them) float in z but for one node of plate A far out.
        nset(out, "HOLD", m.nodes_where(lambda x, y, z: abs(x - 24) + abs(y - 24) + abs(z) < 1e-9, "PLATE_A"))
        out += ["*SURFACE INTERACTION, NAME=FRICTIONLESS",
                "*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=NODE TO SURFACE", "B_BOTTOM, A_TOP"]


OUTPUT = ["*NODE PRINT, NSET=PT", "U, RF", "*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S",
          "*CONTACT OUTPUT", "CPRESS, COPEN, CSTATUS, CFN"]
# Equilibrium to round-off (R_n = 1e-10 of the average force instead of Abaqus's 5e-3): the
# test balances forces to 1e-9.
CONTROLS = ["*CONTROLS, PARAMETERS=FIELD", "1e-10"]
JOINT_REGIONS = {"PLATE_A": "STEEL", "PLATE_B": "STEEL", "SHANK": "STEEL", "HEAD_NUT": "RIGID"}
DELTA = 1e-3  # the clamping faces' relative displacement in the stiffness runs


def joint():
    m = joint_mesh(True, True)
    out = ["*HEADING", " Quarter of a bolted joint with a pre-tension section (tests/verification/test_pretension.cpp)"]
    write_mesh(out, m, JOINT_REGIONS)
    joint_common(out, m, True, True)
    out += ["*TIE, NAME=HEAD, TYPE=NODE TO SURFACE", "HEAD_CLAMP, B_TOP",
            "*TIE, NAME=NUT, TYPE=NODE TO SURFACE", "NUT_CLAMP, A_BOTTOM",
            "*NODE, NSET=PT", "9001, 0., 0., 10.", "*PRE-TENSION SECTION, SURFACE=CUT, NODE=PT",
            "*BOUNDARY", "X0, 1, 1", "Y0, 2, 2", "HOLD, 3, 3"]
    out += ["*STEP, NAME=TIGHTEN", "*STATIC", "1., 1."] + CONTROLS + ["*CLOAD", "PT, 1, 250."] + OUTPUT + ["*END STEP"]
    # P = 100 on the quarter, a suction on the head's top and the nut's bottom (6 x 6 each).
    out += ["*STEP, NAME=PULL", "*STATIC", "0.25, 1."] + CONTROLS + ["*BOUNDARY, FIXED", "PT, 1, 1",
            "*DSLOAD", f"HEAD_TOP, P, {-100.0 / 36:.17g}", f"NUT_BOTTOM, P, {-100.0 / 36:.17g}"] + OUTPUT + ["*END STEP"]
    return out


def joint_bolt():
    m = joint_mesh(True, False)
    out = ["*HEADING", " The joint's bolt alone, its section held: k_b (tests/verification/test_pretension.cpp)"]
    write_mesh(out, m, {"SHANK": "STEEL", "HEAD_NUT": "RIGID"})
    joint_common(out, m, True, False)
    out += ["*NODE, NSET=PT", "9001, 0., 0., 10.", "*PRE-TENSION SECTION, SURFACE=CUT, NODE=PT",
            "*BOUNDARY", "X0, 1, 1", "Y0, 2, 2", "HEAD_RING, 3, 3", "PT, 1, 1"]
    out += ["*STEP, NAME=PULL", "*STATIC", "1., 1.", "*BOUNDARY", f"NUT_RING, 3, 3, {-DELTA:g}"] + OUTPUT[:5] + ["*END STEP"]
    return out


def joint_plates():
    m = joint_mesh(False, True)
    out = ["*HEADING", " The joint's plates alone, pressed by their clamping faces: k_c "
           "(tests/verification/test_pretension.cpp)"]
    write_mesh(out, m, {"PLATE_A": "STEEL", "PLATE_B": "STEEL"})
    joint_common(out, m, False, True)
    # The clamping faces held in x and y too: in the joint they are tied to a rigid head and nut.
    out += ["*NODE, NSET=PT", "9001, 0., 0., 10.", "*BOUNDARY", "X0, 1, 1", "Y0, 2, 2", "A_RING, 1, 3", "B_RING, 1, 2"]
    out += ["*STEP, NAME=PRESS", "*STATIC", "1., 1."] + CONTROLS + ["*BOUNDARY", f"B_RING, 3, 3, {-DELTA:g}"] + \
        OUTPUT[2:] + ["*END STEP"]
    return out


def truss(beam=False):
    """The column with its truss bolt (gen_verification's deck writer and brick grid); beam: the bolt a B31
    (CIRC of area 1) whose lower end's rotations are held (its upper end is a hinge on the column's node)."""
    from gen_verification import Deck, grid_hex, select
    coords, conn = grid_hex(2, 2, 8, (0, 0, 0), (1, 1, 4), False)[:2]
    eps = 1e-9
    centre = lambda z: next(n for n, x in coords.items() if abs(x[0] - 0.5) < eps and abs(x[1] - 0.5) < eps
                            and abs(x[2] - z) < eps)
    p_node = max(coords) + 1
    kind = "B31" if beam else "T3D2"
    d = Deck(f"A column clamped by a {kind} bolt along its axis, pretensioned through ELEMENT=",
             ["Reference: step 1, the bolt force (S11 A, a beam's SF1) = 1000 (the CLOAD on the pre-tension node), RF1 there",
              "reports it, and the base reactions sum to zero (the bolt and column balance each other);",
              "step 2, the node FIXED and the top face pulled up by 400: the bolt force RF1 = S11 A again, and",
              "the base carries the 400."])
    coords[p_node] = (0.5, 0.5, 5.0)
    d.nodes(coords, 3)
    d.elements("C3D8", "COLUMN", conn)
    d.elements(kind, "BOLT", [[centre(0.0), centre(4.0)]], first=len(conn) + 1)
    d.nset("BASE", select(coords, lambda x: abs(x[2]) < eps))
    top = select(coords, lambda x: abs(x[2] - 4) < eps)
    d.nset("TOP", top)
    d.nset("P", [p_node])
    section = (["*BEAM SECTION, ELSET=BOLT, MATERIAL=STEEL, SECTION=CIRC", f"{(1 / math.pi) ** 0.5:.17g}", "1., 0., 0."]
               if beam else ["*SOLID SECTION, ELSET=BOLT, MATERIAL=STEEL", "1."])
    d.add("*SOLID SECTION, ELSET=COLUMN, MATERIAL=STEEL", *section, "*MATERIAL, NAME=STEEL", "*ELASTIC", "210000., 0.3")
    d.add("*PRE-TENSION SECTION, ELEMENT=BOLT, NODE=P")
    d.add("*BOUNDARY", "BASE, 3, 3", f"{select(coords, lambda x: x[2] == 0 and x[0] == 0 and x[1] == 0)[0]}, 1, 2",
          f"{select(coords, lambda x: x[2] == 0 and x[0] == 1 and x[1] == 0)[0]}, 2, 2")
    if beam:
        d.add(f"{centre(0.0)}, 4, 6")
    output = "SF" if beam else "S"
    d.add("*STEP", "*STATIC", "*CLOAD", "P, 1, 1000.")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT, ELSET=BOLT", output, "*END STEP")
    d.add("*STEP", "*STATIC", "*BOUNDARY, FIXED", "P, 1, 1", "*CLOAD", f"TOP, 3, {400.0 / len(top):.17g}")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT, ELSET=BOLT", output, "*END STEP")
    return d.lines


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    args = ap.parse_args()
    for name, lines in [("pretension_bar.inp", bar()), ("pretension_joint.inp", joint()),
                        ("pretension_joint_bolt.inp", joint_bolt()), ("pretension_joint_plates.inp", joint_plates()),
                        ("pretension_truss.inp", truss()), ("pretension_beam.inp", truss(beam=True))]:
        with open(os.path.join(args.out, name), "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
