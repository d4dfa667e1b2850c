#!/usr/bin/python3
"""Runs a pvpython script on a Debian 12 machine with libvtk9-dev:
    run_pvpython.py PV_DIR SCRIPT [ARGS...]

Debian's python3-paraview (pvpython) conflicts with python3-vtk9, which
libvtk9-dev needs, so it is not installed but unpacked into PV_DIR ('apt-get
download python3-paraview', 'dpkg -x'; done once, then reused). Its libraries
come from the 'paraview' package and it renders through X: setup.sh installs
'paraview' and 'xvfb'. The script runs on its own Xvfb server with ParaView's
Python folder first and Debian's last (pvpython_main.py); PYTHONPATH from the
caller is kept (tetblend_blend's folder, for the plugin).

The server is started with -displayfd, which names the display only once the
server accepts clients.

Exit status: the script's. 77 when pvpython cannot be had here (no 'paraview'
or 'xvfb' package, or the download fails), with the reason on stderr: ctest
reports the test as skipped. A run killed by a signal is tried again on a new
server, up to ATTEMPTS runs.
"""

import os
import shutil
import subprocess
import sys
import tempfile

SKIP = 77
# Runs of a script killed by a signal, at most. On a loaded machine pvpython
# sometimes aborts creating its first render window ("bad X server
# connection", although the server accepts other clients then): 4 of 8
# runs with two busy loops beside it, none of 8 on an idle machine.
ATTEMPTS = 3
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


def start_xvfb():
    """An Xvfb server on a free display, and that display (":N"), once the
    server accepts clients."""
    read_end, write_end = os.pipe()
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0",
                               "1280x1024x24", "-nolisten", "tcp"],
                              pass_fds=(write_end,), stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL)
    os.close(write_end)
    with os.fdopen(read_end) as announced:
        number = announced.readline().strip()
    if not number.isdigit():
        server.kill()
        server.wait()
        sys.exit("run_pvpython: Xvfb did not start (exit status %s)" % server.returncode)
    return server, ":" + number


def run_on_xvfb(command, env):
    """The exit status of `command` run on a fresh Xvfb server (negative:
    killed by that signal)."""
    server, display = start_xvfb()
    try:
        return subprocess.run(command, env=dict(env, DISPLAY=display)).returncode
    finally:
        server.terminate()
        server.wait()


def main():
    if len(sys.argv) < 3:
        print(__doc__.strip().splitlines()[1], file=sys.stderr)
        return 2
    pv_dir, script = sys.argv[1], sys.argv[2]
    if shutil.which("Xvfb") is None:
        skip("Xvfb is missing (package 'xvfb'; setup.sh installs it)")
    unpack_pvpython(pv_dir)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [os.path.join(os.path.abspath(pv_dir), PYTHON_DIR)]
        + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    command = [os.path.join(pv_dir, PVPYTHON),
               os.path.join(os.path.dirname(os.path.abspath(__file__)), "pvpython_main.py"),
               script] + sys.argv[3:]
    status = run_on_xvfb(command, env)
    for attempt in range(2, ATTEMPTS + 1):
        if status >= 0:
            break
        print("run_pvpython: pvpython died (signal %d); attempt %d of %d"
              % (-status, attempt, ATTEMPTS), file=sys.stderr)
        status = run_on_xvfb(command, env)
    return 128 - status if status < 0 else status


if __name__ == "__main__":
    sys.exit(main())
