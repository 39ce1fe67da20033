"""Plane-strain contact decks as one-element-thick C3D8 slabs, readable by CalculiX and inpact alike.

CalculiX expands 2-D elements into 3-D ones itself (three node layers, its own labels), so a 2-D deck
would not give both solvers the same system. Instead, the CPE4 decks of
decks/contact_verification/gen_contact_verification.py are extruded here into one layer of C3D8
elements of thickness t, with U3 = 0 on every node: plane strain, the same mesh and DOF count for
both solvers, node labels known (layer 2 = label + offset).

    slab_deck(lines_2d, t, contact, step_output, no_contact=False, ccx=True)  -> deck text
"""
import math

# CPE4 edge → C3D8 face of the extruded element [a b c d | a' b' c' d']
FACE = {"S1": "S3", "S2": "S4", "S3": "S5", "S4": "S6"}


def parse_2d(lines):
    """Blocks of a generated 2-D deck: nodes, elements (by elset), elsets, nsets, surfaces, the
    material lines, boundary lines before the step, the step's *STATIC line and its boundary lines."""
    d = dict(nodes=[], elements={}, elsets={}, nsets={}, surfaces={}, sections=[], material=[], boundary=[],
             static=None, step_boundary=[], heading=[])
    kw, name, in_step = None, None, False
    for ln in lines:
        s = ln.strip()
        if not s or s.startswith("**"):
            continue
        if s.startswith("*"):
            parts = [p.strip() for p in s.split(",")]
            kw = parts[0].upper()
            opts = {}
            for p in parts[1:]:
                if "=" in p:
                    k, v = p.split("=", 1)
                    opts[k.strip().upper()] = v.strip()
            if kw == "*ELEMENT":
                name = opts["ELSET"]
                d["elements"][name] = (opts["TYPE"], [])
            elif kw in ("*ELSET", "*NSET"):
                name = opts["ELSET" if kw == "*ELSET" else "NSET"]
                d["elsets" if kw == "*ELSET" else "nsets"].setdefault(name, [])
            elif kw == "*SURFACE":
                name = opts["NAME"]
                d["surfaces"][name] = []
            elif kw == "*SOLID SECTION":
                d["sections"].append((opts["ELSET"], opts["MATERIAL"]))
            elif kw == "*MATERIAL":
                d["material"].append(s)
            elif kw in ("*ELASTIC", "*PLASTIC"):
                d["material"].append(s)
            elif kw == "*STEP":
                in_step = True
            continue
        if kw == "*HEADING":
            d["heading"].append(s)
        elif kw == "*NODE":
            f = [x.strip() for x in s.split(",")]
            d["nodes"].append((int(f[0]), float(f[1]), float(f[2])))
        elif kw == "*ELEMENT":
            d["elements"][name][1].append([int(x) for x in s.split(",")])
        elif kw == "*ELSET":
            d["elsets"][name] += [int(x) for x in s.split(",") if x.strip()]
        elif kw == "*NSET":
            d["nsets"][name] += [int(x) for x in s.split(",") if x.strip()]
        elif kw == "*SURFACE":
            es, face = [x.strip() for x in s.split(",")]
            d["surfaces"][name].append((es, face))
        elif kw in ("*ELASTIC", "*PLASTIC"):
            d["material"].append(s)
        elif kw == "*BOUNDARY":
            (d["step_boundary"] if in_step else d["boundary"]).append(s)
        elif kw == "*STATIC":
            d["static"] = s
    return d


def lines_of(labels, per=16):
    labels = sorted(set(labels))
    return [", ".join(str(n) for n in labels[i:i + per]) for i in range(0, len(labels), per)]


def offset_of(d):
    top = max(n for n, _, _ in d["nodes"])
    return 10 ** len(str(top))


def slab_deck(lines_2d, t, contact, step_output, no_contact=False, ccx=True, title="", nlgeom=False):
    """The 3-D slab deck. `contact`: the interaction and pair lines (with {slave} and {master}
    already filled); `step_output`: output request lines of the step. ccx: CalculiX spelling of
    *STEP (no NAME parameter). nlgeom: the step has NLGEOM."""
    d = parse_2d(lines_2d)
    off = offset_of(d)
    out = ["*HEADING", f" {title or ' '.join(d['heading'])[:200]}",
           "** Extruded into a one-element-thick C3D8 slab with U3 = 0 (plane strain) by bench/contact_ccx/slab.py",
           f"** thickness {t:.17g}; node n of the 2-D mesh is n (z = 0) and n + {off} (z = t)"]
    out += ["*NODE, NSET=ALL"]
    for z, add in ((0.0, 0), (t, off)):
        # 15 digits: CalculiX reads at most 20 characters a field (17 digits and an exponent are 22)
        out += [f"{n + add}, {x:.15g}, {y:.15g}, {z:.15g}" for n, x, y in d["nodes"]]
    for es, (etype, rows) in d["elements"].items():
        assert etype == "CPE4", etype
        out += [f"*ELEMENT, TYPE=C3D8, ELSET={es}"]
        out += [f"{e}, {a}, {b}, {c}, {dd}, {a + off}, {b + off}, {c + off}, {dd + off}" for e, a, b, c, dd in rows]
    for name, labels in d["elsets"].items():
        out += [f"*ELSET, ELSET={name}"] + lines_of(labels)
    for name, labels in d["nsets"].items():
        out += [f"*NSET, NSET={name}"] + lines_of(labels + [n + off for n in labels])
    for name, faces in d["surfaces"].items():
        out += [f"*SURFACE, NAME={name}"] + [f"{es}, {FACE[f]}" for es, f in faces]
    for es, mat in d["sections"]:
        out += [f"*SOLID SECTION, ELSET={es}, MATERIAL={mat}"]
    out += d["material"]
    if not no_contact:
        out += contact
    out += ["*BOUNDARY", "ALL, 3"] + d["boundary"]
    step = "*STEP" if ccx else "*STEP, NAME=S1"
    out += [step + (", NLGEOM" if nlgeom else ""), "*STATIC", d["static"]]
    if d["step_boundary"]:
        out += ["*BOUNDARY"] + d["step_boundary"]
    out += step_output + ["*END STEP"]
    return "\n".join(out) + "\n", d, off


def slave_geometry(d, off, surface, t):
    """Slave nodes (both layers) of a 2-D surface extruded, with their tributary areas (a quarter of
    each 3-D face) and 2-D coordinates: {label: (area, x, y)}."""
    xy = {n: (x, y) for n, x, y in d["nodes"]}
    elems = {}
    for etype, rows in d["elements"].values():
        for e, *nodes in rows:
            elems[e] = nodes
    edge = {"S1": (0, 1), "S2": (1, 2), "S3": (2, 3), "S4": (3, 0)}
    out = {}
    for es, face in d["surfaces"][surface]:
        for e in d["elsets"][es]:
            i, j = edge[face]
            a, b = elems[e][i], elems[e][j]
            length = math.dist(xy[a], xy[b])
            for n in (a, b, a + off, b + off):
                x, y = xy[n if n < off else n - off]
                area = out.get(n, (0.0, x, y))[0] + 0.25 * length * t
                out[n] = (area, x, y)
    return out
