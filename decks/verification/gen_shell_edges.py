#!/usr/bin/env python3
"""Generator of the shell-edge verification decks (decks/verification/):

    gen_shell_edges.py --out DIR

  pretension_shell_s8.inp    a strip 1 x 2, 0.1 thick, of four S8 along y, both ends held in y, cut at
                             y = 1 by a pre-tension section on element 3's edge E1. Step 1: F = 100 on
                             the pre-tension node: S22 = F/(b t) = 1000, u_P1 = F L/(E b t); step 2: the
                             tightening prescribed to 0.01 (CalculiX's pret7): S22 = E 0.01/L = 1050.
  pretension_shell_s4.inp    the same with 2 x 4 S4, the section on two elements' edges, spelled S3
                             (CalculiX's name of edge E1).
  edge_load_ednor_s4.inp     the strip (2 x 4 S4) held at y = 0, pulled at y = 2 by *DLOAD EDNOR3 = -50:
                             S22 = q/t, U2 = q L/(E t), U1(x = 1) = -nu q b/(E t).
  edge_load_ednor_s8r.inp    the same with four S8R and *DSLOAD EDNOR on an edge-based surface (E3).
  tie_shell_edge_c3d8.inp    a plate 2 x 1, 0.1 thick (4 x 2 S4, nu = 0), its edge x = 0 tied (*TIE, slave E4)
                             to the face x = 0 of a C3D8 block (1000 times as stiff) held at x = -1, pulled at
                             x = 2 by EDNOR = -50: S11 = q/t, S22 = S12 = 0 as on a rigid support, the block's
                             reactions sum to -q b.
  edge_load_edt_edshr_s4.inp a plate 1 x 2 (4 x 16 S4) built in at y = 0: step 1 EDT3 = 0.05 on the free
                             edge (reactions (0, 0, q b), deflection between the narrow beam's and the
                             wide plate's), step 2 EDSHR3 = 0.05 (reactions (q b, 0, 0)).

Pure standard-library Python.
"""
import argparse
import os

def strip_s8(n_along=4, width=1.0, length=2.0):
    nodes, elems = {}, []
    rows = 2 * n_along + 1
    lab = lambda r, c: r * 3 + c + 1
    for r in range(rows):
        for c in range(3):
            if r % 2 == 1 and c == 1: continue
            nodes[lab(r, c)] = (0.5 * width * c, length * r / (rows - 1), 0.0)
    for k in range(n_along):
        r0, r2 = 2 * k, 2 * k + 2
        elems.append((k + 1, [lab(r0, 0), lab(r0, 2), lab(r2, 2), lab(r2, 0), lab(r0, 1), lab(r0 + 1, 2), lab(r2, 1), lab(r0 + 1, 0)]))
    bottom = [lab(0, c) for c in range(3)]
    top = [lab(rows - 1, c) for c in range(3)]
    return nodes, elems, bottom, top

def strip_s4(n_across=2, n_along=4, width=1.0, length=2.0):
    nodes, elems = {}, []
    lab = lambda r, c: r * (n_across + 1) + c + 1
    for r in range(n_along + 1):
        for c in range(n_across + 1):
            nodes[lab(r, c)] = (width * c / n_across, length * r / n_along, 0.0)
    e = 1
    for r in range(n_along):
        for c in range(n_across):
            elems.append((e, [lab(r, c), lab(r, c + 1), lab(r + 1, c + 1), lab(r + 1, c)])); e += 1
    bottom = [lab(0, c) for c in range(n_across + 1)]
    top = [lab(n_along, c) for c in range(n_across + 1)]
    return nodes, elems, bottom, top

def fmt_nodes(nodes):
    return "\n".join(f"{k}, {x:g}, {y:g}, {z:g}" for k, (x, y, z) in sorted(nodes.items()))

def fmt_elems(elems):
    return "\n".join(f"{k}, " + ", ".join(map(str, c)) for k, c in elems)
E, NU, T = 210000.0, 0.3, 0.1


def shell_model(nodes, elems, etype, elset, top_elems, bottom, top):
    """The mesh, a steel shell section of thickness T, the elements at the edge y = max
    (TOP_ELEMS) and the node sets BOTTOM and TOP of a strip or plate."""
    return f"""*NODE, NSET=ALL
{fmt_nodes(nodes)}
*ELEMENT, TYPE={etype}, ELSET={elset}
{fmt_elems(elems)}
*ELSET, ELSET=TOP_ELEMS
{", ".join(map(str, top_elems))}
*MATERIAL, NAME=STEEL
*ELASTIC
{E:g}, {NU:g}
*SHELL SECTION, ELSET={elset}, MATERIAL=STEEL
{T:g}
*NSET, NSET=BOTTOM
{", ".join(map(str, bottom))}
*NSET, NSET=TOP
{", ".join(map(str, top))}"""


