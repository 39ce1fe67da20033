#!/usr/bin/env python3
"""Writes the solver benchmark problem, a unit cube of N x N x N C3D8 elements, in two dialects.

    python3 bench/solver_gen_cube.py N OUT_INPACT.inp OUT_CCX.inp

The problem: the face z = 0 is clamped (*BOUNDARY 1-3), a uniform pressure of 100 pushes on
the face z = 1 (*DLOAD P2 on the top element layer), steel (E = 210000, nu = 0.3); one linear
static step (*STATIC, one increment). The "tip" is the corner node (1, 1, 1); both decks print
its displacement (*NODE PRINT), which is how the benchmark checks that inpact and CalculiX
solve the same problem. Both files are generated into the build tree; never commit them.

The CalculiX deck differs only where the dialects do: *NODE PRINT writes ccx's .dat, and
*NODE FILE / *EL FILE request U and S in its .frd (as inpact's *OUTPUT requests in its .h5).
"""
import sys

import cube_mesh


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: solver_gen_cube.py N OUT_INPACT.inp OUT_CCX.inp")
    n = int(sys.argv[1])
    m = n + 1
    h = 1.0 / n

    def node(i, j, k):
        return cube_mesh.node_label(n, i, j, k)

    def elem(i, j, k):
        return cube_mesh.element_label(n, i, j, k)

    mesh = []
    mesh.append("*NODE, NSET=ALLN\n")
    for k in range(m):
        for j in range(m):
            base = node(0, j, k)
            mesh.append("".join("%d, %.12g, %.12g, %.12g\n" % (base + i, i * h, j * h, k * h) for i in range(m)))
    mesh.append("*ELEMENT, TYPE=C3D8, ELSET=CUBE\n")
    for block in cube_mesh.element_rows(n):
        mesh.append(block)
    mesh.append("*NSET, NSET=BOTTOM, GENERATE\n1, %d, 1\n" % (m * m))
    mesh.append("*NSET, NSET=TIP\n%d\n" % node(n, n, n))
    mesh.append("*ELSET, ELSET=TOP_EL, GENERATE\n%d, %d, 1\n" % (elem(0, 0, n - 1), elem(n - 1, n - 1, n - 1)))
    mesh.append("*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n")
    mesh.append("*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL\n")
    mesh.append("*BOUNDARY\nBOTTOM, 1, 3\n")
    mesh = "".join(mesh)

    step = "*STEP\n*STATIC\n1., 1.\n*DLOAD\nTOP_EL, P2, 100.\n"
    title = "*HEADING\nSolver benchmark: clamped C3D8 cube %d^3 under pressure (bench/solver_gen_cube.py)\n" % n

    with open(sys.argv[2], "w", buffering=1 << 22) as out:
        out.write(title + mesh + step)
        out.write("*OUTPUT, FIELD\n*NODE OUTPUT\nU\n*NODE PRINT, NSET=TIP\nU\n*END STEP\n")
    with open(sys.argv[3], "w", buffering=1 << 22) as out:
        out.write(title + mesh + step)
        out.write("*NODE FILE\nU\n*EL FILE\nS\n*NODE PRINT, NSET=TIP\nU\n*END STEP\n")


if __name__ == "__main__":
    main()
