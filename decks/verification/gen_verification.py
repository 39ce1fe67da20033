#!/usr/bin/env python3
"""Generator of the solid-mechanics verification decks (decks/verification/).

Each deck states its analytic reference and tolerance in its header; the GoogleTests in
tests/verification/ read the committed decks and, for the convergence studies, regenerate the
finer meshes into the build tree at test time:

    gen_verification.py --out DIR                  # every committed deck
    gen_verification.py --out DIR --cantilever C3D20R 8 2 2   # one cantilever mesh level

Pure standard-library Python (no numpy), so it runs wherever python3 does.
"""
import argparse
import math
import os

# --------------------------------------------------------------------------- deck writing


class Deck:
    def __init__(self, heading, comments):
        self.lines = ["*HEADING", " " + heading]
        self.lines += ["** " + c for c in comments]

    def add(self, *lines):
        self.lines.extend(lines)

    def nodes(self, coords, dim, nset="ALL"):
        self.add(f"*NODE, NSET={nset}")
        for label in sorted(coords):
            x = coords[label]
            self.add(f"{label}, " + ", ".join(f"{v:.15g}" for v in x[:dim]))

    def elements(self, etype, elset, conn, first=1):
        self.add(f"*ELEMENT, TYPE={etype}, ELSET={elset}")
        for i, c in enumerate(conn):
            vals = [str(first + i)] + [str(n) for n in c]
            # at most 16 entries per line; continuation lines for C3D20
            line = ", ".join(vals[:16])
            if len(vals) > 16:
                self.add(line + ",")
                self.add(", ".join(vals[16:]))
            else:
                self.add(line)

    def nset(self, name, labels):
        labels = sorted(set(labels))
        self.add(f"*NSET, NSET={name}")
        for i in range(0, len(labels), 16):
            self.add(", ".join(str(n) for n in labels[i:i + 16]))

    def elset(self, name, labels):
        labels = sorted(set(labels))
        self.add(f"*ELSET, ELSET={name}")
        for i in range(0, len(labels), 16):
            self.add(", ".join(str(n) for n in labels[i:i + 16]))

    def write(self, path):
        with open(path, "w") as f:
            f.write("\n".join(self.lines) + "\n")


OUTPUT = ["*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S, E"]

# --------------------------------------------------------------------------- structured meshes


