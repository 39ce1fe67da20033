#!/usr/bin/python3
"""h5py reads every dataset of the sample results files and checks the values.

The formulas are those of tests/io/sample_jobs.cpp. Usage: check_h5py.py SAMPLE_DIR
"""
import math
import sys

try:
    import h5py
    import numpy as np
except ImportError as e:  # the Debian packages are installed by .ci/install-deps.sh
    print(f"skipped: {e}")
    sys.exit(77)

sample = sys.argv[1]


def u_value(k, n, c):
    return 0.001 * (k + 1) * (n + 1) + 0.1 * c


def s_value(k, loc, c):
    return 100.0 * k + 10.0 * c + loc


def read_everything(f):
    """Reads every dataset (h5py follows the hard links of /VTKHDF too)."""
    names = []

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset):
            obj[()]
            names.append(name)
    f.visititems(visit)
    return names


with h5py.File(f"{sample}/three_body.h5", "r") as f:
    names = read_everything(f)
    assert len(names) > 40, names
    a = f.attrs
    assert a["schema"] == "inpact-results", a["schema"]
    assert a["schema_version"] == 1
    assert a["status"] == "COMPLETED"
    assert a["deck_sha256"] == "a" * 64

    nodes = f["model/nodes"]
    assert nodes["coordinates"].shape == (15, 3) and nodes["coordinates"].dtype == np.float64
    assert list(nodes["labels"][()]) == list(range(1, 16))
    assert nodes["labels"].dtype == np.int64 and nodes["instance"].dtype == np.int32
    assert list(f["model/instances"].asstr()[()]) == [""]
    assert list(f["model/elements"].keys()) == ["C3D4", "C3D6", "C3D8"]
    assert f["model/elements/C3D8/connectivity"].shape == (1, 8)
    assert list(f["model/elements/C3D4/connectivity"][0]) == [4, 5, 6, 8]
    assert list(f["model/sets/elsets/ALL_E"][()]) == [0, 1, 2]
    assert f["model/sets/surfaces/SLAVE_S"][()].tolist() == [[2, 4]]
    assert f["model/sets/surfaces/TIPS"].attrs["kind"] == "NODE"
    assert list(f["model/contact/pairs"].asstr()[()]) == ["SLAVE_S/MASTER_S"]

    # Steps and fields in the order they were written (creation order is tracked).
    assert list(f["steps"].keys()) == ["Load", "Unload"], list(f["steps"].keys())
    load = f["steps/Load"]
    assert load.attrs["procedure"] == "STATIC" and load.attrs["nlgeom"] == 1
    assert load.attrs["time_period"] == 1.0
    assert list(load["fieldOutputs"].keys()) == ["U", "RF", "S", "CPRESS"]
    assert f["steps/Unload/frames/total_time"][()].tolist() == [2.0, 3.0]
    assert f["steps/Unload/frames/increment"][()].tolist() == [1, 2]

    u = f["steps/Unload/fieldOutputs/U"]
    assert u.attrs["position"] == "NODAL"
    assert list(u.attrs["componentLabels"]) == ["U1", "U2", "U3"]
    data = u["data"][()]
    assert data.shape == (2, 15, 3)
    for fr in range(2):
        for n in range(15):
            for c in range(3):
                assert data[fr, n, c] == u_value(2 + fr, n, c)
    rf = f["steps/Unload/fieldOutputs/RF/data"][()]
    assert rf.shape == (2, 4, 3) and np.isnan(rf[1]).all() and not np.isnan(rf[0]).any()
    s = f["steps/Load/fieldOutputs/S"]
    assert s.attrs["position"] == "INTEGRATION_POINT"
    assert s["data"].shape == (2, 11, 6)
    assert s["data"][1, 10, 5] == s_value(1, 10, 5)
    assert s["elements"][()].tolist() == [1] * 8 + [2, 7, 7]
    assert s["ip"][()].tolist() == list(range(1, 9)) + [1, 1, 2]
    cp = f["steps/Load/fieldOutputs/CPRESS"]
    assert cp.attrs["region"] == "SLAVE_S/MASTER_S"
    assert cp["pair"][()].tolist() == [0, 0, 0, 0]
    assert cp["data"][0, :, 0].tolist() == [1000.0, 1001.0, 1002.0, 1003.0]

    st = f["status"][()]
    assert st.dtype.names == ("step", "increment", "attempt", "cut_back", "severe_discon_iters", "equil_iters",
                              "total_iters", "total_time", "step_time", "inc_of_time", "augmentations"), st.dtype
    assert st["cut_back"].tolist() == [1, 0, 0]
    assert st["total_iters"].tolist() == [12, 5, 2]

    vtk = f["VTKHDF"]
    assert list(vtk.attrs["Version"]) == [1, 0]
    assert vtk.attrs["Type"] == b"UnstructuredGrid"
    assert vtk["Types"][()].tolist() == [12, 10, 13]
    assert vtk["PointData/U"][14, 1] == u_value(3, 14, 1)
    sc = vtk["CellData/S"][()]
    assert math.isclose(sc[0, 0], sum(s_value(3, i, 0) for i in range(8)) / 8)
    assert sorted(f["xdmf/frames"].keys(), key=int) == ["0", "1", "2", "3"]

with h5py.File(f"{sample}/all_types.h5", "r") as f:
    read_everything(f)
    assert f["VTKHDF/Types"][()].tolist() == [12, 25, 10, 24, 13, 9, 23, 5, 22]
    assert f["model/elements/C3D20/connectivity"].shape == (1, 20)
    xyz = f["model/nodes/coordinates"][()]
    assert (xyz[48:, 2] == 0).all()  # 2D elements: z = 0

print("h5py: every dataset read, values as written")
