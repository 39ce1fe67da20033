#!/usr/bin/python3
"""meshio reads every frame of the XDMF sidecars (XDMF 3 TimeSeriesReader).

Usage: check_meshio.py SAMPLE_DIR
"""
import sys

try:
    import meshio
    import numpy as np
except ImportError as e:  # the Debian packages are installed by .ci/install-deps.sh
    print(f"skipped: {e}")
    sys.exit(77)

sample = sys.argv[1]


def u_value(k, n, c):
    return 0.001 * (k + 1) * (n + 1) + 0.1 * c


with meshio.xdmf.TimeSeriesReader(f"{sample}/three_body.xdmf") as r:
    points, cells = r.read_points_cells()
    assert points.shape == (15, 3)
    assert [(c.type, len(c.data)) for c in cells] == [("hexahedron", 1), ("tetra", 1), ("wedge", 1)], cells
    assert cells[1].data.tolist() == [[4, 5, 6, 8]]
    assert r.num_steps == 4
    times = []
    for k in range(r.num_steps):
        t, point_data, cell_data = r.read_data(k)
        times.append(t)
        u = point_data["U"]
        assert u.shape == (15, 3)
        expected = np.array([[u_value(k, n, c) for c in range(3)] for n in range(15)])
        assert (u == expected).all(), (k, u)
        assert ("RF" in point_data) == (k != 3)
        assert [a.shape for a in cell_data["S"]] == [(1, 6)] * 3
        assert len(cell_data["S_Mises"]) == 3
    assert times == [0.5, 1.0, 2.0, 3.0], times

with meshio.xdmf.TimeSeriesReader(f"{sample}/hex20.xdmf") as r:
    points, cells = r.read_points_cells()
    assert [(c.type, c.data.shape) for c in cells] == [("hexahedron20", (1, 20))]
    assert r.num_steps == 2
    for k in range(2):
        t, point_data, cell_data = r.read_data(k)
        assert t == 0.5 * (k + 1)
        assert np.allclose(point_data["U"], 0.01 * (k + 1) * points)
        assert cell_data["S"][0][0, 0] == k + 1

print("meshio: every frame read")
