#!/usr/bin/env python3
"""Writes the 2D solver benchmark problem: a unit square of N x N CPE4 elements (plane strain),
the 2D counterpart of solver_gen_cube.py, for the direct/petsc crossover in two dimensions.

    python3 bench/solver_gen_square.py N OUT.inp

The problem: the edge y = 0 is clamped (*BOUNDARY 1-2), a uniform pressure of 100 pushes on the
edge y = 1 (*DLOAD P3 on the top element row), steel (E = 210000, nu = 0.3); one linear static
step. The "tip" is the corner node (1, 1), printed as in the cube. Generated into the bench's
work folder; never commit it.
"""
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: solver_gen_square.py N OUT.inp")
    n = int(sys.argv[1])
    m = n + 1
    h = 1.0 / n
    with open(sys.argv[2], "w", buffering=1 << 22) as out:
        out.write("*HEADING\nSolver benchmark: clamped CPE4 square %d^2 under pressure (bench/solver_gen_square.py)\n" % n)
        out.write("*NODE, NSET=ALLN\n")
        for j in range(m):
            out.write("".join("%d, %.12g, %.12g\n" % (1 + i + m * j, i * h, j * h) for i in range(m)))
        out.write("*ELEMENT, TYPE=CPE4, ELSET=SQUARE\n")
        for j in range(n):
            out.write("".join("%d, %d, %d, %d, %d\n" % (1 + i + n * j, 1 + i + m * j, 2 + i + m * j, 2 + i + m * (j + 1),
                                                        1 + i + m * (j + 1)) for i in range(n)))
        out.write("*NSET, NSET=BOTTOM, GENERATE\n1, %d, 1\n" % m)
        out.write("*NSET, NSET=TIP\n%d\n" % (m * m))
        out.write("*ELSET, ELSET=TOP_EL, GENERATE\n%d, %d, 1\n" % (1 + n * (n - 1), n * n))
        out.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n")
        out.write("*SOLID SECTION, ELSET=SQUARE, MATERIAL=STEEL\n1.\n")
        out.write("*BOUNDARY\nBOTTOM, 1, 2\n")
        out.write("*STEP\n*STATIC\n1., 1.\n*DLOAD\nTOP_EL, P3, 100.\n")
        out.write("*OUTPUT, FIELD\n*NODE OUTPUT\nU\n*NODE PRINT, NSET=TIP\nU\n*END STEP\n")


if __name__ == "__main__":
    main()
