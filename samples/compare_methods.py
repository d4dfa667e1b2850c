"""Every blend method side by side, one picture (pvpython):

    pvpython compare_methods.py MODEL.tbm --weights 0.5,0 -o methods.png

One panel per method of the model blended at the same weights (the ParaView
plugin, paraview_plugin/tetblend_plugin.py, does the blending), coloured by
volume_ratio on one scale for all: white where a tet keeps its volume, blue
where it shrinks, red where it grows, black where it is inverted (volume
ratio <= 0); every panel has the same camera and is titled with its method
and its inverted tets (or says that it failed: alexa has no blend of a turn
by pi). On Debian 12 run it through tools/run_pvpython.py
(pvpython cannot be installed beside libvtk9-dev there):

    tools/run_pvpython.py build/release/pvpython samples/compare_methods.py \\
        out/samples/bar.tbm --weights 0.5,0 -o methods.png
"""

import argparse
import math
import os
import sys

import paraview.simple
from paraview import servermanager
from paraview.simple import (AssignViewToLayout, ColorBy, CreateLayout, CreateView,
                             GetColorTransferFunction, LoadPlugin, SaveScreenshot, Show, Text)
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_PLUGIN = os.environ.get(
    "TETBLEND_PLUGIN", os.path.join(HERE, "..", "build", "release", "python", "tetblend_plugin.py"))
# The colour scale of volume_ratio: 1 (volume kept) in the middle.
VOLUME_RATIO_RANGE = (0.0, 2.0)
PANEL_SIZE = (400, 300)
# Where the camera looks from, relative to the shapes' centre (z up), and its
# view angle in degrees (ParaView's default).
VIEW_DIRECTION = (0.35, -1.0, 0.55)
CAMERA_VIEW_ANGLE = 30.0


def grid_shape(count):
    """(rows, columns) of the panels: as square as possible, rows first."""
    columns = math.ceil(math.sqrt(count))
    return math.ceil(count / columns), columns


def split(layout, cell, parts, vertical):
    """Splits a layout cell into `parts` equal cells; returns their indices."""
    if parts == 1:
        return [cell]
    first = (layout.SplitVertical if vertical else layout.SplitHorizontal)(cell, 1.0 / parts)
    return [first] + split(layout, first + 1, parts - 1, vertical)


def panel_cells(layout, count):
    """The layout's cells for `count` panels, row by row."""
    rows, columns = grid_shape(count)
    cells = [cell for row in split(layout, 0, rows, True)
             for cell in split(layout, row, columns, False)]
    return cells[:count]


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument("model", help="a model file written by 'tetblend prepare'")
    parser.add_argument("-w", "--weights", required=True,
                        help="one weight per example, comma-separated (as 'tetblend blend')")
    parser.add_argument("-o", "--output", required=True, help="the PNG to write")
    parser.add_argument("--consistency", choices=["on", "off"], default="on",
                        help="consistent rotation logarithms (default on)")
    parser.add_argument("--plugin", default=DEFAULT_PLUGIN,
                        help="tetblend_plugin.py (default: $TETBLEND_PLUGIN, else the one of "
                             "build/release)")
    return parser.parse_args(argv)


def main(argv):
    """Writes the picture; returns {method: inverted tets, None where it failed}."""
    args = parse(argv)
    weights = [float(w) for w in args.weights.split(",")]
    LoadPlugin(args.plugin, remote=False, ns=globals())
    import tetblend_blend  # importable once the plugin is loaded (it finds it)
    examples = tetblend_blend.load(args.model).example_count
    if len(weights) != examples:
        sys.exit("compare_methods.py: %s has %d examples, --weights gives %d weights"
                 % (args.model, examples, len(weights)))
    make_source = globals()["TetblendBlend"]
    methods = make_source().GetProperty("Method").Available  # the drop-down's entries
    lut = GetColorTransferFunction("volume_ratio")
    lut.ApplyPreset("Cool to Warm", True)
    lut.RescaleTransferFunction(*VOLUME_RATIO_RANGE)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.UseBelowRangeColor = 1
    lut.BelowRangeColor = [0.0, 0.0, 0.0]

    paraview.simple._DisableFirstRenderCameraReset()  # the camera is set below
    layout = CreateLayout("tetblend methods")
    rows, columns = grid_shape(len(methods))
    inverted = {}
    views = []
    bounds = []
    for method, cell in zip(methods, panel_cells(layout, len(methods))):
        source = make_source(FileName=os.path.abspath(args.model))
        for slider, weight in enumerate(weights):
            setattr(source, "Weight%d" % (slider + 1), weight)
        source.Method = method
        source.Consistency = int(args.consistency == "on")
        output = servermanager.Fetch(source)
        # A method undefined for these examples (alexa on turns of pi) fails
        # in the plugin, which logs why: its panel says so and stays empty.
        flags = output.GetCellData().GetArray("inverted")
        inverted[method] = None if flags is None else int(vtk_to_numpy(flags).sum())
        if flags is not None:
            bounds.append(output.GetBounds())

        view = CreateView("RenderView")
        AssignViewToLayout(view=view, layout=layout, hint=cell)
        view.OrientationAxesVisibility = 0
        display = Show(source, view)
        ColorBy(display, ("CELLS", "volume_ratio"))
        title = Show(Text(Text="%s: %s" % (method, "failed (see the log)" if inverted[method] is None
                                           else "%d inverted" % inverted[method])), view)
        title.WindowLocation = "Upper Center"
        title.FontSize = 22
        views.append(view)

    # One camera for all, framing every blend as ResetCamera frames one: the
    # bounding sphere of the union of the blends' boxes fills the view angle.
    union = [min(b[i] for b in bounds) if i % 2 == 0 else max(b[i] for b in bounds)
             for i in range(6)]
    centre = [(union[2 * i] + union[2 * i + 1]) / 2 for i in range(3)]
    radius = math.dist(union[0::2], union[1::2]) / 2
    distance = radius / math.sin(math.radians(CAMERA_VIEW_ANGLE) / 2)
    norm = math.hypot(*VIEW_DIRECTION)
    for view in views:
        view.CameraFocalPoint = centre
        view.CameraPosition = [c + distance * d / norm for c, d in zip(centre, VIEW_DIRECTION)]
        view.CameraViewUp = [0.0, 0.0, 1.0]
        view.CameraViewAngle = CAMERA_VIEW_ANGLE
    # ColorBy fitted the scale to each blend: back to the fixed one.
    lut.RescaleTransferFunction(*VOLUME_RATIO_RANGE)
    display.SetScalarBarVisibility(views[-1], True)
    SaveScreenshot(args.output, layout,
                   ImageResolution=[columns * PANEL_SIZE[0], rows * PANEL_SIZE[1]])
    return inverted


if __name__ == "__main__":
    for name, count in main(sys.argv[1:]).items():
        print("%s: %s" % (name, "failed" if count is None else "%d inverted tets" % count))
