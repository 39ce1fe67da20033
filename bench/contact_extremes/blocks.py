"""Two-block contact patch test with every knob the extremes benchmark turns, and its analytic answer.

An upper block (the slave, its bottom face) rests on a lower block (the master, its top face), both
W wide (W × W in 3-D), heights Hs and Hm, side rollers (U1 = 0 on x = 0, W; U2 = 0 on y = 0, W in
3-D), the lower block's bottom held normal to it. The upper block is either pressed by a pressure
p on its top (load control; it is held only by the contact) or its top is moved down by d
(displacement control). The exact state is uniaxial strain in each block:

    CPRESS = p at every slave node,   top displacement = −(p Hs/Ms + p Hm/Mm + h(p) + g)

with M = E(1−ν)/((1+ν)(1−2ν)) the constrained modulus, g the initial gap (negative: overclosure)
and h(p) the penetration of the enforcement method: 0 (direct), p/k (linear penalty), the inverse
of the nonlinear penalty law, at most the tolerance (augmented Lagrange). Displacement control
solves d = p (Hs/Ms + Hm/Mm) + h(p) + g for p. Node-to-surface passes this test exactly when
every master node lies under a slave node (nested meshes: n_s a multiple of n_m, or n_m = 1).

k_e is computed as inpact documents it (contact/normal_behavior.cpp): M/h of the slave element
under the facet (h its thickness normal to the facet, M the softer of the two blocks' constrained
moduli), median over the facets; the
characteristic length is the median facet size (edge in 2-D, √area in 3-D).

discretization: NODE TO SURFACE, SURFACE TO SURFACE (the pair's TYPE) or GENERAL (general contact,
*CONTACT INCLUSIONS, ALL EXTERIOR, instead of the pair). IFACE is the node set of both sides of the
interface (general contact reports CPRESS on the exterior nodes of both bodies).

Pure standard-library Python; `deck(**case)` returns (deck text, expectation dict).
"""
import math

# mm, N, MPa: steel-like defaults
BASE = dict(dim=2, elem=None, W=2.0, Hs=1.0, Hm=1.0, ns=4, nms=None, nm=2, nmm=None,
            Es=210000.0, Em=210000.0, nus=0.3, num=0.3, load="pressure", p=10.0, d=None, gap=0.0,
            method="DIRECT", sf=None, stiffness=None, tol=None, discretization="NODE TO SURFACE",
            inc=0.5, unit="mm", stabilize=None)


def constrained(E, nu):
    return E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))


def lines(items, per=12):
    items = [str(i) for i in items]
    return "".join(", ".join(items[k:k + per]) + "\n" for k in range(0, len(items), per))


def grid(dim, first, n, nz, W, z0, z1):
    """Nodes (label, coords) and connectivity of an n (× n) × nz grid over [0, W]^(dim−1) × [z0, z1]."""
    nodes, elems = [], []
    m = n + 1
    if dim == 2:
        lab = lambda i, k: first + k * m + i
        for k in range(nz + 1):
            for i in range(m):
                nodes.append((lab(i, k), (W * i / n, z0 + (z1 - z0) * k / nz)))
        e = first
        for k in range(nz):
            for i in range(n):
                elems.append((e, lab(i, k), lab(i + 1, k), lab(i + 1, k + 1), lab(i, k + 1)))
                e += 1
        return nodes, elems
    lab = lambda i, j, k: first + k * m * m + j * m + i
    for k in range(nz + 1):
        for j in range(m):
            for i in range(m):
                nodes.append((lab(i, j, k), (W * i / n, W * j / n, z0 + (z1 - z0) * k / nz)))
    e = first
    for k in range(nz):
        for j in range(n):
            for i in range(n):
                elems.append((e, lab(i, j, k), lab(i + 1, j, k), lab(i + 1, j + 1, k), lab(i, j + 1, k),
                              lab(i, j, k + 1), lab(i + 1, j, k + 1), lab(i + 1, j + 1, k + 1), lab(i, j + 1, k + 1)))
                e += 1
    return nodes, elems


def nonlinear_penalty(s, kf, ki, se, sd):
    """inpact's / Abaqus's nonlinear penalty pressure at overclosure s (contact/pressure_overclosure.cpp)."""
    if s <= 0:
        return 0.0
    if s <= se:
        return ki * s
    if s <= sd:
        return ki * s + (kf - ki) * (s - se) ** 2 / (2.0 * (sd - se))
    return ki * sd + 0.5 * (kf - ki) * (sd - se) + kf * (s - sd)


def invert(f, y, hi):
    """s ≥ 0 with f(s) = y for increasing f (bisection)."""
    lo = 0.0
    while f(hi) < y:
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) < y:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