def grid_hex(nx, ny, nz, x0, x1, quadratic):
    """Structured brick mesh on the box x0..x1 (3-tuples). Returns coords {label: (x,y,z)},
    connectivity (Abaqus C3D8 / C3D20 order) and the grid index -> label function."""
    m = 2 if quadratic else 1
    NX, NY, NZ = m * nx + 1, m * ny + 1, m * nz + 1

    def lab(i, j, k):
        return 1 + i + NX * (j + NY * k)

    def xyz(i, j, k):
        return tuple(x0[d] + (x1[d] - x0[d]) * (ijk / (m * n))
                     for d, ijk, n in zip(range(3), (i, j, k), (nx, ny, nz)))

    conn = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                I, J, K = m * i, m * j, m * k
                c = [(I, J, K), (I + m, J, K), (I + m, J + m, K), (I, J + m, K),
                     (I, J, K + m), (I + m, J, K + m), (I + m, J + m, K + m), (I, J + m, K + m)]
                nodes = [lab(*p) for p in c]
                if quadratic:
                    def mid(a, b):
                        return lab(*[(c[a][d] + c[b][d]) // 2 for d in range(3)])
                    nodes += [mid(0, 1), mid(1, 2), mid(2, 3), mid(3, 0), mid(4, 5), mid(5, 6), mid(6, 7),
                              mid(7, 4), mid(0, 4), mid(1, 5), mid(2, 6), mid(3, 7)]
                conn.append(nodes)
    used = {n for c in conn for n in c}
    coords = {}
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                if lab(i, j, k) in used:
                    coords[lab(i, j, k)] = xyz(i, j, k)
    return coords, conn


def grid_tet10(nx, ny, nz, x0, x1):
    """Each brick of a structured grid split into 6 tetrahedra along its 0-7 diagonal (a
    conforming Kuhn split), with midside nodes: C3D10 in Abaqus order."""
    NX, NY, NZ = 2 * nx + 1, 2 * ny + 1, 2 * nz + 1

    def lab(p):
        return 1 + p[0] + NX * (p[1] + NY * p[2])

    def xyz(p):
        return tuple(x0[d] + (x1[d] - x0[d]) * p[d] / (2 * n) for d, n in zip(range(3), (nx, ny, nz)))

    perms = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    conn = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                base = (2 * i, 2 * j, 2 * k)
                for perm in perms:
                    path = [list(base)]
                    cur = list(base)
                    for axis in perm:
                        cur = cur.copy()
                        cur[axis] += 2
                        path.append(cur)
                    a, b, c, d = [tuple(p) for p in path]
                    # orientation: (b-a)x(c-a).(d-a) > 0 (face 1-2-3 turns into the element)
                    A, B, C, D = (xyz(p) for p in (a, b, c, d))
                    u = [B[t] - A[t] for t in range(3)]
                    v = [C[t] - A[t] for t in range(3)]
                    w = [D[t] - A[t] for t in range(3)]
                    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                           u[2] * (v[0] * w[1] - v[1] * w[0]))
                    if det < 0:
                        b, c = c, b

                    def mid(p, q):
                        return tuple((p[t] + q[t]) // 2 for t in range(3))
                    pts = [a, b, c, d, mid(a, b), mid(b, c), mid(c, a), mid(a, d), mid(b, d), mid(c, d)]
                    conn.append([lab(p) for p in pts])
    used = {n for c in conn for n in c}
    coords = {}
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                p = (i, j, k)
                if lab(p) in used:
                    coords[lab(p)] = xyz(p)
    return coords, conn


def grid_quad(n1, n2, mapping, quadratic):
    """Structured quadrilateral mesh of the unit square mapped by mapping(s, t) -> (x, y).
    Corner order (s0,t0), (s1,t0), (s1,t1), (s0,t1); edge S4 lies on s = 0."""
    m = 2 if quadratic else 1
    N1, N2 = m * n1 + 1, m * n2 + 1

    def lab(i, j):
        return 1 + i + N1 * j

    conn = []
    for j in range(n2):
        for i in range(n1):
            I, J = m * i, m * j
            c = [(I, J), (I + m, J), (I + m, J + m), (I, J + m)]
            nodes = [lab(*p) for p in c]
            if quadratic:
                nodes += [lab(I + 1, J), lab(I + 2, J + 1), lab(I + 1, J + 2), lab(I, J + 1)]
            conn.append(nodes)
    used = {n for c in conn for n in c}
    coords = {}
    for j in range(N2):
        for i in range(N1):
            if lab(i, j) in used:
                x, y = mapping(i / (N1 - 1), j / (N2 - 1))
                coords[lab(i, j)] = (x, y, 0.0)
    return coords, conn


def select(coords, pred):
    return [n for n, x in coords.items() if pred(x)]


# --------------------------------------------------------------------------- quadrature

G4 = [(-0.8611363115940526, 0.3478548451374538), (-0.3399810435848563, 0.6521451548625461),
      (0.3399810435848563, 0.6521451548625461), (0.8611363115940526, 0.3478548451374538)]


def line_shape(n, xi):
    if n == 2:
        return [(1 - xi) / 2, (1 + xi) / 2]
    return [xi * (xi - 1) / 2, xi * (xi + 1) / 2, 1 - xi * xi]  # ends, then middle


def quad_shape(n, xi, eta):
    c = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    if n == 4:
        return [(1 + a * xi) * (1 + b * eta) / 4 for a, b in c]
    N = [(1 + a * xi) * (1 + b * eta) * (a * xi + b * eta - 1) / 4 for a, b in c]
    N += [(1 - xi * xi) * (1 - eta) / 2, (1 + xi) * (1 - eta * eta) / 2, (1 - xi * xi) * (1 + eta) / 2,
          (1 - xi) * (1 - eta * eta) / 2]
    return N


def tri_shape(n, L2, L3):
    L1 = 1 - L2 - L3
    L = [L1, L2, L3]
    if n == 3:
        return L
    return [L[0] * (2 * L[0] - 1), L[1] * (2 * L[1] - 1), L[2] * (2 * L[2] - 1), 4 * L[0] * L[1], 4 * L[1] * L[2],
            4 * L[2] * L[0]]


def consistent_face_loads(face_nodes, coords, traction, kind):
    """Consistent nodal forces ∫ N_i t(x) dA of a traction t(x) (scalar) on one planar face.
    kind: 'line' (2D edge, end nodes first then middle), 'quad', 'tri'. Face nodes: corners
    first, then midside nodes, in the usual order. Returns {node: force}."""
    out = {n: 0.0 for n in face_nodes}
    X = [coords[n] for n in face_nodes]
    if kind == "line":
        a, b = X[0], X[1]
        half = math.dist(a, b) / 2
        for xi, w in G4:
            N = line_shape(len(face_nodes), xi)
            p = [(a[d] * (1 - xi) + b[d] * (1 + xi)) / 2 for d in range(3)]
            for n, Ni in zip(face_nodes, N):
                out[n] += Ni * traction(p) * w * half
    elif kind == "quad":
        for xi, wx in G4:
            for eta, we in G4:
                N1 = quad_shape(4, xi, eta)
                p = [sum(N1[i] * X[i][d] for i in range(4)) for d in range(3)]
                # rectangle: |J| = area / 4
                dx = [(X[1][d] - X[0][d]) / 2 for d in range(3)]
                dy = [(X[3][d] - X[0][d]) / 2 for d in range(3)]
                cr = [dx[1] * dy[2] - dx[2] * dy[1], dx[2] * dy[0] - dx[0] * dy[2], dx[0] * dy[1] - dx[1] * dy[0]]
                J = math.sqrt(sum(v * v for v in cr))
                N = quad_shape(len(face_nodes), xi, eta)
                for n, Ni in zip(face_nodes, N):
                    out[n] += Ni * traction(p) * wx * we * J
    else:  # triangle, collapsed Gauss rule
        e1 = [X[1][d] - X[0][d] for d in range(3)]
        e2 = [X[2][d] - X[0][d] for d in range(3)]
        cr = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
        twice_area = math.sqrt(sum(v * v for v in cr))
        for gu, wu in G4:
            u = (gu + 1) / 2
            for gs, ws in G4:
                s = (gs + 1) / 2
                L2, L3 = u, (1 - u) * s
                w = wu * ws / 4 * (1 - u)
                p = [X[0][d] + L2 * e1[d] + L3 * e2[d] for d in range(3)]
                N = tri_shape(len(face_nodes), L2, L3)
                for n, Ni in zip(face_nodes, N):
                    out[n] += Ni * traction(p) * w * twice_area
    return out


# --------------------------------------------------------------------------- 1. cantilever

CANT = dict(L=8.0, c=0.5, b=1.0, E=1.0e5, P=10.0)


def cantilever_exact(x, y, nu, L=CANT["L"], c=CANT["c"], b=CANT["b"], E=CANT["E"], P=CANT["P"]):
    """Timoshenko & Goodier (Theory of Elasticity, 3rd ed., §21) plane-stress cantilever: load
    P (parabolic shear, +y) at x = 0, built in at x = L with u = v = 0 and ∂u/∂y = 0 at (L, 0)
    (the vertical element of the section fixed). v(0, 0) = PL³/(3EI) + PLc²/(2IG): Euler–
    Bernoulli plus the shear deflection 3PL/(2GA) of the centre line."""
    I = 2 * b * c ** 3 / 3
    G = E / (2 * (1 + nu))
    u = (-P * x * x * y / (2 * E * I) + P * L * L * y / (2 * E * I) - nu * P * y ** 3 / (6 * E * I) +
         P * y ** 3 / (6 * I * G))
    v = (nu * P * x * y * y / (2 * E * I) + P * x ** 3 / (6 * E * I) - (P * L * L / (2 * E * I) + P * c * c / (2 * I * G)) * x
         + P * L ** 3 / (3 * E * I) + P * L * c * c / (2 * I * G))
    return u, v


def cantilever_tip_deflection(nu):
    return cantilever_exact(0.0, 0.0, nu)[1]


def cantilever(etype, nx, ny, nz):
    L, c, b, E, P = CANT["L"], CANT["c"], CANT["b"], CANT["E"], CANT["P"]
    three_d = etype.startswith("C3D")
    nu = 0.0 if three_d else 0.3  # ν = 0 makes the plane-stress solution exact in 3D (w = 0)
    I = 2 * b * c ** 3 / 3

    def traction(p):
        return P * (c * c - p[1] ** 2) / (2 * I)

    eps = 1e-9
    if etype == "C3D10":
        coords, conn = grid_tet10(nx, ny, nz, (0, -c, 0), (L, c, b))
    elif three_d:
        coords, conn = grid_hex(nx, ny, nz, (0, -c, 0), (L, c, b), etype == "C3D20R" or etype == "C3D20")
    else:
        quadratic = etype[-2] == "8" or etype[-1] == "8"
        coords, conn = grid_quad(nx, ny, lambda s, t: (L * s, -c + 2 * c * t), quadratic)
    loads = {}
    # faces on x = 0
    if etype == "C3D10":
        for el in conn:
            for f in ((0, 1, 2, 4, 5, 6), (0, 1, 3, 4, 8, 7), (1, 2, 3, 5, 9, 8), (2, 0, 3, 6, 7, 9)):
                fn = [el[i] for i in f]
                if all(abs(coords[n][0]) < eps for n in fn):
                    for n, v in consistent_face_loads(fn, coords, traction, "tri").items():
                        loads[n] = loads.get(n, 0.0) + v
    elif three_d:
        for el in conn:
            # face x = x_min: corners 1, 4, 8, 5; midsides 12 (1-4), 20 (4-8), 16 (8-5), 17 (5-1)
            fn = [el[0], el[3], el[7], el[4]]
            if len(el) == 20:
                fn += [el[11], el[19], el[15], el[16]]
            if all(abs(coords[n][0]) < eps for n in fn):
                for n, v in consistent_face_loads(fn, coords, traction, "quad").items():
                    loads[n] = loads.get(n, 0.0) + v
    else:
        for el in conn:
            fn = [el[3], el[0]] + ([el[7]] if len(el) == 8 else [])
            if all(abs(coords[n][0]) < eps for n in fn):
                for n, v in consistent_face_loads(fn, coords, traction, "line").items():
                    loads[n] = loads.get(n, 0.0) + v * b
    total = sum(loads.values())
    assert abs(total - P) < 1e-12 * P, total
    tip = ("tip deflection v(0,0) = PL^3/(3EI) + PLc^2/(2IG) = "
           f"{cantilever_tip_deflection(nu):.12g}")
    d = Deck(f"Cantilever {etype} {nx}x{ny}x{nz}: Timoshenko-Goodier plane-stress solution",
             [f"L = {L}, depth 2c = {2 * c}, width b = {b}, E = {E}, nu = {nu}, P = {P} (parabolic shear at x = 0)",
              "Built-in end x = L: the exact displacements of Timoshenko & Goodier §21 prescribed on every node.",
              tip,
              "Tolerance: observed log-log rate of |error| over three meshes (tests/verification)."])
    d.nodes(coords, 3 if three_d else 2)
    d.elements(etype, "BEAM", conn)
    clamp = select(coords, lambda x: abs(x[0] - L) < eps)
    tipline = select(coords, lambda x: abs(x[0]) < eps and abs(x[1]) < eps)
    d.nset("CLAMP", clamp)
    d.nset("TIPLINE", tipline)
    d.add("*SOLID SECTION, ELSET=BEAM, MATERIAL=MAT")
    d.add(f"{b}" if not three_d else "")
    if three_d:
        d.lines.pop()
    d.add("*MATERIAL, NAME=MAT", "*ELASTIC", f"{E}, {nu}")
    d.add("*BOUNDARY")
    for n in sorted(clamp):
        x = coords[n]
        u, v = cantilever_exact(x[0], x[1], nu)
        d.add(f"{n}, 1, 1, {u:.17g}", f"{n}, 2, 2, {v:.17g}")
        if three_d:
            d.add(f"{n}, 3, 3, 0.")
    d.add("*STEP, NAME=LOAD", "*STATIC", "*CLOAD")
    for n in sorted(loads):
        if loads[n] != 0.0:
            d.add(f"{n}, 2, {loads[n]:.17g}")
    d.add(*OUTPUT, "*END STEP")
    return d


# --------------------------------------------------------------------------- 2. Lamé cylinder

LAME = dict(ri=10.0, ro=20.0, p=100.0, E=210000.0, nu=0.3)


def lame(etype, nr, nt):
    ri, ro, p, E, nu = LAME["ri"], LAME["ro"], LAME["p"], LAME["E"], LAME["nu"]
    quadratic = "8" in etype
    k = p * ri * ri / (ro * ro - ri * ri)
    if etype.startswith("CPS"):
        ur = k / E * ((1 - nu) * ri + (1 + nu) * ro * ro / ri)
        kind = "plane stress"
    else:
        ur = (1 + nu) * k / E * ((1 - 2 * nu) * ri + ro * ro / ri)
        kind = "plane strain" if etype.startswith("CPE") else \
            "axisymmetric, axial displacement held at both ends (= plane strain)"
    s_hoop = p * (ro * ro + ri * ri) / (ro * ro - ri * ri)
    eps = 1e-9
    if etype.startswith("CAX"):
        H = 2.0
        coords, conn = grid_quad(nr, nt, lambda s, t: (ri + (ro - ri) * s, H * t), quadratic)
        ends = select(coords, lambda x: abs(x[1]) < eps or abs(x[1] - H) < eps)
    else:
        coords, conn = grid_quad(nr, nt, lambda s, t: ((ri + (ro - ri) * s) * math.cos(math.pi / 2 * t),
                                                      (ri + (ro - ri) * s) * math.sin(math.pi / 2 * t)), quadratic)
    bore_el = [i + 1 for i, el in enumerate(conn) if all(abs(math.hypot(*coords[el[j]][:2]) - ri) < 1e-6 if not
                                                        etype.startswith("CAX") else abs(coords[el[j]][0] - ri) < eps
                                                        for j in (0, 3))]
    d = Deck(f"Lame thick cylinder under internal pressure, {kind}, {etype} {nr}x{nt}",
             [f"ri = {ri}, ro = {ro}, p = {p}, E = {E}, nu = {nu}",
              f"u_r(ri) = {ur:.12g}; sigma_theta(ri) = p (ro^2 + ri^2)/(ro^2 - ri^2) = {s_hoop:.12g}",
              "Tolerances in tests/verification/test_lame_cylinder.cpp."])
    d.nodes(coords, 2)
    d.elements(etype, "WALL", conn)
    d.elset("BORE_EL", bore_el)
    d.add("*SURFACE, NAME=BORE", "BORE_EL, S4")
    d.add("*SOLID SECTION, ELSET=WALL, MATERIAL=STEEL", "1.")
    d.add("*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {nu}")
    if etype.startswith("CAX"):
        d.nset("ENDS", ends)
        d.add("*BOUNDARY", "ENDS, 2, 2")
    else:
        d.nset("ON_X", select(coords, lambda x: abs(x[1]) < eps))
        d.nset("ON_Y", select(coords, lambda x: abs(x[0]) < eps))
        d.add("*BOUNDARY", "ON_X, YSYMM", "ON_Y, XSYMM")
    d.add("*STEP, NAME=PRESSURIZE", "*STATIC", "*DSLOAD", f"BORE, P, {p}", *OUTPUT, "*END STEP")
    return d


# --------------------------------------------------------------------------- 3. thermal

THERM = dict(E=200000.0, nu=0.3, alpha=1.2e-5, T0=20.0, T1=120.0)


def thermal_ring(etype, nr, nt):
    ri, ro = 10.0, 20.0
    E, nu, alpha, T0, T1 = (THERM[k] for k in ("E", "nu", "alpha", "T0", "T1"))
    quadratic = "8" in etype
    eps = 1e-9
    if etype.startswith("CAX"):
        H = 2.0
        coords, conn = grid_quad(nr, nt, lambda s, t: (ri + (ro - ri) * s, H * t), quadratic)
    else:
        coords, conn = grid_quad(nr, nt, lambda s, t: ((ri + (ro - ri) * s) * math.cos(math.pi / 2 * t),
                                                      (ri + (ro - ri) * s) * math.sin(math.pi / 2 * t)), quadratic)
    d = Deck(f"Free thermal expansion of a ring, {etype}",
             [f"ri = {ri}, ro = {ro}, E = {E}, nu = {nu}, alpha = {alpha}, T: {T0} -> {T1}",
              "Stress free, u_r = alpha dT r (and u_z = alpha dT z for the axisymmetric ring)."])
    d.nodes(coords, 2)
    d.elements(etype, "RING", conn)
    d.add("*SOLID SECTION, ELSET=RING, MATERIAL=MAT", "1.")
    d.add("*MATERIAL, NAME=MAT", "*ELASTIC", f"{E}, {nu}", "*EXPANSION", f"{alpha}")
    if etype.startswith("CAX"):
        d.nset("BOTTOM", select(coords, lambda x: abs(x[1]) < eps))
        d.add("*BOUNDARY", "BOTTOM, 2, 2")
    else:
        d.nset("ON_X", select(coords, lambda x: abs(x[1]) < eps))
        d.nset("ON_Y", select(coords, lambda x: abs(x[0]) < eps))
        d.add("*BOUNDARY", "ON_X, YSYMM", "ON_Y, XSYMM")
    d.add("*INITIAL CONDITIONS, TYPE=TEMPERATURE", f"ALL, {T0}")
    d.add("*STEP, NAME=HEAT", "*STATIC", "*TEMPERATURE", f"ALL, {T1}", *OUTPUT, "*END STEP")
    return d


def thermal_bar():
    E, nu, alpha, T0, T1 = (THERM[k] for k in ("E", "nu", "alpha", "T0", "T1"))
    L, a = 4.0, 1.0
    coords, conn = grid_hex(4, 2, 2, (0, 0, 0), (L, a, a), False)
    eps = 1e-9
    d = Deck("Bar held at both ends, heated: sigma_11 = -E alpha dT",
             [f"E = {E}, nu = {nu}, alpha = {alpha}, T: {T0} -> {T1}; quarter of a 2a x 2a bar (a = {a}),"
              " symmetry on y = 0 and z = 0, faces y = a and z = a free.",
              f"sigma_11 = -E alpha dT = {-E * alpha * (T1 - T0):.12g}, sigma_22 = sigma_33 = 0,"
              " u_2 = (1 + nu) alpha dT y; RF_1 on x = L: E alpha dT a^2."])
    d.nodes(coords, 3)
    d.elements("C3D8", "BAR", conn)
    d.nset("END0", select(coords, lambda x: abs(x[0]) < eps))
    d.nset("END1", select(coords, lambda x: abs(x[0] - L) < eps))
    d.nset("Y0", select(coords, lambda x: abs(x[1]) < eps))
    d.nset("Z0", select(coords, lambda x: abs(x[2]) < eps))
    d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=MAT", "*MATERIAL, NAME=MAT", "*ELASTIC", f"{E}, {nu}",
          "*EXPANSION", f"{alpha}")
    d.add("*BOUNDARY", "END0, 1, 1", "END1, 1, 1", "Y0, 2, 2", "Z0, 3, 3")
    d.add("*INITIAL CONDITIONS, TYPE=TEMPERATURE", f"ALL, {T0}")
    d.add("*STEP, NAME=HEAT", "*STATIC", "*TEMPERATURE", f"ALL, {T1}", *OUTPUT, "*END STEP")
    return d


# Temperature-dependent *ELASTIC and *EXPANSION: E, nu, alpha linear between the rows and held
# outside; eps_th = alpha(T)(T - ZERO) - alpha(Ti)(Ti - ZERO). Three steps of uniform T: inside
# the tables, above them, below them.
TABLE = dict(elastic=((200000.0, 0.30, 0.0), (150000.0, 0.32, 500.0), (100000.0, 0.35, 1000.0)),
             expansion=((1.0e-5, 0.0), (1.4e-5, 600.0), (2.0e-5, 1200.0)), zero=20.0, Ti=150.0,
             steps=(400.0, 1300.0, -100.0))


def thermal_table(etype, held):
    """A bar (C3D8), plate (CPS4, CPE4) or axisymmetric tube (CAX4) heated uniformly with the
    TABLE material: free (symmetry planes only), or held at both ends along its axis."""
    eps = 1e-9
    closed = {"C3D8": "S11 = -E eps_th, U2 = (1 + nu) eps_th y, U3 = (1 + nu) eps_th z",
              "CPS4": "S11 = -E eps_th, U2 = (1 + nu) eps_th y, E33 = (1 + nu) eps_th",
              "CPE4": "S11 = S33 = -E eps_th/(1 - nu), U2 = (1 + nu)/(1 - nu) eps_th y",
              "CAX4": "S22 (axial) = -E eps_th, U1 = (1 + nu) eps_th r"}[etype]
    d = Deck(f"{'Held' if held else 'Free'} {etype} {'bar' if etype != 'CAX4' else 'tube'} heated with "
             "temperature-dependent *ELASTIC and *EXPANSION",
             ["E, nu at T: " + ", ".join(f"({E:g}, {nu:g}) at {T:g}" for E, nu, T in TABLE["elastic"]) +
              "; alpha at T: " + ", ".join(f"{a:g} at {T:g}" for a, T in TABLE["expansion"]) +
              f", ZERO = {TABLE['zero']:g}; linear between rows, held outside.",
              f"Initial T = {TABLE['Ti']:g}; steps to T = " + ", ".join(f"{T:g}" for T in TABLE["steps"]) +
              ": eps_th = alpha(T)(T - ZERO) - alpha(Ti)(Ti - ZERO).",
              ("Held at both ends along the axis: " + closed) if held else
              "Free (symmetry planes only): stress free, U = eps_th x.",
              "Tolerances in tests/verification/test_thermal_tables.cpp."])
    if etype == "C3D8":
        L = 4.0
        coords, conn = bar_mesh(0.0, L, 4)
        c3d8_bar(d, coords, conn, L)
        d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=MAT")
        ends = "LEFT, 1, 1", "RIGHT, 1, 1"
        d.add("*BOUNDARY", *(ends if held else ends[:1]), "Y0, 2, 2", "Z0, 3, 3")
    elif etype == "CAX4":
        coords, conn = grid_quad(2, 4, lambda s, t: (1.0 + s, 4.0 * t), False)
        d.nodes(coords, 2)
        d.elements(etype, "BAR", conn)
        d.nset("BOTTOM", select(coords, lambda x: abs(x[1]) < eps))
        d.nset("TOP", select(coords, lambda x: abs(x[1] - 4.0) < eps))
        d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=MAT", "1.")
        d.add("*BOUNDARY", "BOTTOM, 2, 2", *(["TOP, 2, 2"] if held else []))
    else:
        coords, conn = grid_quad(4, 2, lambda s, t: (4.0 * s, t), False)
        d.nodes(coords, 2)
        d.elements(etype, "BAR", conn)
        d.nset("LEFT", select(coords, lambda x: abs(x[0]) < eps))
        d.nset("RIGHT", select(coords, lambda x: abs(x[0] - 4.0) < eps))
        d.nset("Y0", select(coords, lambda x: abs(x[1]) < eps))
        d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=MAT", "1.")
        d.add("*BOUNDARY", "LEFT, 1, 1", *(["RIGHT, 1, 1"] if held else []), "Y0, 2, 2")
    d.add("*MATERIAL, NAME=MAT", "*ELASTIC", *(f"{E:g}, {nu:g}, {T:g}" for E, nu, T in TABLE["elastic"]),
          f"*EXPANSION, ZERO={TABLE['zero']:g}", *(f"{a:g}, {T:g}" for a, T in TABLE["expansion"]))
    d.add("*INITIAL CONDITIONS, TYPE=TEMPERATURE", f"ALL, {TABLE['Ti']:g}")
    for k, T in enumerate(TABLE["steps"], 1):
        d.add(f"*STEP, NAME=T{k}", "*STATIC", "*TEMPERATURE", f"ALL, {T:g}", *OUTPUT, "*END STEP")
    return d


# --------------------------------------------------------------------------- 4. NLGEOM


def rigid_rotation(etype="C3D8", n=2, increments=10):
    """A cube rotated rigidly by 90° about z through boundary conditions on three nodes, with
    tabular amplitudes sampled exactly at the increment times (DIRECT incrementation)."""
    eps = 1e-9
    coords, conn = grid_hex(n, n, n, (0, 0, 0), (1, 1, 1), etype in ("C3D20", "C3D20R"))
    origin = select(coords, lambda x: max(abs(v) for v in x) < eps)
    xnode = select(coords, lambda x: abs(x[0] - 1) < eps and abs(x[1]) < eps and abs(x[2]) < eps)
    znode = select(coords, lambda x: abs(x[0]) < eps and abs(x[1]) < eps and abs(x[2] - 1) < eps)
    d = Deck(f"Rigid rotation of a cube by 90 degrees about z, NLGEOM, {etype}",
             ["Node (0,0,0) pinned; node (0,0,1) on the axis: u1 = u2 = 0; node (1,0,0): u1 = cos(a) - 1,",
              "u2 = sin(a), u3 = 0 with a = 90 deg * t. Every frame: U = (R - I) X and S = 0."])
    d.nodes(coords, 3)
    d.elements(etype, "CUBE", conn)
    d.nset("ORIGIN", origin)
    d.nset("XNODE", xnode)
    d.nset("ZNODE", znode)
    d.add("*SOLID SECTION, ELSET=CUBE, MATERIAL=MAT", "*MATERIAL, NAME=MAT", "*ELASTIC", "1000., 0.3")
    ts = [i / increments for i in range(increments + 1)]
    for name, f in (("COSM1", lambda a: math.cos(a) - 1), ("SIN", math.sin)):
        d.add(f"*AMPLITUDE, NAME={name}")
        for t in ts:
            d.add(f"{t:.17g}, {f(math.pi / 2 * t):.17g}")
    d.add("*BOUNDARY", "ORIGIN, 1, 3", "ZNODE, 1, 2", "XNODE, 3, 3")
    # Tight Newton tolerances (R_n = C_n = 1e-10 instead of Abaqus's 5e-3 and 1e-2): the check
    # is that the converged state is stress free to round-off, not to the default tolerance.
    d.add("*STEP, NAME=ROTATE, NLGEOM=YES, INC=50", "*CONTROLS, PARAMETERS=FIELD", "1e-10, 1e-10",
          "*STATIC, DIRECT", f"{1 / increments:.17g}, 1.")
    d.add("*BOUNDARY, AMPLITUDE=COSM1", "XNODE, 1, 1, 1.", "*BOUNDARY, AMPLITUDE=SIN", "XNODE, 2, 2, 1.")
    d.add(*OUTPUT, "*END STEP")
    return d


ELASTICA = dict(L=10.0, h=0.2, b=1.0, E=1.0e6)


def elastica(etype="CPE8R", nx=40, ny=2, alpha_max=3.0, inc=0.25):
    """Cantilever under a vertical dead tip load with NLGEOM: the Bisshopp–Drucker elastica.
    Step time t = PL²/(EI)."""
    L, h, b, E = (ELASTICA[k] for k in ("L", "h", "b", "E"))
    I = b * h ** 3 / 12
    eps = 1e-9
    coords, conn = grid_quad(nx, ny, lambda s, t: (L * s, -h / 2 + h * t), "8" in etype)
    P = E * I / L ** 2  # load at t = 1: PL²/EI = 1
    tip = select(coords, lambda x: abs(x[0] - L) < eps)
    # consistent loads of a uniform shear traction on the tip edge (sum = P)
    loads = {}
    for el in conn:
        fn = [el[1], el[2]] + ([el[5]] if len(el) == 8 else [])
        if all(abs(coords[n][0] - L) < eps for n in fn):
            for n, v in consistent_face_loads(fn, coords, lambda p: P / (h * b), "line").items():
                loads[n] = loads.get(n, 0.0) + v * b
    d = Deck(f"Large-deflection cantilever (elastica), NLGEOM, {etype} {nx}x{ny}",
             [f"L = {L}, h = {h}, b = {b}, E = {E}, nu = 0; vertical dead load at the tip, PL^2/EI = step time.",
              "Reference: Bisshopp & Drucker, Q. Appl. Math. 3 (1945) 272-275; values as tabulated by",
              "Mattiasson, IJNME 17 (1981) 145-153: PL^2/EI = 1: v/L = 0.30172, (L-x)/L = 0.05643;",
              "2: 0.49346, 0.16064; 3: 0.60325, 0.25442."])
    d.nodes(coords, 2)
    d.elements(etype, "BEAM", conn)
    d.nset("ROOT", select(coords, lambda x: abs(x[0]) < eps))
    d.nset("TIP", tip)
    d.nset("TIPMID", select(coords, lambda x: abs(x[0] - L) < eps and abs(x[1]) < eps))
    d.add("*SOLID SECTION, ELSET=BEAM, MATERIAL=MAT", f"{b}", "*MATERIAL, NAME=MAT", "*ELASTIC", f"{E}, 0.")
    d.add("*BOUNDARY", "ROOT, 1, 2")
    d.add("*STEP, NAME=BEND, NLGEOM=YES, INC=100", "*STATIC, DIRECT", f"{inc}, {alpha_max}", "*CLOAD")
    # the load ramps over the step: magnitude alpha_max * P, so PL²/EI = t at step time t
    for n in sorted(loads):
        d.add(f"{n}, 2, {loads[n] * alpha_max:.17g}")
    d.add(*OUTPUT, "*END STEP")
    return d


def elastica_reference(alpha, n=2000):
    """Tip of the inextensible elastica under a vertical dead load, by shooting on
    θ'' = −α cos θ, θ(0) = 0, θ'(1) = 0 (s = arc length / L), RK4. Returns (v/L, (L − x)/L, θ_tip)."""
    def integrate(k0):
        th, k, v, x = 0.0, k0, 0.0, 0.0
        ds = 1.0 / n

        def f(state):
            th, k, v, x = state
            return (k, -alpha * math.cos(th), math.sin(th), math.cos(th))
        s = (th, k, v, x)
        for _ in range(n):
            k1 = f(s)
            k2 = f(tuple(a + ds / 2 * b for a, b in zip(s, k1)))
            k3 = f(tuple(a + ds / 2 * b for a, b in zip(s, k2)))
            k4 = f(tuple(a + ds * b for a, b in zip(s, k3)))
            s = tuple(a + ds / 6 * (b1 + 2 * b2 + 2 * b3 + b4) for a, b1, b2, b3, b4 in zip(s, k1, k2, k3, k4))
        return s
    lo, hi = 0.0, alpha  # θ'(0) = M(0)/EI ∈ (0, α]
    for _ in range(80):
        mid = (lo + hi) / 2
        if integrate(mid)[1] > 0:
            hi = mid
        else:
            lo = mid
    th, k, v, x = integrate((lo + hi) / 2)
    return v, 1 - x, th


# --------------------------------------------------------------------------- 6. multi-step


def bar_mesh(x0, x1, nx, first_node=1):
    coords, conn = grid_hex(nx, 1, 1, (x0, 0, 0), (x1, 1, 1), False)
    if first_node != 1:
        coords = {k + first_node - 1: v for k, v in coords.items()}
        conn = [[n + first_node - 1 for n in c] for c in conn]
    return coords, conn


def c3d8_bar(d, coords, conn, length):
    """The nodes and C3D8 elements of a bar_mesh (ELSET BAR) and its sets: the ends LEFT (x = 0)
    and RIGHT (x = length), the symmetry planes Y0 and Z0."""
    eps = 1e-9
    d.nodes(coords, 3)
    d.elements("C3D8", "BAR", conn)
    d.nset("LEFT", select(coords, lambda x: abs(x[0]) < eps))
    d.nset("RIGHT", select(coords, lambda x: abs(x[0] - length) < eps))
    d.nset("Y0", select(coords, lambda x: abs(x[1]) < eps))
    d.nset("Z0", select(coords, lambda x: abs(x[2]) < eps))


def multistep():
    eps = 1e-9
    coords, conn = bar_mesh(0.0, 4.0, 4)
    face = lambda xv: select(coords, lambda x: abs(x[0] - xv) < eps)
    d = Deck("Multi-step bar: OP=NEW on *CLOAD and *BOUNDARY, an amplitude-driven load, a new BC",
             ["Bar 4 x 1 x 1, E = 1000, nu = 0 (uniaxial), x = 0 held. Hand values in",
              "tests/verification/test_multistep.cpp. Step 1: MID (x = 2) held, 100 at x = 4.",
              "Step 2 (OP=NEW): MID released (its reaction ramps to zero), the x = 4 load removed",
              "(ramps to zero), 60 * a(t) at x = 3 with a = (0,0) (0.5,1) (1,0.5).",
              "Step 3: x = 4 driven to u1 = 0.4 (ramped from where it is), 30 held at x = 3."])
    d.nodes(coords, 3)
    d.elements("C3D8", "BAR", conn)
    for name, xv in (("LEFT", 0.0), ("MID", 2.0), ("Q", 3.0), ("RIGHT", 4.0)):
        d.nset(name, face(xv))
    d.nset("Y0", select(coords, lambda x: abs(x[1]) < eps))
    d.nset("Z0", select(coords, lambda x: abs(x[2]) < eps))
    d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=MAT", "*MATERIAL, NAME=MAT", "*ELASTIC", "1000., 0.")
    d.add("*AMPLITUDE, NAME=A2", "0., 0., 0.5, 1., 1., 0.5")
    d.add("*BOUNDARY", "LEFT, 1, 1", "Y0, 2, 2", "Z0, 3, 3")
    d.add("*STEP, NAME=LOAD", "*STATIC, DIRECT", "0.5, 1.", "*BOUNDARY", "MID, 1, 1", "*CLOAD", "RIGHT, 1, 25.",
          *OUTPUT, "*END STEP")
    d.add("*STEP, NAME=RELEASE", "*STATIC, DIRECT", "0.25, 1.", "*BOUNDARY, OP=NEW", "LEFT, 1, 1", "Y0, 2, 2",
          "Z0, 3, 3", "*CLOAD, OP=NEW, AMPLITUDE=A2", "Q, 1, 15.", "*END STEP")
    d.add("*STEP, NAME=DRIVE", "*STATIC, DIRECT", "0.25, 1.", "*BOUNDARY", "RIGHT, 1, 1, 0.4", "*CLOAD, OP=NEW",
          "Q, 1, 7.5", "*END STEP")
    return d


# --------------------------------------------------------------------------- 7. *EQUATION


def equation_tie():
    eps = 1e-9
    ca, ea = bar_mesh(0.0, 1.0, 1, 1)       # block A, nodes 1..8
    cb, eb = bar_mesh(1.5, 2.5, 1, 101)     # block B, nodes 101..108
    cc, ec = bar_mesh(-1.5, -0.5, 1, 201)   # block C, nodes 201..208
    coords = {**ca, **cb, **cc}
    d = Deck("Equation ties: block B tied to block A, block C tied to the held nodes of A",
             ["Unit cubes, nu = 0. A (E = 1000): x = 0 face held. B (E = 2000) at x = 1.5..2.5: its x = 1.5",
              "nodes tied in u1 to A's x = 1 nodes; 100 at B's far face: u1(A, x=1) = 0.1, u1(B, x=2.5) = 0.15.",
              "C (E = 1000) at x = -1.5..-0.5: its x = -0.5 nodes tied in u1 to A's held x = 0 nodes;",
              "-50 at its x = -1.5 face: u1 = -0.05 there; RF1 on A's x = 0 face = -100 + 50 = -50."])
    d.nodes(coords, 3)
    d.elements("C3D8", "A", ea, 1)
    d.elements("C3D8", "B", eb, 101)
    d.elements("C3D8", "C", ec, 201)
    face = lambda xv: sorted(select(coords, lambda x: abs(x[0] - xv) < eps), key=lambda n: (coords[n][1], coords[n][2]))
    d.nset("LEFT", face(0.0))
    d.nset("BLOAD", face(2.5))
    d.nset("CLOAD", face(-1.5))
    d.nset("Y0", select(coords, lambda x: abs(x[1]) < eps))
    d.nset("Z0", select(coords, lambda x: abs(x[2]) < eps))
    d.add("*SOLID SECTION, ELSET=A, MATERIAL=SOFT", "*SOLID SECTION, ELSET=B, MATERIAL=STIFF",
          "*SOLID SECTION, ELSET=C, MATERIAL=SOFT")
    d.add("*MATERIAL, NAME=SOFT", "*ELASTIC", "1000., 0.", "*MATERIAL, NAME=STIFF", "*ELASTIC", "2000., 0.")
    d.add("*EQUATION")
    for nb, na in zip(face(1.5), face(1.0)):
        d.add("2", f"{nb}, 1, 1., {na}, 1, -1.")
    for nc, na in zip(face(-0.5), face(0.0)):
        d.add("2", f"{nc}, 1, 1., {na}, 1, -1.")
    d.add("*BOUNDARY", "LEFT, 1, 1", "Y0, 2, 2", "Z0, 3, 3")
    d.add("*STEP, NAME=PULL", "*STATIC", "*CLOAD", "BLOAD, 1, 25.", "CLOAD, 1, -12.5", *OUTPUT, "*END STEP")
    return d


# --------------------------------------------------------------------------- 8. no convergence


def rigid_mode():
    coords, conn = bar_mesh(0.0, 2.0, 2)
    d = Deck("A deck that cannot converge: step 2 removes every support of a loaded bar",
             ["Step 1 converges (held at x = 0, 10 at x = 2). Step 2: *BOUNDARY, OP=NEW with no data",
              "line removes the supports while the load stays: a rigid-body mode, singular stiffness.",
              "Expected: AnalysisOutcome.completed == false naming step 2 increment 1; exit code 4,",
              "step 1's frames readable in the .h5 with status ABORTED."])
    c3d8_bar(d, coords, conn, 2)
    d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=MAT", "*MATERIAL, NAME=MAT", "*ELASTIC", "1000., 0.3")
    d.add("*STEP, NAME=HOLD", "*STATIC", "*BOUNDARY", "LEFT, 1, 1", "Y0, 2, 2", "Z0, 3, 3", "*CLOAD", "RIGHT, 1, 2.5",
          *OUTPUT, "*END STEP")
    d.add("*STEP, NAME=LETGO", "*STATIC", "*BOUNDARY, OP=NEW", "*END STEP")
    return d


# --------------------------------------------------------------------------- 9. plasticity

PLAST = dict(E=200000.0, nu=0.3, sy=250.0, H=20000.0, L=4.0, eps_max=8e-3)


def plastic_bar():
    """Bar 4 x 1 x 1 of 4 C3D8, symmetry planes x = y = z = 0, linear isotropic hardening."""
    E, nu, sy, H, L, eps_max = (PLAST[k] for k in ("E", "nu", "sy", "H", "L", "eps_max"))
    coords, conn = bar_mesh(0.0, L, 4)
    Et = E * H / (E + H)
    s_max = sy + Et * (eps_max - sy / E)
    ep_max = (s_max - sy) / H
    d = Deck("Bar in uniaxial tension, Mises plasticity with linear hardening: loading, then unloading",
             [f"E = {E}, nu = {nu}, sigma_y = {sy} + H eps_p, H = {H} (E_t = E H/(E + H) = {Et:.12g}).",
              f"Step LOAD: x = {L} driven to u1 = {L * eps_max:g} (strain {eps_max:g}) in 10 increments:",
              "sigma = E eps up to eps_y = sigma_y/E, then sigma_y + E_t (eps - eps_y);",
              f"sigma_max = {s_max:.12g}, eps_p = {ep_max:.12g}. Step UNLOAD: the end released",
              "(*BOUNDARY, OP=NEW: its reaction ramps to zero) in 4 increments: elastic,",
              "sigma = sigma_max (1 - t), at the end sigma = 0 and PEEQ = PE11 = eps_p, PE22 = -eps_p/2.",
              "*CONTROLS: residuals to 1e-12 of the average force (R_n, R_l), so that the values are exact to round-off.",
              "Tolerances in tests/verification/test_plastic_bar.cpp."])
    c3d8_bar(d, coords, conn, L)
    d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL", "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {nu}",
          "*PLASTIC", f"{sy}, 0.", f"{sy + H * 0.1:g}, 0.1")
    d.add("*BOUNDARY", "LEFT, 1, 1", "Y0, 2, 2", "Z0, 3, 3")
    out = ["*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S, E, PE, PEEQ, PEMAG"]
    controls = ["*CONTROLS, PARAMETERS=FIELD", "1e-12, 1e-8, , , , , , 1e-12"]
    d.add("*STEP, NAME=LOAD", "*STATIC, DIRECT", "0.1, 1.", *controls, "*BOUNDARY", f"RIGHT, 1, 1, {L * eps_max:g}",
          *out, "*END STEP")
    d.add("*STEP, NAME=UNLOAD", "*STATIC, DIRECT", "0.25, 1.", *controls, "*BOUNDARY, OP=NEW", "LEFT, 1, 1", "Y0, 2, 2",
          "Z0, 3, 3", "*END STEP")
    return d


