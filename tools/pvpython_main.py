"""Runs a script in ParaView's pvpython unpacked beside Debian's VTK:
    pvpython pvpython_main.py SCRIPT [ARGS...]   (run_pvpython.py calls it)

pvpython puts Debian's dist-packages (spelt //lib/python3/dist-packages) before
ParaView's own folder, so 'import vtkmodules' would load Debian's VTK 9.1 and
crash ParaView 5.11. This moves Debian's folder (however spelt) to the end of
sys.path, puts the script's folder first, and runs the script as __main__.

Debian 12's ParaView 5.11.0 loads no Python plugin as shipped:
paraview/detail/pythonalgorithm.py imports inspect.getargspec, which Python
3.11 removed. It only reads .args, which getfullargspec has too, so that is
put in its place first.
"""

import inspect
import os
import runpy
import sys

if not hasattr(inspect, "getargspec"):
    inspect.getargspec = inspect.getfullargspec

debian = os.path.realpath("/usr/lib/python3/dist-packages")
script = os.path.abspath(sys.argv[1])
sys.path = ([os.path.dirname(script)]
            + [p for p in sys.path if os.path.realpath(p) != debian] + [debian])
sys.argv = sys.argv[1:]
runpy.run_path(script, run_name="__main__")
