#!/usr/bin/env python3
"""Generator of the *RIGID BODY verification decks (decks/verification/rigid_*.inp).

    gen_rigid_bodies.py --out DIR

Each deck states its reference in its header; tests/verification/test_rigid_bodies.cpp checks
them. Uses gen_verification.py's deck writer and structured meshes.
"""
import argparse
import math
import os

from gen_verification import Deck, grid_hex, grid_quad, select

EPS = 1e-9
MATERIAL = ["*MATERIAL, NAME=STEEL", "*ELASTIC", "210000., 0.3"]


def moment_block():
    """A 1 x 1 x 4 column built in at z = 0 whose top face is tied to a reference node above it,
    loaded there by a force and a moment (*CLOAD DOFs 1 and 5)."""
    coords, conn = grid_hex(2, 2, 8, (0, 0, 0), (1, 1, 4), False)[:2]
    ref = max(coords) + 1
    coords[ref] = (0.5, 0.5, 4.5)
    d = Deck("A column with a rigid top face, loaded through the reference node by F1 = 10 and M2 = 100",
             ["Reference: the base carries the whole load, sum RF = (-10, 0, 0) and sum (x - x_ref) x RF",
              "= -(0, 100, 0) - (x_b - x_ref) x F; the top face moves rigidly (u = u_R + UR x r)."])
    d.nodes(coords, 3)
    d.elements("C3D8", "COLUMN", conn)
    d.nset("BASE", select(coords, lambda x: abs(x[2]) < EPS))
    d.nset("TOP", select(coords, lambda x: abs(x[2] - 4) < EPS))
    d.nset("REF", [ref])
    d.add("*SOLID SECTION, ELSET=COLUMN, MATERIAL=STEEL", *MATERIAL)
    d.add("*RIGID BODY, REF NODE=REF, TIE NSET=TOP")
    d.add("*BOUNDARY", "BASE, ENCASTRE")
    d.add("*STEP", "*STATIC", "*CLOAD", "REF, 1, 10.", "REF, 5, 100.")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*NODE PRINT, NSET=REF", "U, UR", "*END STEP")
    return d


def spin_block(increments=4):
    """A block made rigid as a whole (ELSET) turned by 90 degrees about z through its reference
    node, NLGEOM: no support but the reference node's."""
    coords, conn = grid_hex(2, 2, 2, (1, 0, 0), (2, 1, 1), False)[:2]
    ref = max(coords) + 1
    coords[ref] = (0.0, 0.0, 0.0)
    d = Deck("A rigid block turned by 90 degrees about z through its reference node at the origin, NLGEOM",
             ["Reference: every node at R X (u = (R - I) X, R the rotation by UR3 = pi/2 * t about z),",
              "no reaction at the reference node: the rigid elements carry no force."])
    d.nodes(coords, 3)
    d.elements("C3D8", "BLOCK", conn)
    d.nset("REF", [ref])
    d.add("*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL", *MATERIAL)
    d.add("*RIGID BODY, REF NODE=REF, ELSET=BLOCK")
    d.add("*STEP, NLGEOM", "*STATIC, DIRECT", f"{1 / increments:.17g}, 1.")
    d.add("*BOUNDARY", "REF, 1, 5", f"REF, 6, 6, {math.pi / 2:.17g}")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


def spin_plate(increments=4):
    """The plane-strain counterpart: CPE4 elements made rigid, turned by DOF 6 (the 2D rotation)."""
    coords, conn = grid_quad(2, 2, lambda s, t: (1 + s, t), False)[:2]
    ref = max(coords) + 1
    coords[ref] = (0.0, 0.0)
    d = Deck("A rigid plane-strain plate turned by 90 degrees about the origin through DOF 6, NLGEOM",
             ["Reference: every node at R X, no reaction at the reference node."])
    d.nodes(coords, 2)
    d.elements("CPE4", "PLATE", conn)
    d.nset("REF", [ref])
    d.add("*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL", *MATERIAL)
    d.add("*RIGID BODY, REF NODE=REF, ELSET=PLATE")
    d.add("*STEP, NLGEOM", "*STATIC, DIRECT", f"{1 / increments:.17g}, 1.")
    d.add("*BOUNDARY", "REF, 1, 2", f"REF, 6, 6, {math.pi / 2:.17g}")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*END STEP")
    return d


