#!/usr/bin/env python3
"""Generator of decks/pin_in_hole.inp: the pin insertion model of [AX] 38.1.3 (Figure 38.1.31).

    gen_pin_in_hole.py                                  # the committed deck (level 1, smoothed), here
    gen_pin_in_hole.py --out DIR --level 2 --faceted    # a finer mesh without smoothing, into DIR

A C3D8 pin (cylindrical body, hemispherical tip) is pushed by a prescribed displacement into the
hole of a hub (a thick ring). The hole is cylindrical with a shallow conical entry (a lead-in
chamfer) and smaller than the pin by a radial interference DELTA: the tip slides down the chamfer,
and the pin body ends up press-fitted, sliding with friction, over 2.5 mm of the hole below it.
Quarter model (Y = 0 and Z = 0 are symmetry planes). The axis is the global X axis, so that
Abaqus's first contact tangent (the projection of X onto the surface) is axial on the pin and the
hole: CSHEAR1 and CSLIP1 are the axial friction stress and slip. The pin moves in -X.

  - General contact: *CONTACT, *CONTACT INCLUSIONS `PIN, HOLE`, *CONTACT PROPERTY ASSIGNMENT of
    an interaction with *FRICTION. Penalty, general contact's default (*SURFACE BEHAVIOR, <method>).
  - Smoothing ([AX] 38.1.3, its pin-in-hole example): *SURFACE PROPERTY ASSIGNMENT,
    PROPERTY=GEOMETRIC CORRECTION: PIN_TIP SPHERICAL about the tip's centre, PIN_BODY and HOLE
    CIRCUMFERENTIAL about the X axis (the hole's line covers its cone and its cylinder). PIN_TIP
    and PIN_BODY are regions of the contact surface PIN. --faceted leaves the block out.
  - *PARAMETERs: mu (0.1), method (PENALTY), push (the travel), dt (the largest increment).

Mesh: the pin's quarter cross-section is an O-grid (a core square of NC x NC elements and a ring
of 2 NC elements around), the tip an octant of a ball meshed as a core cube and three shell
blocks (an equiangular cubed sphere, so that its equator matches the body's ring). The hub is a
structured ring of NH elements around (non-matching with the pin's 2 NC), graded across.
  level 1: NC = 2 (4 pin facets per quarter), NH = 6, axial element length 1.0 (the deck);
  level 2: NC = 3, NH = 8, 0.75;   level 3: NC = 4, NH = 11, 0.5.
Without smoothing the coarse meshes lose the fit: on level 1 the chords of the pin (sag 0.096 mm)
lie on average 0.010 mm inside those of the hole (sag 0.043 mm), more than DELTA = 0.025 mm takes
back, and surface to surface contact averages the gap over the facets: the pin slides in freely.

Estimate (same material, E, nu; open-ended Lame, i.e. plane stress, solid shaft in a hub):
  p = E delta (c^2 - b^2) / (2 b c^2),  b = hole radius, c = hub outer radius;
and the sliding push force of the quarter model mu p (pi b / 2) L, L the engaged length. Both are
lower bounds here: the engagement is short (L / b ~ 0.6) and the unloaded parts of the pin and
the hub around it stiffen the fitted section.
The figures and tolerances are in tests/contact_verification/test_pin_in_hole.cpp.

Pure standard-library Python.
"""
import argparse
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# Units: N, mm, MPa. Steel.
E, NU = 210000.0, 0.3
B = 5.0          # hole radius (cylindrical part); the local axis w is the deck's X
DELTA = 0.025    # radial interference: pin radius B + DELTA
C = 10.0         # hub outer radius
T = 7.5          # hub length: its top at w = 0, its end at w = -T (the hole goes through; the tip comes out)
CHAMFER = 1.5    # depth of the conical entry
TAN_CONE = 0.08  # its slope dr/dz (4.6 deg; shallow enough that the tip sphere meets it tangentially)
L_BODY = 8.0     # pin body length behind the tip's equator
Z0 = -0.75       # the tip centre (the equator) at the start: in the chamfer, 0.24 above where the tip sphere touches it
PUSH = 3.25      # prescribed travel of the pin's top: the equator ends at -4, 2.5 below the chamfer
MU = 0.1
DT = 0.25        # the step's (largest) increment

LEVELS = {1: dict(nc=2, nl=1, nh=6, nr=3, dz=1.0), 2: dict(nc=3, nl=2, nh=8, nr=3, dz=0.75),
          3: dict(nc=4, nl=2, nh=11, nr=4, dz=0.5)}


def lame_pressure():
    return E * DELTA * (C * C - B * B) / (2.0 * B * C * C)


