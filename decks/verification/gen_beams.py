#!/usr/bin/env python3
"""Writes the beam decks of tests/verification/test_beams.cpp: the cantilevers (beam_cantilever_*.inp),
the roll-up (beam_rollup_*.inp), the 45-degree bend (beam_bend45_b31_8.inp) and a moment on a turned
end (beam_turned_moment_b32_20.inp) under NLGEOM.

A cantilever along x, L = 10, built in at x = 0 (ENCASTRE), RECT 0.3 (along n1 = y) x 0.2 (along
n2 = z), E = 2e5, nu = 0.3; at the tip P2 = 1 along y, P3 = 2 along z and a torque T = 5 about x,
each in its own step so that each answer stands alone; then gravity alone (GRAV 9810 along y,
rho = 7.8e-9: q = rho g A per length). Run: python3 gen_beams.py (in this folder).
"""
import math

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


def rollup(etype, n):
    """The cantilever above, bent by an end moment M = 2 pi EI22 / L about z under NLGEOM: it rolls
    up into a full circle of radius L / (2 pi). U3, UR1 and UR2 are held at every node (a planar
    problem: a total rotation vector of 2 pi about z is singular for tilts about x and y)."""
    moment = 2 * math.pi * 2.0e5 * (0.3 ** 3 * 0.2 / 12) / 10.0
    lines = [f"*HEADING\nRoll-up of a cantilever of {n} {etype} beams, L = 10, RECT 0.3 x 0.2, n1 = y: an end moment "
             f"2 pi EI/L about z\n** bends it into a full circle of radius L/(2 pi) (tests/verification/test_beams.cpp).",
             "*NODE, NSET=ALL"]
    per = 2 if etype == "B32" else 1  # node steps per element
    lines += [f"{i + 1}, {10.0 * i / (n * per):.15g}, 0., 0." for i in range(n * per + 1)]
    lines.append(f"*ELEMENT, TYPE={etype}, ELSET=BEAM")
    lines += [", ".join(str(k) for k in [e + 1] + list(range(per * e + 1, per * e + per + 2))) for e in range(n)]
    lines += [f"*NSET, NSET=TIP\n{n * per + 1}", "*NSET, NSET=ROOT\n1", "*MATERIAL, NAME=STEEL", "*ELASTIC", "200000., 0.3",
              "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT", "0.3, 0.2", "0., 1., 0.",
              "*BOUNDARY", "ROOT, ENCASTRE", "ALL, 3, 5", "*STEP, NLGEOM, INC=100", "*STATIC", "0.1, 1.",
              "*CLOAD", f"TIP, 6, {moment:.15g}", "*NODE PRINT, NSET=TIP", "U, UR", "*NODE PRINT, NSET=ROOT", "RF, RM",
              "*OUTPUT, FIELD", "*NODE OUTPUT", "U, UR, RF, RM", "*ELEMENT OUTPUT", "SF, SM", "*END STEP"]
    return "\n".join(lines) + "\n"


def bend45(n):
    """Bathe and Bolourchi's 45-degree bend (1979): an arc of radius 100 in the x-y plane, square
    1 x 1 section, E = 1e7, nu = 0, built in at one end, a force of 600 along z at the other.
    Simo and Vu-Quoc (1986, 8 elements) give the tip at (47.23, 15.79, 53.37)."""
    lines = [f"*HEADING\n45-degree bend of {n} B31 beams, R = 100, 1 x 1, E = 1e7: tip force 600 along z under NLGEOM\n"
             "** Simo and Vu-Quoc (1986): tip at (47.23, 15.79, 53.37) (tests/verification/test_beams.cpp).",
             "*NODE, NSET=ALL"]
    for i in range(n + 1):
        phi = math.pi / 4 * i / n
        lines.append(f"{i + 1}, {100 * math.sin(phi):.15g}, {100 * (1 - math.cos(phi)):.15g}, 0.")
    lines.append("*ELEMENT, TYPE=B31, ELSET=BEAM")
    lines += [f"{e + 1}, {e + 1}, {e + 2}" for e in range(n)]
    lines += [f"*NSET, NSET=TIP\n{n + 1}", "*NSET, NSET=ROOT\n1", "*MATERIAL, NAME=M", "*ELASTIC", "1e7, 0.",
              "*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=RECT", "1., 1.", "0., 0., 1.",
              "*BOUNDARY", "ROOT, ENCASTRE", "*STEP, NLGEOM, INC=100", "*STATIC", "0.1, 1.", "*CLOAD", "TIP, 3, 600.",
              "*NODE PRINT, NSET=TIP", "U", "*NODE PRINT, NSET=ROOT", "RF, RM", "*END STEP"]
    return "\n".join(lines) + "\n"


