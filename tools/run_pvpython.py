#!/usr/bin/python3
"""Runs a pvpython script on a Debian 12 machine with libvtk9-dev:
    run_pvpython.py PV_DIR SCRIPT [ARGS...]

Debian's python3-paraview (pvpython) conflicts with python3-vtk9, which
libvtk9-dev needs, so it is not installed but unpacked into PV_DIR ('apt-get
download python3-paraview', 'dpkg -x'; done once, then reused). Its libraries
come from the 'paraview' package and it renders through X: setup.sh installs
'paraview' and 'xvfb'. The script runs under xvfb-run with ParaView's Python
folder first and Debian's last (pvpython_main.py); PYTHONPATH from the caller
is kept (tetblend_blend's folder, for the plugin).

Exit status: the script's. 77 when pvpython cannot be had here (no 'paraview'
or 'xvfb' package, or the download fails), with the reason on stderr: ctest
reports the test as skipped. pvpython sometimes dies by a signal while Xvfb
starts: a run killed by a signal is retried once.
"""

import os
import shutil
import subprocess
import sys
import tempfile

SKIP = 77
PYTHON_DIR = "usr/lib/python3/dist-packages"
PVPYTHON = "usr/bin/pvpython3.11"


def skip(reason):
    print("run_pvpython: skipped: " + reason, file=sys.stderr)
    sys.exit(SKIP)


def installed_version(package):
    done = subprocess.run(["dpkg-query", "-W", "-f=${Status} ${Version}", package],
                          capture_output=True, text=True)
    words = done.stdout.split()
    return words[-1] if done.returncode == 0 and words[:3] == ["install", "ok", "installed"] \
        else None


def unpack_pvpython(pv_dir):
    """Unpacks python3-paraview (the version of the installed paraview) into
    pv_dir unless it is there; concurrent callers each unpack into a temporary
    folder and the first rename wins."""
    if os.path.exists(os.path.join(pv_dir, PVPYTHON)):
        return
    version = installed_version("paraview")
    if version is None:
        skip("the Debian package 'paraview' is not installed (setup.sh installs it)")
    parent = os.path.dirname(os.path.abspath(pv_dir))
    os.makedirs(parent, exist_ok=True)
    with tempfile.TemporaryDirectory(dir=parent) as work:
        done = subprocess.run(["apt-get", "download", "python3-paraview=" + version],
                              cwd=work, capture_output=True, text=True)
        debs = [f for f in os.listdir(work) if f.endswith(".deb")]
        if done.returncode != 0 or len(debs) != 1:
            lines = done.stderr.strip().splitlines() or ["exit status %d" % done.returncode]
            skip("'apt-get download python3-paraview=%s' failed: %s" % (version, lines[-1]))
        root = os.path.join(work, "root")
        subprocess.run(["dpkg", "-x", os.path.join(work, debs[0]), root], check=True)
        try:
            os.rename(root, pv_dir)
        except OSError:
            if not os.path.exists(os.path.join(pv_dir, PVPYTHON)):
                raise


def main():
    if len(sys.argv) < 3:
        print(__doc__.strip().splitlines()[1], file=sys.stderr)
        return 2
    pv_dir, script = sys.argv[1], sys.argv[2]
    if shutil.which("xvfb-run") is None:
        skip("xvfb-run is missing (package 'xvfb'; setup.sh installs it)")
    unpack_pvpython(pv_dir)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [os.path.join(os.path.abspath(pv_dir), PYTHON_DIR)]
        + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    command = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
               os.path.join(pv_dir, PVPYTHON),
               os.path.join(os.path.dirname(os.path.abspath(__file__)), "pvpython_main.py"),
               script] + sys.argv[3:]
    status = subprocess.run(command, env=env).returncode
    # xvfb-run is a shell script: a child killed by signal n exits 128 + n.
    if status < 0 or status > 128:
        print("run_pvpython: pvpython died (status %d); retrying once" % status, file=sys.stderr)
        status = subprocess.run(command, env=env).returncode
    return status


if __name__ == "__main__":
    sys.exit(main())
