#!/usr/bin/env python3
"""Generator of the contact verification decks with analytic references (decks/contact_verification/).

    gen_contact_verification.py                      # the committed (coarse, level 1) decks, here
    gen_contact_verification.py --out DIR --level 2  # the same decks on a finer mesh, into DIR

Three problems, each one deck whose enforcement method and tolerances are *PARAMETERs, so that
`inpact run DECK -P method=... -P sf=... -P tol=...` (or parser::ReadOptions::parameters) runs
every variant of it:

  hertz_2d          Hertz line contact, plane strain: a cylinder segment of radius R pressed on a
                    block (same material), quarter-symmetric (x = 0 plane), Johnson §4.2; the
                    two meshes have the same node positions along the contact before loading
  hertz_2d_nonmatching  the same with master (block) elements 1.25 × the slave's
  hertz_2d_force    the same cylinder held only by its contact (touching the block at one node)
                    and pushed down by a force, surface to surface (issue 14: the first system
                    of a force-driven contact problem); parameters method, type, inc0
  hertz_2d_rigid    hertz_2d_force with a rigid cylinder: R2D2 elements of a *RIGID BODY loaded at
                    its reference node, the block the slave (rigid-indenter Hertz)
  hertz_2d_analytical  the same rigid cylinder as an analytical surface (*SURFACE, TYPE=SEGMENTS,
                    one CIRCL arc): the exact circle instead of its chords
  hertz_cylinder_3d  hertz_2d_analytical as one layer of C3D8 (plane strain by U3 = 0) under a
                    *SURFACE, TYPE=CYLINDER: the 2D deck's answer
  sphere_3d         sphere (segment) on a block, quarter model (x = 0 and y = 0 planes), Johnson §4.2
  sphere_3d_force   the same sphere resting on the block (touching at the pole) and held only by its
                    contact and the symmetry planes, pushed down by a force; parameters method,
                    type, inc0
  sphere_3d_analytical  a rigid sphere (*SURFACE, TYPE=REVOLUTION) resting on the block of
                    sphere_3d_force, pushed down through its reference node (rigid-indenter Hertz)
  interference_2d   thick-cylinder interference fit, plane strain, quarter model, non-matching
                    ring meshes, interference δ set up by the geometry (Lamé)
  interference_2d_smoothed  the same, both ring surfaces smoothed (CIRCUMFERENTIAL, [AX] 38.1.3)
  interference_2d_general   the same smoothed fit in general contact: one inclusion pair, the
                    smoothing by *SURFACE PROPERTY ASSIGNMENT (balanced master-slave for penalty)

Smoothing verification (issue 5), surface to surface by default, each deck also as *_smoothed
(the pair's GEOMETRIC CORRECTION names a *SURFACE SMOOTHING of both surfaces):
  spherical_seat_axi  a solid ball in a spherical socket (thick spherical shell) with radial
                      interference δ, axisymmetric (CAX4), a half meridian; SPHERICAL about the
                      origin; reference: the thick-walled sphere (Lamé for spheres)
  spherical_seat_3d   the same as a 3D octant (C3D8, cube-sphere meshes)
  oring_axi           an O-ring (solid circular cross-section) in a toroidal sleeve with radial
                      interference δ in the tube, axisymmetric, half the cross-section; TOROIDAL
                      about the y axis; reference: the same deck on a finer level

Parameters of every deck:
  method   DIRECT | PENALTY | PENALTY=NONLINEAR | AUGMENTED LAGRANGE   (*SURFACE BEHAVIOR)
  type     NODE TO SURFACE | SURFACE TO SURFACE   (*CONTACT PAIR; the smoothing decks default to the latter)
  sf       *CONTACT CONTROLS, STIFFNESS SCALE FACTOR (penalty-type methods; 1 = the default)
  tolkind  RELATIVE | ABSOLUTE, tol: *CONTACT CONTROLS, <tolkind> PENETRATION TOLERANCE=<tol>
           (augmented Lagrange only; RELATIVE 0.001 is Abaqus's default for node-to-surface)

Mesh levels: level L has element size h = a / 2^(L+1) at the contact in hertz_2d, a / (3·2^(L−1))
in sphere_3d, a / (4·2^(L−1)) in sphere_3d_force (a: the contact half-width or radius of the
design load, ≈ 1), and 24·2^(L−1) / 34·2^(L−1) elements per quarter on the interference rings and
the axisymmetric seat (inner / outer body), 12·2^(L−1) / 16·2^(L−1) per quarter great circle in the 3D seat, 48·2^(L−1) / 68·2^(L−1)
along the half cross-section of the O-ring and its sleeve. The tolerances and references are in tests/contact_verification/.

Pure standard-library Python.
"""
import argparse
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# Material (both bodies the same: E* = E / (2 (1 − ν²))). Units: N, mm, MPa.
E, NU = 210000.0, 0.3

# Hertz geometry: radius R, design half-width a ≈ 1 (the prescribed approach d gives it).
R_HERTZ = 20.0
HERTZ_W = 10.0   # half-width of both bodies (10 a)
HERTZ_H = 10.0   # height of the block below, and of the indenter above its lowest point
D_2D = 0.095     # approach prescribed at the indenter's top (calibrated: a ≈ 1)
R_SPHERE = 20.0
SPHERE_W = 4.0   # half-width of both bodies (4 a)
SPHERE_H = 4.0
D_3D = 0.045     # approach (calibrated: a ≈ 1)

# Interference fit: inner ring r ∈ [A, B + δ], outer ring r ∈ [B, C].
RING_A, RING_B, RING_C, DELTA = 0.5, 1.0, 2.0, 0.01


def parameter_block():
    return ["*PARAMETER",
            'method = "DIRECT"',
            'type = "NODE TO SURFACE"',
            "sf = 1.0",
            'tolkind = "RELATIVE"',
            "tol = 0.001"]


def contact_block(slave, master, pair_options=""):
    return ["*SURFACE INTERACTION, NAME=SMOOTH",
            "*SURFACE BEHAVIOR, <method>",
            "*CONTACT PAIR, INTERACTION=SMOOTH, TYPE=<type>" + pair_options,
            f"{slave}, {master}"]


STEP_CONTROLS = "*CONTACT CONTROLS, STIFFNESS SCALE FACTOR=<sf>, <tolkind> PENETRATION TOLERANCE=<tol>"
OUTPUT = ["*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*CONTACT OUTPUT", "CPRESS, COPEN, CSTATUS, CNAREA, CFN"]


def graded(h, fine, length, ratio=1.25):
    """0 … length: uniform steps h up to `fine`, then steps growing by at most `ratio`."""
    n_fine = max(1, int(round(fine / h)))
    xs = [h * i for i in range(n_fine + 1)]
    rest = length - xs[-1]
    # smallest number of growing steps (h·r, h·r², …) that reaches `rest` with r ≤ ratio
    n = 1
    while h * sum(ratio ** k for k in range(1, n + 1)) < rest:
        n += 1
    # the ratio giving exactly `rest` in n steps (bisection; r ≥ 1)
    lo, hi = 1.0, ratio
    for _ in range(100):
        r = 0.5 * (lo + hi)
        if h * sum(r ** k for k in range(1, n + 1)) < rest:
            lo = r
        else:
            hi = r
    step = h
    for _ in range(n):
        step *= r
        xs.append(xs[-1] + step)
    xs[-1] = length
    return xs


def lines_of(labels, per=16):
    labels = sorted(set(labels))
    return [", ".join(str(n) for n in labels[i:i + per]) for i in range(0, len(labels), per)]


def header(title, reference, level, h):
    return ["*HEADING", f" {title}",
            f"** {reference}",
            f"** Mesh level {level}: element size at the contact h = {h:g}.",
            "** Generated by decks/contact_verification/gen_contact_verification.py; references and",
            "** tolerances in tests/contact_verification/test_contact_verification.cpp."]


# --------------------------------------------------------------------------- Hertz, plane strain

