#!/usr/bin/env python3
"""Writes the shell verification decks of tests/verification/test_shells.cpp: the standard
shell benchmarks of MacNeal and Harder (1985) and a cantilever strip against closed forms.

  scordelis_lo   Scordelis-Lo roof, quarter model: R = 25, L = 50, 40 deg, t = 0.25, E = 4.32e8,
                 nu = 0, gravity 90 per area (rho = 360, g = 1); rigid diaphragms at the ends.
                 Vertical displacement at the middle of the free edge: 0.3024.
  pinched        Pinched cylinder with diaphragms, octant: R = 300, L = 600, t = 3, E = 3e6,
                 nu = 0.3, two opposite loads P = 1 at mid-length (1/4 in the octant).
                 Displacement under the load: 1.8248e-5.
  hemisphere     Pinched hemisphere with an 18 deg hole, quarter: R = 10, t = 0.04, E = 6.825e7,
                 nu = 0.3, loads of 2 in and out at the equator (1 in the quarter, each point lies
                 on a symmetry plane). Radial displacement under the loads: 0.094.
  twisted        Twisted beam: L = 12, width 1.1, 90 deg of twist, E = 29e6, nu = 0.22; t = 0.32
                 with P = 1 (in-plane 5.424e-3, out-of-plane 1.754e-3) or t = 0.0032 with
                 P = 1e-6 (5.256e-3, 1.294e-3). Step 1 in-plane (z at the tip), step 2 out of plane (y).
  strip          Cantilever strip L = 10, b = 1, t = 0.1, E = 2e5, nu = 0: a tip line load P = 1
                 along z, as the elements' consistent nodal loads.
  torsion        The same strip twisted by T = 1 about x (nodal moments on the tip), its width
                 graded towards the free edges.
  plastic        The strip (L = 10, b = 1, t = 0.1, E = 2e5, nu = 0) of an elastic-perfectly plastic
                 metal (yield 200) bent by a prescribed tip rotation: 0.3 (curvature 1.5 times the
                 first yield's), then 1.0 (5 times).
  pressure       the cantilever strip (S8R: nodally exact) under a uniform pressure 1: *DLOAD P
                 lifts it along the shell normal (+z), *DSLOAD on the SPOS surface pushes it down.
  tapered        the strip with *NODAL THICKNESS 0.1 (1 + x/L) under the tip line load 1: the
                 nodes' thicknesses interpolated to the points (Euler-Bernoulli 11.5888 plus
                 shear 8.3e-4).
  plastic_nlgeom the plastic strip under NLGEOM (the tip turned by 0.3, then 1 rad).
  plastic_plate  a clamped square plate 1 x 1, t = 0.01, of a hardening metal under a pressure 5,
                 NLGEOM: about 13 thicknesses of deflection, yielded through its thickness.
  laminate       the strip (L = 10, b = 1) of a lamina E1 = 1.4e5, E2 = 1e4, nu12 = 0, G12 = 5e3,
                 G13 = 5e3, G23 = 3e3 under the tip line load 1, *SHELL SECTION, COMPOSITE; the variant
                 picks the layup: cross [0/90/90/0] by angles, orient the same by *ORIENTATION
                 names, normal1 the same by orientations whose axis 1 is the normal (second line
                 "1, 0.": Abaqus projects axis 2), unsym [0/90] (t = 0.05 each), turned one layer at 30 deg, composed the
                 same as a section ORIENTATION at 20 deg and a layer at 10 deg; all 0.1 thick.
  rollup         Sze, Liu and Lo's (2004) strip under an end moment, NLGEOM: L = 12, b = 1,
                 t = 0.1, E = 1.2e6, nu = 0, M = 50 pi / 3 = 2 pi EI / L about -y rolls it into a
                 full circle (U2, UR1, UR3 held: a planar problem).

Usage: gen_shells.py --out DIR NAME ETYPE N [VARIANT]   (writes DIR/NAME_ETYPE_N[_VARIANT].inp;
VARIANT is thin for twisted, the layup for laminate)
ETYPE is S4, S4R, S8R, S3 (each quad of the S4 grid cut into two triangles) or S6 (each quad of
the S8R grid, centre node added, cut likewise).
"""
import argparse
import math
import os


