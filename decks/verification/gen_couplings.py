#!/usr/bin/env python3
"""Generator of the *COUPLING verification decks (decks/verification/coupling_*.inp).

    gen_couplings.py --out DIR [--ccx]

Each deck states its reference in its header; tests/verification/test_couplings.cpp checks
them. Uses gen_verification.py's deck writer and structured meshes. --ccx writes the two
column decks in CalculiX's dialect (reference node by number, DOF lines spelled out, no
ENCASTRE, the top face printed), whose results the tests hold as references.
"""
import argparse
import os

from gen_verification import Deck, grid_hex, grid_quad, select

EPS = 1e-9
MATERIAL = ["*MATERIAL, NAME=STEEL", "*ELASTIC", "210000., 0.3"]


def column(title, comments, nz=8, height=4.0):
    """A 1 x 1 x height C3D8 column (2 x 2 x nz), built in at z = 0, with its top face as the
    element surface TOPS and a reference node REF 0.5 above the face's centre."""
    coords, conn = grid_hex(2, 2, nz, (0, 0, 0), (1, 1, height), False)[:2]
    ref = max(coords) + 1
    coords[ref] = (0.5, 0.5, height + 0.5)
    d = Deck(title, comments)
    d.nodes(coords, 3)
    d.elements("C3D8", "COLUMN", conn)
    d.nset("BASE", select(coords, lambda x: abs(x[2]) < EPS))
    d.nset("TOP", select(coords, lambda x: abs(x[2] - height) < EPS))
    d.nset("REF", [ref])
    d.elset("TOPEL", range(len(conn) - 3, len(conn) + 1))
    d.add("*SURFACE, NAME=TOPS, TYPE=ELEMENT", "TOPEL, S2")
    d.add("*SOLID SECTION, ELSET=COLUMN, MATERIAL=STEEL", *MATERIAL)
    return d


def kinematic_column():
    """The rigid column of gen_rigid_bodies.py, its top face held by a kinematic coupling."""
    d = column("A column whose top face is kinematically coupled to a reference node loaded by F1 = 10 and M2 = 100",
               ["Reference: the same column with *RIGID BODY, TIE NSET=TOP (rigid_moment_block_c3d8.inp):",
                "every displacement equal; the base carries the whole load."])
    d.add("*COUPLING, CONSTRAINT NAME=TOPC, REF NODE=REF, SURFACE=TOPS", "*KINEMATIC")
    d.add("*BOUNDARY", "BASE, ENCASTRE")
    d.add("*STEP", "*STATIC", "*CLOAD", "REF, 1, 10.", "REF, 5, 100.")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


def kinematic_push():
    """Only DOF 3 coupled: the top face pushed down evenly, free to spread sideways."""
    d = column("A column pushed down through a kinematic coupling of DOF 3 only",
               ["Reference: every top node has u3 = -0.001 (the reference node's, no rotation by symmetry),",
                "u1 and u2 free (the Poisson spread); RF3 at the reference node = -sum RF3 at the base."])
    d.add("*COUPLING, CONSTRAINT NAME=PUSH, REF NODE=REF, SURFACE=TOPS", "*KINEMATIC", "3, 3")
    d.add("*BOUNDARY", "BASE, ENCASTRE", "REF, 4, 5")
    d.add("*STEP", "*STATIC", "*BOUNDARY", "REF, 3, 3, -0.001")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


def kinematic_twist():
    """Only the tangential DOF (2) of a cylindrical ORIENTATION about the column's axis coupled:
    the top face is twisted by the reference node's UR3 and free to move radially and axially."""
    d = column("A column whose top face is twisted by 0.01 about its axis through a kinematic coupling of the "
               "tangential DOF of a cylindrical orientation",
               ["Reference: each top node's tangential displacement e_t . u = e_t . (u_R + UR x r) (r from the",
                "reference node), radial and axial free; CalculiX 2.20 on the same deck in its dialect."])
    d.add("*ORIENTATION, NAME=AXIS, SYSTEM=CYLINDRICAL", "0.5, 0.5, 0., 0.5, 0.5, 1.")
    d.add("*COUPLING, CONSTRAINT NAME=TWIST, REF NODE=REF, SURFACE=TOPS, ORIENTATION=AXIS", "*KINEMATIC", "2")
    # The tangential rows alone leave a tilt of the reference node with the matching sideways
    # move free (the face's axial motion is not coupled): held, as Abaqus wants it.
    d.add("*BOUNDARY", "BASE, ENCASTRE", "REF, 1, 5")
    d.add("*STEP", "*STATIC", "*BOUNDARY", "REF, 6, 6, 0.01")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