def hertz_2d(level, master_ratio=1.0):
    """Indenter: x ∈ [0, W], bottom y_b(x) = R − √(R² − x²) (the circle touching y = 0 at x = 0),
    top y = H. Block: x ∈ [0, W], y ∈ [−H, 0]. x = 0 is a symmetry plane (U1 = 0); the block's
    bottom is held (U2 = 0); the indenter's top moves down by d (U2 = −d)."""
    h = 1.0 / 2 ** (level + 1)
    hm = master_ratio * h  # master (block) elements: a ratio ≠ 1 makes the meshes non-matching
    xs_s = graded(h, 2.0, HERTZ_W)
    ys_s = graded(h, 2.0, HERTZ_H)          # distances up from the bottom arc (at x = 0)
    xs_m = graded(hm, 2.0, HERTZ_W)
    ys_m = graded(hm, 2.0, HERTZ_H)         # depths below y = 0
    match = "matching meshes" if master_ratio == 1.0 else f"non-matching meshes (master elements {master_ratio:g} h)"
    out = header(f"Hertz line contact, plane strain: cylinder R = {R_HERTZ:g} on a block, E = {E:g}, nu = {NU:g} "
                 f"(both); quarter-symmetric, node to surface, {match}",
                 "Reference: Johnson, Contact Mechanics (1985), §4.2: a = sqrt(4PR/(pi E*)), p0 = sqrt(P E*/(pi R)), "
                 "P per unit length = 2 x the reaction of this half model, E* = E/(2(1-nu^2)).", level, h)
    out += parameter_block()
    nodes, slave_elems, master_elems = [], [], []
    nx, ny = len(xs_s), len(ys_s)
    sid = lambda i, j: 1 + j * nx + i
    for j, s in enumerate(ys_s):
        for i, x in enumerate(xs_s):
            yb = R_HERTZ - math.sqrt(R_HERTZ ** 2 - x * x)
            nodes.append((sid(i, j), x, yb + (HERTZ_H - yb) * s / HERTZ_H))
    for j in range(ny - 1):
        for i in range(nx - 1):
            slave_elems.append((1 + j * (nx - 1) + i, sid(i, j), sid(i + 1, j), sid(i + 1, j + 1), sid(i, j + 1)))
    mx, my = len(xs_m), len(ys_m)
    ys_block = [-y for y in reversed(ys_m)]  # bottom (−H) to top (0)
    mid = lambda i, j: 100001 + j * mx + i
    for j, y in enumerate(ys_block):
        for i, x in enumerate(xs_m):
            nodes.append((mid(i, j), x, y))
    for j in range(my - 1):
        for i in range(mx - 1):
            master_elems.append((100001 + j * (mx - 1) + i, mid(i, j), mid(i + 1, j), mid(i + 1, j + 1), mid(i, j + 1)))
    out += ["*NODE, NSET=ALL"] + [f"{n}, {x:.15g}, {y:.15g}" for n, x, y in nodes]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=INDENTER"] + [", ".join(map(str, e)) for e in slave_elems]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=BLOCK"] + [", ".join(map(str, e)) for e in master_elems]
    out += ["*ELSET, ELSET=INDENTER_BOTTOM"] + lines_of([e[0] for e in slave_elems[:nx - 1]])
    out += ["*ELSET, ELSET=BLOCK_TOP"] + lines_of([e[0] for e in master_elems[-(mx - 1):]])
    out += ["*SURFACE, NAME=INDENTER_S", "INDENTER_BOTTOM, S1", "*SURFACE, NAME=BLOCK_S", "BLOCK_TOP, S3"]
    out += ["*NSET, NSET=SYMMETRY"] + lines_of([sid(0, j) for j in range(ny)] + [mid(0, j) for j in range(my)])
    out += ["*NSET, NSET=INDENTER_TOP"] + lines_of([sid(i, ny - 1) for i in range(nx)])
    out += ["*NSET, NSET=BLOCK_BOTTOM"] + lines_of([mid(i, 0) for i in range(mx)])
    out += ["*SOLID SECTION, ELSET=INDENTER, MATERIAL=STEEL", "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]
    out += contact_block("INDENTER_S", "BLOCK_S")
    out += ["*BOUNDARY", "SYMMETRY, 1", "BLOCK_BOTTOM, 2"]
    out += ["*STEP, NAME=PRESS", "*STATIC", "0.25, 1.0", "*BOUNDARY", f"INDENTER_TOP, 2, 2, {-D_2D:g}", STEP_CONTROLS]
    out += OUTPUT + ["*END STEP"]
    return out


# --------------------------------------------------------------------------- Hertz under a force

A_FORCE = 1.0  # the design half-width of hertz_2d_force: the load is chosen to give it exactly


def hertz_force_load(a=A_FORCE):
    """P per unit length (the whole cylinder) giving the half-width a: a = √(4PR/(πE*))."""
    e_star = E / (2.0 * (1.0 - NU * NU))
    return math.pi * e_star * a * a / (4.0 * R_HERTZ)


def hertz_2d_force(level):
    """The cylinder of hertz_2d held only by its contact and pushed down by a force. The same
    geometry: the indenter's bottom nodes lie exactly on the circle, so the lowest one (x = 0)
    touches the block with zero gap and every other is open (by x²/2R). The indenter is free but
    for the x-rollers on x = 0 (both bodies); the block's bottom is fixed. The load: P/2 on this
    half model, as the consistent nodal forces of a uniform pressure on the indenter's top flat
    (concentrated loads, so that the applied force is exactly P/2 whatever the deformation).
    Surface to surface, finite sliding; the method is a parameter (PENALTY by default, Abaqus's
    for finite-sliding surface-to-surface pairs), and so is the type. Level L: h = a / 2^(L+2)
    (level 1: a/h = 8)."""
    h = A_FORCE / 2 ** (level + 2)
    xs = graded(h, 2.0, HERTZ_W)
    ys = graded(h, 2.0, HERTZ_H)
    load = hertz_force_load()
    out = header(f"Hertz line contact under a force, plane strain: cylinder R = {R_HERTZ:g} resting on a block "
                 f"(touching at one node), E = {E:g}, nu = {NU:g} (both); half model, surface to surface",
                 "Reference: Johnson, Contact Mechanics (1985), §4.2: a = sqrt(4PR/(pi E*)), p0 = 2P/(pi a), "
                 f"E* = E/(2(1-nu^2)); P = {load:.10g} per unit length (this half model carries P/2): "
                 f"a = {A_FORCE:g}, p0 = {2 * load / (math.pi * A_FORCE):.10g}.", level, h)
    out[-1] = "** tolerances in tests/contact_verification/test_hertz_force.cpp."
    # inc0: the first increment (a fraction of the load). Augmented Lagrange at its 1000 k_e
    # converges the first one from 0.01 (tests/contact_verification/test_hertz_force.cpp).
    out += ["*PARAMETER", 'method = "PENALTY"', 'type = "SURFACE TO SURFACE"', "inc0 = 0.25"]
    nx, ny = len(xs), len(ys)
    sid = lambda i, j: 1 + j * nx + i
    mid = lambda i, j: 100001 + j * nx + i
    nodes = []
    for j, s in enumerate(ys):
        for i, x in enumerate(xs):
            yb = R_HERTZ - math.sqrt(R_HERTZ ** 2 - x * x)
            nodes.append((sid(i, j), x, yb + (HERTZ_H - yb) * s / HERTZ_H))
    for j, d in enumerate(reversed(ys)):  # block: bottom (−H) to top (0)
        for i, x in enumerate(xs):
            nodes.append((mid(i, j), x, -d))
    quad = lambda first, ids, i, j: (first + j * (nx - 1) + i, ids(i, j), ids(i + 1, j), ids(i + 1, j + 1),
                                     ids(i, j + 1))
    slave = [quad(1, sid, i, j) for j in range(ny - 1) for i in range(nx - 1)]
    master = [quad(100001, mid, i, j) for j in range(ny - 1) for i in range(nx - 1)]
    out += ["*NODE, NSET=ALL"] + [f"{n}, {x:.15g}, {y:.15g}" for n, x, y in nodes]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=INDENTER"] + [", ".join(map(str, e)) for e in slave]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=BLOCK"] + [", ".join(map(str, e)) for e in master]
    out += ["*ELSET, ELSET=INDENTER_BOTTOM"] + lines_of([e[0] for e in slave[:nx - 1]])
    out += ["*ELSET, ELSET=BLOCK_TOP"] + lines_of([e[0] for e in master[-(nx - 1):]])
    out += ["*SURFACE, NAME=INDENTER_S", "INDENTER_BOTTOM, S1", "*SURFACE, NAME=BLOCK_S", "BLOCK_TOP, S3"]
    out += ["*NSET, NSET=SYMMETRY"] + lines_of([sid(0, j) for j in range(ny)] + [mid(0, j) for j in range(ny)])
    out += ["*NSET, NSET=INDENTER_TOP"] + lines_of([sid(i, ny - 1) for i in range(nx)])
    out += ["*NSET, NSET=BLOCK_BOTTOM"] + lines_of([mid(i, 0) for i in range(nx)])
    out += ["*SOLID SECTION, ELSET=INDENTER, MATERIAL=STEEL", "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]
    out += ["*SURFACE INTERACTION, NAME=SMOOTH", "*SURFACE BEHAVIOR, <method>",
            "*CONTACT PAIR, INTERACTION=SMOOTH, TYPE=<type>", "INDENTER_S, BLOCK_S"]
    out += ["*BOUNDARY", "SYMMETRY, 1", "BLOCK_BOTTOM, 1, 2"]
    # The top's nodal forces: q × (half the lengths of the top edges on either side), q = (P/2)/W.
    q = 0.5 * load / HERTZ_W
    forces = [0.5 * q * ((xs[min(i + 1, nx - 1)] - xs[i]) + (xs[i] - xs[max(i - 1, 0)])) for i in range(nx)]
    out += ["*STEP, NAME=PRESS", "*STATIC", "<inc0>, 1.0", "*CLOAD"]
    out += [f"{sid(i, ny - 1)}, 2, {-f:.17g}" for i, f in enumerate(forces)]
    out += OUTPUT + ["*END STEP"]
    return out


def hertz_2d_rigid(level, analytical=False):
    """hertz_2d_force with a rigid indenter: the cylinder is its bottom arc alone, R2D2 elements of
    a *RIGID BODY whose reference node (the centre, x = 0, y = R) carries the force P/2 of this
    half model and is held in x and in rotation (the symmetry plane). The block is the slave (a
    rigid surface is always the master), with the same nodes along x as the arc. Reference: the
    rigid-indenter Hertz solution, E* = E/(1 - nu^2), P chosen for a = 1. Level L: h = a / 2^(L+2).
    `analytical`: the cylinder is an analytical surface instead, one CIRCL arc about the centre
    from x = W (where the chords end) across the symmetry plane to x = −2, travelled clockwise so
    that its normal (the direction of travel turned counter-clockwise) points down, at the block."""
    h = A_FORCE / 2 ** (level + 2)
    xs = graded(h, 2.0, HERTZ_W)
    ys = graded(h, 2.0, HERTZ_H)
    e_star = E / (1.0 - NU * NU)
    load = math.pi * e_star * A_FORCE ** 2 / (4.0 * R_HERTZ)
    out = header(f"Hertz line contact under a force, plane strain: a rigid cylinder R = {R_HERTZ:g} (R2D2 elements) "
                 f"resting on a block, E = {E:g}, nu = {NU:g}; half model, surface to surface",
                 "Reference: Johnson, Contact Mechanics (1985), §4.2 with a rigid indenter: a = sqrt(4PR/(pi E*)), "
                 f"p0 = 2P/(pi a), E* = E/(1-nu^2); P = {load:.10g} per unit length (this half model carries P/2): "
                 f"a = {A_FORCE:g}, p0 = {2 * load / (math.pi * A_FORCE):.10g}.", level, h)
    out[-1] = "** tolerances in tests/contact_verification/test_hertz_force.cpp."
    out += ["*PARAMETER", 'method = "PENALTY"', 'type = "SURFACE TO SURFACE"', "inc0 = 0.25"]
    nx, ny = len(xs), len(ys)
    arc = lambda i: 1 + i
    mid = lambda i, j: 100001 + j * nx + i
    ref = nx + 1
    nodes = [(arc(i), x, R_HERTZ - math.sqrt(R_HERTZ ** 2 - x * x)) for i, x in enumerate(xs)]
    nodes.append((ref, 0.0, R_HERTZ))
    for j, d in enumerate(reversed(ys)):  # block: bottom (−H) to top (0)
        for i, x in enumerate(xs):
            nodes.append((mid(i, j), x, -d))
    master = [(100001 + j * (nx - 1) + i, mid(i, j), mid(i + 1, j), mid(i + 1, j + 1), mid(i, j + 1))
              for j in range(ny - 1) for i in range(nx - 1)]
    # Node order +x: the positive normal (1 → 2 turned counter-clockwise) points up, into the
    # cylinder; the surface facing the block is SNEG.
    segments = [(1 + i, arc(i), arc(i + 1)) for i in range(nx - 1)]
    if analytical:
        nodes = nodes[nx:]
        out[1] = out[1].replace("(R2D2 elements)", "(an analytical surface)")
    out += ["*NODE, NSET=ALL"] + [f"{n}, {x:.15g}, {y:.15g}" for n, x, y in nodes]
    if not analytical:
        out += ["*ELEMENT, TYPE=R2D2, ELSET=INDENTER"] + [", ".join(map(str, e)) for e in segments]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=BLOCK"] + [", ".join(map(str, e)) for e in master]
    out += ["*ELSET, ELSET=BLOCK_TOP"] + lines_of([e[0] for e in master[-(nx - 1):]])
    if analytical:
        bottom = lambda x: R_HERTZ - math.sqrt(R_HERTZ ** 2 - x * x)
        out += ["*SURFACE, TYPE=SEGMENTS, NAME=INDENTER_S", f"START, {HERTZ_W:.15g}, {bottom(HERTZ_W):.15g}",
                f"CIRCL, -2, {bottom(2.0):.15g}, 0, {R_HERTZ:.15g}"]
    else:
        out += ["*SURFACE, NAME=INDENTER_S", "INDENTER, SNEG"]
    out += ["*SURFACE, NAME=BLOCK_S", "BLOCK_TOP, S3"]
    out += ["*NSET, NSET=SYMMETRY"] + lines_of([mid(0, j) for j in range(ny)])
    out += ["*NSET, NSET=REF", str(ref), "*NSET, NSET=BLOCK_BOTTOM"] + lines_of([mid(i, 0) for i in range(nx)])
    out += ["*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL", "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]
    out += ["*RIGID BODY, REF NODE=REF, ANALYTICAL SURFACE=INDENTER_S" if analytical else
            "*RIGID BODY, REF NODE=REF, ELSET=INDENTER"]
    out += ["*SURFACE INTERACTION, NAME=SMOOTH", "*SURFACE BEHAVIOR, <method>",
            "*CONTACT PAIR, INTERACTION=SMOOTH, TYPE=<type>", "BLOCK_S, INDENTER_S"]
    out += ["*BOUNDARY", "SYMMETRY, 1", "BLOCK_BOTTOM, 1, 2", "REF, 1", "REF, 6"]
    out += ["*STEP, NAME=PRESS", "*STATIC", "<inc0>, 1.0", "*CLOAD", f"REF, 2, {-0.5 * load:.17g}"]
    out += OUTPUT + ["*END STEP"]
    return out


def hertz_cylinder_3d(level):
    """hertz_2d_analytical extruded into one layer of C3D8 (z ∈ [0, 1], U3 = 0 everywhere: plane
    strain) under a *SURFACE, TYPE=CYLINDER with the same profile, its generator along z: the
    same finite element problem, so the same answer as the 2D deck."""
    out = []
    block = None
    offset = 1000000
    lines = hertz_2d_rigid(level, True)
    ref = int(lines[lines.index("*NSET, NSET=REF") + 1])  # the reference node stays one node
    for line in lines:
        if line.startswith("*"):
            block = line
            if line.startswith("*HEADING"):
                out.append(line)
                continue
            if line.startswith("*ELEMENT"):
                line = line.replace("TYPE=CPE4", "TYPE=C3D8")
            elif line.startswith("*SURFACE, TYPE=SEGMENTS"):
                line = line.replace("TYPE=SEGMENTS", "TYPE=CYLINDER")
                out += [line, "0, 0, 0, 1, 0, 0", "0, 0, 1"]
                continue
            elif line.startswith("*BOUNDARY"):
                out.append(line)
                out.append("ALL, 3")
                continue
            out.append(line)
            continue
        if block is None or block.startswith("*HEADING"):
            out.append(line.replace("plane strain:", "plane strain (one layer of C3D8 under a TYPE=CYLINDER surface):")
                       if line.startswith(" Hertz") else line)
        elif block == "*NODE, NSET=ALL":
            n, x, y = [v.strip() for v in line.split(",")]
            out += [f"{n}, {x}, {y}, 0"] + ([f"{int(n) + offset}, {x}, {y}, 1"] if int(n) != ref else [])
        elif block.startswith("*ELEMENT"):
            e = [int(v) for v in line.split(",")]
            out.append(", ".join(map(str, [e[0]] + e[1:5] + [v + offset for v in e[1:5]])))
        elif block.startswith("*NSET") and "NSET=ALL" not in block:
            labels = [int(v) for v in line.split(",") if v.strip()]
            out.append(", ".join(map(str, labels + [v + offset for v in labels if v != ref])))
        elif block.startswith("*SURFACE, NAME=BLOCK_S"):
            out.append(line.replace("S3", "S5"))
        elif block.startswith("*BOUNDARY") and line.startswith("REF"):
            out += ["REF, 1" if line == "REF, 1" else "REF, 4, 6"] if line in ("REF, 1", "REF, 6") else [line]
        else:
            out.append(line)
    return out


# --------------------------------------------------------------------------- sphere on a block

def sphere_block(h):
    """The block of the sphere decks: x, y ∈ [0, W] (quarter model), z ∈ [−H, 0], element size h
    at the contact (graded away from it), node labels from 1000001. Returns (nodes, elements,
    label(i, j, k), number of grid lines along x and y, along z)."""
    xs_m = graded(h, 1.34, SPHERE_W, 1.5)
    zs_m = graded(h, 1.34, SPHERE_H, 1.5)
    nodes, me = [], []
    m, mz = len(xs_m), len(zs_m)
    zs_block = [-z for z in reversed(zs_m)]
    mid = lambda i, j, k: 1000001 + k * m * m + j * m + i
    for k, z in enumerate(zs_block):
        for j, y in enumerate(xs_m):
            for i, x in enumerate(xs_m):
                nodes.append((mid(i, j, k), x, y, z))
    for k in range(mz - 1):
        for j in range(m - 1):
            for i in range(m - 1):
                me.append((1000001 + len(me), mid(i, j, k), mid(i + 1, j, k), mid(i + 1, j + 1, k), mid(i, j + 1, k),
                           mid(i, j, k + 1), mid(i + 1, j, k + 1), mid(i + 1, j + 1, k + 1), mid(i, j + 1, k + 1)))
    return nodes, me, mid, m, mz


def sphere_bodies(h):
    """The two bodies of the sphere decks, matching meshes at element size h at the contact:
    indenter bottom z_b = R − √(R² − x² − y²), top z = H; block z ∈ [−H, 0]; quarter model
    (x ≥ 0, y ≥ 0). Returns the mesh lines (nodes, elements, element sets, the surfaces
    INDENTER_S and BLOCK_S, the node sets XSYM, YSYM, INDENTER_TOP, BLOCK_BOTTOM), the material,
    and the grid (x positions) of the indenter's top with its node labels: (lines, xs, top_id)."""
    xs_s = graded(h, 1.34, SPHERE_W, 1.5)
    zs_s = graded(h, 1.34, SPHERE_H, 1.5)
    nodes, se = [], []
    n, nz = len(xs_s), len(zs_s)
    sid = lambda i, j, k: 1 + k * n * n + j * n + i
    for k, s in enumerate(zs_s):
        for j, y in enumerate(xs_s):
            for i, x in enumerate(xs_s):
                zb = R_SPHERE - math.sqrt(R_SPHERE ** 2 - x * x - y * y)
                nodes.append((sid(i, j, k), x, y, zb + (SPHERE_H - zb) * s / SPHERE_H))
    for k in range(nz - 1):
        for j in range(n - 1):
            for i in range(n - 1):
                se.append((1 + len(se), sid(i, j, k), sid(i + 1, j, k), sid(i + 1, j + 1, k), sid(i, j + 1, k),
                           sid(i, j, k + 1), sid(i + 1, j, k + 1), sid(i + 1, j + 1, k + 1), sid(i, j + 1, k + 1)))
    block_nodes, me, mid, m, mz = sphere_block(h)
    nodes += block_nodes
    out = ["*NODE, NSET=ALL"] + [f"{a}, {x:.15g}, {y:.15g}, {z:.15g}" for a, x, y, z in nodes]
    out += ["*ELEMENT, TYPE=C3D8, ELSET=INDENTER"] + [", ".join(map(str, e)) for e in se]
    out += ["*ELEMENT, TYPE=C3D8, ELSET=BLOCK"] + [", ".join(map(str, e)) for e in me]
    out += ["*ELSET, ELSET=INDENTER_BOTTOM"] + lines_of([e[0] for e in se[:(n - 1) ** 2]])
    out += ["*ELSET, ELSET=BLOCK_TOP"] + lines_of([e[0] for e in me[-(m - 1) ** 2:]])
    out += ["*SURFACE, NAME=INDENTER_S", "INDENTER_BOTTOM, S1", "*SURFACE, NAME=BLOCK_S", "BLOCK_TOP, S2"]
    xsym = [sid(0, j, k) for k in range(nz) for j in range(n)] + [mid(0, j, k) for k in range(mz) for j in range(m)]
    ysym = [sid(i, 0, k) for k in range(nz) for i in range(n)] + [mid(i, 0, k) for k in range(mz) for i in range(m)]
    out += ["*NSET, NSET=XSYM"] + lines_of(xsym) + ["*NSET, NSET=YSYM"] + lines_of(ysym)
    out += ["*NSET, NSET=INDENTER_TOP"] + lines_of([sid(i, j, nz - 1) for j in range(n) for i in range(n)])
    out += ["*NSET, NSET=BLOCK_BOTTOM"] + lines_of([mid(i, j, 0) for j in range(m) for i in range(m)])
    out += ["*SOLID SECTION, ELSET=INDENTER, MATERIAL=STEEL", "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]
    return out, xs_s, lambda i, j: sid(i, j, nz - 1)


def sphere_3d(level):
    """Quarter model (x ≥ 0, y ≥ 0): indenter bottom z_b = R − √(R² − x² − y²), top z = H; block
    z ∈ [−H, 0]; symmetry U1 = 0 on x = 0, U2 = 0 on y = 0; block bottom U3 = 0; the indenter's
    top moves down by d."""
    h = 1.0 / (3 * 2 ** (level - 1))
    out = header(f"Sphere on a block: R = {R_SPHERE:g}, E = {E:g}, nu = {NU:g} (both); quarter model, node to surface",
                 "Reference: Johnson, Contact Mechanics (1985), §4.2: a = (3PR/(4E*))^(1/3), p0 = 3P/(2 pi a^2), "
                 "P = 4 x the reaction of this quarter model, E* = E/(2(1-nu^2)).", level, h)
    out += parameter_block()
    out += sphere_bodies(h)[0]
    out += contact_block("INDENTER_S", "BLOCK_S")
    out += ["*BOUNDARY", "XSYM, 1", "YSYM, 2", "BLOCK_BOTTOM, 3"]
    out += ["*STEP, NAME=PRESS", "*STATIC", "0.5, 1.0", "*BOUNDARY", f"INDENTER_TOP, 3, 3, {-D_3D:g}", STEP_CONTROLS]
    out += OUTPUT + ["*END STEP"]
    return out


def sphere_force_load(a=A_FORCE):
    """P (the whole sphere) giving the contact radius a: a = (3PR/(4E*))^(1/3)."""
    e_star = E / (2.0 * (1.0 - NU * NU))
    return 4.0 * e_star * a ** 3 / (3.0 * R_SPHERE)


def sphere_3d_force(level):
    """The sphere of sphere_3d resting on the block and pushed down by a force: the indenter's
    lowest node (the pole, on the axis) touches the block with zero gap, every other is open by
    about r²/2R. The indenter is held by nothing but that contact and the symmetry planes
    (U1 = 0 on x = 0, U2 = 0 on y = 0, which leave it only its vertical motion); the block's
    bottom is held (U3 = 0). The load: P/4 on this quarter model, as the consistent nodal forces
    of a uniform pressure on the indenter's flat top (concentrated loads: the applied force is
    P/4 whatever the deformation), P chosen to give a = 1. Surface to surface, penalty by default
    (Abaqus's for finite-sliding surface-to-surface pairs); method, type and the first increment
    inc0 are parameters. Level L: h = a / (4·2^(L−1)) (level 1: a/h = 4, the coarse 3D mesh of
    issue 14; at a/h = 3, sphere_3d's, surface to surface closes the zone a node short)."""
    h = 1.0 / (4 * 2 ** (level - 1))
    load = sphere_force_load()
    p0 = 3.0 * load / (2.0 * math.pi * A_FORCE ** 2)
    out = header(f"Sphere on a block under a force: R = {R_SPHERE:g} resting on a block (touching at the pole), "
                 f"E = {E:g}, nu = {NU:g} (both); quarter model, surface to surface",
                 "Reference: Johnson, Contact Mechanics (1985), §4.2: a = (3PR/(4E*))^(1/3), p0 = 3P/(2 pi a^2), "
                 f"E* = E/(2(1-nu^2)); P = {load:.10g} (this quarter model carries P/4): "
                 f"a = {A_FORCE:g}, p0 = {p0:.10g}.", level, h)
    out[-1] = "** tolerances in tests/contact_verification/test_method_agreement.cpp."
    out += ["*PARAMETER", 'method = "PENALTY"', 'type = "SURFACE TO SURFACE"', "inc0 = 0.25"]
    mesh, xs, top = sphere_bodies(h)
    out += mesh
    out += ["*SURFACE INTERACTION, NAME=SMOOTH", "*SURFACE BEHAVIOR, <method>",
            "*CONTACT PAIR, INTERACTION=SMOOTH, TYPE=<type>", "INDENTER_S, BLOCK_S"]
    out += ["*BOUNDARY", "XSYM, 1", "YSYM, 2", "BLOCK_BOTTOM, 3"]
    # The top's nodal forces: q × the tributary area of each node, q = (P/4)/W².
    q = 0.25 * load / SPHERE_W ** 2
    nx = len(xs)
    width = [0.5 * ((xs[min(i + 1, nx - 1)] - xs[i]) + (xs[i] - xs[max(i - 1, 0)])) for i in range(nx)]
    out += ["*STEP, NAME=PRESS", "*STATIC", "<inc0>, 1.0", "*CLOAD"]
    out += [f"{top(i, j)}, 3, {-q * width[i] * width[j]:.17g}" for j in range(nx) for i in range(nx)]
    out += OUTPUT + ["*END STEP"]
    return out


def sphere_3d_analytical(level):
    """A rigid sphere as an analytical surface (*SURFACE, TYPE=REVOLUTION about the z axis through
    its centre (0, 0, R): one CIRCL arc in (r, z) from r = 6 at the bottom across the axis to
    r = −0.5, travelled clockwise so that its normal points down, at the block) resting on the
    block of sphere_3d_force (touching it at the pole) and pushed down through its reference node
    (the centre, held but in z) by P/4 on this quarter model. The block is the slave; no
    indenter mesh. Reference: rigid-indenter Hertz, E* = E/(1 - nu^2), P chosen for a = 1.
    Level L: h = a / (4·2^(L−1))."""
    h = 1.0 / (4 * 2 ** (level - 1))
    e_star = E / (1.0 - NU * NU)
    load = 4.0 * e_star * A_FORCE ** 3 / (3.0 * R_SPHERE)
    p0 = 3.0 * load / (2.0 * math.pi * A_FORCE ** 2)
    out = header(f"A rigid sphere R = {R_SPHERE:g} (an analytical surface of revolution) resting on a block under a "
                 f"force, E = {E:g}, nu = {NU:g}; quarter model",
                 "Reference: Johnson, Contact Mechanics (1985), §4.2 with a rigid indenter: a = (3PR/(4E*))^(1/3), "
                 f"p0 = 3P/(2 pi a^2), E* = E/(1-nu^2); P = {load:.10g} (this quarter model carries P/4): "
                 f"a = {A_FORCE:g}, p0 = {p0:.10g}.", level, h)
    out[-1] = "** tolerances in tests/contact_verification/test_hertz_force.cpp."
    out += ["*PARAMETER", 'method = "PENALTY"', 'type = "SURFACE TO SURFACE"', "inc0 = 0.25"]
    nodes, me, mid, m, mz = sphere_block(h)
    ref = 1
    out += ["*NODE, NSET=ALL", f"{ref}, 0, 0, {R_SPHERE:g}"] + [f"{a}, {x:.15g}, {y:.15g}, {z:.15g}" for a, x, y, z in nodes]
    out += ["*ELEMENT, TYPE=C3D8, ELSET=BLOCK"] + [", ".join(map(str, e)) for e in me]
    out += ["*ELSET, ELSET=BLOCK_TOP"] + lines_of([e[0] for e in me[-(m - 1) ** 2:]])
    lowest = lambda r: -math.sqrt(R_SPHERE ** 2 - r * r)
    out += ["*SURFACE, NAME=BLOCK_S", "BLOCK_TOP, S2",
            "*SURFACE, TYPE=REVOLUTION, NAME=SPHERE_S", f"0, 0, {R_SPHERE:g}, 0, 0, {R_SPHERE + 1:g}",
            f"START, 6, {lowest(6.0):.15g}", f"CIRCL, -0.5, {lowest(0.5):.15g}, 0, 0"]
    out += ["*NSET, NSET=XSYM"] + lines_of([mid(0, j, k) for k in range(mz) for j in range(m)])
    out += ["*NSET, NSET=YSYM"] + lines_of([mid(i, 0, k) for k in range(mz) for i in range(m)])
    out += ["*NSET, NSET=BLOCK_BOTTOM"] + lines_of([mid(i, j, 0) for j in range(m) for i in range(m)])
    out += ["*NSET, NSET=REF", str(ref)]
    out += ["*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL", "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]
    out += ["*RIGID BODY, REF NODE=REF, ANALYTICAL SURFACE=SPHERE_S"]
    out += ["*SURFACE INTERACTION, NAME=SMOOTH", "*SURFACE BEHAVIOR, <method>",
            "*CONTACT PAIR, INTERACTION=SMOOTH, TYPE=<type>", "BLOCK_S, SPHERE_S"]
    out += ["*BOUNDARY", "XSYM, 1", "YSYM, 2", "BLOCK_BOTTOM, 3", "REF, 1, 2", "REF, 4, 6"]
    out += ["*STEP, NAME=PRESS", "*STATIC", "<inc0>, 1.0", "*CLOAD", f"REF, 3, {-0.25 * load:.17g}"]
    out += OUTPUT + ["*END STEP"]
    return out


# --------------------------------------------------------------------------- interference fit

def interference_2d(level, smoothed=False, general=False):
    """Quarter rings, plane strain: inner ring r ∈ [A, B + δ] (n_in elements around), outer ring
    r ∈ [B, C] (n_out around, n_out ≠ n_in: non-matching). Slave: the outer ring's inner
    surface; master: the inner ring's outer surface. U2 = 0 on y = 0, U1 = 0 on x = 0. The
    overclosure δ is there at the start and is resolved in the first increment. `general`:
    general contact with the one inclusion pair (the ring surfaces) instead of the contact pair,
    its smoothing by *SURFACE PROPERTY ASSIGNMENT."""
    scale = 2 ** (level - 1)
    n_in, n_out = 24 * scale, 34 * scale
    nr_in, nr_out = 4 * scale, 8 * scale
    b_in = RING_B + DELTA
    out = header("Thick-cylinder interference fit (Lame), plane strain, quarter model, non-matching ring meshes "
                 f"({n_in} and {n_out} elements around); radial interference delta = {DELTA:g} from the geometry",
                 "Reference (Lame, same material): p = E' delta (c^2-b^2)(b^2-a^2) / (2 b^3 (c^2-a^2)), "
                 f"E' = E/(1-nu^2), a = {RING_A:g}, b = {RING_B:g}, c = {RING_C:g}.",
                 level, RING_B * math.pi / 2 / n_out)
    params = parameter_block()
    if smoothed:  # geometric correction is for surface-to-surface pairs (and general contact)
        params[params.index('type = "NODE TO SURFACE"')] = 'type = "SURFACE TO SURFACE"'
        out[1:1] = ["** Smoothed: both ring surfaces corrected toward circles about the z axis ([AX] 38.1.3)."]
    if general:  # general contact is surface to surface: no TYPE
        params.remove('type = "SURFACE TO SURFACE"')
        out[1:1] = ["** General contact: one inclusion pair, the smoothing by *SURFACE PROPERTY ASSIGNMENT."]
        out[-1] = "** tolerances in tests/contact_verification/test_method_agreement.cpp."
    out += params
    nodes, inner, outer = [], [], []
    iid = lambda i, j: 1 + j * (nr_in + 1) + i        # i radial, j around
    oid = lambda i, j: 100001 + j * (nr_out + 1) + i

    def ring(ids, r0, r1, nr, nt, first, elems):
        for j in range(nt + 1):
            t = 0.5 * math.pi * j / nt
            for i in range(nr + 1):
                r = r0 + (r1 - r0) * i / nr
                x, y = r * math.cos(t), r * math.sin(t)
                if j == nt:
                    x = 0.0  # exactly on the symmetry line
                if j == 0:
                    y = 0.0
                nodes.append((ids(i, j), x, y))
        for j in range(nt):
            for i in range(nr):
                elems.append((first + j * nr + i, ids(i, j), ids(i + 1, j), ids(i + 1, j + 1), ids(i, j + 1)))

    ring(iid, RING_A, b_in, nr_in, n_in, 1, inner)
    ring(oid, RING_B, RING_C, nr_out, n_out, 100001, outer)
    out += ["*NODE, NSET=ALL"] + [f"{n}, {x:.15g}, {y:.15g}" for n, x, y in nodes]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=INNER"] + [", ".join(map(str, e)) for e in inner]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=OUTER"] + [", ".join(map(str, e)) for e in outer]
    out += ["*ELSET, ELSET=INNER_OUT"] + lines_of([inner[j * nr_in + nr_in - 1][0] for j in range(n_in)])
    out += ["*ELSET, ELSET=OUTER_IN"] + lines_of([outer[j * nr_out][0] for j in range(n_out)])
    out += ["*SURFACE, NAME=INNER_S", "INNER_OUT, S2", "*SURFACE, NAME=OUTER_S", "OUTER_IN, S4"]
    out += ["*NSET, NSET=YSYM"] + lines_of([iid(i, 0) for i in range(nr_in + 1)] + [oid(i, 0) for i in range(nr_out + 1)])
    out += ["*NSET, NSET=XSYM"] + lines_of([iid(i, n_in) for i in range(nr_in + 1)] + [oid(i, n_out) for i in range(nr_out + 1)])
    out += ["*SOLID SECTION, ELSET=INNER, MATERIAL=STEEL", "*SOLID SECTION, ELSET=OUTER, MATERIAL=STEEL",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]
    # The initial overclosure δ may exceed the default HCRIT (half the slave facet) on fine
    # meshes: HCRIT limits only what an increment adds to the penetration it starts from.
    rings = ["INNER_S, CIRCUMFERENTIAL, 0., 0., 0., 0., 0., 1.", "OUTER_S, CIRCUMFERENTIAL, 0., 0., 0., 0., 0., 1."]
    if general:
        out += ["*SURFACE INTERACTION, NAME=SMOOTH", "*SURFACE BEHAVIOR, <method>", "*CONTACT",
                "*CONTACT INCLUSIONS", "OUTER_S, INNER_S", "*CONTACT PROPERTY ASSIGNMENT", "OUTER_S, INNER_S, SMOOTH",
                "*SURFACE PROPERTY ASSIGNMENT, PROPERTY=GEOMETRIC CORRECTION"] + rings
    elif smoothed:
        out += ["*SURFACE SMOOTHING, NAME=RINGS"] + rings
        out += contact_block("OUTER_S", "INNER_S", ", GEOMETRIC CORRECTION=RINGS")
    else:
        out += contact_block("OUTER_S", "INNER_S")
    out += ["*BOUNDARY", "YSYM, 2", "XSYM, 1"]
    out += ["*STEP, NAME=FIT", "*STATIC", "0.5, 1.0", STEP_CONTROLS]
    out += OUTPUT + ["*END STEP"]
    return out


# --------------------------------------------------------------------------- smoothing: sphere and torus

# Spherical seat: a solid ball of radius SEAT_B + δ in a socket (thick spherical shell) r ∈ [SEAT_B, SEAT_C].
SEAT_B, SEAT_C, SEAT_DELTA = 1.0, 2.0, 0.01
# O-ring in a toroidal sleeve: tube centre circle radius TORUS_R about the y axis; the ring's solid
# cross-section has radius TORUS_RHO + δ, the sleeve's annular one TORUS_RHO … TORUS_RHO_OUT.
TORUS_R, TORUS_RHO, TORUS_RHO_OUT, TORUS_DELTA = 4.0, 1.0, 2.0, 0.01


class Mesh:
    """Nodes merged by position (within `tol`), elements by node labels. Coordinates within 1e-12 of
    zero are set to zero, so that nodes on symmetry planes and on the axis lie exactly there."""

    def __init__(self, dim, tol=1e-9):
        self.dim, self.tol = dim, tol
        self.coords, self.body, self.grid = {}, {}, {}
        self.elements = []  # (label, body, node labels)
        self.n_nodes, self.n_elements = {}, {}  # per body

    def node(self, p, body, first):
        p = tuple(0.0 if abs(c) < 1e-12 else c for c in p)
        cell = tuple(int(math.floor(c / self.tol)) for c in p)
        for off in _OFFSETS[self.dim]:  # its own cell first
            for label in self.grid.get(tuple(c + o for c, o in zip(cell, off)) if any(off) else cell, ()):
                if self.body[label] == body and max(abs(a - b) for a, b in zip(self.coords[label], p)) < self.tol:
                    return label
        label = first + self.n_nodes.get(body, 0)
        self.n_nodes[body] = self.n_nodes.get(body, 0) + 1
        self.coords[label], self.body[label] = p, body
        self.grid.setdefault(cell, []).append(label)
        return label

    def element(self, body, first, labels):
        """A 4-node quadrilateral or 8-node hexahedron, reordered to a positive Jacobian."""
        labels = list(labels)
        x = [self.coords[n] for n in labels]
        if self.dim == 2:
            area = sum(x[i][0] * x[(i + 1) % 4][1] - x[(i + 1) % 4][0] * x[i][1] for i in range(4))
            if area < 0:
                labels = [labels[0], labels[3], labels[2], labels[1]]
        else:
            d = lambda a, b: [x[b][i] - x[a][i] for i in range(3)]
            u, v, w = d(0, 1), d(0, 3), d(0, 4)
            vol = (u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] + (u[0] * v[1] - u[1] * v[0]) * w[2]
            if vol < 0:
                labels = [labels[i] for i in (0, 3, 2, 1, 4, 7, 6, 5)]
        label = first + self.n_elements.get(body, 0)
        self.n_elements[body] = self.n_elements.get(body, 0) + 1
        self.elements.append((label, body, tuple(labels)))

    def faces_on(self, body, on):
        """{face id: [element labels]} of the faces of `body` whose nodes all satisfy on(x)."""
        faces = {}
        table = QUAD4_FACES if self.dim == 2 else HEX8_FACES
        for label, b, nodes in self.elements:
            if b != body:
                continue
            for k, face in enumerate(table):
                if all(on(self.coords[nodes[i]]) for i in face):
                    faces.setdefault(k + 1, []).append(label)
        return faces

    def nodes_where(self, body, test):
        return [n for n, x in self.coords.items() if (body is None or self.body[n] == body) and test(x)]

    def deck_lines(self, etype, elsets):
        fmt = (lambda n, x: f"{n}, {x[0]:.15g}, {x[1]:.15g}") if self.dim == 2 else \
              (lambda n, x: f"{n}, {x[0]:.15g}, {x[1]:.15g}, {x[2]:.15g}")
        out = ["*NODE, NSET=ALL"] + [fmt(n, self.coords[n]) for n in sorted(self.coords)]
        for body, elset in elsets:
            out += [f"*ELEMENT, TYPE={etype}, ELSET={elset}"]
            out += [f"{e[0]}, " + ", ".join(map(str, e[2])) for e in self.elements if e[1] == body]
        return out


_OFFSETS = {2: sorted(((i, j) for i in (-1, 0, 1) for j in (-1, 0, 1)), key=any),
            3: sorted(((i, j, k) for i in (-1, 0, 1) for j in (-1, 0, 1) for k in (-1, 0, 1)), key=any)}


QUAD4_FACES = [(0, 1), (1, 2), (2, 3), (3, 0)]                                              # S1 … S4
HEX8_FACES = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]  # S1 … S6


def surface_lines(mesh, body, name, on):
    """*ELSET and *SURFACE lines for the faces of `body` on the surface `on`."""
    out, refs = [], []
    for face, elems in sorted(mesh.faces_on(body, on).items()):
        out += [f"*ELSET, ELSET={name}_S{face}"] + lines_of(elems)
        refs.append(f"{name}_S{face}, S{face}")
    return out + [f"*SURFACE, NAME={name}"] + refs


def quarter_disk(mesh, body, first_node, first_elem, centre, radius, t0, n_arc, n_layers, core=0.5):
    """A quarter disk of `radius` about `centre` from angle t0 to t0 + π/2, meshed as a butterfly:
    a core square (side core·radius, n_arc/2 elements a side) and n_layers rings of n_arc
    quadrilaterals from the square's outer sides to the arc."""
    m = n_arc // 2
    assert 2 * m == n_arc
    s = core * radius
    c, sn = math.cos(t0), math.sin(t0)
    place = lambda u, v: (centre[0] + c * u - sn * v, centre[1] + sn * u + c * v)  # local (u, v) → model
    node = lambda u, v: mesh.node(place(u, v), body, first_node)
    for j in range(m):
        for i in range(m):
            mesh.element(body, first_elem, [node(s * i / m, s * j / m), node(s * (i + 1) / m, s * j / m),
                                             node(s * (i + 1) / m, s * (j + 1) / m), node(s * i / m, s * (j + 1) / m)])

    def square_edge(k):  # the k-th point (0 … n_arc) along the square's outer sides, from the u axis
        return (s, s * k / m) if k <= m else (s * (2 * m - k) / m, s)

    def arc(k):
        t = 0.5 * math.pi * k / n_arc
        return (radius * math.cos(t), radius * math.sin(t)) if 0 < k < n_arc else ((radius, 0.0) if k == 0 else (0.0, radius))

    def layer(k, i):
        (u0, v0), (u1, v1) = square_edge(k), arc(k)
        return node(u0 + (u1 - u0) * i / n_layers, v0 + (v1 - v0) * i / n_layers)

    for k in range(n_arc):
        for i in range(n_layers):
            mesh.element(body, first_elem, [layer(k, i), layer(k, i + 1), layer(k + 1, i + 1), layer(k + 1, i)])


def annulus(mesh, body, first_node, first_elem, centre, r0, r1, t0, t1, n_arc, n_layers):
    """The annular sector r0 ≤ r ≤ r1, t0 ≤ t ≤ t1 about `centre`, n_arc × n_layers quadrilaterals."""
    def node(i, j):
        t, r = t0 + (t1 - t0) * j / n_arc, r0 + (r1 - r0) * i / n_layers
        return mesh.node((centre[0] + r * math.cos(t), centre[1] + r * math.sin(t)), body, first_node)
    for j in range(n_arc):
        for i in range(n_layers):
            mesh.element(body, first_elem, [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)])


def smoothing_deck(out, smoothed, mesh, etype, bodies, slave, master, correction, bcs, sets):
    """The common part of the smoothing decks: mesh, sets, material, the surface-to-surface pair
    (smoothed or not) and a step in which the initial overclosure is resolved."""
    params = parameter_block()
    params[params.index('type = "NODE TO SURFACE"')] = 'type = "SURFACE TO SURFACE"'
    out += params
    out += mesh.deck_lines(etype, [(b, name) for b, name in bodies])
    out += sets
    out += [f"*SOLID SECTION, ELSET={name}, MATERIAL=STEEL" for _, name in bodies]
    out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]
    if smoothed:
        out += ["*SURFACE SMOOTHING, NAME=IDEAL", f"{master}, {correction}", f"{slave}, {correction}"]
        out += contact_block(slave, master, ", GEOMETRIC CORRECTION=IDEAL")
    else:
        out += contact_block(slave, master)
    out += ["*BOUNDARY"] + bcs
    out += ["*STEP, NAME=FIT", "*STATIC", "0.5, 1.0", STEP_CONTROLS]
    out += OUTPUT + ["*END STEP"]
    return out


