"""Times a slider change of the ParaView plugin (pvpython):
    run_pvpython.py PV_DIR tools/time_plugin_reblend.py PLUGIN MODEL [CHANGES]

After a first update (the model's load, parametrisation and stitch
factorisation), CHANGES (default 10) changes of Weight1 each time: the
module's blend_with_quality alone, the source's update (that blend plus the
output grid), and the update plus a render of the tets' surface in a view.
Prints the median and the range of each, in seconds.
"""

import statistics
import sys
import time

import tetblend_blend
from paraview.simple import ColorBy, CreateView, LoadPlugin, Render, Show


def timed(action):
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


def report(label, seconds):
    print("%-34s median %.3f s (%.3f-%.3f, %d runs)" % (
        label, statistics.median(seconds), min(seconds), max(seconds), len(seconds)))


def main(plugin, model_path, changes):
    LoadPlugin(plugin, remote=False, ns=globals())
    source = globals()["TetblendBlend"](FileName=model_path)
    first = timed(source.UpdatePipeline)
    model = tetblend_blend.load(model_path)
    print("%s: %d tets, %d vertices, %d examples; first update (load, factor) %.2f s" % (
        model_path, len(model.tets), len(model.rest_vertices), model.example_count, first))
    weights = [0.1 + 0.8 * i / changes for i in range(changes)]
    model.blend_with_quality([0.0] * model.example_count)  # its own factorisation, untimed
    blends = [timed(lambda: model.blend_with_quality([w] + [0.0] * (model.example_count - 1)))
              for w in weights]

    def change(weight):
        source.Weight1 = weight
        source.UpdatePipeline()
    updates = [timed(lambda: change(w)) for w in weights]

    view = CreateView("RenderView")
    ColorBy(Show(source, view), ("CELLS", "volume_ratio"))
    view.ResetCamera()
    Render(view)

    def change_and_render(weight):
        source.Weight1 = weight
        Render(view)
    renders = [timed(lambda: change_and_render(w + 0.05)) for w in weights]
    report("blend_with_quality", blends)
    report("slider change (blend + grid)", updates)
    report("slider change + render", renders)


main(sys.argv[1], sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 10)
