"""The types the public functions' arguments take, checked in one place before any call.

A value of the wrong type raises TypeError naming the argument and what it takes
(``argument duration: takes a number (s), not '3' (str)``); without this the compiled modules
raised pybind11's "Unable to cast Python instance to C++ type", naming neither. A value of the
right type that the scene cannot use (``duration=-3``) is left to the library, whose
:class:`SceneError` names the scene key, as the command line's message does.
"""

from __future__ import annotations

import difflib
import functools
import inspect
import numbers
import os
from collections.abc import Mapping
from typing import Any, Callable, Optional

import numpy as np


# Each test first looks at the value's exact type, the common case, for the per-call cost (a
# short simulate takes tens of µs; numbers.Real's isinstance alone takes ~0.3 µs).
def _number(value: Any) -> bool:
    if type(value) in (float, int):
        return True
    # A bool is an int to Python, but True as a spin (1 rad/s) or a step is a flag given to the
    # wrong argument far more often than a number; the scene file refuses `spin: true` too.
    if isinstance(value, np.ndarray) and value.ndim == 0:  # a 0-d array, as NumPy's sums give
        return value.dtype.kind in "fiu"
    return isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))


def _whole(value: Any) -> bool:
    if type(value) is int:
        return True
    if isinstance(value, np.ndarray) and value.ndim == 0:
        return value.dtype.kind in "iu"
    return isinstance(value, numbers.Integral) and not isinstance(value, (bool, np.bool_))


def _flag(value: Any) -> bool:
    # Only True or False: any object is truthy, and check="no" would have run the check.
    return value is True or value is False or isinstance(value, np.bool_)


def _text(value: Any) -> bool:
    return type(value) is str or isinstance(value, str)


def _path(value: Any) -> bool:
    return isinstance(value, (str, os.PathLike))


def _size(value: Any) -> bool:
    if isinstance(value, (str, bytes)):
        return False
    try:
        return len(value) == 2 and all(_whole(side) for side in value)
    except TypeError:  # no length
        return False


def _numbers(count: int) -> Callable[[Any], bool]:
    """A test for `count` numbers: a list, tuple or 1-d array of them."""

    def test(value: Any) -> bool:
        if isinstance(value, (str, bytes, Mapping)):
            return False
        if isinstance(value, np.ndarray) and value.ndim != 1:
            return False
        try:
            return len(value) == count and all(_number(v) for v in value)
        except TypeError:  # no length
            return False

    return test


def _array(kinds: str, shape: Optional[tuple] = None) -> Callable[[Any], bool]:
    """A test for an array (or nested lists) of numbers whose NumPy kind is in `kinds` ("iu"
    whole numbers, "fiu" any; an empty one passes), of `shape` where given (None: any size)."""

    def test(value: Any) -> bool:
        if isinstance(value, (str, bytes, Mapping)):
            return False
        try:
            array = np.asarray(value)
        except (ValueError, TypeError):  # ragged rows
            return False
        if shape is not None and (
            array.ndim != len(shape) or any(n is not None and n != m for n, m in zip(shape, array.shape))
        ):
            return False
        return array.dtype.kind in kinds or (array.size == 0 and array.dtype.kind == "f")

    return test


def _scene(value: Any) -> bool:
    global _Scene
    if _Scene is None:
        from . import Scene as _Scene  # (the package imports this module first)
    return type(value) in (_Scene, str) or isinstance(value, (_Scene, str, os.PathLike, Mapping))


_Scene = None


def _scene_value(value: Any) -> bool:
    """What a scene key can hold: what YAML (as JSON) writes, NumPy's scalars and arrays too."""
    if value is None or isinstance(value, (str, bool, numbers.Real, np.generic, np.ndarray)):
        return True
    if isinstance(value, (list, tuple)):
        return all(_scene_value(v) for v in value)
    if isinstance(value, Mapping):
        return all(isinstance(k, str) and _scene_value(v) for k, v in value.items())
    return False


