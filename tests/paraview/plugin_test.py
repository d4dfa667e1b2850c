"""The ParaView plugin (paraview_plugin/tetblend_plugin.py) in pvpython:
loaded with LoadPlugin, it outputs what tetblend_blend computes in the same
process and what 'tetblend blend' writes, bit for bit, for the weights, the
method drop-down and the consistency switch; its output renders.

Run by ctest through tools/run_pvpython.py (pvpython on its own Xvfb server)."""

import os

import numpy as np
import tetblend_blend
from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, Delete, LoadPlugin, SaveScreenshot, Show,
                             XMLUnstructuredGridReader)
from vtkmodules.util.numpy_support import vtk_to_numpy

import paraview_test_support as support

# The command line's .vtu keeps float64 (zlib is lossless) and the plugin runs
# the same blender, so the comparisons are exact, once both use one BLAS:
# CHOLMOD's supernodal kernels (dgemm, dsyrk, dtrsm) bind to ATLAS's
# libf77blas in the tetblend program but to OpenBLAS's libblas.so.3 in
# pvpython, and the two round differently (1.6e-14 apart on the bar, diagonal
# 2.4). The program runs with this process's BLAS preloaded.
BLAS = support.global_blas()

# (weights, method, consistency): the drop-down's default and two others, the
# switch both ways, and the rest.
CASES = [
    ((0.5, 0.25), "kaji", True),
    ((0.5, 0.0), "dq", True),
    ((0.3, 0.6), "liebodies", False),
    ((0.0, 0.0), "kaji", True),
]
QUALITY_ARRAYS = {"volume_ratio", "inverted", "distortion", "rotation_angle", "target_residual"}


def arrays(data):
    """A fetched vtkDataSet's points and its point and cell arrays as numpy arrays."""
    def named(attributes):
        return {attributes.GetArrayName(i): vtk_to_numpy(attributes.GetArray(i))
                for i in range(attributes.GetNumberOfArrays())}
    return (vtk_to_numpy(data.GetPoints().GetData()), named(data.GetPointData()),
            named(data.GetCellData()))


def cli_blend(model, folder, weights, method, consistency):
    """The points and arrays of 'tetblend blend' read back by ParaView's reader."""
    path = os.path.join(folder, "cli_%s_%s.vtu" % (method, "_".join(map(str, weights))))
    support.cli("blend", model, "--weights", ",".join(map(str, weights)), "--method", method,
                "--consistency", "on" if consistency else "off", "-o", path, "--quiet",
                preload=BLAS)
    reader = XMLUnstructuredGridReader(FileName=[path])
    data = servermanager.Fetch(reader)
    Delete(reader)
    return arrays(data), data.GetNumberOfCells()


def check_blend(source, model, folder, weights, method, consistency):
    source.Weight1, source.Weight2 = weights
    source.Method = method
    source.Consistency = int(consistency)
    output = servermanager.Fetch(source)
    points, point_data, cell_data = arrays(output)
    case = "%s %s consistency=%s" % (method, weights, consistency)

    # The plugin adds nothing to the module's numbers: exact.
    loaded = tetblend_blend.load(model)
    vertices, cells = loaded.blend_with_quality(list(weights), method=method,
                                                consistency=consistency)
    assert np.array_equal(points, vertices), case
    assert np.array_equal(point_data["displacement"], vertices - loaded.rest_vertices), case
    assert cell_data.keys() == cells.keys(), case
    for name, values in cells.items():
        assert np.array_equal(cell_data[name], values, equal_nan=True), "%s: %s" % (case, name)

    # The command line: the same tets, points and arrays.
    (cli_points, cli_point_data, cli_cell_data), cli_cells = cli_blend(
        model, folder, weights, method, consistency)
    assert output.GetNumberOfCells() == cli_cells == len(loaded.tets), case
    assert np.array_equal(points, cli_points), "%s: points differ from the CLI's by up to %g" % (
        case, np.abs(points - cli_points).max())
    assert point_data.keys() == cli_point_data.keys() == {"displacement"}, case
    assert cell_data.keys() == cli_cell_data.keys(), "%s: %s != %s" % (
        case, sorted(cell_data), sorted(cli_cell_data))
    assert QUALITY_ARRAYS <= cell_data.keys(), case
    for name, values in list(point_data.items()) + list(cell_data.items()):
        theirs = cli_point_data.get(name, cli_cell_data.get(name))
        assert np.array_equal(values, theirs, equal_nan=True), "%s: array %s differs" % (case, name)
    print("plugin_test: %s: equals tetblend_blend's blend and the CLI's .vtu (%d points, %d "
          "tets, cell arrays %s; BLAS %s)" % (case, len(points), cli_cells,
                                              ", ".join(sorted(cell_data)), BLAS))


def check_screenshot(source, folder):
    """Half of the bar's 4 pi twist, coloured by volume_ratio, is not blank."""
    source.Weight1, source.Weight2 = 0.5, 0.0
    source.Method = "kaji"
    view = CreateView("RenderView")
    display = Show(source, view)
    ColorBy(display, ("CELLS", "volume_ratio"))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    view.CameraPosition = [-4.0, -3.0, 5.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    path = os.path.join(folder, "plugin.png")
    SaveScreenshot(path, view, ImageResolution=[480, 360])
    foreground, grey = support.assert_not_blank(path)
    print("plugin_test: %s is not blank (%.3f foreground, grey deviation %.1f)" % (
        path, foreground, grey))


def main():
    folder = support.output_folder("plugin")
    model = support.bar_model(folder)
    LoadPlugin(os.environ["TETBLEND_PLUGIN"], remote=False, ns=globals())
    source = globals()["TetblendBlend"]()
    source.UpdatePipelineInformation()
    assert source.GetProperty("ExampleSliders").GetData() == 0
    source.FileName = model
    source.UpdatePipelineInformation()  # the panel shows this many weight sliders
    assert source.GetProperty("ExampleSliders").GetData() == 2
    for weights, method, consistency in CASES:
        check_blend(source, model, folder, weights, method, consistency)
    check_screenshot(source, folder)
    debian_vtk = [lib for lib in support.vtk_process_libraries() if "-9.1.so" in lib]
    assert not debian_vtk, "Debian's VTK is loaded: %s" % debian_vtk


main()
