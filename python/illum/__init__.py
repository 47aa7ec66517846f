"""illum: the lighting models of computer graphics, rendered exactly on the CPU.

    import illum
    picture = illum.render("duck.glb", resolution=(320, 240), model="phong")
    picture            # a NumPy array, H×W×4 uint8 RGBA, shown inline by Jupyter
    illum.eval(model="phong", angle_nl=30, angle_rv=0, shininess=10)["specular"]

The options are the command line's (docs/cli.md), by the same names with underscores for dashes,
checked by the same code: a refused value raises illum.InputError with the command line's message.
"""

import json as _json
import os as _os

import numpy as _np

from . import _illum
from ._illum import Error, InputError, Model

__version__ = _illum.__version__
__all__ = ["render", "eval", "compare", "history", "load_model", "Picture", "Model", "Error", "InputError"]


class Picture(_np.ndarray):
    """A picture: H×W×4 uint8 RGBA, rows top to bottom (or float32 linear RGBA with linear=True),
    shown inline in Jupyter. `warnings` holds what the command line would have warned about."""

    def __array_finalize__(self, obj):
        self.warnings = getattr(obj, "warnings", [])
        self.display = getattr(obj, "display", None)

    def _repr_png_(self):
        shown = self if self.dtype == _np.uint8 else self.display
        if shown is None or shown.ndim != 3 or shown.shape[2] != 4:
            return None
        return _illum.encode_png(_np.ascontiguousarray(shown))

    def png(self):
        """The picture as a PNG file's bytes, as `illum render -o x.png` writes them."""
        return self._repr_png_()

    def save(self, path):
        """Writes the picture as a PNG file."""
        with open(path, "wb") as f:
            f.write(self.png())


def _text(name, value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple, _np.ndarray)):
        return ",".join(_text(name, v) for v in value)
    if isinstance(value, (int, float, str, _np.integer, _np.floating)):
        return str(value)
    raise TypeError(f"{name}: expected a number, a string, a bool or a sequence of numbers, got {type(value).__name__}")


def _options(options):
    return [(name, _text(name, value)) for name, value in options.items() if value is not None]


def _source(scene):
    """A path (str or os.PathLike), a scene as a dict (docs/scene-format.md), a Model, or None for
    the built-in scene."""
    if scene is None:
        return ""
    if isinstance(scene, Model):
        return scene
    if isinstance(scene, dict):
        return ("json", _json.dumps(scene), _os.getcwd())
    if isinstance(scene, (str, _os.PathLike)):
        return _os.fspath(scene)
    raise TypeError(f"expected a path, a scene dict, an illum.Model or None, got {type(scene).__name__}")


def _picture(arrays, linear=False):
    rgba, linear_values, warnings = arrays
    picture = (linear_values if linear else rgba).view(Picture)
    picture.warnings = list(warnings)
    picture.display = rgba if linear else None
    return picture


def render(scene=None, *, linear=False, progress=None, **options):
    """Draws a scene file, a model file, a scene dict, an illum.Model, or (None) the built-in scene.

    Returns a Picture: H×W×4 uint8, or with linear=True float32 linear values, unclamped. `progress`
    is called with the fraction done (0..1) while the ray and path tracers draw; an exception it
    raises, or Ctrl+C, stops the render. The GIL is released while illum draws."""
    return _picture(_illum.render(_source(scene), _options(options), linear, progress), linear)


def compare(scene=None, **options):
    """`illum compare`: the scene under two axes of settings (rows=, cols=, diff=) as one sheet."""
    return _picture(_illum.compare(_source(scene), _options(options)))


def history(scene=None, **options):
    """`illum history`: the scene as each model from Wylie (1967) to Kajiya (1986) drew it."""
    return _picture(_illum.history(_source(scene), _options(options)))


def eval(**options):  # noqa: A001 (the command's name)
    """`illum eval`: every term of the lighting equation at one point for one light, as a dict
    (emission, ambient, diffuse, specular, total, the vectors and factors); with a sweep
    (angle_nl="0:90:5" or shininess=[1, 10, 100]) a list of such dicts."""
    return _json.loads(_illum.evaluate_json(_options(options)))


def load_model(path, **options):
    """Reads a model file once (in a limited child process) to draw it many times with render()."""
    return _illum.load_model(_os.fspath(path), _options(options))