def plastic_plate(combined=False):
    """The bar of plastic_bar() as a plate 4 x 1 of 4 CPS4 (plane stress, thickness 1); with
    `combined` its hardening as HARDENING=COMBINED with C = H, gamma = 0 (the same curve while
    loading, and unloading stays elastic)."""
    E, nu, sy, H, L, eps_max = (PLAST[k] for k in ("E", "nu", "sy", "H", "L", "eps_max"))
    eps = 1e-9
    coords, conn = grid_quad(4, 1, lambda s_, t: (L * s_, t), False)
    lines = ["The bar of plastic_bar_c3d8.inp as a plane-stress plate (the local sigma_33 = 0 iteration of the",
             "material): the same closed forms, and the thickness strain E33 = -nu sigma/E - eps_p/2."]
    if combined:
        lines += [f"Hardening given as HARDENING=COMBINED, DATATYPE=PARAMETERS: sigma|0 = {sy}, C = H = {H}, gamma = 0",
                  "(linear kinematic): the same stress while loading; unloading to zero stress stays elastic",
                  "(X = H eps_p < sigma|0). The Chaboche law through the plane-stress condensation."]
    d = Deck("Plate in uniaxial tension, plane stress (CPS4), Mises plasticity with linear hardening: load, unload",
             lines + ["Tolerances in tests/verification/test_plastic_bar.cpp."])
    d.nodes(coords, 2)
    d.elements("CPS4", "BAR", conn)
    d.nset("LEFT", select(coords, lambda x: abs(x[0]) < eps))
    d.nset("RIGHT", select(coords, lambda x: abs(x[0] - L) < eps))
    d.nset("Y0", select(coords, lambda x: abs(x[1]) < eps))
    hardening = (["*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS", f"{sy}, {H}, 0."] if combined
                 else ["*PLASTIC", f"{sy}, 0.", f"{sy + H * 0.1:g}, 0.1"])
    d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL", "1.", "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {nu}",
          *hardening)
    d.add("*BOUNDARY", "LEFT, 1, 1", "Y0, 2, 2")
    out = ["*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S, E, PE, PEEQ, PEMAG"]
    controls = ["*CONTROLS, PARAMETERS=FIELD", "1e-12, 1e-8, , , , , , 1e-12"]
    d.add("*STEP, NAME=LOAD", "*STATIC, DIRECT", "0.1, 1.", *controls, "*BOUNDARY", f"RIGHT, 1, 1, {L * eps_max:g}",
          *out, "*END STEP")
    d.add("*STEP, NAME=UNLOAD", "*STATIC, DIRECT", "0.25, 1.", *controls, "*BOUNDARY, OP=NEW", "LEFT, 1, 1", "Y0, 2, 2",
          "*END STEP")
    return d