class Mesh:
    """Nodes deduplicated by position; C3D8 elements oriented to a positive volume."""

    def __init__(self, first_node):
        self.nodes = {}   # rounded position -> label
        self.xyz = {}     # label -> position
        self.next = first_node
        self.elems = []   # (label, 8 node labels)

    def node(self, p):
        key = tuple(round(v, 9) + 0.0 for v in p)
        if key not in self.nodes:
            self.nodes[key] = self.next
            self.xyz[self.next] = p
            self.next += 1
        return self.nodes[key]

    def block(self, f, na, nb, nc, first_elem):
        """Maps the unit cube through f(a, b, c) and adds its na x nb x nc hexahedra."""
        ids = {}
        for k in range(nc + 1):
            for j in range(nb + 1):
                for i in range(na + 1):
                    ids[i, j, k] = self.node(f(i / na, j / nb, k / nc))
        label = first_elem
        for k in range(nc):
            for j in range(nb):
                for i in range(na):
                    e = [ids[i, j, k], ids[i + 1, j, k], ids[i + 1, j + 1, k], ids[i, j + 1, k],
                         ids[i, j, k + 1], ids[i + 1, j, k + 1], ids[i + 1, j + 1, k + 1], ids[i, j + 1, k + 1]]
                    if volume_sign(self.xyz, e) < 0:
                        e = e[4:] + e[:4]
                    self.elems.append((label, e))
                    label += 1
        return label


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def volume_sign(xyz, e):
    p = [xyz[n] for n in e]
    c0 = [sum(p[i][d] for i in (0, 1, 2, 3)) / 4 for d in range(3)]
    c1 = [sum(p[i][d] for i in (4, 5, 6, 7)) / 4 for d in range(3)]
    a = sub([(p[1][d] + p[2][d]) / 2 for d in range(3)], [(p[0][d] + p[3][d]) / 2 for d in range(3)])
    b = sub([(p[2][d] + p[3][d]) / 2 for d in range(3)], [(p[0][d] + p[1][d]) / 2 for d in range(3)])
    c = sub(c1, c0)
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]))


# C3D8 faces (Abaqus numbering) by local node positions.
FACES = {1: (0, 1, 2, 3), 2: (4, 7, 6, 5), 3: (0, 4, 5, 1), 4: (1, 5, 6, 2), 5: (2, 6, 7, 3), 6: (3, 7, 4, 0)}


def faces_where(mesh, elems, pred):
    """(element label, face number) of every face whose four nodes satisfy pred(x, y, z)."""
    out = []
    for label, e in elems:
        for fnum, loc in FACES.items():
            if all(pred(*mesh.xyz[e[i]]) for i in loc):
                out.append((label, fnum))
    return out


def lerp(p, q, t):
    return [p[i] + (q[i] - p[i]) * t for i in range(3)]


def pin(level, mesh):
    """The pin: tip octant (centre (0, 0, Z0), z <= Z0) and the body above it."""
    L = LEVELS[level]
    nc, nl = L["nc"], L["nl"]
    R = B + DELTA
    c = 0.45 * R  # the core's half-size

    def sphere_dir(d):
        n = math.sqrt(sum(v * v for v in d))
        return [R * v / n for v in d]

    def t4(u):
        return math.tan(0.25 * math.pi * u)

    zc = Z0
    first = 1
    # core cube [0, c]^2 x [-c, 0] (relative to the centre)
    first = mesh.block(lambda a, b, s: [c * a, c * b, zc - c * s], nc, nc, nc, first)
    # shell block behind the cube face x = c: (u, v) on the face, t outward
    first = mesh.block(lambda u, v, t: lerp([c, c * u, zc - c * v],
                                            [p + q for p, q in zip(sphere_dir([1.0, t4(u), -t4(v)]), [0, 0, zc])], t),
                       nc, nc, nl, first)
    first = mesh.block(lambda u, v, t: lerp([c * u, c, zc - c * v],
                                            [p + q for p, q in zip(sphere_dir([t4(u), 1.0, -t4(v)]), [0, 0, zc])], t),
                       nc, nc, nl, first)
    first = mesh.block(lambda u, v, t: lerp([c * u, c * v, zc - c],
                                            [p + q for p, q in zip(sphere_dir([t4(u), t4(v), -1.0]), [0, 0, zc])], t),
                       nc, nc, nl, first)
    tip_last = first
    # body: the equator's cross-section (core square + ring) extruded to zc + L_BODY, in layers of
    # dz over the length that ends up below the hub's top, coarser above
    fine = PUSH - Z0
    n_fine = max(2, int(round(fine / L["dz"])))
    n_coarse = max(1, int(round((L_BODY - fine) / (3 * L["dz"]))))
    zs = [fine * k / n_fine for k in range(n_fine + 1)] + [fine + (L_BODY - fine) * k / n_coarse for k in range(1, n_coarse + 1)]
    nz = len(zs) - 1

    def z_at(s):
        return zc + zs[int(round(s * nz))]

    first = mesh.block(lambda a, b, s: [c * a, c * b, z_at(s)], nc, nc, nz, first)

    def ring(u_to_xy):
        return lambda u, t, s: [*(lambda sq, arc: [sq[0] + (arc[0] - sq[0]) * t, sq[1] + (arc[1] - sq[1]) * t])(*u_to_xy(u)),
                                z_at(s)]

    first = mesh.block(ring(lambda u: ((c, c * u), (R * math.cos(0.25 * math.pi * u), R * math.sin(0.25 * math.pi * u)))),
                       nc, nl, nz, first)
    first = mesh.block(ring(lambda u: ((c * u, c), (R * math.sin(0.25 * math.pi * u), R * math.cos(0.25 * math.pi * u)))),
                       nc, nl, nz, first)
    return tip_last, first