def grid(etype, nx, ny, place):
    """Nodes and elements of an nx x ny structured shell mesh over (s, t) in [0, 1]^2, placed by
    place(s, t) -> (x, y, z). Returns (nodes {label: (s, t, xyz)}, elements [[labels]])."""
    quad = etype == "S8R"
    step = 2 if etype in ("S8R", "S6") else 1
    cols, rows = nx * step + 1, ny * step + 1
    label = lambda i, j: j * cols + i + 1
    nodes = {}
    for j in range(rows):
        for i in range(cols):
            if quad and i % 2 == 1 and j % 2 == 1:
                continue  # no centre node in an S8R
            s, t = i / (cols - 1), j / (rows - 1)
            nodes[label(i, j)] = (s, t, place(s, t))
    elements = []
    for ey in range(ny):
        for ex in range(nx):
            i, j = ex * step, ey * step
            if quad:
                elements.append([label(i, j), label(i + 2, j), label(i + 2, j + 2), label(i, j + 2),
                                 label(i + 1, j), label(i + 2, j + 1), label(i + 1, j + 2), label(i, j + 1)])
            elif etype == "S6":
                a, b, c, d = label(i, j), label(i + 2, j), label(i + 2, j + 2), label(i, j + 2)
                ab, bc, cd, da, ac = label(i + 1, j), label(i + 2, j + 1), label(i + 1, j + 2), label(i, j + 1), \
                    label(i + 1, j + 1)
                elements += [[a, b, c, ab, bc, ac], [a, c, d, ac, cd, da]]
            elif etype == "S3":
                a, b, c, d = label(i, j), label(i + 1, j), label(i + 1, j + 1), label(i, j + 1)
                elements += [[a, b, c], [a, c, d]]
            else:
                elements.append([label(i, j), label(i + 1, j), label(i + 1, j + 1), label(i, j + 1)])
    return nodes, elements


def near(a, b):
    return abs(a - b) < 1e-9


def write(path, heading, etype, nodes, elements, material, sets, tail):
    lines = ["*HEADING", heading, "*NODE"]
    lines += [f"{n}, {x:.15g}, {y:.15g}, {z:.15g}" for n, (_, _, (x, y, z)) in sorted(nodes.items())]
    lines.append(f"*ELEMENT, TYPE={'S3' if etype == 'S3' else etype}, ELSET=SHELL")
    lines += [", ".join(str(k) for k in [e + 1] + conn) for e, conn in enumerate(elements)]
    for name, test in sets.items():
        members = [n for n, (s, t, _) in sorted(nodes.items()) if test(s, t)]
        lines.append(f"*NSET, NSET={name}")
        lines += [", ".join(str(m) for m in members[k:k + 12]) for k in range(0, len(members), 12)]
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", material]
    lines += tail
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def section(thickness):
    return ["*SHELL SECTION, ELSET=SHELL, MATERIAL=M", f"{thickness:.15g}, 5"]


def scordelis_lo(etype, n):
    R, phi = 25.0, math.radians(40.0)
    place = lambda s, t: (25.0 * s, R * math.sin(phi * t), R * math.cos(phi * t))
    nodes, elements = grid(etype, n, n, place)
    sets = {"MIDSPAN": lambda s, t: near(s, 0), "DIAPHRAGM": lambda s, t: near(s, 1), "CROWN": lambda s, t: near(t, 0),
            "POINT": lambda s, t: near(s, 0) and near(t, 1)}
    tail = ["*DENSITY", "360."] + section(0.25) + [
        "*BOUNDARY", "DIAPHRAGM, 2, 3", "MIDSPAN, XSYMM", "CROWN, YSYMM",
        "*STEP", "*STATIC", "*DLOAD", "SHELL, GRAV, 1., 0., 0., -1.", "*NODE PRINT, NSET=POINT", "U", "*END STEP"]
    return "Scordelis-Lo roof, quarter model: U3 at the middle of the free edge -0.3024", nodes, elements, \
        "4.32e8, 0.", sets, tail


def pinched(etype, n):
    R = 300.0
    place = lambda s, t: (300.0 * s, R * math.sin(0.5 * math.pi * t), R * math.cos(0.5 * math.pi * t))
    nodes, elements = grid(etype, n, n, place)
    sets = {"MIDSPAN": lambda s, t: near(s, 0), "DIAPHRAGM": lambda s, t: near(s, 1), "TOP": lambda s, t: near(t, 0),
            "SIDE": lambda s, t: near(t, 1), "POINT": lambda s, t: near(s, 0) and near(t, 0)}
    tail = section(3.0) + ["*BOUNDARY", "DIAPHRAGM, 2, 3", "MIDSPAN, XSYMM", "TOP, YSYMM", "SIDE, ZSYMM",
                           "*STEP", "*STATIC", "*CLOAD", "POINT, 3, -0.25", "*NODE PRINT, NSET=POINT", "U", "*END STEP"]
    return "Pinched cylinder with diaphragms, octant: U3 under the load -1.8248e-5", nodes, elements, \
        "3.e6, 0.3", sets, tail


