#!/usr/bin/env python3
"""Generator of the *TRANSFORM verification decks (decks/verification/transform_*.inp).

    gen_transforms.py --out DIR

  transform_cube_c3d8      a unit cube turned by 30° about z, held by rollers on three faces
                           and stretched by 0.01 along its own x, every condition in its local
                           rectangular axes (TYPE=R): uniaxial stress, exact
  transform_ring_c3d20r    a 30° sector of a thick cylinder under internal pressure, its cut
                           faces held in the tangential direction of a cylindrical system
                           (TYPE=C) about z, plane strain: Lamé

Each deck states its reference in its header; tests/verification/test_transform.cpp checks them.
Uses gen_verification.py's deck writer and structured meshes.
"""
import argparse
import math
import os

from gen_verification import Deck, grid_hex, select

EPS = 1e-9
E, NU = 210000.0, 0.3
MATERIAL = ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}"]


def transform_cube():
    """The cube [0, 1]³ in local axes x' = (cos 30°, sin 30°, 0), y' = (−sin 30°, cos 30°, 0),
    z' = z, placed by that rotation: rollers U1' = 0 on x' = 0, U2' = 0 on y' = 0, U3 = 0 on
    z = 0, and U1' = 0.01 on x' = 1."""
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    coords, conn = grid_hex(2, 2, 2, (0, 0, 0), (1, 1, 1), False)[:2]
    local = dict(coords)
    coords = {k: (c * x - s * y, s * x + c * y, z) for k, (x, y, z) in local.items()}
    d = Deck("A turned unit cube stretched along its own x, every condition in its *TRANSFORM axes (TYPE=R)",
             ["Reference: uniaxial stress along x': U1' = 0.01 x', U2' = -nu 0.01 y', U3' = -nu 0.01 z',",
              f"S11' = E 0.01 = {E * 0.01:g}; the stretched face's RF1' sums to {E * 0.01:g} (exact)."])
    d.nodes(coords, 3)
    d.elements("C3D8", "CUBE", conn)
    d.nset("X0", select(local, lambda x: abs(x[0]) < EPS))
    d.nset("Y0", select(local, lambda x: abs(x[1]) < EPS))
    d.nset("Z0", select(local, lambda x: abs(x[2]) < EPS))
    d.nset("X1", select(local, lambda x: abs(x[0] - 1) < EPS))
    d.add("*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL", *MATERIAL)
    d.add("*TRANSFORM, NSET=ALL, TYPE=R", f"{c:.17g}, {s:.17g}, 0., {-s:.17g}, {c:.17g}, 0.")
    d.add("*BOUNDARY", "X0, 1, 1", "Y0, 2, 2", "Z0, 3, 3")
    d.add("*STEP", "*STATIC", "*BOUNDARY", "X1, 1, 1, 0.01")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*ELEMENT OUTPUT", "S",
          "*NODE PRINT, NSET=X1", "U, RF", "*NODE PRINT, NSET=X1, GLOBAL=YES", "U, RF", "*END STEP")
    return d


RING = dict(ri=10.0, ro=20.0, p=100.0, angle=30.0, h=1.0)


def transform_ring():
    """The sector ri ≤ r ≤ ro, 0 ≤ θ ≤ 30°, 0 ≤ z ≤ h, C3D20R 4 × 3 × 1, every node in a
    cylindrical system about z: U2 (tangential) = 0 on both cut faces, U3 = 0 everywhere
    (plane strain), pressure p on the bore."""
    ri, ro, p, angle, h = RING["ri"], RING["ro"], RING["p"], math.radians(RING["angle"]), RING["h"]
    polar, conn = grid_hex(4, 3, 1, (ri, 0.0, 0.0), (ro, angle, h), True)[:2]
    coords = {k: (r * math.cos(t), r * math.sin(t), z) for k, (r, t, z) in polar.items()}
    k = p * ri * ri / (ro * ro - ri * ri)
    ur = (1 + NU) * k / E * ((1 - 2 * NU) * ri + ro * ro / ri)
    d = Deck(f"A {RING['angle']:g} degree sector of a thick cylinder under internal pressure, its cut faces held "
             "in a cylindrical *TRANSFORM (TYPE=C), plane strain, C3D20R 4x3x1",
             [f"ri = {ri:g}, ro = {ro:g}, p = {p:g}, E = {E:g}, nu = {NU:g}",
              "Reference: Lame, u_r(r) = (1 + nu) k / E ((1 - 2 nu) r + ro^2 / r), k = p ri^2 / (ro^2 - ri^2);",
              f"u_r(ri) = {ur:.12g}, no tangential displacement."])
    d.nodes(coords, 3)
    d.elements("C3D20R", "WALL", conn)
    bore = [i + 1 for i, el in enumerate(conn) if all(abs(polar[n][0] - ri) < EPS for n in (el[0], el[3], el[4], el[7]))]
    d.elset("BORE_EL", bore)
    d.add("*SURFACE, NAME=BORE", "BORE_EL, S6")
    d.nset("CUTS", select(polar, lambda x: abs(x[1]) < EPS or abs(x[1] - angle) < EPS))
    d.add("*SOLID SECTION, ELSET=WALL, MATERIAL=STEEL", *MATERIAL)
    d.add("*TRANSFORM, NSET=ALL, TYPE=C", "0., 0., 0., 0., 0., 1.")
    d.add("*BOUNDARY", "CUTS, 2, 2", "ALL, 3, 3")
    d.add("*STEP", "*STATIC", "*DSLOAD", f"BORE, P, {p:g}")
    d.add("*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF", "*NODE PRINT, NSET=ALL", "U", "*END STEP")
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    for name, d in {"transform_cube_c3d8.inp": transform_cube(), "transform_ring_c3d20r.inp": transform_ring()}.items():
        d.write(os.path.join(a.out, name))


if __name__ == "__main__":
    main()