def kinematic_hinge():
    """CalculiX's hinge.inp in our own mesh: a free C3D20R bar swung by 1.57 rad about an axis
    beside it, its side face kinematically coupled (DOFs 1-3) to the reference node, in one
    NLGEOM step whose first try the solver must cut back."""
    nx, ny, nz = 2, 2, 8
    coords, conn = grid_hex(nx, ny, nz, (0, 0, 0), (1, 1, 8), True)[:2]
    ref = max(coords) + 1
    coords[ref] = (10.0, 0.0, 0.0)
    d = Deck("A free bar swung by 1.57 rad about the z axis through (10, 0) by a kinematic coupling of its face x = 1",
             ["Reference: a rigid rotation, u = (R - I)(X - X_R) at every node, no stress; CalculiX's",
              "hinge.inp (the same set-up, its own mesh) prints u = (8.992435, -9.999599, 0) at (0.5, 0.5, 8)."])
    d.nodes(coords, 3)
    d.elements("C3D20R", "BAR", conn)
    d.nset("REF", [ref])
    d.nset("TIP", select(coords, lambda x: abs(x[0] - 0.5) < EPS and abs(x[1] - 0.5) < EPS and abs(x[2] - 8) < EPS))
    d.elset("SIDE", [1 + (nx - 1) + nx * (j + ny * k) for k in range(nz) for j in range(ny)])
    d.add("*SURFACE, NAME=FACE, TYPE=ELEMENT", "SIDE, S4")
    d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL", *MATERIAL)
    d.add("*COUPLING, CONSTRAINT NAME=HINGE, REF NODE=REF, SURFACE=FACE", "*KINEMATIC", "1, 3")
    d.add("*STEP, NLGEOM", "*STATIC", "*BOUNDARY", "REF, 1, 5", "REF, 6, 6, 1.57")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S", "*END STEP")
    return d


def distributing_column():
    d = column("A column loaded through a distributing coupling of its top face: F1 = 10, M2 = 100, M3 = 20",
               ["Reference: the base carries the whole load (sum RF and sum r x RF exact); the reference node",
                "moves with the face's weighted mean: u_R = sum w u + UR x d, UR = J^-1 sum w r x u."])
    d.add("*COUPLING, CONSTRAINT NAME=TOPD, REF NODE=REF, SURFACE=TOPS", "*DISTRIBUTING")
    d.add("*BOUNDARY", "BASE, ENCASTRE")
    d.add("*STEP", "*STATIC", "*CLOAD", "REF, 1, 10.", "REF, 5, 100.", "REF, 6, 20.")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


def distributing_held():
    """A 1 x 1 x 2 column of two C3D8 whose top face is held: the reactions there are the
    coupling's distribution of the reference node's load, by hand."""
    d = column("The distribution of F1 = 10, M3 = 5 by a distributing coupling over a held square face",
               ["Reference (by hand): the face's 3 x 3 nodes weigh 1/16 (corners), 1/8 (edges), 1/4 (centre);",
                "centroid (0.5, 0.5, 2), d = x_R - centroid = (0, 0, 0.5), J = diag(1/8, 1/8, 1/4),",
                "omega = J^-1 (M + d x F) = (0, 40, 20); node i at r = (rx, ry, 0) from the centroid gets",
                "f = w (10 - 20 ry, 20 rx, -40 rx), and RF = -f as the face is held."],
               nz=2, height=2.0)
    d.add("*COUPLING, CONSTRAINT NAME=HELD, REF NODE=REF, SURFACE=TOPS", "*DISTRIBUTING")
    d.add("*BOUNDARY", "BASE, ENCASTRE", "TOP, ENCASTRE")
    d.add("*STEP", "*STATIC", "*CLOAD", "REF, 1, 10.", "REF, 6, 5.")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


def distributing_coupling_held():
    """CalculiX's node-based *DISTRIBUTING COUPLING (a DCOUP3D element holds the reference
    node) over a held square face: each node carries its weight's share of the force."""
    coords, conn = grid_hex(2, 2, 2, (0, 0, 0), (1, 1, 2), False)[:2]
    ref = max(coords) + 1
    coords[ref] = (0.5, 0.5, 2.5)
    d = Deck("F = (10, 5, 0) spread by a *DISTRIBUTING COUPLING over a held square face by the weights given",
             ["Reference (by hand): the 3 x 3 face nodes weigh 1 (corners), 2 (edges), 4 (centre), 16 in all;",
              "node i carries w_i / 16 of F and no moment (CalculiX's meaning: the reference node moves with",
              "the weighted mean, its offset 0.5 above the face adds nothing), so RF = -(w_i / 16) F."])
    d.nodes(coords, 3)
    d.elements("C3D8", "COLUMN", conn)
    d.nset("BASE", select(coords, lambda x: abs(x[2]) < EPS))
    top = select(coords, lambda x: abs(x[2] - 2) < EPS)
    d.nset("TOP", top)
    d.nset("REF", [ref])
    d.add("*ELEMENT, TYPE=DCOUP3D, ELSET=DC", f"{len(conn) + 1}, {ref}")
    weight = {n: (2 if abs(coords[n][0] - 0.5) < EPS else 1) * (2 if abs(coords[n][1] - 0.5) < EPS else 1) for n in top}
    d.add("*DISTRIBUTING COUPLING, ELSET=DC", *[f"{n}, {weight[n]}." for n in sorted(top)])
    d.add("*SOLID SECTION, ELSET=COLUMN, MATERIAL=STEEL", *MATERIAL)
    d.add("*BOUNDARY", "BASE, ENCASTRE", "TOP, ENCASTRE")
    d.add("*STEP", "*STATIC", "*CLOAD", "REF, 1, 10.", "REF, 2, 5.")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