def hemisphere(etype, n):
    R, hole = 10.0, math.radians(18.0)
    def place(s, t):
        polar = hole + (0.5 * math.pi - hole) * t  # t = 1 on the equator
        lam = 0.5 * math.pi * s
        return (R * math.sin(polar) * math.cos(lam), R * math.sin(polar) * math.sin(lam), R * math.cos(polar))
    nodes, elements = grid(etype, n, n, place)
    sets = {"XZ": lambda s, t: near(s, 0), "YZ": lambda s, t: near(s, 1),
            "LOADX": lambda s, t: near(s, 0) and near(t, 1), "LOADY": lambda s, t: near(s, 1) and near(t, 1)}
    tail = section(0.04) + ["*BOUNDARY", "XZ, YSYMM", "YZ, XSYMM", "LOADX, 3",
                            "*STEP", "*STATIC", "*CLOAD", "LOADX, 1, 1.", "LOADY, 2, -1.",
                            "*NODE PRINT, NSET=LOADX", "U", "*END STEP"]
    return "Pinched hemisphere with an 18 degree hole, quarter: U1 under the load 0.094", nodes, elements, \
        "6.825e7, 0.3", sets, tail


def tip_loads(nodes, on_tip, coordinate, total, dof):
    """Nodal loads of a line load `total` spread evenly along the tip edge (lumped by tributary
    length over the edge coordinate), as *CLOAD lines."""
    tip = sorted((coordinate(s, t), m) for m, (s, t, _) in nodes.items() if on_tip(s, t))
    out = []
    for k, (c, m) in enumerate(tip):
        lo = tip[k - 1][0] if k > 0 else c
        hi = tip[k + 1][0] if k + 1 < len(tip) else c
        out.append(f"{m}, {dof}, {total * (hi - lo) / 2 / (tip[-1][0] - tip[0][0]):.15g}")
    return out


def consistent_tip_loads(etype, nodes, on_tip, coordinate, total, dof):
    """A uniform line load on the tip edge as the elements' consistent nodal loads (linear: 1/2,
    1/2 of each edge; quadratic: 1/6, 2/3, 1/6), for the exact-answer strip."""
    if etype not in ("S8R", "S6"):
        return tip_loads(nodes, on_tip, coordinate, total, dof)
    tip = sorted((coordinate(s, t), m) for m, (s, t, _) in nodes.items() if on_tip(s, t))
    length = tip[-1][0] - tip[0][0]
    load = {m: 0.0 for _, m in tip}
    for k in range(0, len(tip) - 2, 2):
        h = tip[k + 2][0] - tip[k][0]
        for j, w in ((0, 1 / 6), (1, 2 / 3), (2, 1 / 6)):
            load[tip[k + j][1]] += total * w * h / length
    return [f"{m}, {dof}, {v:.15g}" for m, v in load.items()]


def twisted(etype, n, thin):
    t, P = (0.0032, 1e-6) if thin else (0.32, 1.0)
    def place(s, w):
        a = 0.5 * math.pi * s
        return (12.0 * s, 1.1 * (w - 0.5) * math.cos(a), 1.1 * (w - 0.5) * math.sin(a))
    nodes, elements = grid(etype, 6 * n, n, place)
    on_tip = lambda s, w: near(s, 1)
    sets = {"ROOT": lambda s, w: near(s, 0), "TIP": on_tip, "CENTRE": lambda s, w: near(s, 1) and near(w, 0.5)}
    width = lambda s, w: w
    tail = section(t) + ["*BOUNDARY", "ROOT, ENCASTRE",
                         "*STEP, NAME=INPLANE", "*STATIC", "*CLOAD, OP=NEW"] + tip_loads(nodes, on_tip, width, P, 3) + [
        "*NODE PRINT, NSET=CENTRE", "U", "*END STEP",
        "*STEP, NAME=OUTOFPLANE", "*STATIC", "*CLOAD, OP=NEW"] + tip_loads(nodes, on_tip, width, P, 2) + [
        "*NODE PRINT, NSET=CENTRE", "U", "*END STEP"]
    return (f"Twisted beam, t = {t:g}, P = {P:g}: tip U3 (in-plane) {'5.256e-3' if thin else '5.424e-3'}, "
            f"U2 (out of plane) {'1.294e-3' if thin else '1.754e-3'}"), nodes, elements, "29.e6, 0.22", sets, tail


