"""A blend from Python equals the command line's, bit for bit."""

import numpy as np
import pytest

import tetblend


@pytest.mark.parametrize("method", ["kaji", "dq", "vertex-linear"])
def test_blend_equals_the_cli_output_bit_for_bit(bar_model, cli, tmp_path, method):
    out = tmp_path / f"bar_{method}.vtu"
    cli("blend", bar_model, "--weights", "0.5,0.25", "--method", method, "-o", out, "--quiet")
    tet_vertices, tets = tetblend.read_tet_mesh(str(out))
    surface_vertices, triangles = tetblend.read_surface(str(out.with_suffix(".vtp")))

    model = tetblend.load(str(bar_model))
    vertices = model.blend([0.5, 0.25], method=method)
    assert vertices.dtype == np.float64 and vertices.shape == model.rest_vertices.shape
    assert np.array_equal(vertices, tet_vertices)
    assert np.array_equal(tets, model.tets)
    assert np.array_equal(vertices[: model.surface_vertex_count], surface_vertices)
    assert np.array_equal(triangles, model.surface_triangles)


def test_prepare_from_arrays_equals_the_cli_model(samples, bar_model):
    rest, triangles = tetblend.read_surface(str(samples / "bar_rest.obj"))
    examples = [tetblend.read_surface(str(samples / name))[0]
                for name in ("bar_twist4pi.obj", "bar_bend.obj")]
    prepared = tetblend.prepare(rest, triangles.astype(np.int64), examples)
    loaded = tetblend.load(str(bar_model))
    assert np.array_equal(prepared.rest_vertices, loaded.rest_vertices)
    assert np.array_equal(prepared.tets, loaded.tets)
    for mine, theirs in zip(prepared.examples, loaded.examples):
        assert np.array_equal(mine, theirs)
    assert np.array_equal(prepared.blend([0.5, 0.25]), loaded.blend([0.5, 0.25]))


def test_save_and_load_round_trip(bar_model, tmp_path):
    model = tetblend.load(str(bar_model))
    model.save(str(tmp_path / "again.tbm"))
    again = tetblend.load(str(tmp_path / "again.tbm"))
    assert np.array_equal(again.rest_vertices, model.rest_vertices)
    assert np.array_equal(again.tets, model.tets)
    assert again.example_sources == model.example_sources


def test_fast_load_keeps_the_factor_and_blends_the_same(bar_model, tmp_path):
    model = tetblend.load(str(bar_model))
    fast, plain = tmp_path / "fast.tbm", tmp_path / "plain.tbm"
    model.save(str(fast), fast_load=True)
    assert fast.stat().st_size > bar_model.stat().st_size
    loaded = tetblend.load(str(fast))
    for method in ("kaji", "dq"):
        assert np.array_equal(loaded.blend([0.5, 0.25], method=method),
                              model.blend([0.5, 0.25], method=method))
    loaded.save(str(plain), fast_load=False)
    assert plain.read_bytes() == bar_model.read_bytes()


def test_quality_arrays_are_per_tet(bar_model):
    model = tetblend.load(str(bar_model))
    vertices, cells = model.blend_with_quality([0.5, 0.0])
    assert np.array_equal(vertices, model.blend([0.5, 0.0]))
    assert {"volume_ratio", "inverted", "distortion", "rotation_angle",
            "target_residual"} <= cells.keys()
    for values in cells.values():
        assert values.shape == (len(model.tets),)
        assert values.dtype == np.float64