def hub(level, mesh, first_elem):
    L = LEVELS[level]
    nh, nr = L["nh"], L["nr"]
    # z levels from the bottom (-T) up to the top (0): the cylinder, then the chamfer
    n_cyl = max(2, int(round((T - CHAMFER) / L["dz"])))
    n_cham = max(1, int(round(CHAMFER / L["dz"])))

    def r_in(z):
        return B + TAN_CONE * (z + CHAMFER) if z > -CHAMFER else B

    ratio = 1.35  # radial grading: finer at the hole

    def radial(t, rin):
        w = (ratio ** (t * nr) - 1.0) / (ratio ** nr - 1.0)
        return rin + (C - rin) * w

    def z_of(s):  # s in [0, 1] over n_cyl + n_cham layers
        k = s * (n_cyl + n_cham)
        if k <= n_cyl + 1e-12:
            return -T + (T - CHAMFER) * k / n_cyl
        return -CHAMFER + CHAMFER * (k - n_cyl) / n_cham

    def f(t, a, s):
        z = z_of(s)
        rr = radial(t, r_in(z))
        th = 0.5 * math.pi * a
        x, y = rr * math.cos(th), rr * math.sin(th)
        if a == 1.0:
            x = 0.0
        if a == 0.0:
            y = 0.0
        return [x, y, z]

    return mesh.block(f, nr, nh, n_cyl + n_cham, first_elem)


def lines_of(labels, per=16):
    labels = sorted(set(labels))
    return [", ".join(str(n) for n in labels[i:i + per]) for i in range(0, len(labels), per)]


def surface(name, faces, prefix):
    """*SURFACE from (element, face) pairs, through one element set per face number."""
    out, data = [], []
    for fnum in sorted({f for _, f in faces}):
        elset = f"{prefix}_S{fnum}"
        out += [f"*ELSET, ELSET={elset}"] + lines_of([e for e, f in faces if f == fnum])
        data.append(f"{elset}, S{fnum}")
    return out, [f"*SURFACE, NAME={name}"] + data


def to_global(p):
    """The mesh is built about the local w axis (u, v across it); the deck's axis is the global X
    axis: (X, Y, Z) = (w, u, v), a rotation. Abaqus's first contact tangent t1 is the projection of
    the global X axis onto the surface, so along the pin and the hole CSHEAR1 and CSLIP1 are the
    axial friction stress and slip."""
    return (p[2], p[0], p[1])


