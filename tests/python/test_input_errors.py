"""Wrong shapes, dtypes and values raise clear errors before any work:
TypeError for a dtype, tetblend.InputError (a ValueError) for a shape or a
value, each naming the array and what was given."""

import numpy as np
import pytest

import tetblend

# One tet's surface and a stretched copy: the smallest valid example set.
REST = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
TRIANGLES = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int32)
EXAMPLE = REST * [2.0, 1.0, 1.0]

PREPARE_CASES = [
    # (rest, triangles, examples, exception, words in the message)
    (REST[:, :2], TRIANGLES, [EXAMPLE], tetblend.InputError,
     ["rest_vertices", "shape (n, 3)", "(4, 2)"]),
    (REST.ravel(), TRIANGLES, [EXAMPLE], tetblend.InputError, ["rest_vertices", "(12,)"]),
    (REST.astype(np.complex128), TRIANGLES, [EXAMPLE], TypeError,
     ["rest_vertices", "complex128"]),
    (REST > 0, TRIANGLES, [EXAMPLE], TypeError, ["rest_vertices", "bool"]),
    ("rest.obj", TRIANGLES, [EXAMPLE], TypeError, ["rest_vertices", "<U8"]),
    (REST, TRIANGLES.astype(np.float64), [EXAMPLE], TypeError,
     ["triangles", "float64", "integer"]),
    (REST, TRIANGLES[:, :2], [EXAMPLE], tetblend.InputError, ["triangles", "(4, 2)"]),
    (REST, TRIANGLES + 1, [EXAMPLE], tetblend.InputError,
     ["triangles[", "= 4", "not a vertex index"]),
    (REST, TRIANGLES - 1, [EXAMPLE], tetblend.InputError, ["triangles[", "= -1"]),
    (REST, TRIANGLES, [EXAMPLE[:3]], tetblend.InputError, ["example_vertices[0]"]),
    (REST, TRIANGLES, [EXAMPLE, EXAMPLE[:, :1]], tetblend.InputError,
     ["example_vertices[1]", "(4, 1)"]),
    (REST, TRIANGLES, [np.where(EXAMPLE == 2.0, np.nan, EXAMPLE)], tetblend.InputError,
     ["example_vertices[0][1, 0]", "nan", "finite"]),
    (REST, TRIANGLES, [], tetblend.InputError, ["at least one example"]),
    (REST, TRIANGLES, [REST * [-1.0, 1.0, 1.0]], tetblend.InputError,
     ["example_vertices[0]", "mirrored", "mirror it back"]),
    (np.full_like(REST, 0.5), TRIANGLES, [REST], tetblend.InputError,
     ["zero area in the rest but not in example_vertices[0]", "as the rest"]),
]


@pytest.mark.parametrize("rest, triangles, examples, error, words", PREPARE_CASES)
def test_prepare_refuses_bad_arrays(rest, triangles, examples, error, words):
    with pytest.raises(error) as raised:
        tetblend.prepare(rest, triangles, examples)
    message = str(raised.value)
    assert "\n" not in message
    for word in words:
        assert word in message


def test_integer_and_float32_inputs_are_converted():
    model = tetblend.prepare(REST.astype(np.int64), TRIANGLES.astype(np.int64),
                             [EXAMPLE.astype(np.float32)], tetrise=True)
    assert model.rest_vertices.dtype == np.float64
    assert model.tets.dtype == np.int32
    assert model.surface_triangles.dtype == np.int32


@pytest.fixture(scope="module")
def model():
    return tetblend.prepare(REST, TRIANGLES, [EXAMPLE])


BLEND_CASES = [
    # (weights, keyword arguments, exception, words in the message)
    ([0.5, 0.5], {}, tetblend.InputError, ["2 weights given for 1 examples"]),
    ([[0.5]], {}, tetblend.InputError, ["weights", "1-D", "(1, 1)"]),
    (["half"], {}, TypeError, ["weights", "<U4"]),
    ([float("inf")], {}, tetblend.InputError, ["weight 0", "finite"]),
    ([0.5], {"method": "cubic"}, tetblend.InputError, ["cubic", "kaji"]),
]


@pytest.mark.parametrize("weights, options, error, words", BLEND_CASES)
def test_blend_refuses_bad_weights(model, weights, options, error, words):
    with pytest.raises(error) as raised:
        model.blend(weights, **options)
    for word in words:
        assert word in str(raised.value)


def test_every_tetblend_error_is_an_error_and_input_errors_are_value_errors():
    assert issubclass(tetblend.InputError, tetblend.Error)
    assert issubclass(tetblend.InputError, ValueError)
    assert issubclass(tetblend.DomainError, ValueError)
    assert issubclass(tetblend.NumericalError, tetblend.Error)
    assert issubclass(tetblend.ResourceError, tetblend.Error)
    assert issubclass(tetblend.ResourceError, MemoryError)


def test_a_missing_file_is_an_input_error_naming_it(tmp_path):
    missing = str(tmp_path / "missing.tbm")
    with pytest.raises(tetblend.InputError, match="missing.tbm"):
        tetblend.load(missing)
    with pytest.raises(tetblend.InputError, match="missing.obj"):
        tetblend.read_surface(str(tmp_path / "missing.obj"))


def test_bad_options_are_input_errors_naming_the_keyword(model):
    with pytest.raises(tetblend.InputError, match="quality must be 0 or greater than 1, got 0.5"):
        tetblend.prepare(REST, TRIANGLES, [EXAMPLE], quality=0.5)
    with pytest.raises(tetblend.InputError, match="count must be >= 0, got -1"):
        model.variations(-1)
    with pytest.raises(tetblend.InputError, match="falloff must be > 0"):
        tetblend.deform(REST, [{"centre": [0, 0, 0]}], falloff=0.0)