def pretension(kind):
    if kind == "s8":
        nodes, elems, bottom, top = strip_s8()
        etype, surf, ident, hdr = "S8", "3", "E1", "four S8 along y"
    else:
        nodes, elems, bottom, top = strip_s4()
        etype, surf, ident, hdr = "S4", "CUT", "S3", "2 x 4 S4 (the section spelled S3, CalculiX's name of edge E1)"
    out = [f"""*HEADING
 A shell strip 1 wide, 2 long, 0.1 thick ({hdr}), both ends held in y, cut at y = 1 along
 a shell edge by a pre-tension section
** Reference: step 1, bolt load F = 100 on the pre-tension node: S22 = F/(b t) = 1000 at every
** section point, S11 = S12 = 0, the tightening U1(PT) = F L/(E b t) = 9.5238095e-3, RF1(PT) = 100;
** step 2, the tightening prescribed to 0.01 (CalculiX's pret7): S22 = E 0.01 / L = 1050 and
** RF1(PT) = 105.
*NODE, NSET=ALL
{fmt_nodes(nodes)}
*NODE, NSET=PT
100, 0, 0, 0
*ELEMENT, TYPE={etype}, ELSET=STRIP
{fmt_elems(elems)}
*MATERIAL, NAME=STEEL
*ELASTIC
{E:g}, {NU:g}
*SHELL SECTION, ELSET=STRIP, MATERIAL=STEEL
{T:g}
*NSET, NSET=BOTTOM
{", ".join(map(str, bottom))}
*NSET, NSET=TOP
{", ".join(map(str, top))}"""]
    if kind == "s8":
        out.append(f"*SURFACE, NAME=CUT\n{surf}, {ident}")
    else:
        out.append(f"*ELSET, ELSET=CUT\n5, 6\n*SURFACE, NAME=CUT_EDGES\nCUT, {ident}")
        surf = "CUT_EDGES"
    out.append(f"""*PRE-TENSION SECTION, SURFACE={"CUT" if kind == "s8" else surf}, NODE=PT
*BOUNDARY
BOTTOM, 2
TOP, 2
1, 1
ALL, 3, 6
*STEP
*STATIC
*CLOAD
PT, 1, 100.
*NODE PRINT, NSET=PT
U, RF
*EL PRINT, ELSET=STRIP
S
*END STEP
*STEP
*STATIC
*CLOAD, OP=NEW
*BOUNDARY
PT, 1, 1, 0.01
*NODE PRINT, NSET=PT
U, RF
*EL PRINT, ELSET=STRIP
S
*END STEP""")
    return "\n".join(out) + "\n"

def edge_loads(kind):
    if kind == "s8r":
        nodes, elems, bottom, top = strip_s8()
        etype = "S8R"
    else:
        nodes, elems, bottom, top = strip_s4()
        etype = "S4"
    top_elems = [k for k, c in elems if set(c[2:4]) <= set(top)]
    q = 50.0
    load = (f"*DLOAD\nTOP_ELEMS, EDNOR3, {-q:g}" if kind == "s4" else f"*DSLOAD\nTOP_EDGE, EDNOR, {-q:g}")
    surface = "" if kind == "s4" else "\n*SURFACE, NAME=TOP_EDGE\nTOP_ELEMS, E3"
    return f"""*HEADING
 A shell strip 1 wide, 2 long, 0.1 thick ({etype}), its end y = 0 held in y, pulled at y = 2 by an
 edge traction of {q:g} per unit length (EDNOR = -{q:g}: a positive EDNOR pushes into the shell)
** Reference: S22 = q/t = {q / T:g} at every point, U2(y = 2) = q L/(E t) = {q * 2 / (E * T):.8g},
** U1(x = 1) = -nu q b/(E t) = {-NU * q * 1 / (E * T):.8g}; the reactions sum to -q b = -{q:g}.
{shell_model(nodes, elems, etype, "STRIP", top_elems, bottom, top)}{surface}
*BOUNDARY
BOTTOM, 2
1, 1
ALL, 3, 6
*STEP
*STATIC
{load}
*NODE PRINT, NSET=TOP
U
*NODE PRINT, NSET=BOTTOM, TOTALS=YES
RF
*EL PRINT, ELSET=STRIP
S
*END STEP
"""

def edge_cantilever():
    nodes, elems, bottom, top = strip_s4(n_across=4, n_along=16)
    top_elems = [k for k, c in elems if set(c[2:4]) <= set(top)]
    q = 0.05
    return f"""*HEADING
 A shell plate 1 wide, 2 long, 0.1 thick (4 x 16 S4), built in at y = 0, loaded on its edge y = 2
 by a transverse edge traction (step 1, EDT3) and then an in-plane shear along the edge (step 2, EDSHR3)
** Reference: step 1, EDT = {q:g} acts against the shell normal (+z): the reactions sum to (0, 0, q b),
** and the free edge deflects between the narrow beam's P L^3/(3 E I) + P L/(k G A) and the wide plate's
** (1 - nu^2) P L^3/(3 E I), P = q b; step 2, EDSHR = {q:g} runs along the edge in the node order of
** E3 (from x = 1 to x = 0): the reactions sum to (q b, 0, 0).
{shell_model(nodes, elems, "S4", "PLATE", top_elems, bottom, top)}
*BOUNDARY
BOTTOM, ENCASTRE
*STEP
*STATIC
*DLOAD
TOP_ELEMS, EDT3, {q:g}
*NODE PRINT, NSET=TOP
U
*NODE PRINT, NSET=BOTTOM, TOTALS=YES
RF
*END STEP
*STEP
*STATIC
*DLOAD, OP=NEW
TOP_ELEMS, EDSHR3, {q:g}
*NODE PRINT, NSET=TOP
U
*NODE PRINT, NSET=BOTTOM, TOTALS=YES
RF
*END STEP
"""