def deck(level, smoothed=True):
    L = LEVELS[level]
    R = B + DELTA
    pm = Mesh(1)
    pin(level, pm)
    hm = Mesh(100001)
    hub(level, hm, 100001)
    tol = 1e-7
    tip_faces = faces_where(pm, pm.elems, lambda u, v, w: w <= Z0 + tol and abs(math.sqrt(u * u + v * v + (w - Z0) ** 2) - R) < 1e-6)
    body_faces = faces_where(pm, pm.elems, lambda u, v, w: w >= Z0 - tol and abs(math.hypot(u, v) - R) < 1e-6)

    def on_hole(u, v, w):
        rin = B + TAN_CONE * (w + CHAMFER) if w > -CHAMFER else B
        return abs(math.hypot(u, v) - rin) < 1e-6

    hole_faces = faces_where(hm, hm.elems, on_hole)
    out = ["*HEADING",
           f" Pin in hole ([AX] 38.1.3, Fig. 38.1.31): a C3D8 pin with a hemispherical tip pushed {PUSH:g} mm into a hub "
           f"with a radial interference of {DELTA:g} mm; general contact with friction, "
           + ("smoothed (SPHERICAL tip, CIRCUMFERENTIAL body and hole)" if smoothed else "faceted (no smoothing)"),
           f"** Quarter model (symmetry planes Y = 0 and Z = 0), axis X, the pin moves in -X. Pin radius {R:g} "
           f"({2 * L['nc']} facets per quarter), hole radius {B:g} ({L['nh']} facets)",
           f"** with a conical entry {CHAMFER:g} deep (slope {TAN_CONE:g}); hub outer radius {C:g}, X from {-T:g} to 0 "
           f"(its end X = {-T:g} held in X). Mesh level {level}. Units N, mm, MPa.",
           f"** Estimate (open-ended Lame, same material): p = E delta (c^2-b^2)/(2 b c^2) = {lame_pressure():.6g} MPa; "
           "sliding push force of this quarter mu p (pi b/2) L_engaged.",
           "** Generated by decks/gen_pin_in_hole.py; figures and tolerances in tests/contact_verification/test_pin_in_hole.cpp.",
           "*PARAMETER",
           f"mu = {MU:g}",
           'method = "PENALTY"',
           f"push = {PUSH:g}",
           f"dt = {DT:g}",
           "*NODE, NSET=ALL"]
    for mesh in (pm, hm):
        out += [f"{n}, " + ", ".join(f"{c:.12g}" for c in to_global(p)) for n, p in sorted(mesh.xyz.items())]
    out += ["*ELEMENT, TYPE=C3D8, ELSET=PIN"] + [f"{lab}, " + ", ".join(map(str, e)) for lab, e in pm.elems]
    out += ["*ELEMENT, TYPE=C3D8, ELSET=HUB"] + [f"{lab}, " + ", ".join(map(str, e)) for lab, e in hm.elems]
    sets = []
    for name, faces, prefix in (("PIN_TIP", tip_faces, "TIP"), ("PIN_BODY", body_faces, "BODY"), ("HOLE", hole_faces, "HOLE")):
        elsets, surf = surface(name, faces, prefix)
        out += elsets
        sets.append(surf)
    # PIN, the pin's contact surface: the faces of the tip and of the body (PIN_TIP and PIN_BODY
    # are its regions, each with its own smoothing)
    sets.insert(0, ["*SURFACE, NAME=PIN"] + sets[0][1:] + sets[1][1:])
    out += [line for s in sets for line in s]
    both = list(pm.xyz.items()) + list(hm.xyz.items())
    out += ["*NSET, NSET=PIN_TOP"] + lines_of([n for n, p in pm.xyz.items() if abs(p[2] - (Z0 + L_BODY)) < tol])
    out += ["*NSET, NSET=HUB_END"] + lines_of([n for n, p in hm.xyz.items() if abs(p[2] + T) < tol])
    out += ["*NSET, NSET=YSYM"] + lines_of([n for n, p in both if abs(p[0]) < tol])
    out += ["*NSET, NSET=ZSYM"] + lines_of([n for n, p in both if abs(p[1]) < tol])
    out += ["*SOLID SECTION, ELSET=PIN, MATERIAL=STEEL", "*SOLID SECTION, ELSET=HUB, MATERIAL=STEEL",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]
    out += ["*SURFACE INTERACTION, NAME=FRICTION1", "*SURFACE BEHAVIOR, <method>", "*FRICTION", "<mu>",
            "*CONTACT", "*CONTACT INCLUSIONS", "PIN, HOLE", "*CONTACT PROPERTY ASSIGNMENT", ", , FRICTION1"]
    if smoothed:
        out += ["*SURFACE PROPERTY ASSIGNMENT, PROPERTY=GEOMETRIC CORRECTION",
                f"PIN_TIP, SPHERICAL, {Z0:g}, 0., 0.",
                "PIN_BODY, CIRCUMFERENTIAL, 0., 0., 0., 1., 0., 0.",
                "HOLE, CIRCUMFERENTIAL, 0., 0., 0., 1., 0., 0."]
    out += ["*BOUNDARY", "YSYM, 2", "ZSYM, 3", "HUB_END, 1"]
    out += ["*STEP, NAME=INSERT", "*STATIC", "<dt>, 1.0, 1e-5, <dt>",
            "*BOUNDARY", "PIN_TOP, 1, 1, -<push>",
            "*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S",
            "*CONTACT OUTPUT", "CPRESS, COPEN, CSHEAR1, CSLIP1, CSTATUS, CNAREA",
            "*END STEP"]
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=HERE, help="folder to write into (default: this one)")
    ap.add_argument("--level", type=int, default=1, choices=sorted(LEVELS), help="mesh level (1: the committed deck)")
    ap.add_argument("--faceted", action="store_true", help="no *SURFACE PROPERTY ASSIGNMENT (no smoothing)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    name = "pin_in_hole" + ("_faceted" if args.faceted else "") + ("" if args.level == 1 else f"_l{args.level}")
    with open(os.path.join(args.out, name + ".inp"), "w") as f:
        f.write("\n".join(deck(args.level, not args.faceted)) + "\n")


if __name__ == "__main__":
    main()
