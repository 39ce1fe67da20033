#!/usr/bin/env python3
"""Writes the shell solver benchmark problem: a unit square plate of N x N S4 shells, the shell
counterpart of solver_gen_cube.py / solver_gen_square.py, for the direct/petsc crossover on
shells (3D models whose sparsity is 2D-like).

    python3 bench/solver_gen_plate.py N OUT.inp [ELTYPE]

The problem: the edge y = 0 is clamped (*BOUNDARY ENCASTRE), a uniform pressure P = 1 acts on
every element (*DLOAD P, along the +z normal), thickness 0.01, steel (E = 210000, nu = 0.3); one
linear static step. The "tip" is the corner node (1, 1), printed as in the cube. ELTYPE defaults
to S4 (S4R also works). Generated into the bench's work folder; never commit it.
"""
import sys


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: solver_gen_plate.py N OUT.inp [ELTYPE]")
    n = int(sys.argv[1])
    eltype = sys.argv[3] if len(sys.argv) == 4 else "S4"
    m = n + 1
    h = 1.0 / n
    with open(sys.argv[2], "w", buffering=1 << 22) as out:
        out.write("*HEADING\nSolver benchmark: clamped %s plate %d^2 under pressure (bench/solver_gen_plate.py)\n"
                  % (eltype, n))
        out.write("*NODE, NSET=ALLN\n")
        for j in range(m):
            out.write("".join("%d, %.12g, %.12g, 0.\n" % (1 + i + m * j, i * h, j * h) for i in range(m)))
        out.write("*ELEMENT, TYPE=%s, ELSET=PLATE\n" % eltype)
        for j in range(n):
            out.write("".join("%d, %d, %d, %d, %d\n" % (1 + i + n * j, 1 + i + m * j, 2 + i + m * j, 2 + i + m * (j + 1),
                                                        1 + i + m * (j + 1)) for i in range(n)))
        out.write("*NSET, NSET=BOTTOM, GENERATE\n1, %d, 1\n" % m)
        out.write("*NSET, NSET=TIP\n%d\n" % (m * m))
        out.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n")
        out.write("*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL\n0.01\n")
        out.write("*BOUNDARY\nBOTTOM, ENCASTRE\n")
        out.write("*STEP\n*STATIC\n1., 1.\n*DLOAD\nPLATE, P, 1.\n")
        out.write("*OUTPUT, FIELD\n*NODE OUTPUT\nU\n*NODE PRINT, NSET=TIP\nU\n*END STEP\n")


if __name__ == "__main__":
    main()