def seat_pressure_text():
    return ("Reference (thick-walled sphere, same material, linear elasticity on the undeformed geometry): "
            "delta = u_socket(b) - u_ball(b + delta), u_socket(b) = p b ((1-2nu) b^3 + (1+nu) c^3/2) / (E (c^3-b^3)), "
            f"u_ball(r) = -p (1-2nu) r / E; b = {SEAT_B:g}, c = {SEAT_C:g}, delta = {SEAT_DELTA:g}.")


def seat_header(variant, level, element_size, smoothed):
    """The heading of a spherical-seat deck: the problem, this variant's mesh, the reference."""
    out = header(f"Spherical seat: a ball in a spherical socket with radial interference delta = {SEAT_DELTA:g}, "
                 f"{variant}", seat_pressure_text(), level, element_size)
    if smoothed:
        out[1:1] = ["** Smoothed: ball and socket corrected toward spheres about the origin ([AX] 38.1.3)."]
    return out


def spherical_seat_axi(level, smoothed=False):
    """A solid ball (radius b + δ) in a spherical socket r ∈ [b, c], axisymmetric (CAX4, the r–z plane
    x = r, y = z), a half meridian: the quarter disk and quarter annulus 0 ≤ polar angle from the
    equator ≤ π/2, U2 = 0 on the equator y = 0, U1 = 0 on the axis x = 0. Ball: butterfly, n_in
    elements along the arc; socket: n_out along its inner arc (non-matching). Slave: the socket's
    inner surface; master: the ball's. The overclosure δ is resolved in the first increment."""
    scale = 2 ** (level - 1)
    n_in, n_out, nr_in, nr_out = 24 * scale, 34 * scale, 4 * scale, 8 * scale
    b_in = SEAT_B + SEAT_DELTA
    out = seat_header(f"axisymmetric, a half meridian, non-matching meshes ({n_in} and {n_out} elements along the arc)",
                      level, SEAT_B * math.pi / 2 / n_out, smoothed)
    mesh = Mesh(2)
    quarter_disk(mesh, 1, 1, 1, (0.0, 0.0), b_in, 0.0, n_in, nr_in)
    annulus(mesh, 2, 100001, 100001, (0.0, 0.0), SEAT_B, SEAT_C, 0.0, 0.5 * math.pi, n_out, nr_out)
    on_ball = lambda x: abs(math.hypot(x[0], x[1]) - b_in) < 1e-9
    on_socket = lambda x: abs(math.hypot(x[0], x[1]) - SEAT_B) < 1e-9
    sets = surface_lines(mesh, 1, "BALL_S", on_ball) + surface_lines(mesh, 2, "SOCKET_S", on_socket)
    sets += ["*NSET, NSET=AXIS"] + lines_of(mesh.nodes_where(None, lambda x: x[0] == 0.0))
    sets += ["*NSET, NSET=BALL_EQUATOR"] + lines_of(mesh.nodes_where(1, lambda x: x[1] == 0.0))
    sets += ["*NSET, NSET=SOCKET_EQUATOR"] + lines_of(mesh.nodes_where(2, lambda x: x[1] == 0.0))
    return smoothing_deck(out, smoothed, mesh, "CAX4", [(1, "BALL"), (2, "SOCKET")], "SOCKET_S", "BALL_S",
                          "SPHERICAL, 0., 0., 0.", ["AXIS, 1", "BALL_EQUATOR, 2", "SOCKET_EQUATOR, 2"], sets)


