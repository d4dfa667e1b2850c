"""Model.variations, Model.pca and tetblend.deform give what the command
line's variations and deform give."""

import csv
import json
import pathlib

import numpy as np
import pytest

import tetblend

SAMPLES = pathlib.Path(__file__).resolve().parents[2] / "samples"


def weight_rows(path):
    """{name: weights} of a weights.csv written by 'tetblend variations'."""
    with open(path, newline="") as f:
        return {row["name"]: [float(row[k]) for k in row if k.startswith("w")]
                for row in csv.DictReader(f)}


def test_variations_are_the_cli_weights(bar_model, cli, tmp_path):
    cli("variations", bar_model, "--count", "4", "--seed", "7", "--extrapolate", "0.5",
        "-o", tmp_path, "--quiet")
    rows = weight_rows(tmp_path / "weights.csv")
    weights = tetblend.load(str(bar_model)).variations(4, seed=7, extrapolate=0.5)
    assert weights.shape == (4, 2)
    for i, w in enumerate(weights):
        assert list(w) == rows[f"variation_{i:03d}"]


def test_pca_mean_and_steps_are_the_cli_weights(bar_model, cli, tmp_path):
    cli("variations", bar_model, "--pca", "--count", "1", "--range", "1", "--components", "1",
        "-o", tmp_path, "--quiet")
    rows = weight_rows(tmp_path / "weights.csv")
    pca = tetblend.load(str(bar_model)).pca()
    assert np.array_equal(pca["mean_weights"], [1 / 3, 1 / 3])
    assert list(pca["mean_weights"]) == rows["pca_mean"]
    assert list(pca["mean_weights"] + pca["steps"][0]) == rows["pc1_000"]
    assert np.all(np.diff(pca["sigmas"]) <= 0)


@pytest.mark.parametrize("method", ["kaji", "dq", "dqs"])
def test_deform_equals_the_cli_output_bit_for_bit(samples, cli, tmp_path, method):
    out = tmp_path / f"probe_{method}.vtp"
    handles = SAMPLES / "probe_handles.json"
    cli("deform", samples / "bar_rest.obj", "--handles", handles, "--method", method,
        "-o", out, "--quiet")
    expected, _ = tetblend.read_surface(str(out))
    rest, _ = tetblend.read_surface(str(samples / "bar_rest.obj"))
    spec = json.loads(handles.read_text())["handles"]
    assert np.array_equal(tetblend.deform(rest, spec, method=method), expected)


def test_deform_names_the_bad_handle_entry():
    rest = np.eye(3)
    with pytest.raises(tetblend.InputError, match=r"handles\[0\]\.centre"):
        tetblend.deform(rest, [{"centre": [0, 1]}])
    with pytest.raises(tetblend.InputError, match=r"weights: expected an array of shape \(3, 1\)"):
        tetblend.deform(rest, [{"centre": [0, 0, 0]}], weights=np.ones((3, 2)))
