"""Renders the contact pressure of the default job's last frame with ParaView (pvpython):

    xvfb-run -a pvpython bench/figures/render_cpress.py JOB.xdmf OUT.png [ELSET]

The last frame of the results file (through its XDMF sidecar, which ParaView 5.11 reads with its
time steps) is warped by U; the elements of ELSET (default PIN: the default job's pin, the
slave of its first contact row, whose nodes carry CPRESS in the view) are kept, mirrored about
the quarter model's symmetry planes (y = 0, z = 0), and coloured by CPRESS, grey where there is
no contact. The element set's rows come from the results file itself (/model/sets/elsets)."""
import os
import sys

import h5py
from paraview.simple import (ColorBy, GenerateIds, GetActiveViewOrCreate, GetAnimationScene,
                             GetColorTransferFunction, GetScalarBar, OpenDataFile, Reflect, ResetCamera, SaveScreenshot, Show,
                             Threshold, WarpByVector)


def element_rows(xdmf, elset):
    """Rows of ELSET's elements in the view's cell order (element rows of one element type)."""
    with h5py.File(os.path.splitext(xdmf)[0] + ".h5", "r") as f:
        rows = f[f"model/sets/elsets/{elset}"][:]
    return int(rows.min()), int(rows.max())


def last_frame(xdmf, view):
    source = OpenDataFile(xdmf)
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    times = list(source.TimestepValues) if source.TimestepValues else [0.0]
    scene.AnimationTime = times[-1]
    view.ViewTime = times[-1]
    return source


def whole_body(source, first, last):
    ids = GenerateIds(Input=WarpByVector(Input=source, Vectors=["POINTS", "U"]))
    ids.GeneratePointIds = 0  # point ids would take CPRESS's place as the active scalars
    ids.GenerateCellIds = 1
    ids.CellIdsArrayName = "row"
    body = Threshold(Input=ids, Scalars=["CELLS", "row"], LowerThreshold=first, UpperThreshold=last)
    return Reflect(Input=Reflect(Input=body, Plane="Y Min", CopyInput=1), Plane="Z Min", CopyInput=1)


def main(xdmf, png, elset="PIN"):
    first, last = element_rows(xdmf, elset)
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [900, 520]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    body = whole_body(last_frame(xdmf, view), first, last)
    body.UpdatePipeline(view.ViewTime)
    shown = Show(body, view)
    ColorBy(shown, ("POINTS", "CPRESS"))
    lut = GetColorTransferFunction("CPRESS")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.NanColor = [0.75, 0.75, 0.75]
    shown.RescaleTransferFunctionToDataRange(False, True)
    shown.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = "CPRESS (MPa)"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    view.CameraPosition = [-14.0, -22.0, 12.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    SaveScreenshot(png, view, ImageResolution=[900, 520])


if __name__ == "__main__":
    main(*sys.argv[1:])
