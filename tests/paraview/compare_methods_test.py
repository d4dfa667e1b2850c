"""samples/compare_methods.py in pvpython: one PNG with a panel per method,
each showing its blend (or, for a method that fails on these examples,
nothing below its title).

Run by ctest through tools/run_pvpython.py (pvpython on its own Xvfb server)."""

import importlib.util
import os

import numpy as np
import tetblend_blend

import paraview_test_support as support

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "samples",
                      "compare_methods.py")
# The top of a panel holds its title: the blend is looked for below it.
TITLE_SHARE = 0.15


def load_script():
    spec = importlib.util.spec_from_file_location("compare_methods", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def main():
    folder = support.output_folder("compare_methods")
    model = support.bar_model(folder)
    png = os.path.join(folder, "methods.png")
    script = load_script()
    # Half of the bar's 4 pi twist: alexa has no blend of its turns by pi.
    inverted = script.main([model, "--weights", "0.5,0", "-o", png])
    assert list(inverted) == tetblend_blend.methods(), list(inverted)
    support.assert_not_blank(png)

    pixels = support.png_pixels(png)[:, :, :3]
    rows, columns = script.grid_shape(len(inverted))
    height, width = pixels.shape[0] // rows, pixels.shape[1] // columns
    background = pixels[-1, 0]
    for index, (method, count) in enumerate(inverted.items()):
        row, column = divmod(index, columns)
        panel = pixels[row * height:(row + 1) * height, column * width:(column + 1) * width]
        body = panel[int(TITLE_SHARE * height):-2, 2:-2]
        drawn = np.any(body != background, axis=2).mean()
        if count is None:
            assert drawn == 0, "%s failed but its panel shows %.3f foreground" % (method, drawn)
        else:
            assert drawn >= support.MIN_FOREGROUND_SHARE, (
                "the panel of %s is blank (%.4f foreground)" % (method, drawn))
        print("compare_methods_test: panel %d (%s, %s inverted): %.3f foreground" % (
            index, method, count, drawn))


main()