def punch(ccx=False):
    """A flat rigid punch (C3D8 elements made rigid) pressed 0.01 into a block through its
    reference node; frictionless surface-to-surface contact, the punch the master."""
    coords, conn = grid_hex(8, 8, 4, (0, 0, 0), (4, 4, 2), False)[:2]
    base = max(coords)
    pc, pconn = grid_hex(4, 4, 1, (1, 1, 2), (3, 3, 2.5), False)[:2]
    coords.update({base + k: x for k, x in pc.items()})
    ref = max(coords) + 1
    coords[ref] = (2.0, 2.0, 3.0)
    first_punch = len(conn) + 1
    d = Deck("A rigid flat punch 2 x 2 pressed 0.01 into a 4 x 4 x 2 block through its reference node",
             ["Reference: the reaction at the reference node balances the contact force,",
              "RF3 = sum CPRESS * CNAREA (1e-9); CalculiX 2.20 on the same deck in its dialect",
              "(*RIGID BODY with ROT NODE, gen_rigid_bodies.py --ccx): RF3 = -1.017847E+04."])
    d.nodes(coords, 3)
    d.elements("C3D8", "BLOCK", conn)
    d.elements("C3D8", "PUNCH", [[n + base for n in c] for c in pconn], first=first_punch)
    d.nset("BASE", select(coords, lambda x: abs(x[2]) < EPS))
    d.nset("REF", [ref])
    d.elset("BLOCK_TOP_EL", [e + 1 for e, c in enumerate(conn) if all(abs(coords[n][2] - 2) < EPS for n in c[4:8])])
    d.elset("PUNCH_BOTTOM_EL", range(first_punch, first_punch + len(pconn)))
    d.add("*SURFACE, NAME=BLOCK_TOP", "BLOCK_TOP_EL, S2", "*SURFACE, NAME=PUNCH_BOTTOM", "PUNCH_BOTTOM_EL, S1")
    d.add("*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL", "*SOLID SECTION, ELSET=PUNCH, MATERIAL=STEEL", *MATERIAL)
    if ccx:
        rot = ref + 1
        d.lines[d.lines.index(f"{ref}, 2, 2, 3")] += f"\n{rot}, 2, 2, 3"
        d.add(f"*RIGID BODY, ELSET=PUNCH, REF NODE={ref}, ROT NODE={rot}")
    else:
        d.add("*RIGID BODY, REF NODE=REF, ELSET=PUNCH")
    # A linear law stiff enough to penetrate by 1e-4 of the indentation, the same in both
    # dialects (CalculiX's hard surface-to-surface contact is a penalty of its own stiffness).
    d.add("*SURFACE INTERACTION, NAME=FRICTIONLESS", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", "1e11")
    d.add("*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=SURFACE TO SURFACE", "BLOCK_TOP, PUNCH_BOTTOM")
    d.add("*BOUNDARY", "BASE, 1, 3")
    d.add("*STEP", "*STATIC", "*BOUNDARY", "REF, 1, 2", "REF, 3, 3, -0.01")
    d.add(f"{rot}, 1, 3" if ccx else "REF, 4, 6")
    if ccx:
        d.add(f"*NODE PRINT, NSET=REF, TOTALS=NO", "RF", "*NODE FILE", "U", "*END STEP")
    else:
        d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*CONTACT OUTPUT", "CPRESS, CNAREA, CSTATUS",
              "*NODE PRINT, NSET=REF", "RF", "*END STEP")
    return d


def punch_r3d4():
    """The same punch as a sheet of R3D4 rigid elements (its bottom face alone), the surface
    their SNEG side: the node order turns counter-clockwise seen from above, so SPOS faces up."""
    coords, conn = grid_hex(8, 8, 4, (0, 0, 0), (4, 4, 2), False)[:2]
    base = max(coords)
    pc, pconn = grid_hex(4, 4, 1, (1, 1, 2), (3, 3, 2.5), False)[:2]
    pc = {k: x for k, x in pc.items() if abs(x[2] - 2) < EPS}  # the bottom layer of nodes
    coords.update({base + k: x for k, x in pc.items()})
    ref = max(coords) + 1
    coords[ref] = (2.0, 2.0, 3.0)
    first_punch = len(conn) + 1
    d = Deck("The rigid flat punch of rigid_punch_c3d8.inp as R3D4 elements, pressed 0.01 into the block",
             ["Reference: the punch made of C3D8 elements (rigid_punch_c3d8.inp): its bottom face is",
              "this sheet, so RF3 and the contact pressures are the same; RF3 = sum CPRESS * CNAREA."])
    d.nodes(coords, 3)
    d.elements("C3D8", "BLOCK", conn)
    d.elements("R3D4", "PUNCH", [[n + base for n in c[:4]] for c in pconn], first=first_punch)
    d.nset("BASE", select(coords, lambda x: abs(x[2]) < EPS))
    d.nset("REF", [ref])
    d.elset("BLOCK_TOP_EL", [e + 1 for e, c in enumerate(conn) if all(abs(coords[n][2] - 2) < EPS for n in c[4:8])])
    d.add("*SURFACE, NAME=BLOCK_TOP", "BLOCK_TOP_EL, S2", "*SURFACE, NAME=PUNCH_BOTTOM", "PUNCH, SNEG")
    d.add("*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL", *MATERIAL)
    d.add("*RIGID BODY, REF NODE=REF, ELSET=PUNCH")
    d.add("*SURFACE INTERACTION, NAME=FRICTIONLESS", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", "1e11")
    d.add("*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=SURFACE TO SURFACE", "BLOCK_TOP, PUNCH_BOTTOM")
    d.add("*BOUNDARY", "BASE, 1, 3")
    d.add("*STEP", "*STATIC", "*BOUNDARY", "REF, 1, 2", "REF, 3, 3, -0.01", "REF, 4, 6")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*CONTACT OUTPUT", "CPRESS, CNAREA, CSTATUS",
          "*NODE PRINT, NSET=REF", "RF", "*END STEP")
    return d