HOT = dict(T0=20.0, T1=420.0, sy0=250.0, H0=500.0, sy1=150.0, H1=250.0, eps=4e-3)


def heated_bar_steps(d, L, eps, T0, T1):
    """The temperature bars' set-up after the material: the supports, T = T0 at the start, and
    the steps PULL (the end to strain eps at T0) and HEAT (T to T1 at fixed length)."""
    d.add("*BOUNDARY", "LEFT, 1, 1", "Y0, 2, 2", "Z0, 3, 3")
    d.add("*INITIAL CONDITIONS, TYPE=TEMPERATURE", f"ALL, {T0:g}")
    out = ["*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S, E, PE, PEEQ"]
    d.add("*STEP, NAME=PULL", "*STATIC, DIRECT", "0.25, 1.", *EXACT_CONTROLS, "*BOUNDARY",
          f"RIGHT, 1, 1, {L * eps:g}", *out, "*END STEP")
    d.add("*STEP, NAME=HEAT", "*STATIC, DIRECT", "0.1, 1.", *EXACT_CONTROLS, "*TEMPERATURE", f"ALL, {T1:g}", "*END STEP")


def release_step(d, name="RELEASE"):
    """The last step of the plastic bars: the end released (OP=NEW) in two increments."""
    d.add(f"*STEP, NAME={name}", "*STATIC, DIRECT", "0.5, 1.", *EXACT_CONTROLS, "*BOUNDARY, OP=NEW", "LEFT, 1, 1",
          "Y0, 2, 2", "Z0, 3, 3", "*END STEP")