GENERAL = "GENERAL"  # discretization value: general contact instead of the pair


def contact_lines(discretization, slave="SLAVE_S", master="MASTER_S", interaction="SMOOTH"):
    """The pair (TYPE=NODE TO SURFACE | SURFACE TO SURFACE), or general contact for GENERAL:
    *CONTACT / *CONTACT INCLUSIONS, ALL EXTERIOR / *CONTACT PROPERTY ASSIGNMENT `, , interaction`
    (inpact expands it to surface-to-surface rows between the bodies, balanced master-slave for
    penalty-type methods: contact/interaction_table.hpp)."""
    if discretization == GENERAL:
        return ["*CONTACT", "*CONTACT INCLUSIONS, ALL EXTERIOR", "*CONTACT PROPERTY ASSIGNMENT", f", , {interaction}"]
    return [f"*CONTACT PAIR, INTERACTION={interaction}, TYPE={discretization}", f"{slave}, {master}"]


def deck(**kw):
    c = dict(BASE, **kw)
    dim = c["dim"]
    elem = c["elem"] or ("CPE4" if dim == 2 else "C3D8")
    W, Hs, Hm, gap = c["W"], c["Hs"], c["Hm"], c["gap"]
    ns, nm = c["ns"], c["nm"]
    nms = c["nms"] or max(1, round(ns * Hs / W))   # rows: square-ish elements unless given
    nmm = c["nmm"] or max(1, round(nm * Hm / W))
    mn, me = grid(dim, 1, nm, nmm, W, 0.0, Hm)
    first_s = 10 ** len(str(len(mn) + len(me) + 1))
    sn, se = grid(dim, first_s, ns, nms, W, Hm + gap, Hm + gap + Hs)
    per_layer_m, per_layer_s = nm ** (dim - 1), ns ** (dim - 1)
    up = "2" if dim == 2 else "3"
    s_bottom, s_top, m_top = ("S1", "S3", "S3") if dim == 2 else ("S1", "S2", "S2")
    out = ["*HEADING",
           f" Two-block contact patch test ({dim}-D, {elem}): slave {ns} x {nms} (E = {c['Es']:g}, nu = {c['nus']:g}) on "
           f"master {nm} x {nmm} (E = {c['Em']:g}, nu = {c['num']:g}), gap {gap:g}, {c['load']} load, {c['method']}",
           "** Generated by bench/contact_extremes/blocks.py (inpact); analytic answer in its docstring"]
    fmt = lambda x: f"{x:.17g}"
    out += ["*NODE, NSET=ALL"] + [f"{n}, " + ", ".join(fmt(v) for v in x) for n, x in mn + sn]
    out += [f"*ELEMENT, TYPE={elem}, ELSET=LOWER"] + [", ".join(map(str, e)) for e in me]
    out += [f"*ELEMENT, TYPE={elem}, ELSET=UPPER"] + [", ".join(map(str, e)) for e in se]
    out += ["*ELSET, ELSET=LOWER_TOP"] + lines([e[0] for e in me[-per_layer_m:]]).splitlines()
    out += ["*ELSET, ELSET=UPPER_BOTTOM"] + lines([e[0] for e in se[:per_layer_s]]).splitlines()
    out += ["*ELSET, ELSET=UPPER_TOP"] + lines([e[0] for e in se[-per_layer_s:]]).splitlines()
    out += ["*SURFACE, NAME=MASTER_S", f"LOWER_TOP, {m_top}", "*SURFACE, NAME=SLAVE_S", f"UPPER_BOTTOM, {s_bottom}",
            "*SURFACE, NAME=TOP_S", f"UPPER_TOP, {s_top}"]
    out += ["*SOLID SECTION, ELSET=LOWER, MATERIAL=MASTER_MAT", "*SOLID SECTION, ELSET=UPPER, MATERIAL=SLAVE_MAT",
            "*MATERIAL, NAME=MASTER_MAT", "*ELASTIC", f"{c['Em']:.17g}, {c['num']:g}",
            "*MATERIAL, NAME=SLAVE_MAT", "*ELASTIC", f"{c['Es']:.17g}, {c['nus']:g}"]
    out += ["*SURFACE INTERACTION, NAME=SMOOTH"]
    if c["method"] != "DEFAULT":
        out += [f"*SURFACE BEHAVIOR, {c['method']}"]
        if c["stiffness"] is not None:
            out += [f"{c['stiffness']:.17g}"]
    out += contact_lines(c["discretization"])
    eps = 1e-9 * W
    on = lambda x, v: abs(x - v) < eps
    out += ["*NSET, NSET=BOTTOM"] + lines([n for n, x in mn if on(x[-1], 0.0)]).splitlines()
    out += ["*NSET, NSET=TOP"] + lines([n for n, x in sn if on(x[-1], Hm + gap + Hs)]).splitlines()
    # both sides of the interface (general contact reports CPRESS on every exterior node of both)
    out += ["*NSET, NSET=IFACE"] + lines([n for n, x in mn if on(x[-1], Hm)] +
                                         [n for n, x in sn if on(x[-1], Hm + gap)]).splitlines()
    out += ["*NSET, NSET=XSIDES"] + lines([n for n, x in mn + sn if on(x[0], 0.0) or on(x[0], W)]).splitlines()
    bcs = ["*BOUNDARY", f"BOTTOM, {up}", "XSIDES, 1"]
    if dim == 3:
        out += ["*NSET, NSET=YSIDES"] + lines([n for n, x in mn + sn if on(x[1], 0.0) or on(x[1], W)]).splitlines()
        bcs += ["YSIDES, 2"]
    out += bcs
    # stabilize: "contact" (*CONTACT STABILIZATION, damping ramped off over the step) or "static"
    # (*STATIC, STABILIZE: automatic damping of the whole model) for a body that is free until
    # the contact closes
    static = "*STATIC, STABILIZE" if c["stabilize"] == "static" else "*STATIC"
    out += ["*STEP, NAME=PRESS", static, f"{c['inc']:g}, 1.0"]
    if c["stabilize"] == "contact":
        out += ["*CONTACT STABILIZATION"]
    if c["load"] == "pressure":
        out += ["*DSLOAD", f"TOP_S, P, {c['p']:.17g}"]
    else:
        out += ["*BOUNDARY", f"TOP, {up}, {up}, {-c['d']:.17g}"]
    controls = []
    if c["sf"] is not None:
        controls.append(f"STIFFNESS SCALE FACTOR={c['sf']:.17g}")
    if c["tol"] is not None:
        controls.append(f"RELATIVE PENETRATION TOLERANCE={c['tol']:g}")
    if controls:
        out += ["*CONTACT CONTROLS, " + ", ".join(controls)]
    out += ["*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*CONTACT OUTPUT", "CPRESS, COPEN, CSTATUS, CNAREA, CFN",
            "*END STEP"]
    text = "\n".join(out) + "\n"
    if c["unit"] == "m":
        text = to_metres(text)
    return text, expectation(c)