def distributing_pull():
    """The reference node of a distributing coupling prescribed: a lift and a tilt."""
    d = column("A column whose top face is lifted by 0.001 and tilted by 0.0005 about x through a distributing coupling",
               ["Reference: the face's weighted mean u3 is 0.001 and its least-squares rotation about x is",
                "0.0005 (the coupled DOFs of the reference node); RF at the reference node = -sum RF at the base."])
    d.add("*COUPLING, CONSTRAINT NAME=LIFT, REF NODE=REF, SURFACE=TOPS", "*DISTRIBUTING, WEIGHTING METHOD=UNIFORM")
    d.add("*BOUNDARY", "BASE, ENCASTRE")
    d.add("*STEP", "*STATIC", "*BOUNDARY", "REF, 3, 3, 0.001", "REF, 4, 4, 0.0005")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


def distributing_plate():
    """Plane strain: a 4 x 1 cantilever plate with a moment (DOF 6) on its end edge."""
    coords, conn = grid_quad(8, 2, lambda s, t: (4 * s, t), False)[:2]
    ref = max(coords) + 1
    coords[ref] = (4.5, 0.5)
    d = Deck("A plane-strain cantilever plate loaded through a distributing coupling of its end edge: F2 = 3, M6 = 7",
             ["Reference: the built-in edge carries the whole load: sum RF = -F, sum r x RF = -(M + r_R x F)."])
    d.nodes(coords, 2)
    d.elements("CPE4", "PLATE", conn)
    d.nset("ROOT", select(coords, lambda x: abs(x[0]) < EPS))
    d.nset("REF", [ref])
    end = [n for n in select(coords, lambda x: abs(x[0] - 4) < EPS)]
    d.nset("END", end)
    d.add("*SURFACE, NAME=ENDS, TYPE=NODE", "END")
    d.add("*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL", *MATERIAL)
    d.add("*COUPLING, CONSTRAINT NAME=ENDD, REF NODE=REF, SURFACE=ENDS", "*DISTRIBUTING", "1, 6")
    d.add("*BOUNDARY", "ROOT, ENCASTRE")
    d.add("*STEP", "*STATIC", "*CLOAD", "REF, 2, 3.", "REF, 6, 7.")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


DECKS = {
    "coupling_kinematic_column_c3d8.inp": kinematic_column,
    "coupling_kinematic_push_c3d8.inp": kinematic_push,
    "coupling_kinematic_twist_c3d8.inp": kinematic_twist,
    "coupling_kinematic_hinge_c3d20r.inp": kinematic_hinge,
    "coupling_distributing_column_c3d8.inp": distributing_column,
    "coupling_distributing_held_c3d8.inp": distributing_held,
    "distributing_coupling_held_c3d8.inp": distributing_coupling_held,
    "coupling_distributing_pull_c3d8.inp": distributing_pull,
    "coupling_distributing_plate_cpe4.inp": distributing_plate,
}


def calculix_dialect(deck):
    """The same deck as CalculiX 2.20 reads it: it wants the reference node's number, couples
    nothing without DOF lines, and has no ENCASTRE."""
    ref = None
    for i, line in enumerate(deck.lines):
        if line == "*NSET, NSET=REF":
            ref = deck.lines[i + 1].strip()
    out = []
    for i, line in enumerate(deck.lines):
        line = line.replace("REF NODE=REF", f"REF NODE={ref}").replace(", ENCASTRE", ", 1, 3")
        if line.startswith("REF, "):
            line = ref + line[3:]
        if line == "*END STEP":
            out += ["*NODE PRINT, NSET=TOP", "U"]
        out.append(line)
        given = i + 1 < len(deck.lines) and not deck.lines[i + 1].startswith("*")
        if line == "*KINEMATIC" and not given:
            out.append("1, 3")
        if line == "*DISTRIBUTING" and not given:
            out.append("1, 6")
    deck.lines = out
    return deck


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--ccx", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.ccx:
        for name in ("coupling_kinematic_column_c3d8.inp", "coupling_distributing_column_c3d8.inp",
                     "coupling_kinematic_twist_c3d8.inp"):
            calculix_dialect(DECKS[name]()).write(os.path.join(args.out, name.replace(".inp", "_ccx.inp")))
        return
    for name, make in DECKS.items():
        make().write(os.path.join(args.out, name))


if __name__ == "__main__":
    main()