def tie_shell_edge():
    q = 50.0
    nx, ny = 4, 2
    lab = lambda i, j: j * (nx + 1) + i + 1
    nodes = {lab(i, j): (2.0 * i / nx, 1.0 * j / ny, 0.0) for i in range(nx + 1) for j in range(ny + 1)}
    elems = [(j * nx + i + 1, [lab(i, j), lab(i + 1, j), lab(i + 1, j + 1), lab(i, j + 1)])
             for j in range(ny) for i in range(nx)]
    edge_elems = [k for k, c in elems if nodes[c[0]][0] == 0.0]
    end_elems = [k for k, c in elems if nodes[c[1]][0] == 2.0]
    blab = lambda i, j, k: 1001 + i + 3 * j + 9 * k
    block = {blab(i, j, k): (-1.0 + 0.5 * i, -0.5 + j, -0.5 + 0.5 * k) for i in range(3) for j in range(3) for k in range(3)}
    bel = []
    for k in range(2):
        for j in range(2):
            for i in range(2):
                c = [blab(i, j, k), blab(i + 1, j, k), blab(i + 1, j + 1, k), blab(i, j + 1, k)]
                bel.append((101 + i + 2 * j + 4 * k, c + [n + 9 for n in c]))
    face_elems = [k for k, c in bel if block[c[1]][0] == 0.0]
    held = [n for n, x in block.items() if x[0] == -1.0]
    return f"""*HEADING
 A shell plate 2 x 1, 0.1 thick (4 x 2 S4, nu = 0), its edge x = 0 tied to the face x = 0 of a C3D8 block
 (1000 times as stiff, held at x = -1) by a *TIE whose slave is the shell edge E4, pulled at x = 2 by
 EDNOR = -{q:g}
** Reference: S11 = q/t = {q / T:g}, S22 = S12 = 0 at every section point, as on a rigid support (nu = 0:
** nothing holds back a lateral contraction; the block's own compliance bends the tied edge by about
** 1e-3); the block's reactions sum to (-q b, 0, 0) = (-{q:g}, 0, 0) exactly. The plate's U3 and
** rotations are held: a tied shell edge is a hinge (its rotations are not tied).
*NODE, NSET=PLATE_NODES
{fmt_nodes(nodes)}
*NODE, NSET=BLOCK_NODES
{fmt_nodes(block)}
*ELEMENT, TYPE=S4, ELSET=PLATE
{fmt_elems(elems)}
*ELEMENT, TYPE=C3D8, ELSET=BLOCK
{fmt_elems(bel)}
*ELSET, ELSET=EDGE_ELEMS
{", ".join(map(str, edge_elems))}
*ELSET, ELSET=END_ELEMS
{", ".join(map(str, end_elems))}
*ELSET, ELSET=FACE_ELEMS
{", ".join(map(str, face_elems))}
*NSET, NSET=HELD
{", ".join(map(str, held))}
*MATERIAL, NAME=SHEET
*ELASTIC
{E:g}, 0.
*MATERIAL, NAME=STIFF
*ELASTIC
{1000 * E:g}, {NU:g}
*SHELL SECTION, ELSET=PLATE, MATERIAL=SHEET
{T:g}
*SOLID SECTION, ELSET=BLOCK, MATERIAL=STIFF
*SURFACE, NAME=SHELL_EDGE
EDGE_ELEMS, E4
*SURFACE, NAME=BLOCK_FACE
FACE_ELEMS, S4
*TIE, NAME=JOINT
SHELL_EDGE, BLOCK_FACE
*BOUNDARY
HELD, ENCASTRE
PLATE_NODES, 3, 6
*STEP
*STATIC
*DLOAD
END_ELEMS, EDNOR2, {-q:g}
*NODE PRINT, NSET=HELD, TOTALS=YES
RF
*EL PRINT, ELSET=PLATE
S
*END STEP
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".")
    out = parser.parse_args().out
    decks = {"pretension_shell_s8.inp": pretension("s8"), "pretension_shell_s4.inp": pretension("s4"),
             "edge_load_ednor_s4.inp": edge_loads("s4"), "edge_load_ednor_s8r.inp": edge_loads("s8r"),
             "edge_load_edt_edshr_s4.inp": edge_cantilever(), "tie_shell_edge_c3d8.inp": tie_shell_edge()}
    for name, text in decks.items():
        with open(os.path.join(out, name), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