def expectation(c):
    """The analytic answer in the deck's units (mm, MPa; for unit m: m, Pa).

    General contact with a penalty law is two rows of weight ½ (balanced master-slave,
    contact/interaction_table.cpp, general_contact_one_row), both with the law of the mean of the
    two surfaces' k_e and characteristic lengths: the pressure that acts is that law at the
    common penetration h. Direct and augmented Lagrange hold a multiplier per node: one row, the
    finer surface as slave, with its own k_e."""
    dim = c["dim"]
    Ms, Mm = constrained(c["Es"], c["nus"]), constrained(c["Em"], c["num"])
    ns, nms = c["ns"], c["nms"] or max(1, round(c["ns"] * c["Hs"] / c["W"]))
    nm, nmm = c["nm"], c["nmm"] or max(1, round(c["nm"] * c["Hm"] / c["W"]))
    method = c["method"]
    sf = c["sf"] if c["sf"] is not None else 1.0
    general = c["discretization"] == GENERAL
    # (k_e, characteristic length) of each row's slave: the upper block's bottom; with balanced
    # general contact also the lower block's top
    # k_e with the softer of the two materials (contact/normal_behavior.cpp, softer_element_stiffness)
    M = min(Ms, Mm)
    upper, lower = (M / (c["Hs"] / nms), c["W"] / ns), (M / (c["Hm"] / nmm), c["W"] / nm)
    if not general:
        sides = [upper]
    elif method not in ("DIRECT", "AUGMENTED LAGRANGE"):
        # both rows take the mean of the two surfaces' k_e and characteristic length
        # (contact/resolved_interaction.cpp, resolve_scales): one law, the same gap
        mean = ((upper[0] + lower[0]) / 2, (upper[1] + lower[1]) / 2)
        sides = [mean, mean]
    else:  # one row: the smaller facets are the slave (ties: the first body, the lower block)
        sides = [upper if upper[1] < lower[1] else lower]
    ke, l_char = sides[0]
    laws = []
    for ke_i, l_i in sides:
        if method == "PENALTY":
            k_i = (c["stiffness"] if c["stiffness"] is not None else 10.0 * ke_i) * sf
            laws.append((k_i, lambda s, k_i=k_i: k_i * s if s > 0 else 0.0))
        elif method == "AUGMENTED LAGRANGE":
            k_i = (c["stiffness"] if c["stiffness"] is not None else 1000.0 * ke_i) * sf
            laws.append((k_i, None))
        elif method == "PENALTY=NONLINEAR":
            kf = (c["stiffness"] if c["stiffness"] is not None else 100.0 * ke_i) * sf
            sd = 0.03 * l_i
            laws.append((kf, lambda s, kf=kf, sd=sd: nonlinear_penalty(s, kf, 0.01 * kf, sd / 3.0, sd)))
    k = sum(k_i for k_i, _ in laws) / len(laws) if laws else None
    compliance = c["Hs"] / Ms + c["Hm"] / Mm

    def pen(p):
        if method == "PENALTY" and len(laws) == 1:
            return p / k
        if method in ("PENALTY", "PENALTY=NONLINEAR"):
            law = lambda s: sum(f(s) for _, f in laws) / len(laws)
            return invert(law, p, p / k)
        return 0.0  # direct; augmented Lagrange within its tolerance (checked apart)

    gap = c["gap"]
    if c["load"] == "pressure":
        p = c["p"]
    else:
        # d = p C + h(p) + g
        target = c["d"] - gap
        p = invert(lambda q: q * compliance + pen(q), target, target / compliance) if target > 0 else 0.0
    h = pen(p)
    u_top = -(p * compliance + h + gap)
    tol_pen = None
    if method == "AUGMENTED LAGRANGE":
        # default: 0.1 % of the characteristic length, 5 % for finite-sliding surface to surface
        # (general contact included), / sqrt(sf) when sf < 1 (contact/normal_behavior.cpp)
        base = 0.001 if c["discretization"] == "NODE TO SURFACE" else 0.05
        tol_pen = (c["tol"] if c["tol"] is not None else (base / math.sqrt(sf) if sf < 1 else base)) * \
            min(l for _, l in sides)  # every row under its own tolerance
    exp = dict(p=p, penetration=h, u_top=u_top, ke=ke, l_char=l_char, k=k, tol_pen=tol_pen,
               force=p * c["W"] ** (dim - 1), dim=dim, compliance=compliance, load=c["load"], gap=float(gap),
               d=float(c["d"] or 0.0), general=general, rows=len(sides),
               ks=[k_i for k_i, _ in laws], kes=[ke_i for ke_i, _ in sides], W=c["W"])
    if c["unit"] == "m":
        exp = {key: (v * SCALE.get(key, 1.0) if isinstance(v, float) else v) for key, v in exp.items()}
        exp["ks"] = [v * SCALE["k"] for v in exp["ks"]]
        exp["kes"] = [v * SCALE["ke"] for v in exp["kes"]]
        exp["force"] *= force_scale(dim)
    return exp


