"""Numbering and C3D8 connectivity of a structured N x N x N cube, shared by the benchmark
deck generators (gen_cube_deck.py for reading, solver_gen_cube.py for the solver)."""


def node_label(n, i, j, k):
    """Label of node (i, j, k), 0 <= i, j, k <= n, numbered x fastest."""
    m = n + 1
    return 1 + i + m * j + m * m * k


def element_label(n, i, j, k):
    """Label of element (i, j, k), 0 <= i, j, k < n."""
    return 1 + i + n * j + n * n * k


def element_rows(n):
    """The *ELEMENT, TYPE=C3D8 data lines, one string per row of elements along x."""
    m = n + 1
    for k in range(n):
        for j in range(n):
            rows = []
            for i in range(n):
                a = node_label(n, i, j, k)
                b = a + m * m
                rows.append("%d, %d, %d, %d, %d, %d, %d, %d, %d\n" % (
                    element_label(n, i, j, k), a, a + 1, a + 1 + m, a + m, b, b + 1, b + 1 + m, b + m))
            yield "".join(rows)
