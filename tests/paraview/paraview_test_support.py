"""What the pvpython tests share (run inside pvpython by tools/run_pvpython.py;
ctest passes the programs' and the plugin's paths in the environment)."""

import ctypes
import os
import subprocess

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

# A picture is blank when it is (nearly) one colour: at least this share of
# its pixels must differ from the corner pixel (the background), and the
# standard deviation of its grey values (0-255) must be at least this.
MIN_FOREGROUND_SHARE = 0.02
MIN_GREY_STDDEV = 5.0


def run(*args, env=None):
    """Runs a program; raises with its stderr when it fails."""
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True, env=env)
    if done.returncode != 0:
        raise RuntimeError("%s failed: %s" % (" ".join(map(str, args)), done.stderr))
    return done


def cli(*args, preload=None):
    """Runs the tetblend command line, with the library `preload` (a path)
    in LD_PRELOAD when given."""
    env = dict(os.environ, LD_PRELOAD=preload) if preload else None
    return run(os.environ["TETBLEND_EXE"], *args, env=env)


class _DlInfo(ctypes.Structure):
    _fields_ = [("dli_fname", ctypes.c_char_p), ("dli_fbase", ctypes.c_void_p),
                ("dli_sname", ctypes.c_char_p), ("dli_saddr", ctypes.c_void_p)]


def global_blas():
    """The library this process's global symbols take dgemm_ from, or None.
    A module loaded later (CHOLMOD, through tetblend_blend) binds its BLAS
    calls there first: pvpython has OpenBLAS's libblas.so.3 loaded globally,
    while the tetblend program binds ATLAS's libf77blas, a direct dependency."""
    try:
        dgemm = ctypes.CDLL(None).dgemm_
    except AttributeError:
        return None
    dladdr = ctypes.CDLL("libc.so.6").dladdr
    dladdr.argtypes = [ctypes.c_void_p, ctypes.POINTER(_DlInfo)]
    info = _DlInfo()
    if not dladdr(ctypes.cast(dgemm, ctypes.c_void_p), ctypes.byref(info)):
        return None
    return os.fsdecode(info.dli_fname)


def output_folder(name):
    """A fresh folder for one test's files, under the test's binary folder."""
    folder = os.path.join(os.environ["TETBLEND_PV_TEST_DIR"], name)
    os.makedirs(folder, exist_ok=True)
    return folder


def bar_model(folder):
    """The samples' twisted and bent bar (1029 tets, 2 examples) prepared by
    'tetblend prepare' into folder; returns its path."""
    surfaces = os.path.join(folder, "surfaces")
    run(os.environ["TETBLEND_MAKE_SAMPLES"], surfaces)
    model = os.path.join(folder, "bar.tbm")
    cli("prepare", *[os.path.join(surfaces, name)
                     for name in ("bar_rest.obj", "bar_twist4pi.obj", "bar_bend.obj")],
        "-o", model, "--quiet")
    return model


def png_pixels(path):
    """The PNG's pixels as a (height, width, channels) uint8 array, top row first
    (VTK's images start at the bottom)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    return vtk_to_numpy(scalars).reshape(height, width, scalars.GetNumberOfComponents())[::-1]


def assert_not_blank(path):
    """Fails unless the PNG shows something besides its background."""
    pixels = png_pixels(path)[:, :, :3].astype(np.float64)
    foreground = np.any(pixels != pixels[0, 0], axis=2).mean()
    grey = pixels.mean(axis=2).std()
    assert foreground >= MIN_FOREGROUND_SHARE and grey >= MIN_GREY_STDDEV, (
        "%s is blank: %.4f of its pixels differ from the background (need %.2f), grey "
        "standard deviation %.2f (need %.1f)" % (path, foreground, MIN_FOREGROUND_SHARE, grey,
                                                 MIN_GREY_STDDEV))
    return foreground, grey


def vtk_process_libraries():
    """The VTK shared libraries mapped into this process."""
    with open("/proc/self/maps") as maps:
        return {line.split()[-1] for line in maps if "libvtk" in line}