def strip(etype, n):
    """n elements along the strip, n/10 (at least 1) across: a tip line load along z."""
    place = lambda s, w: (10.0 * s, w - 0.5, 0.0)
    nodes, elements = grid(etype, n, max(1, n // 10), place)
    on_tip = lambda s, w: near(s, 1)
    sets = {"ROOT": lambda s, w: near(s, 0), "TIP": on_tip}
    tail = section(0.1) + ["*BOUNDARY", "ROOT, ENCASTRE", "*STEP", "*STATIC", "*CLOAD"] + \
        consistent_tip_loads(etype, nodes, on_tip, lambda s, w: w, 1.0, 3) + ["*NODE PRINT, NSET=TIP", "U", "*END STEP"]
    return "Cantilever strip L = 10, b = 1, t = 0.1, nu = 0: a tip line load P = 1 along z", nodes, elements, \
        "2.e5, 0.", sets, tail


LAYUPS = {
    "cross": ("", [(0.025, "0."), (0.025, "90."), (0.025, "90."), (0.025, "0.")]),
    "orient": ("", [(0.025, "OX"), (0.025, "OY"), (0.025, "OY"), (0.025, "OX")]),
    "normal1": ("", [(0.025, "NX"), (0.025, "NY"), (0.025, "NY"), (0.025, "NX")]),
    "unsym": ("", [(0.05, "0."), (0.05, "90.")]),
    "turned": ("", [(0.1, "30.")]),
    "composed": (", ORIENTATION=O20", [(0.1, "10.")]),
}


def laminate(etype, n, variant):
    """The strip of `strip` made of layers of a lamina (LAYUPS[variant])."""
    heading, nodes, elements, material, sets, tail = strip(etype, n)
    option, layers = LAYUPS[variant]
    c, s = math.cos(math.radians(20)), math.sin(math.radians(20))
    ply = ["*MATERIAL, NAME=PLY", "*ELASTIC, TYPE=LAMINA", "1.4e5, 1.e4, 0., 5.e3, 5.e3, 3.e3",
           "*ORIENTATION, NAME=OX", "1., 0., 0., 0., 1., 0.", "*ORIENTATION, NAME=OY", "0., 1., 0., -1., 0., 0.",
           "*ORIENTATION, NAME=O20", f"{c:.17g}, {s:.17g}, 0., {-s:.17g}, {c:.17g}, 0.",
           # Axis 1 along the normal, named so on the second line: Abaqus projects axis 2 (x, y).
           "*ORIENTATION, NAME=NX", "0., 0., 1., 1., 0., 0.", "1, 0.",
           "*ORIENTATION, NAME=NY", "0., 0., 1., 0., 1., 0.", "1, 0.",
           f"*SHELL SECTION, ELSET=SHELL, COMPOSITE{option}"]
    ply += [f"{t:.15g}, 3, PLY, {o}" for t, o in layers]
    load = tail[len(section(0.1)):-1]  # without *END STEP
    return f"Laminated cantilever strip ({variant}) L = 10, b = 1, t = 0.1: a tip line load P = 1 along z", nodes, \
        elements, material, sets, ply + load + ["*EL PRINT, ELSET=SHELL", "S", "*END STEP"]


def pressure(etype, n):
    """The cantilever strip under a uniform pressure 1: *DLOAD P (along the shell's normal, +z
    here), then *DSLOAD on the SPOS surface (against that surface's normal, -z)."""
    place = lambda s, w: (10.0 * s, w - 0.5, 0.0)
    nodes, elements = grid(etype, n, max(1, n // 10), place)
    on_tip = lambda s, w: near(s, 1)
    sets = {"ROOT": lambda s, w: near(s, 0), "TIP": on_tip}
    tail = section(0.1) + ["*SURFACE, NAME=TOP, TYPE=ELEMENT", "SHELL, SPOS", "*BOUNDARY", "ROOT, ENCASTRE",
                           "*STEP, NAME=DLOAD", "*STATIC", "*DLOAD", "SHELL, P, 1.", "*NODE PRINT, NSET=TIP", "U",
                           "*END STEP", "*STEP, NAME=DSLOAD", "*STATIC", "*DLOAD, OP=NEW", "*DSLOAD", "TOP, P, 1.",
                           "*NODE PRINT, NSET=TIP", "U", "*END STEP"]
    return "Cantilever strip L = 10, b = 1, t = 0.1, nu = 0 under a uniform pressure 1 (P, then SPOS)", nodes, \
        elements, "2.e5, 0.", sets, tail


def tapered(etype, n):
    """The strip of `strip` with *NODAL THICKNESS t = 0.1 (1 + x/L), 0.1 at the root and 0.2 at
    the tip, under the tip line load 1 along z."""
    place = lambda s, w: (10.0 * s, w - 0.5, 0.0)
    nodes, elements = grid(etype, n, max(1, n // 10), place)
    on_tip = lambda s, w: near(s, 1)
    sets = {"ROOT": lambda s, w: near(s, 0), "TIP": on_tip}
    thickness = [f"{m}, {0.1 * (1 + s):.15g}" for m, (s, _, _) in sorted(nodes.items())]
    tail = ["*SHELL SECTION, ELSET=SHELL, MATERIAL=M, NODAL THICKNESS", "0.1, 5", "*NODAL THICKNESS"] + thickness + \
        ["*BOUNDARY", "ROOT, ENCASTRE", "*STEP", "*STATIC", "*CLOAD"] + \
        consistent_tip_loads(etype, nodes, on_tip, lambda s, w: w, 1.0, 3) + ["*NODE PRINT, NSET=TIP", "U", "*END STEP"]
    return "Tapered cantilever strip L = 10, b = 1, t = 0.1 (1 + x/L), nu = 0: a tip line load 1 along z", nodes, \
        elements, "2.e5, 0.", sets, tail


def torsion(etype, n):
    """n elements along the strip, n/2 across, graded towards the free edges (their transverse
    shear boundary layer is t/sqrt(10) wide): a torque T = 1 as nodal moments on the tip."""
    y = lambda s, w: 0.5 * math.sin(math.pi * (w - 0.5))
    nodes, elements = grid(etype, n, n // 2, lambda s, w: (10.0 * s, y(s, w), 0.0))
    on_tip = lambda s, w: near(s, 1)
    sets = {"ROOT": lambda s, w: near(s, 0), "TIP": on_tip, "AXIS": lambda s, w: near(w, 0.5)}
    tail = section(0.1) + ["*BOUNDARY", "ROOT, ENCASTRE", "*STEP", "*STATIC", "*CLOAD"] + \
        tip_loads(nodes, on_tip, y, 1.0, 4) + ["*NODE PRINT, NSET=AXIS", "UR", "*END STEP"]
    return "Cantilever strip L = 10, b = 1, t = 0.1, nu = 0: a tip torque T = 1", nodes, elements, \
        "2.e5, 0.", sets, tail


def rollup(etype, n):
    """n elements along the strip, one across: the end moment as nodal moments on the tip."""
    nodes, elements = grid(etype, n, 1, lambda s, w: (12.0 * s, w, 0.0))
    on_tip = lambda s, w: near(s, 1)
    sets = {"ROOT": lambda s, w: near(s, 0), "TIP": on_tip, "ALL": lambda s, w: True}
    tail = section(0.1) + ["*BOUNDARY", "ROOT, ENCASTRE", "ALL, 2, 2", "ALL, 4, 4", "ALL, 6, 6",
                           "*STEP, NLGEOM, INC=100", "*STATIC", "0.1, 1.", "*CLOAD"] + \
        consistent_tip_loads(etype, nodes, on_tip, lambda s, w: w, -50 * math.pi / 3, 5) + \
        ["*NODE PRINT, NSET=TIP", "U, UR", "*NODE PRINT, NSET=ROOT", "RF, RM", "*END STEP"]
    return "Strip L = 12, b = 1, t = 0.1, nu = 0 rolled up by an end moment 50 pi / 3 (a full circle)", nodes, \
        elements, "1.2e6, 0.", sets, tail


def plastic_nlgeom(etype, n):
    """The plastic strip of `plastic` bent under NLGEOM: the tip turned by 0.3, then 1 rad."""
    heading, nodes, elements, material, sets, tail = plastic(etype, n)
    tail = [line.replace(", INC=100", ", INC=100, NLGEOM") for line in tail]
    return heading + ", NLGEOM", nodes, elements, material, sets, tail


def plastic_plate(etype, n):
    """A clamped square plate 1 x 1, t = 0.01, of a hardening metal (E = 210000, nu = 0.3, yield
    250 rising to 400 at a plastic strain of 0.2) under a pressure of 5 along its normal, NLGEOM:
    it deflects about 13 thicknesses, stretched and yielded through its thickness."""
    nodes, elements = grid(etype, n, n, lambda s, t: (s, t, 0.0))
    sets = {"EDGE": lambda s, t: near(s, 0) or near(s, 1) or near(t, 0) or near(t, 1),
            "CENTER": lambda s, t: near(s, 0.5) and near(t, 0.5)}
    tail = ["*PLASTIC", "250., 0.", "400., 0.2", "*SHELL SECTION, ELSET=SHELL, MATERIAL=M", "0.01, 5",
            "*BOUNDARY", "EDGE, ENCASTRE", "*STEP, NLGEOM, INC=200", "*STATIC", "0.05, 1.", "*DLOAD", "SHELL, P, 5.",
            "*NODE PRINT, NSET=CENTER", "U", "*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S, PEEQ",
            "*END STEP"]
    return "Clamped plastic plate under a pressure 5, NLGEOM", nodes, elements, "210000., 0.3", sets, tail


def plastic(etype, n):
    """n elements along the strip, one across: the tip's rotation about y prescribed (its
    translations free, so the moment is uniform). The root holds U1, U3 and UR2 (U2 at one
    node): its width is free, so the plastic flow's ε22 = -ε11/2 meets no constraint there."""
    nodes, elements = grid(etype, n, 1, lambda s, w: (10.0 * s, w - 0.5, 0.0))
    on_tip = lambda s, w: near(s, 1)
    sets = {"ROOT": lambda s, w: near(s, 0), "TIP": on_tip, "CORNER": lambda s, w: near(s, 0) and near(w, 0)}
    steps = [0.3, 1.0]
    tail = ["*SHELL SECTION, ELSET=SHELL, MATERIAL=M", "0.1, 5", "*BOUNDARY", "ROOT, 1, 1", "ROOT, 3, 3", "ROOT, 5, 5",
            "CORNER, 2, 2"]
    for k, turn in enumerate(steps):
        tail += [f"*STEP, NAME=BEND{k + 1}, INC=100", "*STATIC", "0.1, 1.",
                 "*BOUNDARY", f"TIP, 5, 5, {-turn:g}", "*NODE PRINT, NSET=ROOT", "RM", "*EL PRINT, ELSET=SHELL",
                 "S, PEEQ", "*OUTPUT, FIELD", "*NODE OUTPUT", "U, UR, RF, RM", "*ELEMENT OUTPUT", "S, PEEQ, SF, SM",
                 "*END STEP"]
    material = "2.e5, 0.\n*PLASTIC\n200., 0."
    return "Elastic-perfectly plastic strip L = 10, b = 1, t = 0.1 bent by its tip's rotation", nodes, elements, \
        material, sets, tail


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("name", choices=["scordelis_lo", "pinched", "hemisphere", "twisted", "strip", "torsion", "rollup",
                                     "plastic", "pressure", "tapered", "plastic_nlgeom", "plastic_plate", "laminate"])
    ap.add_argument("etype", choices=["S4", "S4R", "S8R", "S3", "S6"])
    ap.add_argument("n", type=int)
    ap.add_argument("thin", nargs="?", default="")
    a = ap.parse_args()
    make = {"scordelis_lo": scordelis_lo, "pinched": pinched, "hemisphere": hemisphere, "strip": strip, "torsion": torsion,
            "rollup": rollup, "plastic": plastic, "pressure": pressure, "tapered": tapered,
            "plastic_nlgeom": plastic_nlgeom, "plastic_plate": plastic_plate,
            "twisted": lambda e, n: twisted(e, n, a.thin == "thin"),
            "laminate": lambda e, n: laminate(e, n, a.thin)}[a.name]
    heading, nodes, elements, material, sets, tail = make(a.etype, a.n)
    suffix = f"_{a.thin}" if a.thin else ""
    os.makedirs(a.out, exist_ok=True)
    write(os.path.join(a.out, f"{a.name}_{a.etype}_{a.n}{suffix}.inp"), heading, a.etype, nodes, elements,
          material, sets, tail)


if __name__ == "__main__":
    main()