EXACT_CONTROLS = ["*CONTROLS, PARAMETERS=FIELD", "1e-12, 1e-8, , , , , , 1e-12"]


def plastic_bar_temperature():
    """The bar of plastic_bar() with yield curves at two temperatures, pulled, heated at fixed
    length (the yield surface shrinks: plastic flow at constant strain), cooled, released."""
    E, nu, L = PLAST["E"], PLAST["nu"], PLAST["L"]
    T0, T1, sy0, H0, sy1, H1, eps_max = (HOT[k] for k in ("T0", "T1", "sy0", "H0", "sy1", "H1", "eps"))
    coords, conn = bar_mesh(0.0, L, 4)
    d = Deck("Bar with temperature-dependent plasticity: pulled, heated at fixed length, cooled, released",
             [f"E = {E}, nu = {nu}, no expansion. *PLASTIC at T = {T0:g}: sigma_y = {sy0:g} + {H0:g} eps_p (to eps_p 0.1);",
              f"at T = {T1:g}: {sy1:g} + {H1:g} eps_p (to 0.2); between them linear in T at equal eps_p.",
              f"Step PULL (T = {T0:g}): strain to {eps_max:g}, sigma = sigma_y + E_t (eps - eps_y), E_t = E H/(E + H).",
              f"Step HEAT (length held): T to {T1:g}; with s = (T - {T0:g})/{T1 - T0:g}, A = {sy0:g} + ({sy1 - sy0:g}) s,",
              f"B = {H0:g} + ({H1 - H0:g}) s: eps_p = (E eps - A)/(E + B), sigma = E (eps - eps_p) at every increment.",
              f"Step COOL: T back to {T0:g}, elastic, sigma constant. Step RELEASE: sigma to 0, the end at L eps_p.",
              "Tolerances in tests/verification/test_plastic_bar.cpp."])
    c3d8_bar(d, coords, conn, L)
    d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL", "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {nu}",
          "*PLASTIC", f"{sy0:g}, 0., {T0:g}", f"{sy0 + H0 * 0.1:g}, 0.1, {T0:g}",
          f"{sy1:g}, 0., {T1:g}", f"{sy1 + H1 * 0.2:g}, 0.2, {T1:g}")
    heated_bar_steps(d, L, eps_max, T0, T1)
    d.add("*STEP, NAME=COOL", "*STATIC, DIRECT", "0.25, 1.", *EXACT_CONTROLS, "*TEMPERATURE", f"ALL, {T0:g}",
          "*END STEP")
    release_step(d)
    return d


