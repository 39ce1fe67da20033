"""ParaView 5.11 (Debian python3-paraview, run with pvpython) opens the results file through
its VTKHDF reader and the sidecar through its XDMF readers, validates the cells of every
element type and renders U magnitude and S to PNG images that must not be blank.

Usage: pvpython check_paraview.py SAMPLE_DIR   (needs a display: xvfb-run -a pvpython ...)
"""
import sys

from paraview import servermanager as sm
from paraview.simple import (ColorBy, CreateRenderView, Render, ResetCamera, SaveScreenshot, Show,
                             VTKHDFReader, Xdmf3ReaderT)
from vtkmodules.numpy_interface import dataset_adapter as dsa
from vtkmodules.vtkFiltersGeneral import vtkCellValidator
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy
import numpy as np

sample = sys.argv[1]


def u_value(k, n, c):
    return 0.001 * (k + 1) * (n + 1) + 0.1 * c


def fetch(source, time=None):
    source.UpdatePipeline(time) if time is not None else source.UpdatePipeline()
    return dsa.WrapDataObject(sm.Fetch(source))


def u_expected(k, n_nodes=15):
    return np.array([[u_value(k, n, c) for c in range(3)] for n in range(n_nodes)])


# VTKHDF 1.0: the last frame (k = 3).
h5 = VTKHDFReader(FileName=[f"{sample}/three_body.h5"])
d = fetch(h5)
assert d.GetNumberOfPoints() == 15 and d.GetNumberOfCells() == 3
assert sorted(d.PointData.keys()) == ["CPRESS", "U"], d.PointData.keys()
assert sorted(d.CellData.keys()) == ["S", "S_Mises"], d.CellData.keys()
assert (np.asarray(d.PointData["U"]) == u_expected(3)).all()
assert list(np.asarray(d.CellTypes)) == [12, 10, 13]

# XDMF (Xdmf3ReaderT): every frame.
xdmf = Xdmf3ReaderT(FileName=[f"{sample}/three_body.xdmf"])
assert list(xdmf.TimestepValues) == [0.5, 1.0, 2.0, 3.0], xdmf.TimestepValues
for k, t in enumerate(xdmf.TimestepValues):
    d = fetch(xdmf, t)
    assert (np.asarray(d.PointData["U"]) == u_expected(k)).all(), k
    assert ("RF" in d.PointData.keys()) == (k != 3)
    assert np.asarray(d.CellData["S"]).shape == (3, 6)

# One cell of every type: VTK's validator finds Abaqus's node order valid (orientation,
# non-convexity, non-planar faces), through both readers.
expected_types = [12, 25, 10, 24, 13, 9, 23, 5, 22]
for reader in (VTKHDFReader(FileName=[f"{sample}/all_types.h5"]), Xdmf3ReaderT(FileName=[f"{sample}/all_types.xdmf"])):
    reader.UpdatePipeline(reader.TimestepValues[-1] if len(reader.TimestepValues) else None)
    grid = sm.Fetch(reader)
    assert list(vtk_to_numpy(grid.GetCellTypesArray())) == expected_types, vtk_to_numpy(grid.GetCellTypesArray())
    validator = vtkCellValidator()
    validator.SetInputData(grid)
    validator.Update()
    states = vtk_to_numpy(validator.GetOutput().GetCellData().GetArray("ValidityState"))
    assert (states == 0).all(), f"invalid cells: {list(zip(expected_types, states))}"


def render(source, association, array, component, png, time=None):
    view = CreateRenderView()
    view.ViewSize = [400, 300]
    view.OrientationAxesVisibility = 0
    if time is not None:
        view.ViewTime = time
    display = Show(source, view)
    ColorBy(display, (association, array, component) if component else (association, array))
    display.RescaleTransferFunctionToDataRange(True)
    ResetCamera(view)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[400, 300])
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    img = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3]
    background = img[0]
    drawn = np.any(img != background, axis=1).mean()
    colours = len(np.unique(img[np.any(img != background, axis=1)], axis=0))
    assert drawn > 0.02 and colours > 10, f"{png}: blank image ({drawn:.3f} drawn, {colours} colours)"
    return drawn, colours


print("U magnitude (VTKHDF):", render(h5, "POINTS", "U", "Magnitude", f"{sample}/u_magnitude_vtkhdf.png"))
print("S XX (XDMF, last frame):", render(xdmf, "CELLS", "S", "XX", f"{sample}/s_xdmf.png", 3.0))
print("S_Mises (VTKHDF):", render(h5, "CELLS", "S_Mises", None, f"{sample}/s_mises_vtkhdf.png"))
print("paraview: VTKHDF and XDMF read, cells valid, images drawn")