def spherical_seat_3d(level, smoothed=False):
    """The spherical seat as a 3D octant (x, y, z ≥ 0; C3D8), symmetry U_i = 0 on each plane x_i = 0.
    Both bodies are cube-sphere meshes: three patches over the octant's sphere, each the central
    projection of a face of the cube [0, 1]³ with equal angles between grid lines; the ball has a
    core cube of side 0.4 (b + δ) joined to its sphere by layers. m_in and m_out elements along a
    patch edge (2 m along a quarter great circle): non-matching."""
    scale = 2 ** (level - 1)
    m_in, m_out, nr_in, nr_out = 6 * scale, 8 * scale, 3 * scale, 8 * scale
    b_in = SEAT_B + SEAT_DELTA
    out = seat_header(f"3D octant, non-matching meshes ({2 * m_in} and {2 * m_out} elements along a quarter great circle)",
                      level, SEAT_B * math.pi / 4 / m_out, smoothed)
    mesh = Mesh(3)

    def direction(a, j, k, m):  # the unit vector of patch a (normal to x_a = 1) at grid point (j, k)
        t = lambda i: 1.0 if i == m else math.tan(0.25 * math.pi * i / m)
        v = [0.0, 0.0, 0.0]
        v[a], v[(a + 1) % 3], v[(a + 2) % 3] = 1.0, t(j), t(k)
        n = math.sqrt(sum(c * c for c in v))
        return [c / n for c in v]

    def cube_face(a, j, k, m, side):
        v = [0.0, 0.0, 0.0]
        v[a], v[(a + 1) % 3], v[(a + 2) % 3] = side, side * j / m, side * k / m
        return v

    hexa = lambda f, i, j, k: [f(i, j, k), f(i, j + 1, k), f(i, j + 1, k + 1), f(i, j, k + 1),
                               f(i + 1, j, k), f(i + 1, j + 1, k), f(i + 1, j + 1, k + 1), f(i + 1, j, k + 1)]
    # ball: core cube, then the layers from its outer faces to the sphere
    side = 0.4 * b_in
    core = lambda i, j, k: mesh.node((side * i / m_in, side * j / m_in, side * k / m_in), 1, 1)
    for i in range(m_in):
        for j in range(m_in):
            for k in range(m_in):
                mesh.element(1, 1, [core(i, j, k), core(i + 1, j, k), core(i + 1, j + 1, k), core(i, j + 1, k),
                                    core(i, j, k + 1), core(i + 1, j, k + 1), core(i + 1, j + 1, k + 1), core(i, j + 1, k + 1)])
    for a in range(3):
        def ball(i, j, k, a=a):
            p0, p1 = cube_face(a, j, k, m_in, side), [b_in * c for c in direction(a, j, k, m_in)]
            return mesh.node(tuple(u + (v - u) * i / nr_in for u, v in zip(p0, p1)), 1, 1)
        for i in range(nr_in):
            for j in range(m_in):
                for k in range(m_in):
                    mesh.element(1, 1, hexa(ball, i, j, k))
        def socket(i, j, k, a=a):
            r = SEAT_B + (SEAT_C - SEAT_B) * i / nr_out
            return mesh.node(tuple(r * c for c in direction(a, j, k, m_out)), 2, 1000001)
        for i in range(nr_out):
            for j in range(m_out):
                for k in range(m_out):
                    mesh.element(2, 1000001, hexa(socket, i, j, k))
    on_ball = lambda x: abs(math.sqrt(sum(c * c for c in x)) - b_in) < 1e-9
    on_socket = lambda x: abs(math.sqrt(sum(c * c for c in x)) - SEAT_B) < 1e-9
    sets = surface_lines(mesh, 1, "BALL_S", on_ball) + surface_lines(mesh, 2, "SOCKET_S", on_socket)
    for i, name in enumerate("XYZ"):
        sets += [f"*NSET, NSET={name}SYM"] + lines_of(mesh.nodes_where(None, lambda x, i=i: x[i] == 0.0))
    sets += ["*NSET, NSET=BALL_EQUATOR"] + lines_of(mesh.nodes_where(1, lambda x: x[1] == 0.0))
    sets += ["*NSET, NSET=SOCKET_EQUATOR"] + lines_of(mesh.nodes_where(2, lambda x: x[1] == 0.0))
    return smoothing_deck(out, smoothed, mesh, "C3D8", [(1, "BALL"), (2, "SOCKET")], "SOCKET_S", "BALL_S",
                          "SPHERICAL, 0., 0., 0.", ["XSYM, 1", "YSYM, 2", "ZSYM, 3"], sets)