HALF = dict(sy=250.0, C=40000.0, gamma=400.0, dg1=0.002, dg2=0.005,
            rows=(0.0, 0.001, 0.0025, 0.005, 0.01, 0.02))


def plastic_bar_half_cycle():
    """The bar with HARDENING=COMBINED given as half-cycle data (Abaqus's default DATATYPE):
    rows on the curve sigma = sigma|0 + C/gamma (1 - exp(-gamma eps_p)), which the fit must
    recover, then two single-increment plastic steps whose backward Euler values are closed."""
    E, nu, L = PLAST["E"], PLAST["nu"], PLAST["L"]
    sy, C, g, dg1, dg2 = (HALF[k] for k in ("sy", "C", "gamma", "dg1", "dg2"))
    x1 = C * dg1 / (1 + g * dg1)
    x2 = (x1 + C * (dg2 - dg1)) / (1 + g * (dg2 - dg1))
    coords, conn = bar_mesh(0.0, L, 4)
    d = Deck("Bar in uniaxial tension, combined hardening from half-cycle test data",
             [f"E = {E}, nu = {nu}; *PLASTIC, HARDENING=COMBINED (DATATYPE=HALF CYCLE, one backstress): rows on",
              f"sigma = {sy:g} + C/gamma (1 - exp(-gamma eps_p)), C = {C:g}, gamma = {g:g}, no *CYCLIC HARDENING",
              "(a surface of constant size sigma|0, the first row). The fit recovers C and gamma.",
              f"Step LOAD: one increment to eps = sigma/E + dg1, dg1 = {dg1:g}: X1 = C dg1/(1 + gamma dg1) = {x1:.12g},",
              f"S11 = {sy + x1:.12g}. Step MORE: one increment to dg2 = {dg2:g}: X2 = (X1 + C (dg2 - dg1))/(1 + gamma",
              f"(dg2 - dg1)) = {x2:.12g}, S11 = {sy + x2:.12g}. Step UNLOAD: released, S11 = 0, the end at L dg2.",
              "Tolerances in tests/verification/test_plastic_bar.cpp."])
    c3d8_bar(d, coords, conn, L)
    rows = [f"{sy + C / g * (1 - math.exp(-g * e)):.15g}, {e:g}" for e in HALF["rows"]]
    d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL", "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {nu}",
          "*PLASTIC, HARDENING=COMBINED", *rows)
    d.add("*BOUNDARY", "LEFT, 1, 1", "Y0, 2, 2", "Z0, 3, 3")
    out = ["*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S, E, PE, PEEQ"]
    for name, x, dg in (("LOAD", x1, dg1), ("MORE", x2, dg2)):
        d.add(f"*STEP, NAME={name}", "*STATIC, DIRECT", "1., 1.", *EXACT_CONTROLS, "*BOUNDARY",
              f"RIGHT, 1, 1, {L * ((sy + x) / E + dg):.15g}", *out, "*END STEP")
    release_step(d, "UNLOAD")
    return d


KHOT = dict(T0=20.0, T1=420.0, sy0=250.0, C0=20000.0, sy1=150.0, C1=10000.0, eps=4e-3)


def plastic_bar_kinematic_temperature():
    """Linear kinematic hardening at two temperatures: pulled cold, heated at fixed length."""
    E, nu, L = PLAST["E"], PLAST["nu"], PLAST["L"]
    T0, T1, sy0, C0, sy1, C1, eps = (KHOT[k] for k in ("T0", "T1", "sy0", "C0", "sy1", "C1", "eps"))
    coords, conn = bar_mesh(0.0, L, 4)
    d = Deck("Bar with temperature-dependent linear kinematic hardening: pulled, heated at fixed length, released",
             [f"E = {E}, nu = {nu}, no expansion. *PLASTIC, HARDENING=KINEMATIC at T = {T0:g}: sigma|0 = {sy0:g},",
              f"C = {C0:g}; at T = {T1:g}: sigma|0 = {sy1:g}, C = {C1:g}; both linear in T between. Abaqus's backstress",
              "law carries alpha with C (the term (1/C)(dC/dT) alpha dT), so uniaxially X = 3/2 alpha11 = C(T) eps_p.",
              f"Step PULL (T = {T0:g}): strain to {eps:g}, eps_p = (E eps - sigma|0)/(E + C), sigma = E (eps - eps_p).",
              f"Step HEAT (length held): T to {T1:g}; with s = (T - {T0:g})/{T1 - T0:g}: eps_p = (E eps - sigma|0(s))/(E + C(s))",
              "(it grows: plastic flow at fixed strain), sigma = E (eps - eps_p). Step RELEASE (at T1): elastic down to",
              "sigma = 0 (-X = -C1 eps_p stays above -sigma|0), the end at L eps_p.",
              "Tolerances in tests/verification/test_plastic_bar.cpp."])
    c3d8_bar(d, coords, conn, L)
    d.add("*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL", "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {nu}",
          "*PLASTIC, HARDENING=KINEMATIC", f"{sy0:g}, 0., {T0:g}", f"{sy0 + C0 * 0.01:g}, 0.01, {T0:g}",
          f"{sy1:g}, 0., {T1:g}", f"{sy1 + C1 * 0.01:g}, 0.01, {T1:g}")
    heated_bar_steps(d, L, eps, T0, T1)
    release_step(d)
    return d