# mm → m: lengths × 1e-3, stresses × 1e6; k (stress/length) × 1e9; forces: force_scale
SCALE = dict(p=1e6, penetration=1e-3, u_top=1e-3, ke=1e9, l_char=1e-3, k=1e9, tol_pen=1e-3, force=1.0,
             compliance=1e-9, gap=1e-3, d=1e-3, W=1e-3)


def force_scale(dim):
    """mm → m factor of a nodal force: N in 3-D; in 2-D a force per unit thickness (the section's
    default thickness is 1 model length unit), N/mm → N/m, × 1e3."""
    return 1.0 if dim == 3 else 1e3


def to_metres(text):
    """The same deck in N, m, Pa: coordinates and displacements × 1e-3, moduli and pressures × 1e6,
    penalty stiffnesses × 1e9. Handles the keywords blocks.py and the verification generator write."""
    out, kw, penalty_line = [], "", False
    num = lambda s, f: f"{float(s) * f:.17g}"
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("**"):
            out.append(line)
            continue
        if s.startswith("*"):
            kw = s.split(",")[0].upper().replace(" ", "")
            flat = s.upper().replace(" ", "")
            penalty_line = kw == "*SURFACEBEHAVIOR" and ("PENALTY" in flat or "AUGMENTEDLAGRANGE" in flat)
            out.append(line)
            continue
        f = [x.strip() for x in line.split(",")]
        if kw == "*NODE":
            f = [f[0]] + [num(x, 1e-3) for x in f[1:]]
        elif kw == "*ELASTIC":
            f = [num(f[0], 1e6)] + f[1:]
        elif kw == "*DSLOAD":
            f = f[:2] + [num(f[2], 1e6)]
        elif kw == "*BOUNDARY" and len(f) == 4:
            f = f[:3] + [num(f[3], 1e-3)]
        elif penalty_line and f[0]:
            f = [num(f[0], 1e9)] + f[1:]
        out.append(", ".join(f))
    return "\n".join(out) + "\n"