def oring_axi(level, smoothed=False):
    """An O-ring in a toroidal sleeve, axisymmetric (CAX4): the ring's solid circular cross-section
    of radius ρ + δ about (R, 0) in a sleeve of annular cross-section ρ … ρ_out about the same
    centre, half the cross-section (y ≥ 0, U2 = 0 on y = 0). The idealised surfaces are circles
    about (R, 0) in the r–z plane: the section of the torus TOROIDAL, axis (0,0,0)–(0,1,0), R.
    Ring: two butterfly quarters, n_in elements along the half arc; sleeve: n_out (non-matching).
    Slave: the sleeve's inner surface; master: the ring's. No closed form (the hoop stiffness
    varies around the cross-section): the reference is the same deck on a finer mesh."""
    scale = 2 ** (level - 1)
    n_in, n_out, nr_in, nr_out = 48 * scale, 68 * scale, 4 * scale, 8 * scale
    rho_in = TORUS_RHO + TORUS_DELTA
    out = header(f"O-ring in a toroidal sleeve: tube centre at R = {TORUS_R:g} from the axis, ring cross-section "
                 f"radius {rho_in:g}, sleeve {TORUS_RHO:g} ... {TORUS_RHO_OUT:g} (radial interference delta = "
                 f"{TORUS_DELTA:g}), axisymmetric, half cross-section, non-matching meshes ({n_in} and {n_out} "
                 "elements along the half arc)",
                 "Reference: no closed form; the same deck at a finer level (gen_contact_verification.py --level).",
                 level, TORUS_RHO * math.pi / n_out)
    if smoothed:
        out[1:1] = ["** Smoothed: ring and sleeve corrected toward the torus about the y axis, R = "
                    f"{TORUS_R:g} ([AX] 38.1.3)."]
    mesh = Mesh(2)
    centre = (TORUS_R, 0.0)
    quarter_disk(mesh, 1, 1, 1, centre, rho_in, 0.0, n_in // 2, nr_in)
    quarter_disk(mesh, 1, 1, 1, centre, rho_in, 0.5 * math.pi, n_in // 2, nr_in)
    annulus(mesh, 2, 100001, 100001, centre, TORUS_RHO, TORUS_RHO_OUT, 0.0, math.pi, n_out, nr_out)
    dist = lambda x: math.hypot(x[0] - TORUS_R, x[1])
    sets = surface_lines(mesh, 1, "RING_S", lambda x: abs(dist(x) - rho_in) < 1e-9)
    sets += surface_lines(mesh, 2, "SLEEVE_S", lambda x: abs(dist(x) - TORUS_RHO) < 1e-9)
    sets += ["*NSET, NSET=RING_PLANE"] + lines_of(mesh.nodes_where(1, lambda x: x[1] == 0.0))
    sets += ["*NSET, NSET=SLEEVE_PLANE"] + lines_of(mesh.nodes_where(2, lambda x: x[1] == 0.0))
    return smoothing_deck(out, smoothed, mesh, "CAX4", [(1, "RING"), (2, "SLEEVE")], "SLEEVE_S", "RING_S",
                          f"TOROIDAL, 0., 0., 0., 0., 1., 0., {TORUS_R:g}", ["RING_PLANE, 2", "SLEEVE_PLANE, 2"], sets)


DECKS = {"hertz_2d": hertz_2d, "hertz_2d_nonmatching": lambda level: hertz_2d(level, 1.25),
         "hertz_2d_force": hertz_2d_force,
         "hertz_2d_rigid": hertz_2d_rigid, "hertz_2d_analytical": lambda level: hertz_2d_rigid(level, True),
         "hertz_cylinder_3d": hertz_cylinder_3d,
         "sphere_3d": sphere_3d, "sphere_3d_force": sphere_3d_force, "sphere_3d_analytical": sphere_3d_analytical,
         "interference_2d": interference_2d,
         "interference_2d_smoothed": lambda level: interference_2d(level, smoothed=True),
         "interference_2d_general": lambda level: interference_2d(level, smoothed=True, general=True),
         "spherical_seat_axi": spherical_seat_axi,
         "spherical_seat_axi_smoothed": lambda level: spherical_seat_axi(level, smoothed=True),
         "spherical_seat_3d": spherical_seat_3d,
         "spherical_seat_3d_smoothed": lambda level: spherical_seat_3d(level, smoothed=True),
         "oring_axi": oring_axi,
         "oring_axi_smoothed": lambda level: oring_axi(level, smoothed=True)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=HERE, help="folder to write into (default: this one)")
    ap.add_argument("--level", type=int, default=1, help="mesh level (1: the committed, coarse decks)")
    ap.add_argument("decks", nargs="*", default=sorted(DECKS), help="which decks (default: all)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name in args.decks:
        suffix = "" if args.level == 1 else f"_l{args.level}"
        with open(os.path.join(args.out, f"{name}{suffix}.inp"), "w") as f:
            f.write("\n".join(DECKS[name](args.level)) + "\n")


if __name__ == "__main__":
    main()