CYL = dict(a=10.0, b=20.0, c=15.0, E=200000.0, nu=0.4999, sy=250.0)


def hill_pressure(a, b, c, sy):
    """Hill (The Mathematical Theory of Plasticity, ch. V §3), Mises, plane strain, nu = 1/2:
    the pressure that puts the elastic-plastic boundary at r = c."""
    k = sy / math.sqrt(3.0)
    return k * (2 * math.log(c / a) + 1 - c * c / (b * b))


def plastic_cylinder(etype, nr, nt):
    a, b, c, E, nu, sy = (CYL[key] for key in ("a", "b", "c", "E", "nu", "sy"))
    p = hill_pressure(a, b, c, sy)
    k = sy / math.sqrt(3.0)
    ua = 3 * k * c * c / (2 * E * a)
    eps = 1e-9
    coords, conn = grid_quad(nr, nt, lambda s, t: ((a + (b - a) * s) * math.cos(math.pi / 2 * t),
                                                  (a + (b - a) * s) * math.sin(math.pi / 2 * t)), "8" in etype)
    bore_el = [i + 1 for i, el in enumerate(conn)
               if all(abs(math.hypot(*coords[el[j]][:2]) - a) < 1e-6 for j in (0, 3))]
    d = Deck(f"Thick cylinder under internal pressure, elastic-perfectly plastic (Mises), plane strain, {etype} {nr}x{nt}",
             [f"a = {a}, b = {b}, E = {E}, nu = {nu}, sigma_y = {sy} (k = sigma_y/sqrt 3 = {k:.12g}).",
              "Hill, The Mathematical Theory of Plasticity, ch. V sec. 3, exact for nu = 1/2 (sigma_z = mean of",
              "sigma_r, sigma_theta everywhere); nu = 0.4999 leaves corrections O(1 - 2 nu) = 2e-4:",
              "p = k (2 ln(c/a) + 1 - c^2/b^2), plastic a < r < c: sigma_r = -p + 2k ln(r/a), sigma_theta = sigma_r + 2k;",
              "elastic c < r < b: sigma_r = -k c^2 (1/r^2 - 1/b^2), sigma_theta = k c^2 (1/r^2 + 1/b^2);",
              f"u(a) = 3 k c^2/(2 E a). For c = {c}: p = {p:.12g}, u(a) = {ua:.12g}.",
              "Pressure ramped in 10 increments (DIRECT). Reduced integration: the plastic flow is isochoric.",
              "Tolerances in tests/verification/test_plastic_cylinder.cpp."])
    d.nodes(coords, 2)
    d.elements(etype, "WALL", conn)
    d.elset("BORE_EL", bore_el)
    d.add("*SURFACE, NAME=BORE", "BORE_EL, S4")
    d.add("*SOLID SECTION, ELSET=WALL, MATERIAL=STEEL", "1.")
    d.add("*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {nu}", "*PLASTIC", f"{sy}, 0.")
    d.nset("ON_X", select(coords, lambda x: abs(x[1]) < eps))
    d.nset("ON_Y", select(coords, lambda x: abs(x[0]) < eps))
    d.add("*BOUNDARY", "ON_X, YSYMM", "ON_Y, XSYMM")
    d.add("*STEP, NAME=PRESSURIZE", "*STATIC, DIRECT", "0.1, 1.", "*DSLOAD", f"BORE, P, {p:.15g}",
          "*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S, E, PEEQ", "*END STEP")
    return d


# --------------------------------------------------------------------------- main

CANTILEVER_LEVELS = {
    "CPS8R": [(8, 2, 1), (16, 4, 1), (32, 8, 1)],
    "CPE4I": [(8, 2, 1), (16, 4, 1), (32, 8, 1)],
    "C3D8I": [(8, 2, 1), (16, 4, 2), (32, 8, 4)],
    "C3D20R": [(4, 2, 1), (8, 4, 2), (16, 8, 4)],
    "C3D10": [(4, 2, 2), (8, 4, 4), (16, 8, 8)],
}


# --------------------------------------------------------------------------- 9. centrifugal load

SPIN = dict(ri=10.0, ro=20.0, E=210000.0, nu=0.3, rho=7.8e-9, omega2=1.0e6)


def spinning_disk_displacement(r):
    """Radial displacement of a free annular disk spinning at ω in plane stress (Timoshenko &
    Goodier §32): σ_r = C (a² + b² − a²b²/r² − r²), σ_θ = C (a² + b² + a²b²/r² − (1+3ν)/(3+ν) r²),
    C = (3+ν)/8 ρω², u_r = r (σ_θ − ν σ_r)/E."""
    a, b, E, nu = SPIN["ri"], SPIN["ro"], SPIN["E"], SPIN["nu"]
    C = (3 + nu) / 8 * SPIN["rho"] * SPIN["omega2"]
    s_r = C * (a * a + b * b - a * a * b * b / (r * r) - r * r)
    s_t = C * (a * a + b * b + a * a * b * b / (r * r) - (1 + 3 * nu) / (3 + nu) * r * r)
    return r * (s_t - nu * s_r) / E


def spinning_disk(etype, nr, nt):
    """A free annular disk spinning about its axis (*DLOAD CENTRIF): a quarter in plane stress
    (CPS, about z) or a thin axisymmetric slice (CAX, about y; half the thickness H = 0.2 above a
    symmetry plane, so plane stress holds to O((H/r)²))."""
    ri, ro, E, nu, rho, w2 = (SPIN[k] for k in ("ri", "ro", "E", "nu", "rho", "omega2"))
    quadratic = "8" in etype
    eps = 1e-9
    axisymmetric = etype.startswith("CAX")
    if axisymmetric:
        H = 0.1
        coords, conn = grid_quad(nr, nt, lambda s, t: (ri + (ro - ri) * s, H * t), quadratic)
    else:
        coords, conn = grid_quad(nr, nt, lambda s, t: ((ri + (ro - ri) * s) * math.cos(math.pi / 2 * t),
                                                      (ri + (ro - ri) * s) * math.sin(math.pi / 2 * t)), quadratic)
    d = Deck(f"Free annular disk spinning at omega^2 = {w2:g} (CENTRIF), {etype} {nr}x{nt}",
             [f"ri = {ri}, ro = {ro}, E = {E}, nu = {nu}, rho = {rho}",
              f"plane stress (Timoshenko & Goodier 32): u_r(ri) = {spinning_disk_displacement(ri):.12g}, "
              f"u_r(ro) = {spinning_disk_displacement(ro):.12g}",
              "Tolerances in tests/verification/test_centrifugal_load.cpp."])
    d.nodes(coords, 2)
    d.elements(etype, "DISK", conn)
    d.add("*SOLID SECTION, ELSET=DISK, MATERIAL=STEEL", "1.")
    d.add("*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {nu}", "*DENSITY", f"{rho}")
    if axisymmetric:
        d.nset("MID_PLANE", select(coords, lambda x: abs(x[1]) < eps))
        d.add("*BOUNDARY", "MID_PLANE, 2, 2")
        axis = "0., 0., 0., 0., 1., 0."
    else:
        d.nset("ON_X", select(coords, lambda x: abs(x[1]) < eps))
        d.nset("ON_Y", select(coords, lambda x: abs(x[0]) < eps))
        d.add("*BOUNDARY", "ON_X, YSYMM", "ON_Y, XSYMM")
        axis = "0., 0., 0., 0., 0., 1."
    d.add("*STEP, NAME=SPIN", "*STATIC", "*DLOAD", f"DISK, CENTRIF, {w2:g}, {axis}", *OUTPUT, "*END STEP")
    return d


def spinning_block():
    """A unit cube of C3D8 at 1 ≤ x ≤ 2, built in at z = 0, spinning about the z-axis: the
    built-in face carries the whole centrifugal force, ρω² ∫ (x, y) dV = ρω² (1.5, 0.5) exactly."""
    rho, w2 = SPIN["rho"], SPIN["omega2"]
    coords, conn = grid_hex(2, 2, 2, (1.0, 0.0, 0.0), (2.0, 1.0, 1.0), False)
    d = Deck(f"Unit cube at 1 <= x <= 2 spinning about z (CENTRIF, omega^2 = {w2:g}), built in at z = 0",
             [f"rho = {rho}: sum of RF = -rho omega^2 (1.5, 0.5, 0) = ({-rho * w2 * 1.5:.12g}, {-rho * w2 * 0.5:.12g}, 0)",
              "Tolerances in tests/verification/test_centrifugal_load.cpp."])
    d.nodes(coords, 3)
    d.elements("C3D8", "CUBE", conn)
    d.nset("BASE", select(coords, lambda x: abs(x[2]) < 1e-9))
    d.add("*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL", "*MATERIAL, NAME=STEEL", "*ELASTIC", "210000., 0.3",
          "*DENSITY", f"{rho}", "*BOUNDARY", "BASE, ENCASTRE")
    d.add("*STEP, NAME=SPIN", "*STATIC", "*DLOAD", f"CUBE, CENTRIF, {w2:g}, 0., 0., 0., 0., 0., 1.", *OUTPUT,
          "*END STEP")
    return d