# What each argument takes, by name: an argument means the same in every function that has it
# (`spin` is rad/s in simulate, analyze, still and render), so a name is described once.
_NUMBER = "a number"
_TAKES: dict[str, tuple[Callable[[Any], bool], str]] = {
    "scene": (_scene, "a Scene, a path or a dict"),
    "rate": (_number, f"{_NUMBER} (samples per simulated second)"),
    "duration": (_number, f"{_NUMBER} (s)"),
    "spin": (_number, f"{_NUMBER} (rad/s)"),
    "dt": (_number, f"{_NUMBER} (s)"),
    "tolerance": (_number, _NUMBER),
    "t": (_number, f"{_NUMBER} (s)"),
    # still's t: a time, or a moment the run finds (checked by the library, which names the three)
    "moment": (
        lambda v: _number(v) or isinstance(v, str),
        f"{_NUMBER} (s), or a moment of the run: 'reversal', 'first_reversal' or 'end'",
    ),
    "title": (_text, "text"),
    "until": (_text, "'reversal'"),
    "position": (_numbers(3), "3 numbers (x, y, z), m"),
    "velocity": (_numbers(3), "3 numbers (x, y, z), m/s"),
    "angular_velocity": (_numbers(3), "3 numbers (x, y, z), rad/s"),
    "quaternion": (_numbers(4), "4 numbers (w, x, y, z)"),
    "playback": (_number, f"{_NUMBER} (times real time)"),
    "frame": (_number, f"{_NUMBER} (a length, in the scene's unit)"),
    # A number, not a whole one: fps=29.97 is refused by the library as the other video
    # arguments' values are, with a SceneError naming video.fps.
    "fps": (_number, f"{_NUMBER} (frames per second)"),
    "crf": (_whole, "a whole number"),
    "jobs": (_whole, "a whole number"),
    "segments": (_whole, "a whole number (8 to 4096)"),
    "size": (_size, "(width, height) in pixels, e.g. (640, 360)"),
    "integrator": (_text, "a name (text), e.g. 'rk4'"),
    "view": (_text, "a name (text), e.g. 'oblique'"),
    "surface": (_text, "a name (text), e.g. 'triangles'"),
    "preset": (_text, "a name (text), e.g. 'veryfast'"),
    "backend": (_text, "a name (text), e.g. 'auto'"),
    "check": (_flag, "True or False"),
    "both": (_flag, "True or False"),
    "readouts": (_flag, "True or False"),
    "transparent": (_flag, "True or False"),
    "exactly": (_flag, "True or False"),
    "path": (_path, "a path (text or os.PathLike)"),
    "output": (_path, "a path (text or os.PathLike)"),
    "name": (_text, "text"),
    # A sweep's columns: names, each a column of its table (which the library checks, naming
    # the nearest).
    "columns": (
        lambda v: isinstance(v, (list, tuple)) and all(isinstance(c, str) for c in v),
        "a list of the table's columns (text), e.g. ['first_reversal_s']",
    ),
    "text": (_text, "YAML text"),
    # Any array of numbers: Scene.from_mesh says what shape it takes, and the shape it was given.
    "vertices": (_array("fiu"), "an (N, 3) array of numbers (x, y, z), in units"),
    "faces": (_array("iu"), "an (M, 3) array of whole numbers (vertex indices)"),
    "mass": (_number, f"{_NUMBER} (kg)"),
    "units": (_number, f"{_NUMBER} (m per unit of the vertices: 0.001 for mm)"),
    "center_of_mass": (_numbers(3), "3 numbers (x, y, z), in units"),
    "inertia": (
        _array("fiu", (3, 3)),
        "a 3×3 array of numbers (kg m², about the CM)",
    ),
    "values": (
        lambda v: isinstance(v, Mapping),
        "a dict of dotted keys and values, e.g. {'initial.spin': -5}",
    ),
    "source": (_scene, "a sweep file's path, or with vary a Scene, a scene's path or a dict"),
    "resume": (
        lambda v: type(v).__name__ == "SweepTable" and hasattr(v, "interrupted"),
        "a SweepTable (a KeyboardInterrupt's table)",
    ),
    "vary": (
        lambda v: isinstance(v, Mapping),
        "a dict of dotted keys and their values, e.g. {'initial.spin': [-5, 5]}",
    ),
}


def _shown(value: Any) -> str:
    """The value as the message shows it: its repr, cut short, and its type."""
    text = repr(value)
    if len(text) > 40:
        text = text[:37] + "..."
    return f"{text} ({type(value).__name__})"


def refuse(name: str, value: Any, kind: Optional[str] = None) -> None:
    """Raises the TypeError for `value` given as argument `name` (of _TAKES's `kind`, when the
    function's argument means another kind than the name's)."""
    raise TypeError(f"argument {name}: takes {_TAKES[kind or name][1]}, not {_shown(value)}")


