"""Fixtures of the Python module's tests: the sample surfaces made by
tetblend-make-samples and the bar model prepared by the tetblend command line.
ctest passes the programs' paths in TETBLEND_EXE and TETBLEND_MAKE_SAMPLES and
the module's folder in PYTHONPATH."""

import os
import subprocess

import pytest


def run(*args):
    """Runs a program; fails the test with its stderr when it fails."""
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done


@pytest.fixture(scope="session")
def samples(tmp_path_factory):
    """Folder with the sample surfaces (bar_rest.obj, bar_twist4pi.obj, ...)."""
    folder = tmp_path_factory.mktemp("surfaces")
    run(os.environ["TETBLEND_MAKE_SAMPLES"], folder)
    return folder


@pytest.fixture(scope="session")
def cli():
    """Runs the tetblend command line with the given arguments."""
    return lambda *args: run(os.environ["TETBLEND_EXE"], *args)


@pytest.fixture(scope="session")
def bar_model(samples, cli, tmp_path_factory):
    """The twisted and bent bar prepared by 'tetblend prepare' (its path)."""
    path = tmp_path_factory.mktemp("models") / "bar.tbm"
    cli("prepare", samples / "bar_rest.obj", samples / "bar_twist4pi.obj",
        samples / "bar_bend.obj", "-o", path, "--quiet")
    return path