# --------------------------------------------------------------------------- 10. rotary acceleration

ROTA = dict(ri=10.0, ro=20.0, E=210000.0, nu=0.3, rho=7.8e-9, alpha=1.0e6)


def accelerating_disk_displacement(r):
    """Circumferential displacement of an annular disk held at its bore (r = a) and free at its rim
    (r = b) under the rotary acceleration α (*DLOAD ROTA, whose force is the d'Alembert force
    f_θ = −ρ α r): pure shear, τ_rθ = ρα (r⁴ − b⁴)/(4 r²) from (r² τ)' = −r² f_θ with τ(b) = 0,
    and γ = r (u_θ/r)' = τ/G with u_θ(a) = 0 give u_θ = r ρα/(8G) (r² − a² + b⁴ (1/r² − 1/a²))."""
    a, b, E, nu = ROTA["ri"], ROTA["ro"], ROTA["E"], ROTA["nu"]
    G = E / (2 * (1 + nu))
    return r * ROTA["rho"] * ROTA["alpha"] / (8 * G) * (r * r - a * a + b ** 4 * (1 / (r * r) - 1 / (a * a)))


def accelerating_disk(etype, nr, nt):
    """The whole annulus (the load is not symmetric about any diameter), held at the bore, under
    ROTA about z; the seam of the structured mesh is closed by merging its last row of nodes into
    the first."""
    ri, ro, E, nu, rho, alpha = (ROTA[k] for k in ("ri", "ro", "E", "nu", "rho", "alpha"))
    quadratic = "8" in etype
    coords, conn = grid_quad(nr, nt, lambda s, t: ((ri + (ro - ri) * s) * math.cos(2 * math.pi * t),
                                                  (ri + (ro - ri) * s) * math.sin(2 * math.pi * t)), quadratic)
    n1 = (2 if quadratic else 1) * nr + 1
    seam = n1 * (2 if quadratic else 1) * nt  # label offset of the last row (t = 1) from the first
    last_row = {n for n in coords if n > seam}
    conn = [[n - seam if n in last_row else n for n in c] for c in conn]
    for n in last_row:
        del coords[n]
    d = Deck(f"Annular disk held at its bore under the rotary acceleration alpha = {alpha:g} (ROTA), {etype} {nr}x{nt}",
             [f"ri = {ri}, ro = {ro}, E = {E}, nu = {nu}, rho = {rho}",
              "pure shear: u_theta = r rho alpha/(8G) (r^2 - a^2 + b^4 (1/r^2 - 1/a^2)), u_r = 0; "
              f"u_theta(ro) = {accelerating_disk_displacement(ro):.12g}",
              "Tolerances in tests/verification/test_rotary_acceleration.cpp."])
    d.nodes(coords, 2)
    d.elements(etype, "DISK", conn)
    d.add("*SOLID SECTION, ELSET=DISK, MATERIAL=STEEL", "1.")
    d.add("*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {nu}", "*DENSITY", f"{rho}")
    d.nset("BORE", select(coords, lambda x: abs(math.hypot(x[0], x[1]) - ri) < 1e-9))
    d.add("*BOUNDARY", "BORE, 1, 2")
    d.add("*STEP, NAME=ACCELERATE", "*STATIC", "*DLOAD", f"DISK, ROTA, {alpha:g}, 0., 0., 0., 0., 0., 1.", *OUTPUT,
          "*END STEP")
    return d


def accelerating_block():
    """The unit cube of spinning_block under ROTA about z: the built-in face carries the whole
    d'Alembert force −ρα ẑ × (x, y, 0) integrated, ρα (∫y dV, −∫x dV) = ρα (0.5, −1.5)."""
    rho, alpha = ROTA["rho"], ROTA["alpha"]
    coords, conn = grid_hex(2, 2, 2, (1.0, 0.0, 0.0), (2.0, 1.0, 1.0), False)
    d = Deck(f"Unit cube at 1 <= x <= 2 under the rotary acceleration alpha = {alpha:g} about z (ROTA), built in at z = 0",
             [f"rho = {rho}: sum of RF = -rho alpha (0.5, -1.5, 0) = ({-rho * alpha * 0.5:.12g}, {rho * alpha * 1.5:.12g}, 0)",
              "Tolerances in tests/verification/test_rotary_acceleration.cpp."])
    d.nodes(coords, 3)
    d.elements("C3D8", "CUBE", conn)
    d.nset("BASE", select(coords, lambda x: abs(x[2]) < 1e-9))
    d.add("*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL", "*MATERIAL, NAME=STEEL", "*ELASTIC", "210000., 0.3",
          "*DENSITY", f"{rho}", "*BOUNDARY", "BASE, ENCASTRE")
    d.add("*STEP, NAME=ACCELERATE", "*STATIC", "*DLOAD", f"CUBE, ROTA, {alpha:g}, 0., 0., 0., 0., 0., 1.", *OUTPUT,
          "*END STEP")
    return d


def committed(out):
    decks = {
        "cantilever_cps8r_l1.inp": cantilever("CPS8R", 8, 2, 1),
        "cantilever_c3d8i_l1.inp": cantilever("C3D8I", 8, 2, 1),
        "cantilever_c3d10_l1.inp": cantilever("C3D10", 4, 2, 2),
        "lame_cpe8r.inp": lame("CPE8R", 6, 8),
        "lame_cpe4.inp": lame("CPE4", 16, 24),
        "lame_cps8.inp": lame("CPS8", 6, 8),
        "lame_cps4.inp": lame("CPS4", 16, 24),
        "lame_cax8r.inp": lame("CAX8R", 6, 1),
        "lame_cax4.inp": lame("CAX4", 16, 1),
        "thermal_ring_cps8.inp": thermal_ring("CPS8", 3, 6),
        "thermal_ring_cax4.inp": thermal_ring("CAX4", 4, 2),
        "thermal_bar_c3d8.inp": thermal_bar(),
        "thermal_table_free_c3d8.inp": thermal_table("C3D8", False),
        "thermal_table_held_c3d8.inp": thermal_table("C3D8", True),
        "thermal_table_held_cps4.inp": thermal_table("CPS4", True),
        "thermal_table_held_cpe4.inp": thermal_table("CPE4", True),
        "thermal_table_held_cax4.inp": thermal_table("CAX4", True),
        "nlgeom_rigid_rotation_c3d8.inp": rigid_rotation("C3D8", 2, 10),
        "nlgeom_rigid_rotation_c3d8i.inp": rigid_rotation("C3D8I", 2, 10),
        "nlgeom_elastica_cpe8r.inp": elastica("CPE8R", 40, 2),
        "multistep_bar.inp": multistep(),
        "equation_tie.inp": equation_tie(),
        "rigid_mode_abort.inp": rigid_mode(),
        "spinning_disk_cps8.inp": spinning_disk("CPS8", 8, 8),
        "spinning_disk_cax8r.inp": spinning_disk("CAX8R", 8, 1),
        "spinning_block_c3d8.inp": spinning_block(),
        "accelerating_disk_cps8.inp": accelerating_disk("CPS8", 4, 16),
        "accelerating_block_c3d8.inp": accelerating_block(),
        "plastic_bar_c3d8.inp": plastic_bar(),
        "plastic_plate_cps4.inp": plastic_plate(),
        "plastic_plate_combined_cps4.inp": plastic_plate(combined=True),
        "plastic_bar_temperature_c3d8.inp": plastic_bar_temperature(),
        "plastic_bar_half_cycle_c3d8.inp": plastic_bar_half_cycle(),
        "plastic_bar_kinematic_temperature_c3d8.inp": plastic_bar_kinematic_temperature(),
        "plastic_cylinder_cpe8r.inp": plastic_cylinder("CPE8R", 12, 4),
    }
    for name, d in decks.items():
        d.write(os.path.join(out, name))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    ap.add_argument("--cantilever", nargs=4, metavar=("TYPE", "NX", "NY", "NZ"))
    ap.add_argument("--cantilever-levels", metavar="TYPE", help="write the three levels of TYPE")
    ap.add_argument("--elastica-reference", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.elastica_reference:
        for alpha in (1, 2, 3):
            print(alpha, *(f"{v:.5f}" for v in elastica_reference(alpha)))
        return
    if a.cantilever:
        t, nx, ny, nz = a.cantilever[0], *map(int, a.cantilever[1:])
        cantilever(t, nx, ny, nz).write(os.path.join(a.out, f"cantilever_{t.lower()}_{nx}x{ny}x{nz}.inp"))
        return
    if a.cantilever_levels:
        t = a.cantilever_levels
        for nx, ny, nz in CANTILEVER_LEVELS[t]:
            cantilever(t, nx, ny, nz).write(os.path.join(a.out, f"cantilever_{t.lower()}_{nx}x{ny}x{nz}.inp"))
        return
    committed(a.out)


if __name__ == "__main__":
    main()
