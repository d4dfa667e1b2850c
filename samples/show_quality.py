"""Open a tetblend .pvd collection in ParaView and colour it by a quality array.

    pvpython samples/show_quality.py OUT/batch/batch.pvd [ARRAY] [SCREENSHOT.png]

ARRAY is a cell array written by tetblend: volume_ratio (default; det of the
deformation gradient, 1 = volume kept, <= 0 = inverted), inverted (0/1) or
target_residual (how far the stitch moved a tet from its blended map). With a
screenshot path the picture is saved and the script exits; otherwise an
interactive window opens. pvpython needs a display (use xvfb-run without one).
"""
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetAnimationScene, Interact,
                             PVDReader, ResetCamera, SaveScreenshot, Show)


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    pvd = argv[1]
    array = argv[2] if len(argv) > 2 else "volume_ratio"
    screenshot = argv[3] if len(argv) > 3 else None

    reader = PVDReader(FileName=pvd)
    GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
    view = GetActiveViewOrCreate("RenderView")
    display = Show(reader, view)
    ColorBy(display, ("CELLS", array))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    ResetCamera(view)
    if screenshot:
        SaveScreenshot(screenshot, view, ImageResolution=[1200, 600])
    else:
        Interact(view)


if __name__ == "__main__":
    main(sys.argv)