def _check(name: str, value: Any, kind: Optional[str] = None) -> None:
    test, _ = _TAKES[kind or name]
    if not test(value):
        refuse(name, value, kind)
    if name in ("path", "output") and os.fspath(value) == "":
        # A wrong value, not a wrong type: to_csv("") failed on moving its file into place, and
        # render(output="") wrote its default name as if none had been given.
        way_out = "a file name, or None for the default" if name == "output" else "a file name"
        raise ValueError(f"argument {name}: '' names no file; give {way_out}")
    if name == "vary":  # each key's values: a list (or array) of them, or a range's dict
        for key, v in value.items():
            if not isinstance(key, str):
                raise TypeError(f"argument vary: takes dotted keys as text, not {_shown(key)}")
            if isinstance(v, Mapping):
                continue
            if (
                isinstance(v, (str, bytes))
                or not isinstance(v, (list, tuple, range, np.ndarray))
                or not all(_scene_value(x) for x in v)
            ):
                raise TypeError(
                    f"argument vary: {key} takes a list of values or a range "
                    f"{{'from': A, 'to': B, 'count': N}}, not {_shown(v)}"
                )
    if name == "values":  # and each value, named by its key
        for key, v in value.items():
            if not isinstance(key, str):
                raise TypeError(f"argument values: takes dotted keys as text, not {_shown(key)}")
            if not _scene_value(v):
                raise TypeError(
                    f"argument values: {key} takes a number, text, True or False, "
                    f"a list or a dict, not {_shown(v)}"
                )


def _unknown_keyword(function: Callable, name: str, names: frozenset) -> None:
    """Raises Python's own TypeError for a keyword `function` has not, with the nearest it has
    (``analyze(spinn=3)``: did you mean spin?); without a near one, the call itself raises it."""
    near = difflib.get_close_matches(name, sorted(names), n=1)
    # The physics' own symbols: n = ω·ẑ, the docs' and the theory's name for the spin, and ω.
    symbol = {"n": "spin", "omega": "angular_velocity", "w": "angular_velocity"}.get(name)
    if not near and symbol in names:
        near = [symbol]
    if near:
        raise TypeError(
            f"{function.__name__}() got an unexpected keyword argument {name!r}; did you mean {near[0]!r}?"
        )
    # A scene key's last word (tilt for initial.tilt): it goes in the scene, not the call.
    from . import _core  # (imported with the package; this module is imported before it)

    keys = [k for k in _core.scene_keys if k.rsplit(".", 1)[-1] == name]
    if keys and "scene" in names:
        raise TypeError(
            f"{function.__name__}() got an unexpected keyword argument {name!r}: {keys[0]} is a scene "
            f"key, which the scene gives: rb.Scene.from_file(…).with_values({{{keys[0]!r}: …}})"
        )


def checked(function: Optional[Callable] = None, **kinds: str) -> Callable:
    """`function` with its arguments' types checked first, each by its name in _TAKES (a
    function with an argument not in it fails at import, so none goes unchecked), or by the
    kind `kinds` gives it (``@checked(t="moment")``: still's t takes a moment's name too). An
    argument whose default is None may be None; defaults are not checked."""
    if function is None:
        return functools.partial(checked, **kinds)
    parameters = [p for p in inspect.signature(function).parameters.values() if p.name not in ("self", "cls")]
    unknown = [p.name for p in parameters if kinds.get(p.name, p.name) not in _TAKES]
    if unknown:
        raise AssertionError(f"{function.__qualname__}: no type for {', '.join(unknown)}")
    offset = len(inspect.signature(function).parameters) - len(parameters)
    positional = [p.name for p in parameters if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    optional = frozenset(p.name for p in parameters if p.default is None)
    names = frozenset(p.name for p in parameters)
    open_ended = any(p.kind == p.VAR_KEYWORD for p in parameters)

    @functools.wraps(function)
    def call(*args, **kwargs):
        for name, value in zip(positional, args[offset:]):
            if value is not None or name not in optional:
                _check(name, value, kinds.get(name))
        for name, value in kwargs.items():
            if name not in names and not open_ended:
                _unknown_keyword(function, name, names)
            if name in names and (value is not None or name not in optional):
                _check(name, value, kinds.get(name))
        return function(*args, **kwargs)

    return call