def turned_moment(n):
    """A cantilever of n B32 along x, L = 10, CIRC r = 0.1, E = 1e7, nu = 0 (EI = GJ). Step 1, NLGEOM:
    its root turned by pi/2 about z (rotation prescribed, the free beam follows rigidly: now along y);
    step 2: an end moment M = EI/L about the global x-axis, which keeps its direction: the beam,
    along y, bends in the y-z plane into an arc of angle 1 rad, radius EI/M = L. The tip ends at
    L (0, sin 1, 1 - cos 1) from the root, its rotation R = R_x(1) R_z(pi/2), and the root's
    reaction moment is (-M, 0, 0). The end node has turned about z before the moment about x acts,
    so the moment is not its own conjugate to the node's rotation vector."""
    ei = 1e7 * math.pi * 0.1 ** 4 / 4
    lines = [f"*HEADING\nA cantilever of {n} B32 turned by pi/2 about z, then bent by an end moment EI/L about the global x-axis"
             "\n** (NLGEOM): the arc of 1 rad and radius L in the y-z plane (tests/verification/test_beams.cpp).",
             "*NODE, NSET=ALL"]
    lines += [f"{i + 1}, {10.0 * i / (2 * n):.15g}, 0., 0." for i in range(2 * n + 1)]
    lines.append("*ELEMENT, TYPE=B32, ELSET=BEAM")
    lines += [f"{e + 1}, {2 * e + 1}, {2 * e + 2}, {2 * e + 3}" for e in range(n)]
    lines += [f"*NSET, NSET=TIP\n{2 * n + 1}", "*NSET, NSET=ROOT\n1", "*MATERIAL, NAME=M", "*ELASTIC", "1e7, 0.",
              "*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=CIRC", "0.1", "0., 1., 0.",
              "*BOUNDARY", "ROOT, 1, 5", "*STEP, NLGEOM, INC=100", "*STATIC", "0.25, 1.", "*BOUNDARY",
              f"ROOT, 6, 6, {math.pi / 2:.15g}", "*END STEP", "*STEP, NLGEOM, INC=100", "*STATIC", "0.1, 1.",
              "*CLOAD", f"TIP, 4, {ei / 10:.15g}", "*NODE PRINT, NSET=TIP", "U, UR", "*NODE PRINT, NSET=ROOT", "RF, RM",
              "*END STEP"]
    return "\n".join(lines) + "\n"


for etype, n in (("B31", 10), ("B31", 40), ("B32", 5), ("B33", 2)):
    with open(f"beam_cantilever_{etype.lower()}_{n}.inp", "w") as f:
        f.write(deck(etype, n))
for etype, n in (("B31", 50), ("B33", 50), ("B32", 50)):
    with open(f"beam_rollup_{etype.lower()}_{n}.inp", "w") as f:
        f.write(rollup(etype, n))
with open("beam_bend45_b31_8.inp", "w") as f:
    f.write(bend45(8))
with open("beam_turned_moment_b32_20.inp", "w") as f:
    f.write(turned_moment(20))