def punch_2d(block_type, sheet, analytical=False, fillet=0.0, mu=0.0, wide=False):
    """A flat rigid punch 2 wide pressed 0.01 into a 4 x 2 plane-strain or axisymmetric block:
    made of rigid quads (sheet=False) or of R2D2 / RAX2 line elements along its bottom edge,
    their SNEG side down (node order +x, so the positive normal, turned counter-clockwise, is up),
    or (analytical) an analytical surface, *SURFACE, TYPE=SEGMENTS: its bottom edge as one LINE
    from x = 2 to x = 0 (travelled in −x, so that its normal, turned counter-clockwise, is down);
    with a `fillet`, its side x = 2 comes down to the corner first, and FILLET RADIUS rounds it.
    With friction `mu`, a second step slides the pressed punch along x: by 0.02, or (`wide`: the
    punch reaching 2 beyond the block on either side, x from −2 to 6) by 0.05, every node slipping."""
    coords, conn = grid_quad(8, 4, lambda s, t: (4 * s, 2 * t), False)
    base = max(coords)
    pc, pconn = grid_quad(8 if wide else 4, 1, lambda s, t: (-2 + 8 * s if wide else 2 * s, 2 + 0.5 * t), False)
    if sheet:
        pc = {k: x for k, x in pc.items() if abs(x[1] - 2) < EPS}
        pconn = [c[:2] for c in pconn]
    if analytical:
        pc, pconn = {}, []
    coords.update({base + k: x for k, x in pc.items()})
    ref = max(coords) + 1
    coords[ref] = (1.0, 3.0, 0.0)
    axi = block_type.startswith("CAX")
    line_type = "RAX2" if axi else "R2D2"
    first_punch = len(conn) + 1
    what = ("an analytical surface" if analytical else f"{line_type} elements" if sheet
            else f"{block_type} elements made rigid")
    reference = ["Reference: the punch of rigid quads and the one of rigid line elements along its bottom edge",
                 "give the same RF2; RF2 = sum CPRESS * CNAREA (the contact force, 2 pi r per unit length in CAX)."]
    if mu and not wide:
        reference = ["Reference: no slave node slips farther than the punch slides (0.02); the nodes beyond its",
                     "free ends carry no friction (their closest point, the end, is seen sideways)."]
    elif mu:
        reference = [f"Reference: the pressed punch slides (mu = {mu:g}) with every node of the block's top slipping",
                     "under it: RF1 = -mu RF2 (CSHEAR1 = mu CPRESS at every node)."]
    elif analytical:
        reference = ["Reference: RF2 = -sum RF2 of the base (the punch's force crosses the block)" if fillet else
                     "Reference: RF2 = sum CPRESS * CNAREA (the contact force, 2 pi r per unit length in CAX);",
                     f"the edge rounded by r = {fillet:g} carries less than the sharp punch" if fillet else
                     "the same RF2 as the punch of R2D2 / RAX2 elements along the same line"]
    d = Deck(f"A rigid flat punch ({what}) pressed 0.01 into a {block_type} block through its reference node", reference)
    d.nodes(coords, 2)
    d.elements(block_type, "BLOCK", conn)
    if not analytical:
        d.elements(line_type if sheet else block_type, "PUNCH", [[n + base for n in c] for c in pconn], first=first_punch)
    d.nset("BASE", select(coords, lambda x: abs(x[1]) < EPS))
    d.nset("REF", [ref])
    d.elset("BLOCK_TOP_EL", [e + 1 for e, c in enumerate(conn) if all(abs(coords[n][1] - 2) < EPS for n in c[2:4])])
    d.add("*SURFACE, NAME=BLOCK_TOP", "BLOCK_TOP_EL, S3")
    if analytical:
        if fillet:
            d.add(f"*SURFACE, TYPE=SEGMENTS, NAME=PUNCH_BOTTOM, FILLET RADIUS={fillet:g}", "START, 2, 2.5",
                  "LINE, 2, 2", "LINE, 0, 2")
        else:
            d.add("*SURFACE, TYPE=SEGMENTS, NAME=PUNCH_BOTTOM", "START, 6, 2" if wide else "START, 2, 2",
                  "LINE, -2, 2" if wide else "LINE, 0, 2")
    else:
        d.add("*SURFACE, NAME=PUNCH_BOTTOM", "PUNCH, SNEG" if sheet else "PUNCH, S1")
    d.add("*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL")
    if not sheet and not analytical:
        d.add("*SOLID SECTION, ELSET=PUNCH, MATERIAL=STEEL")
    d.add(*MATERIAL)
    d.add("*RIGID BODY, REF NODE=REF, ANALYTICAL SURFACE=PUNCH_BOTTOM" if analytical else
          "*RIGID BODY, REF NODE=REF, ELSET=PUNCH")
    if mu:
        d.add("*SURFACE INTERACTION, NAME=ROUGH", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", "1e11",
              "*FRICTION", f"{mu:g}")
        d.add("*CONTACT PAIR, INTERACTION=ROUGH, TYPE=SURFACE TO SURFACE", "BLOCK_TOP, PUNCH_BOTTOM")
    else:
        d.add("*SURFACE INTERACTION, NAME=FRICTIONLESS", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", "1e11")
        d.add("*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=SURFACE TO SURFACE", "BLOCK_TOP, PUNCH_BOTTOM")
    d.add("*BOUNDARY", "BASE, 1, 2", "REF, 1, 1", "REF, 6, 6")
    if axi:
        d.add("*NSET, NSET=AXIS", ", ".join(str(n) for n in select({k: x for k, x in coords.items() if k <= base}, lambda x: abs(x[0]) < EPS)),
              "*BOUNDARY", "AXIS, 1, 1")
    d.add("*STEP", "*STATIC", "*BOUNDARY", "REF, 2, 2, -0.01")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*CONTACT OUTPUT", "CPRESS, CNAREA",
          "*END STEP")
    if mu:
        d.add("*STEP", "*STATIC", "0.1, 1.", "*BOUNDARY", f"REF, 1, 1, {0.05 if wide else 0.02:g}",
              "*OUTPUT, FIELD", "*CONTACT OUTPUT", "CPRESS, CNAREA, CSHEAR1, CSLIP1, CSTATUS", "*END STEP")
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    ap.add_argument("--ccx", action="store_true", help="also write the punch in CalculiX's dialect")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    decks = {"rigid_moment_block_c3d8.inp": moment_block(), "rigid_spin_block_c3d8.inp": spin_block(),
             "rigid_spin_plate_cpe4.inp": spin_plate(), "rigid_punch_c3d8.inp": punch(),
             "rigid_punch_r3d4.inp": punch_r3d4(),
             "rigid_punch_cpe4.inp": punch_2d("CPE4", False), "rigid_punch_r2d2.inp": punch_2d("CPE4", True),
             "rigid_punch_cax4.inp": punch_2d("CAX4", False), "rigid_punch_rax2.inp": punch_2d("CAX4", True),
             "rigid_punch_segments_cpe4.inp": punch_2d("CPE4", True, analytical=True),
             "rigid_punch_segments_cax4.inp": punch_2d("CAX4", True, analytical=True),
             "rigid_punch_fillet_cpe4.inp": punch_2d("CPE4", True, analytical=True, fillet=0.25),
             "rigid_punch_slide_r2d2.inp": punch_2d("CPE4", True, mu=0.2, wide=True),
             "rigid_punch_slide_segments_cpe4.inp": punch_2d("CPE4", True, analytical=True, mu=0.2, wide=True),
             "rigid_punch_slide_narrow_r2d2.inp": punch_2d("CPE4", True, mu=0.2)}
    if a.ccx:
        decks["rigid_punch_c3d8_ccx.inp"] = punch(ccx=True)
    for name, d in decks.items():
        d.write(os.path.join(a.out, name))


if __name__ == "__main__":
    main()
