"""tetblend's ParaView plugin: the source "Tetblend Blend".

It opens a model written by 'tetblend prepare' (.tbm) and outputs the blended
tets (vtkUnstructuredGrid) with the arrays of the .vtu of 'tetblend blend':
point data displacement (blend - rest), cell data the per-tet quality
(volume_ratio, inverted, distortion, rotation_angle, target_residual and, for
a model with excluded tets, excluded). Properties: FileName; Method (every
method of tetblend_blend.methods()); Consistency (consistent rotation
logarithms, as 'tetblend blend --consistency'); Weight1 ... Weight16, one
slider per example: the panel shows as many as the loaded model has examples
(the information property ExampleSliders), and examples past the sixteenth
get weight 0, with a warning.

A change of weights, method or consistency re-blends the loaded model: the
model file is read once per FileName, and each (method, consistency) pair
parametrises the examples and factors the stitch on its first use only. The
tet connectivity is built once per model; a re-blend replaces the points and
the cell arrays.

Load it with Tools > Manage Plugins > Load New (this file), or
LoadPlugin("tetblend_plugin.py", ns=globals()) in pvpython. It imports
tetblend_blend, the VTK-free tetblend module (found on sys.path, else beside
this file, where the build and 'cmake --install' put both), and builds the
output with ParaView's own VTK: a module linking Debian's VTK 9.1 would crash
ParaView 5.11.
"""

import os
import sys

import numpy
from paraview.util.vtkAlgorithm import VTKPythonAlgorithmBase, smproperty, smproxy
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkLogger, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkCellArray, vtkUnstructuredGrid

try:
    import tetblend_blend
except ImportError:
    sys.path.append(os.path.dirname(os.path.abspath(__file__)))
    import tetblend_blend

paraview_plugin_name = "tetblend"
paraview_plugin_version = "0.1"

# Weight sliders defined (ParaView's properties are fixed when the plugin
# loads, before any model is known; the panel hides those a model does not use).
WEIGHT_SLIDERS = 16
METHODS = tetblend_blend.methods()


def tet_cells(tets):
    """The (t, 4) int32 tets as a vtkCellArray of t tetrahedra."""
    count = len(tets)
    offsets = numpy_support.numpy_to_vtkIdTypeArray(
        4 * numpy.arange(count + 1, dtype=numpy.int64), deep=1)
    connectivity = numpy_support.numpy_to_vtkIdTypeArray(
        tets.astype(numpy.int64).ravel(), deep=1)
    cells = vtkCellArray()
    cells.SetData(offsets, connectivity)
    return cells


def _properties_xml():
    """The source's properties, in panel order."""
    methods = "".join('<Entry value="%d" text="%s"/>' % (i, name) for i, name in enumerate(METHODS))
    # Slider k shows when the model has at least k examples.
    weights = "".join(
        """<DoubleVectorProperty name="Weight%(k)d" label="Weight %(k)d" command="SetWeight%(k)d"
               number_of_elements="1" default_values="0">
             <DoubleRangeDomain name="range" min="0" max="1"/>
             <Documentation>Weight of example %(k)d (any real number may be typed; the rest
               gets 1 - sum of the weights).</Documentation>
             <Hints><PropertyWidgetDecorator type="GenericDecorator" mode="visibility"
               property="ExampleSliders" values="%(counts)s"/></Hints>
           </DoubleVectorProperty>""" % {
            "k": k + 1, "counts": " ".join(str(n) for n in range(k + 1, WEIGHT_SLIDERS + 1))}
        for k in range(WEIGHT_SLIDERS))
    return """
      <StringVectorProperty name="FileName" command="SetFileName" number_of_elements="1">
        <FileListDomain name="files"/>
        <Documentation>A model file (.tbm) written by 'tetblend prepare'.</Documentation>
        <Hints><FileChooser extensions="tbm" file_description="tetblend models"/></Hints>
      </StringVectorProperty>
      <IntVectorProperty name="Method" command="SetMethod" number_of_elements="1"
                         default_values="%(kaji)d">
        <EnumerationDomain name="enum">%(methods)s</EnumerationDomain>
        <Documentation>The blend method (see the README's Blending methods).</Documentation>
      </IntVectorProperty>
      <IntVectorProperty name="Consistency" command="SetConsistency" number_of_elements="1"
                         default_values="1">
        <BooleanDomain name="bool"/>
        <Documentation>Consistent rotation logarithms across neighbouring tets (kaji,
          liebodies): turns beyond pi blend through the turn instead of collapsing.</Documentation>
      </IntVectorProperty>
      <IntVectorProperty name="ExampleSliders" command="GetExampleSliders"
                         information_only="1" number_of_elements="1" default_values="0">
        <SimpleIntInformationHelper/>
        <Documentation>The sliders the loaded model uses: its example count, at most
          %(sliders)d.</Documentation>
      </IntVectorProperty>
      %(weights)s""" % {"sliders": WEIGHT_SLIDERS, "kaji": METHODS.index("kaji"), "methods": methods, "weights": weights}


