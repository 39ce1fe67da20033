#!/usr/bin/env python3
"""Generator of the *TIE verification decks (decks/verification/tie_*.inp):

    gen_tie.py --out DIR

  tie_patch_c3d8.inp          two non-matching C3D8 blocks tied at x = 1 (3x3 slave faces on
                              2x2 master faces, the slave's interface nodes moved in its plane,
                              its interior nodes distorted), uniform tension by a prescribed u1:
                              every point's S = (1, 0, 0, 0, 0, 0) exactly (E eps, eps = 1e-3).
  tie_patch_adjust_c3d8.inp   the same with the slave block's interface 0.004 short of the
                              master's (the default tolerance is 0.0354): ADJUST=YES moves the
                              slave nodes onto the master, and the answer is the one above.
  tie_patch_chain_c3d8.inp    three blocks in a T: B tied to A at x = 1, C on top tied to the top
                              faces of A and B, whose nodes at x = 1 are B's tied nodes (a chain
                              the DOF map resolves): still S = (1, 0, ...) everywhere.
  tie_cantilever_c3d8i.inp    a cantilever (L = 10, h = b = 1, E = 1000, nu = 0, tip shear 1) made
                              of two meshes tied at x = 5 (10x4x2 slave, 8x3x1 master);
  tie_cantilever_s2s_c3d8i.inp     the same with the default tie (SURFACE TO SURFACE, default
                              tolerance) instead of NODE TO SURFACE;
  tie_cantilever_single_c3d8i.inp  the same cantilever as one 20x4x2 mesh.
                              Beam theory: v = PL^3/3EI + PL/(kGA) = 4 + 0.024 (k = 5/6).

Pure standard-library Python, like gen_verification.py (whose Deck class it uses).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_verification import Deck, OUTPUT  # noqa: E402

EPS = 1e-9


def box(x0, x1, n, first_node, first_elem, move=None):
    """A structured C3D8 box [x0[0], x1[0]] x ... with n = (nx, ny, nz) elements; node labels
    from first_node, element labels from first_elem. move(i, j, k, x) may shift a node."""
    nx, ny, nz = n
    coords, lab = {}, {}
    label = first_node
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                x = [x0[d] + (x1[d] - x0[d]) * (i, j, k)[d] / n[d] for d in range(3)]
                if move:
                    x = move(i, j, k, x)
                coords[label] = x
                lab[i, j, k] = label
                label += 1
    conn, where = [], {}
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                c = [lab[i, j, k], lab[i + 1, j, k], lab[i + 1, j + 1, k], lab[i, j + 1, k],
                     lab[i, j, k + 1], lab[i + 1, j, k + 1], lab[i + 1, j + 1, k + 1], lab[i, j + 1, k + 1]]
                where[first_elem + len(conn)] = (i, j, k)
                conn.append(c)
    return coords, conn, where


def face_elements(where, pred):
    return sorted(e for e, ijk in where.items() if pred(*ijk))


def add_block(d, name, coords, conn, first_elem, etype="C3D8"):
    d.nodes(coords, 3, nset=name + "_N")
    d.elements(etype, name, conn, first_elem)


def surface(d, name, elset, labels, face):
    d.elset(elset, labels)
    d.add(f"*SURFACE, NAME={name}, TYPE=ELEMENT", f"{elset}, {face}")


def patch_block_a(offset=0.0):
    """Block A, x in [0, 1], 3x3x3, the slave: interface nodes moved in the y-z plane (and by
    -offset in x), interior nodes distorted (the uniform field is in the space of any such mesh)."""
    def move(i, j, k, x):
        inner_y, inner_z = 0 < j < 3, 0 < k < 3
        if i == 3:
            x = [x[0] - offset, x[1], x[2]]
        if i == 3 and inner_y and inner_z:
            return [x[0], x[1] + 0.06 * (j - 1.5), x[2] - 0.05 * (k - 1.5)]
        if 0 < i < 3 and inner_y and inner_z:
            return [x[0] + 0.04 * (j - k), x[1] + 0.03 * (i - 1.5), x[2] + 0.05 * (j - 1.5)]
        return x
    return box([0, 0, 0], [1, 1, 1], (3, 3, 3), 1, 1, move)


def patch(offset=0.0, adjust_comment=None):
    ca, ea, wa = patch_block_a(offset)
    cb, eb, wb = box([1, 0, 0], [2, 1, 1], (2, 2, 2), 1001, 1001)
    title = "Tie patch test: two non-matching C3D8 blocks tied at x = 1, uniform tension"
    notes = ["A: x = 0..1, 3x3x3 (slave, nodes 1-64), B: x = 1..2, 2x2x2 (master, nodes 1001-1027).",
             "u1 = 0 at x = 0, u1 = 0.002 at x = 2, rollers on y = 0 and z = 0; E = 1000, nu = 0.3:",
             "exact S11 = 1, every other component 0, at every point of both blocks (tolerance 1e-8)."]
    if adjust_comment:
        notes += adjust_comment
    d = Deck(title, notes)
    add_block(d, "A", ca, ea, 1)
    add_block(d, "B", cb, eb, 1001)
    surface(d, "A_RIGHT", "A_RIGHT_E", face_elements(wa, lambda i, j, k: i == 2), "S4")
    surface(d, "B_LEFT", "B_LEFT_E", face_elements(wb, lambda i, j, k: i == 0), "S6")
    coords = {**ca, **cb}
    d.nset("LEFT", [n for n, x in coords.items() if abs(x[0]) < EPS])
    d.nset("RIGHT", [n for n, x in coords.items() if abs(x[0] - 2) < EPS])
    d.nset("Y0", [n for n, x in coords.items() if abs(x[1]) < EPS])
    d.nset("Z0", [n for n, x in coords.items() if abs(x[2]) < EPS])
    d.add("*SOLID SECTION, ELSET=A, MATERIAL=M", "*SOLID SECTION, ELSET=B, MATERIAL=M",
          "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3")
    d.add("*TIE, NAME=GLUE", "A_RIGHT, B_LEFT")
    d.add("*BOUNDARY", "LEFT, 1, 1", "Y0, 2, 2", "Z0, 3, 3")
    d.add("*STEP, NAME=PULL", "*STATIC", "*BOUNDARY", "RIGHT, 1, 1, 0.002", *OUTPUT, "*END STEP")
    return d


def chain():
    ca, ea, wa = box([0, 0, 0], [1, 1, 1], (2, 2, 2), 1, 1)
    cb, eb, wb = box([1, 0, 0], [2, 1, 1], (3, 3, 3), 101, 101)
    cc, ec, wc = box([0, 1, 0], [2, 2, 1], (5, 2, 2), 201, 201)
    d = Deck("Tie patch test with a chain: B tied to A, C tied to A and B (B's tied nodes among its masters)",
             ["A: x = 0..1, y = 0..1 (2x2x2); B: x = 1..2, y = 0..1 (3x3x3), its x = 1 face tied onto A's;",
              "C: x = 0..2, y = 1..2 (5x2x2), its y = 1 face tied onto the y = 1 faces of A and B.",
              "u1 = 0 at x = 0, u1 = 0.002 at x = 2, rollers on y = 0 and z = 0; E = 1000, nu = 0.3:",
              "exact S11 = 1, the rest 0 (tolerance 1e-8)."])
    add_block(d, "A", ca, ea, 1)
    add_block(d, "B", cb, eb, 101)
    add_block(d, "C", cc, ec, 201)
    surface(d, "A_RIGHT", "A_RIGHT_E", face_elements(wa, lambda i, j, k: i == 1), "S4")
    surface(d, "B_LEFT", "B_LEFT_E", face_elements(wb, lambda i, j, k: i == 0), "S6")
    d.elset("AB_TOP_E", face_elements(wa, lambda i, j, k: j == 1) + face_elements(wb, lambda i, j, k: j == 2))
    d.add("*SURFACE, NAME=AB_TOP, TYPE=ELEMENT", "AB_TOP_E, S5")
    surface(d, "C_BOTTOM", "C_BOTTOM_E", face_elements(wc, lambda i, j, k: j == 0), "S3")
    coords = {**ca, **cb, **cc}
    d.nset("LEFT", [n for n, x in coords.items() if abs(x[0]) < EPS])
    d.nset("RIGHT", [n for n, x in coords.items() if abs(x[0] - 2) < EPS])
    d.nset("Y0", [n for n, x in coords.items() if abs(x[1]) < EPS])
    d.nset("Z0", [n for n, x in coords.items() if abs(x[2]) < EPS])
    d.add(*[f"*SOLID SECTION, ELSET={b}, MATERIAL=M" for b in "ABC"], "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3")
    d.add("*TIE, NAME=AB", "B_LEFT, A_RIGHT", "*TIE, NAME=TOP", "C_BOTTOM, AB_TOP")
    d.add("*BOUNDARY", "LEFT, 1, 1", "Y0, 2, 2", "Z0, 3, 3")
    d.add("*STEP, NAME=PULL", "*STATIC", "*BOUNDARY", "RIGHT, 1, 1, 0.002", *OUTPUT, "*END STEP")
    return d


def tip_loads(coords, x_tip, h, b, ny, nz):
    """Consistent nodal forces of a uniform shear traction (total -1 in y) on the tip face."""
    loads = []
    for n, x in coords.items():
        if abs(x[0] - x_tip) > EPS:
            continue
        j, k = round(x[1] / h * ny), round(x[2] / b * nz)
        wy = (0.5 if j in (0, ny) else 1.0) / ny
        wz = (0.5 if k in (0, nz) else 1.0) / nz
        loads.append((n, -wy * wz))
    return sorted(loads)


CANT_HEADER = ["L = 10, h = b = 1 (y, z), E = 1000, nu = 0; x = 0 face held (all u = 0); tip shear 1 in -y",
               "as consistent nodal forces on the x = 10 face. Beam theory: v = PL^3/3EI + PL/(kGA) = 4.024."]


def cantilever_tied(tie_line="*TIE, NAME=SPAN, TYPE=NODE TO SURFACE, POSITION TOLERANCE=0.01"):
    cl, el, wl = box([0, 0, 0], [5, 1, 1], (10, 4, 2), 1, 1)
    cr, er, wr = box([5, 0, 0], [10, 1, 1], (8, 3, 1), 1001, 1001)
    d = Deck("Cantilever of two non-matching C3D8I meshes tied at x = 5",
             CANT_HEADER + ["x = 0..5: 10x4x2 (slave), x = 5..10: 8x3x1 (master); reference: the single 20x4x2",
                            "mesh (tie_cantilever_single_c3d8i.inp), tip deflection within 0.5 %."])
    add_block(d, "L", cl, el, 1, "C3D8I")
    add_block(d, "R", cr, er, 1001, "C3D8I")
    surface(d, "L_END", "L_END_E", face_elements(wl, lambda i, j, k: i == 9), "S4")
    surface(d, "R_START", "R_START_E", face_elements(wr, lambda i, j, k: i == 0), "S6")
    coords = {**cl, **cr}
    d.nset("ROOT", [n for n, x in coords.items() if abs(x[0]) < EPS])
    d.nset("TIP", [n for n, x in coords.items() if abs(x[0] - 10) < EPS])
    d.add("*SOLID SECTION, ELSET=L, MATERIAL=M", "*SOLID SECTION, ELSET=R, MATERIAL=M",
          "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.")
    d.add(tie_line, "L_END, R_START")
    d.add("*BOUNDARY", "ROOT, 1, 3")
    d.add("*STEP, NAME=BEND", "*STATIC", "*CLOAD",
          *[f"{n}, 2, {f:.15g}" for n, f in tip_loads(cr, 10.0, 1.0, 1.0, 3, 1)], *OUTPUT, "*END STEP")
    return d


def cantilever_single():
    c, e, w = box([0, 0, 0], [10, 1, 1], (20, 4, 2), 1, 1)
    d = Deck("Cantilever as one C3D8I mesh, 20x4x2 (the reference of tie_cantilever_c3d8i.inp)", CANT_HEADER)
    add_block(d, "BEAM", c, e, 1, "C3D8I")
    d.nset("ROOT", [n for n, x in c.items() if abs(x[0]) < EPS])
    d.nset("TIP", [n for n, x in c.items() if abs(x[0] - 10) < EPS])
    d.add("*SOLID SECTION, ELSET=BEAM, MATERIAL=M", "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.")
    d.add("*BOUNDARY", "ROOT, 1, 3")
    d.add("*STEP, NAME=BEND", "*STATIC", "*CLOAD",
          *[f"{n}, 2, {f:.15g}" for n, f in tip_loads(c, 10.0, 1.0, 1.0, 4, 2)], *OUTPUT, "*END STEP")
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    decks = {
        "tie_patch_c3d8.inp": patch(),
        "tie_patch_adjust_c3d8.inp": patch(0.004, ["Here A's x = 1 nodes sit at x = 0.996: ADJUST=YES (the default) moves them",
                                                    "onto B (0.004 < the default tolerance 0.0354): the answer is the one above."]),
        "tie_patch_chain_c3d8.inp": chain(),
        "tie_cantilever_c3d8i.inp": cantilever_tied(),
        "tie_cantilever_s2s_c3d8i.inp": cantilever_tied("*TIE, NAME=SPAN"),
        "tie_cantilever_single_c3d8i.inp": cantilever_single(),
    }
    for name, d in decks.items():
        d.write(os.path.join(a.out, name))


if __name__ == "__main__":
    main()
