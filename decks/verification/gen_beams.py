#!/usr/bin/env python3
"""Writes the beam cantilever decks (beam_cantilever_*.inp) of tests/verification/test_beams.cpp.

A cantilever along x, L = 10, built in at x = 0 (ENCASTRE), RECT 0.3 (along n1 = y) x 0.2 (along
n2 = z), E = 2e5, nu = 0.3; at the tip P2 = 1 along y, P3 = 2 along z and a torque T = 5 about x,
each in its own step so that each answer stands alone; then gravity alone (GRAV 9810 along y,
rho = 7.8e-9: q = rho g A per length). Run: python3 gen_beams.py (in this folder).
"""

HEAD = """*HEADING
Cantilever of {n} {etype} beams, L = 10, RECT 0.3 x 0.2, n1 = y: tip loads along y and z, a torque, gravity, one step each.
** Closed forms in tests/verification/test_beams.cpp (Timoshenko beam with Abaqus's slenderness-compensated
** transverse shear stiffness, Euler-Bernoulli for B33; the torsion constant of the rectangle from St. Venant's series).
"""


def deck(etype, n):
    nodes_per = 3 if etype == "B32" else 2
    n_nodes = n * (nodes_per - 1) + 1
    lines = [HEAD.format(n=n, etype=etype), "*NODE, NSET=ALL"]
    for i in range(n_nodes):
        lines.append(f"{i + 1}, {10.0 * i / (n_nodes - 1):.15g}, 0., 0.")
    lines.append(f"*ELEMENT, TYPE={etype}, ELSET=BEAM")
    for e in range(n):
        first = e * (nodes_per - 1) + 1
        lines.append(", ".join(str(k) for k in [e + 1] + list(range(first, first + nodes_per))))
    lines += [f"*NSET, NSET=TIP\n{n_nodes}", "*NSET, NSET=ROOT\n1",
              "*MATERIAL, NAME=STEEL", "*ELASTIC", "200000., 0.3", "*DENSITY", "7.8e-9",
              "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT", "0.3, 0.2", "0., 1., 0.",
              "*BOUNDARY", "ROOT, ENCASTRE"]
    for name, dof, value in (("Y", 2, 1.0), ("Z", 3, 2.0), ("TORQUE", 4, 5.0)):
        lines += [f"*STEP, NAME={name}", "*STATIC", "*CLOAD, OP=NEW", f"TIP, {dof}, {value}",
                  "*NODE PRINT, NSET=TIP", "U, UR", "*NODE PRINT, NSET=ROOT", "RF, RM",
                  "*EL PRINT, ELSET=BEAM", "SF, SM", "*OUTPUT, FIELD", "*NODE OUTPUT", "U, UR, RF, RM", "*ELEMENT OUTPUT",
                  "SF, SM", "*END STEP"]
    lines += ["*STEP, NAME=GRAVITY", "*STATIC", "*CLOAD, OP=NEW", "*DLOAD", "BEAM, GRAV, 9810., 0., 1., 0.",
              "*NODE PRINT, NSET=TIP", "U, UR", "*END STEP"]
    return "\n".join(lines) + "\n"


for etype, n in (("B31", 10), ("B31", 40), ("B32", 5), ("B33", 2)):
    with open(f"beam_cantilever_{etype.lower()}_{n}.inp", "w") as f:
        f.write(deck(etype, n))