class TetblendBlend(VTKPythonAlgorithmBase):
    """Blends a loaded tetblend model; see the module's documentation."""

    def __init__(self):
        VTKPythonAlgorithmBase.__init__(self, nInputPorts=0, nOutputPorts=1,
                                        outputType="vtkUnstructuredGrid")
        self._file_name = ""
        self._method = METHODS.index("kaji")
        self._consistency = True
        self._weights = [0.0] * WEIGHT_SLIDERS
        self._model = None
        self._model_file = None
        self._cells = None

    def SetFileName(self, name):
        if name != self._file_name:
            self._file_name = name
            self.Modified()

    def SetMethod(self, index):
        if index != self._method:
            self._method = index
            self.Modified()

    def SetConsistency(self, on):
        if bool(on) != self._consistency:
            self._consistency = bool(on)
            self.Modified()

    def _set_weight(self, slider, value):
        if value != self._weights[slider]:
            self._weights[slider] = value
            self.Modified()

    def GetExampleSliders(self):
        if self._model is None:
            return 0
        return min(self._model.example_count, WEIGHT_SLIDERS)

    def RequestInformation(self, request, inInfo, outInfo):
        if self._file_name:
            self._loaded_model()
        return 1

    def _loaded_model(self):
        if self._model_file != self._file_name:
            self._model = tetblend_blend.load(self._file_name)
            self._model_file = self._file_name
            self._cells = tet_cells(self._model.tets)
            if self._model.example_count > WEIGHT_SLIDERS:
                vtkLogger.Log(vtkLogger.VERBOSITY_WARNING, __file__, 0,
                              "%s has %d examples; the %d sliders set the first %d, the others "
                              "get weight 0" % (self._file_name, self._model.example_count,
                                                WEIGHT_SLIDERS, WEIGHT_SLIDERS))
        return self._model

    def RequestData(self, request, inInfo, outInfo):
        if not self._file_name:
            return 1
        model = self._loaded_model()
        count = model.example_count
        weights = (self._weights + [0.0] * max(0, count - WEIGHT_SLIDERS))[:count]
        vertices, cells = model.blend_with_quality(
            weights, method=METHODS[self._method], consistency=self._consistency)
        points = vtkPoints()
        points.SetData(numpy_support.numpy_to_vtk(vertices, deep=1))
        grid = vtkUnstructuredGrid.GetData(outInfo)
        grid.SetPoints(points)
        grid.SetCells(VTK_TETRA, self._cells)
        displacement = numpy_support.numpy_to_vtk(vertices - model.rest_vertices, deep=1)
        displacement.SetName("displacement")
        grid.GetPointData().AddArray(displacement)
        for name, values in cells.items():
            array = numpy_support.numpy_to_vtk(values, deep=1)
            array.SetName(name)
            grid.GetCellData().AddArray(array)
        return 1


def _weight_setter(slider):
    return lambda self, value: self._set_weight(slider, value)


for _slider in range(WEIGHT_SLIDERS):
    setattr(TetblendBlend, "SetWeight%d" % (_slider + 1), _weight_setter(_slider))
del _slider

TetblendBlend = smproxy.source(name="TetblendBlend", label="Tetblend Blend")(
    smproperty.xml(_properties_xml())(TetblendBlend))
