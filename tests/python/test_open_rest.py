"""An open rest surface: prepare closes its holes by default (no new
vertices), the model's surface_triangles stay the input's, and blends
reproduce the rest and the example; fill_holes=False refuses it."""

import numpy as np
import pytest

import tetblend

# Unit weights reproduce each example at the surface to 1e-9 of the
# bounding-box diagonal (tetblend's promise; round-off is ~1e-13 here).
INTERPOLATION_REL_TOL = 1e-9
SEGMENTS = 12


def open_tube(rings=6, radius=0.5, spacing=0.5):
    """A tube of regular 12-gons, open at both ends (two holes of 12 edges)."""
    angles = 2 * np.pi * np.arange(SEGMENTS) / SEGMENTS
    vertices = np.array([[radius * np.cos(a), radius * np.sin(a), spacing * k]
                         for k in range(rings) for a in angles])
    triangles = []
    for k in range(rings - 1):
        for i in range(SEGMENTS):
            a, b = k * SEGMENTS + i, k * SEGMENTS + (i + 1) % SEGMENTS
            c, d = b + SEGMENTS, a + SEGMENTS
            triangles += [[a, b, c], [a, c, d]]
    return vertices, np.array(triangles, dtype=np.int32)


def sheared(vertices):
    out = vertices.copy()
    out[:, 0] += 0.3 * vertices[:, 2]
    return out


def test_holes_are_filled_and_the_surface_stays_the_inputs():
    rest, triangles = open_tube()
    example = sheared(rest)
    model = tetblend.prepare(rest, triangles, [example])
    assert np.array_equal(model.surface_triangles, triangles)
    diagonal = np.linalg.norm(rest.max(axis=0) - rest.min(axis=0))
    n = len(rest)
    for weights, expected in (([0.0], rest), ([1.0], example)):
        blended = model.blend(weights)
        assert np.abs(blended[:n] - expected).max() < INTERPOLATION_REL_TOL * diagonal


def test_fill_holes_false_refuses_an_open_rest():
    rest, triangles = open_tube()
    with pytest.raises(tetblend.InputError, match="boundary edge.*let prepare fill the holes"):
        tetblend.prepare(rest, triangles, [sheared(rest)], fill_holes=False)


def test_a_uv_seam_is_zipped_and_surface_vertex_rows_give_the_inputs_vertices():
    """The tube as a texture seam cuts it: the faces closing each ring use
    copies of its first column's vertices (appended after the originals)."""
    rest, triangles = open_tube()
    rings = len(rest) // SEGMENTS
    first_column = np.arange(rings) * SEGMENTS
    copy_of = {int(v): len(rest) + k for k, v in enumerate(first_column)}
    seamed_triangles = triangles.copy()
    for f, face in enumerate(triangles):
        if (face % SEGMENTS == SEGMENTS - 1).any():  # the faces that wrap around
            seamed_triangles[f] = [copy_of.get(int(v), v) for v in face]
    seamed = np.vstack([rest, rest[first_column]])
    example = sheared(seamed)
    model = tetblend.prepare(seamed, seamed_triangles, [example])
    assert model.surface_vertex_count == len(rest)
    assert np.array_equal(model.surface_triangles, seamed_triangles)
    rows = model.surface_vertex_rows
    assert rows.dtype == np.int32 and len(rows) == len(seamed)
    assert np.array_equal(rows[len(rest):], first_column)
    diagonal = np.linalg.norm(rest.max(axis=0) - rest.min(axis=0))
    for weights, expected in (([0.0], seamed), ([1.0], example)):
        blended = model.blend(weights)[rows]
        assert np.abs(blended - expected).max() < INTERPOLATION_REL_TOL * diagonal
