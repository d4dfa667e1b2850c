"""tetblend_blend, the VTK-free module ParaView imports: it links no VTK and
blends as tetblend does, bit for bit (one process, one BLAS)."""

import subprocess

import numpy as np
import pytest

import tetblend
import tetblend_blend


def test_links_no_vtk():
    # ldd lists every shared library the module loads, directly or not.
    libraries = subprocess.run(["ldd", tetblend_blend.__file__], capture_output=True, text=True,
                               check=True).stdout
    assert "libvtk" not in libraries, libraries


@pytest.mark.parametrize("method", ["kaji", "liebodies", "vertex-linear"])
def test_blend_equals_the_full_module(bar_model, method):
    full = tetblend.load(str(bar_model))
    small = tetblend_blend.load(str(bar_model))
    assert small.example_count == full.example_count
    assert np.array_equal(small.tets, full.tets)
    vertices, cells = small.blend_with_quality([0.5, 0.25], method=method, consistency=False)
    full_vertices, full_cells = full.blend_with_quality([0.5, 0.25], method=method,
                                                        consistency=False)
    assert np.array_equal(vertices, full_vertices)
    assert cells.keys() == full_cells.keys()
    for name, values in cells.items():
        assert np.array_equal(values, full_cells[name], equal_nan=True), name


@pytest.mark.parametrize("module", [tetblend, tetblend_blend])
def test_each_module_raises_its_own_errors(module, tmp_path):
    # Regression: with both modules imported, a translator registered for
    # every module made one module raise the other's classes.
    with pytest.raises(module.InputError, match="missing.tbm") as raised:
        module.load(str(tmp_path / "missing.tbm"))
    assert type(raised.value).__module__ == module.__name__
    assert issubclass(module.InputError, ValueError)


def test_same_methods():
    assert tetblend_blend.methods() == tetblend.methods()
