"""rattleback: the rattleback (celt) simulated, analysed and drawn, from Python.

The same library as the ``rattleback`` command: the same scene checks and messages, the same
numbers, the same CSV. ::

    import rattleback as rb
    run = rb.simulate("scenes/rattleback.yaml")
    print(run.first_reversal, run.spin[:5])

Scenes come from a file, a YAML string or a dict (:class:`Scene`); every call also takes a
path. Long calls release the GIL (runs in several threads go in parallel) and stop on Ctrl-C
with ``KeyboardInterrupt``, leaving no temporary file.
"""

from __future__ import annotations

# The modules and names this file uses go by private names, or are deleted at its end: the
# package's namespace is its API (__all__), as dir() and an editor's completion list it.
import os as _os
import warnings as _warnings
from typing import Any, Mapping, Optional, Sequence, Union

try:
    import numpy as _np
except ImportError:  # a Python of its own (pyenv, a venv) without NumPy: say which and how
    import sys as _sys

    raise ImportError(
        f"rattleback needs NumPy, which {_sys.executable} does not have: `python3 -m pip install "
        "numpy` for it, or use Debian's /usr/bin/python3 (python3-numpy)"
    ) from None

try:
    from . import _core
except ImportError:  # the package's files laid out (at configure time), its modules not built
    _here = _os.path.dirname(_os.path.abspath(__file__))
    _built = [n for n in _os.listdir(_here) if n.startswith("_core.") and not n.endswith(".pyi")]
    import sys as _sys
    import sysconfig as _sysconfig

    _suffix = _sysconfig.get_config_var("EXT_SUFFIX") or ""
    if _built and not any(n.endswith(_suffix) for n in _built):
        # Built for another Python (Debian's 3.11) than this one (a pyenv 3.12, a conda env).
        raise ImportError(
            f"rattleback's compiled modules in {_here} are built for another Python "
            f"({', '.join(_built)}), not {_sys.executable} (which needs *{_suffix}): run it with "
            "the Python they were built for (/usr/bin/python3 for the .deb and scripts/build.sh)"
        ) from None
    if _built:
        raise
    raise ImportError(
        f"rattleback's compiled modules are not built in {_here}: build them with "
        "`bash scripts/build.sh rattleback_python` (scripts/run.sh builds only the command)"
    ) from None
from ._args import checked as _checked
from ._errors import RunStopped, RunWarning, SceneError
from ._names import Keyed as _Keyed
from ._names import nearest as _nearest

__all__ = [
    "Scene",
    "Run",
    "Image",
    "SceneError",
    "RunStopped",
    "RunWarning",
    "simulate",
    "analyze",
    "still",
    "render",
    "sweep",
    "SweepTable",
    "compare",
    "Comparison",
    "Simulation",
    "State",
    "linearize",
    "Linearization",
    "__version__",
]

__version__ = _core.version

# The scene's own module; _sweep takes _yaml_value_default from here, as the others _scene.
from ._scenes import Scene, SceneLike, _scene, _yaml_value_default  # noqa: E402,F401


class Run:
    """A finished run: every telemetry column as a NumPy array, and what the run found.

    Columns (the CSV's, same names and order, from one table: ``t``, ``spin``, ``energy``, …,
    ``mode``, and ``qw, qx, qy, qz``, the attitude quaternion: unit, scalar first, body to
    world); ``units`` gives each one's unit and ``meanings`` what it is. ``result`` is the sidecar's ``result`` (status, reversals, energy, steps, …),
    ``model`` its ``model``. The arrays are read-only, as the CSV they stand for is (``.copy()``
    gives one to change).
    """

    def __init__(self, core_run):
        self._run = core_run
        self._columns = core_run.columns()
        self._result = None
        self._model = None

    @property
    def result(self) -> dict:
        """What the run found: the sidecar's ``result`` (status, reversals, energy, steps, …)."""
        if self._result is None:
            self._result = self._run.result()
        return self._result

    @property
    def model(self) -> dict:
        """The run's settings: the sidecar's ``model`` (contact, integrator, step, initial state)."""
        if self._model is None:
            self._model = self._run.model()
        return self._model

    def __getattr__(self, name: str) -> np.ndarray:
        columns = self.__dict__.get("_columns", {})
        if name in columns:
            return columns[name]
        if name.startswith("_"):  # Python's and IPython's own probes: no hint to work out
            raise AttributeError(name)
        raise AttributeError(f"Run has no column or attribute {name!r}{self._nearest(name)}")

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self._columns:
            raise KeyError(f"{name!r} is not a column{self._nearest(name, columns_only=True)}")
        return self._columns[name]

    def _nearest(self, name: str, columns_only: bool = False) -> str:
        """The way out of a name that is not there: the attribute a result key has (``first_
        reversal`` for ``first_reversal_s``), a key of ``result``, or the nearest name."""
        columns = list(self.__dict__.get("_columns", {}))
        as_attribute = {"first_reversal_s": "first_reversal", "reversals_s": "reversals"}
        if name in ("time", "times"):  # the CSV's name for it is t
            return "; did you mean 't' (the time, s)?"
        if not columns_only and name in as_attribute:
            return f"; did you mean run.{as_attribute[name]} (or run.result[{name!r}])?"
        if not columns_only and "_run" in self.__dict__ and name in self.result:
            return f"; it is a key of the run's result: run.result[{name!r}]"
        names = columns if columns_only else columns + [n for n in dir(type(self)) if not n.startswith("_")]
        return _nearest(name, names) + " (columns: " + ", ".join(columns) + ")"

    def __len__(self) -> int:
        return len(self._columns["t"])

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._columns))

    @property
    def columns(self) -> dict[str, np.ndarray]:
        """Every column by name."""
        return dict(self._columns)

    @property
    def units(self) -> dict[str, str]:
        """Each column's unit, as in the sidecar: ``"rad/s"``, ``"J"``; ``""`` for a count, a
        fraction or text."""
        return {name: unit for name, unit, _ in _core.telemetry_columns}

    @property
    def meanings(self) -> dict[str, str]:
        """What each column is, as in the sidecar (``"n = w.z, + counter-clockwise seen from
        above"``)."""
        return {name: meaning for name, _, meaning in _core.telemetry_columns}

    @property
    def reversals(self) -> list[float]:
        """Times of the spin reversals, s (docs/physics.md P7: the reversal rule)."""
        return list(self.result["reversals_s"])

    @property
    def first_reversal(self) -> Optional[float]:
        """Time of the first reversal, s, or None: the zero crossing of the spin n after which n
        goes on to 1 % of the initial spin the other way and holds there 0.2 s (docs/physics.md
        P7). Where n dithers through zero first, this is a later crossing than the first zero of
        ``spin``; ``reversals`` lists every one the rule counts."""
        return self.result["first_reversal_s"]

    @property
    def summary(self) -> dict:
        """What the run found: the sidecar's ``result``."""
        return self.result

    @property
    def scene(self) -> str:
        """The scene as messages name it: its file's path (or ``scene`` for one given as text)."""
        return self._run.scene

    @property
    def rate(self) -> float:
        """Samples per simulated second."""
        return self._run.rate

    @property
    def check(self) -> Optional[dict]:
        """The estimated errors of the run (``simulate(check=True)``): the sidecar's ``check``
        (``reversal_errors_s``, ``spin_error_rad_s``, the ``setting`` compared with, …); None
        without a check."""
        return self._run.check()

    def sidecar(self) -> dict:
        """The sidecar the command line writes beside its CSV, as a dict."""
        return self._run.sidecar()

    def to_pandas(self):
        """The columns as a ``pandas.DataFrame`` (needs pandas)."""
        import pandas as pd

        return pd.DataFrame(self._columns)

    @_checked
    def to_csv(self, path: Union[str, os.PathLike]) -> None:
        """Writes the command line's exact CSV at ``path`` and its sidecar at
        ``path + ".json"``, each whole or not at all."""
        self._run.to_csv(_os.fspath(path))

    @_checked
    def to_npz(self, path: Union[str, os.PathLike]) -> None:
        """Writes the columns as NumPy arrays at ``path`` (``.npz``: ``np.load(path)["spin"]``,
        the run's own doubles; ``contacts`` int64, ``mode`` text), with ``columns`` and
        ``units`` arrays naming each column and its unit, and the sidecar at ``path + ".json"``;
        as ``rattleback simulate -o RUN.npz``."""
        self._run.to_npz(_os.fspath(path))

    @_checked
    def to_hdf5(self, path: Union[str, os.PathLike]) -> None:
        """Writes the columns as HDF5 datasets at ``path`` (``.h5`` or ``.hdf5``: h5py's
        ``f["spin"][:]``, MATLAB's ``h5read(path, "/spin")``), each with ``unit`` and ``meaning``
        attributes, and the sidecar at ``path + ".json"``; as ``rattleback simulate -o RUN.h5``.
        """
        self._run.to_hdf5(_os.fspath(path))

    def __reduce__(self):
        # Pickled as its samples and sidecar, exactly (every column, result, model and check,
        # and the same to_csv): a multiprocessing.Pool's worker, or joblib's cache, returns one.
        return (Run, (self._run,))

    # A run is read-only (its arrays too): a copy is itself.
    def __copy__(self) -> "Run":
        return self

    def __deepcopy__(self, memo) -> "Run":
        return self

    def __repr__(self) -> str:
        first = self.first_reversal
        rev = f"first reversal {first:.4f} s" if first is not None else "no reversal"
        return f"<Run {self.scene}: {len(self)} samples, {rev}>"


@_checked
def simulate(
    scene: SceneLike,
    *,
    rate: float = _core.default_rate,
    duration: Optional[float] = None,
    spin: Optional[float] = None,
    dt: Optional[float] = None,
    tolerance: Optional[float] = None,
    integrator: Optional[str] = None,
    check: bool = False,
) -> Run:
    """Runs the scene, sampled at ``rate`` samples per simulated second (t_k = k / rate, and
    the end), as ``rattleback simulate`` does.

    Args:
        scene: a :class:`Scene`, a path to a scene file, or a dict.
        rate: samples per simulated second (default 500).
        duration: simulated time, s (overrides simulation.duration).
        spin: initial spin, rad/s (overrides initial.spin).
        dt: a fixed step, s (replaces the scene's dt or tolerance).
        tolerance: adaptive steps (dopri5) to this error per step.
        integrator: ``euler``, ``symplectic``, ``rk4``, ``dopri5`` or ``dop853``.
        check: also run at half the step (or a hundredth of the tolerance) and estimate the
            run's errors, as ``simulate --check`` does: :attr:`Run.check`.

    Raises:
        SceneError: the scene or an argument cannot be used.
        RunStopped: the run stopped by itself (NaN, energy from nowhere, on its rim).
        KeyboardInterrupt: Ctrl-C.
    """
    loaded = _scene(scene)._load(
        duration=duration, spin=spin, dt=dt, tolerance=tolerance, integrator=integrator
    )
    try:
        run = Run(_core.simulate(loaded, float(rate), bool(check)))
    except RunStopped as stopped:
        # The run as far as it went, as a Run (a body that tipped over left nothing to plot of the
        # 2.2 s before).
        if isinstance(stopped.run, _core.Run):
            stopped.run = Run(stopped.run)
        raise
    # What the command line's summary warns of, where a notebook shows it (a mass typed in grams ran
    # in silence, its warning only in run.result["warnings"]).
    for warning in run.result.get("warnings") or []:
        _warnings.warn(RunWarning(f"{run.scene}: {warning['text']}", warning.get("code")), stacklevel=3)
    return run


@_checked
def analyze(scene: SceneLike, *, spin: Optional[float] = None, duration: Optional[float] = None) -> dict:
    """Mass properties, rest, contact limits, the linearised theory and the preferred
    direction: the dict ``rattleback analyze --json`` prints. ``spin`` (rad/s) is where the
    growth rates are evaluated (default: the scene's spin, else 5); ``duration`` (s) is how far
    the forecast looks (default: the scene's)."""
    return _Keyed.of(_core.analyze(_scene(scene)._load(duration=duration), spin))


def _image_array(array: Any) -> np.ndarray:
    """`array` if it is an image the writer takes as it is: the writer cast any other dtype to
    uint8 without a word (0.5 → 0, black; 300 → 44)."""
    if not isinstance(array, _np.ndarray):
        raise TypeError(
            "argument array: takes an H×W×3 or H×W×4 uint8 NumPy array, not " f"{type(array).__name__}"
        )
    what = "argument array: an image is an H×W×3 or H×W×4 uint8 array"
    if array.ndim != 3 or array.shape[2] not in (3, 4):
        raise ValueError(f"{what}, not of shape {array.shape}")
    if array.dtype != _np.uint8:
        if array.dtype.kind == "f":  # 0…1, as matplotlib's images are
            way_out = "np.clip(a * 255, 0, 255).astype(np.uint8)"
        elif array.dtype.kind == "b":
            way_out = "a.astype(np.uint8) * 255"
        else:
            way_out = "np.clip(a, 0, 255).astype(np.uint8)"
        raise ValueError(f"{what}, not {array.dtype} (give {way_out})")
    return array


class Image:
    """A drawn frame: ``array`` is H×W×3 (or H×W×4 with transparency) ``uint8``, rows from
    the top. Shows itself in Jupyter; ``save(path)`` writes PNG."""

    def __init__(self, array: np.ndarray, _still: Optional[dict] = None):
        self.array = _image_array(array)
        # For a still of a scene (rb.still), what the folder's manifest lists of it when saved:
        # its scene, view, initial spin and t.
        self._still = _still

    @property
    def width(self) -> int:
        return self.array.shape[1]

    @property
    def height(self) -> int:
        return self.array.shape[0]

    @property
    def t(self) -> Optional[float]:
        """The simulated time drawn, s, for a still of a scene (``t="reversal"`` resolved);
        None for an image made from an array."""
        return (self._still or {}).get("t")

    def png(self) -> bytes:
        """The image as PNG bytes (libpng, as the command line writes them)."""
        from . import _draw

        return _draw.encode_png(self.array, (self._still or {}).get("drawn_by", ""))

    def _repr_png_(self) -> bytes:
        return self.png()

    @_checked
    def save(self, path: Union[str, os.PathLike]) -> None:
        """Writes the image as PNG, whole or not at all (the command line's writer), at a name
        ending in ``.png`` (another raises ValueError, as ``still -o`` refuses it). A still
        of a scene is listed in the folder's manifest, as ``rattleback still`` lists its PNG,
        so that ``rattleback report`` shows it under Stills with its view, time and spin."""
        from . import _draw

        _draw.write_png(_os.fspath(path), self.array, self._still)

    def __repr__(self) -> str:
        return f"<Image {self.width}x{self.height}>"


@_checked(t="moment")
def still(
    scene: SceneLike,
    t: Union[float, str] = 0.0,
    *,
    view: Optional[str] = None,
    size: Optional[tuple[int, int]] = None,
    spin: Optional[float] = None,
    frame: Optional[float] = None,
    surface: Optional[str] = None,
    readouts: bool = True,
    transparent: bool = False,
    backend: str = "auto",
    title: Optional[str] = None,
) -> Image:
    """The scene's run drawn at time ``t`` (s), as ``rattleback still`` draws it.

    Args:
        t: s, or ``"reversal"`` (also ``"first_reversal"``: the first reversal the reversal
            rule counts, which can be later than n's first zero) or ``"end"`` (the run's end);
            the image's ``t`` says the time drawn.
        view: ``oblique``, ``above``, ``front``, ``side`` or ``follow`` (default the scene's).
        size: (width, height) in pixels, even (default the scene's, else 1280×720).
        spin: initial spin, rad/s.
        frame: every view framed for a body this long, in the scene's length unit (default
            the body's own): bodies drawn with the same ``frame`` are drawn at one scale. A
            body that goes out of the picture is warned of (:class:`RunWarning`, code
            ``"body_leaves_frame"``).
        surface: ``points`` (the body's surface points) or ``triangles`` (its closed surface,
            shaded); red where it faces up, blue where it faces down (default the scene's).
        readouts: the title, read-outs and spin inset.
        transparent: an RGBA image with no floor or background.
        backend: ``auto``, ``egl`` or ``osmesa``.
        title: the frame's title instead of the scene's name and values (the spin is said
            after it): a golden image then does not depend on the scene file's name.
    """
    loaded = _scene(scene)._load(view=view, size=size, spin=spin, frame=frame, surface=surface)
    image, leaves = _drawn_still(loaded, t, readouts, transparent, backend, title)
    _warn_leaves(loaded, leaves)
    return image


def _drawn_still(loaded, t, readouts, transparent, backend, title, **named) -> tuple[Image, Optional[str]]:
    # The still of a loaded scene, and where the body leaves the frame. `named`: how messages
    # name the time and the way to a longer run, where the caller is not still()'s (a snapshot
    # suite's case: its key t, and the scene's duration alone).
    from . import _draw

    when = t if isinstance(t, str) else float(t)
    array, listed, leaves = _draw.still(
        loaded, when, bool(readouts), bool(transparent), backend, title, **named
    )
    return Image(array, listed), leaves


def _warn_leaves(loaded, leaves: Optional[str], stacklevel: int = 4) -> None:
    # What the command line warns of when the body goes out of the frame asked for.
    if leaves:
        _warnings.warn(RunWarning(f"{loaded.file}: {leaves}", "body_leaves_frame"), stacklevel=stacklevel)


@_checked
def render(
    scene: SceneLike,
    output: Union[str, os.PathLike, None] = None,
    *,
    both: bool = False,
    fps: Optional[int] = None,
    size: Optional[tuple[int, int]] = None,
    view: Optional[str] = None,
    playback: Optional[float] = None,
    duration: Optional[float] = None,
    spin: Optional[float] = None,
    frame: Optional[float] = None,
    surface: Optional[str] = None,
    crf: int = 20,
    preset: str = "veryfast",
    backend: str = "auto",
) -> list[dict]:
    """The scene's run as an MP4 video (H.264), as ``rattleback render`` writes it.

    ``output`` is the .mp4 (default ``out/<scene>.mp4``; ``out/scene.mp4`` for a dict or YAML
    text given no name); with ``both=True`` it is the base of
    ``BASE-preferred.mp4``, ``BASE-reversed.mp4`` and ``BASE-both.mp4``. Returns one dict per
    video: ``path``, ``role``, ``frames``, and ``spin``, ``first_reversal_s``, ``reversals_s`` and
    ``final_spin`` of the run it shows (``None`` for a side-by-side video).
    ``frame`` and ``surface`` are :func:`still`'s.
    """
    from . import _draw

    loaded = _scene(scene)._load(
        fps=fps,
        size=size,
        view=view,
        playback=playback,
        duration=duration,
        spin=spin,
        frame=frame,
        surface=surface,
    )
    files, leaves = _draw.render(
        loaded, "" if output is None else _os.fspath(output), both, int(crf), preset, backend
    )
    _warn_leaves(loaded, leaves)
    return files


from ._sweep import SweepTable, sweep  # noqa: E402
from ._compare import Comparison, compare  # noqa: E402
from ._simulation import Simulation, State  # noqa: E402
from ._linearize import Linearization, linearize  # noqa: E402

# The annotations above are text (from __future__ import annotations), read by editors and
# help(); the names they use are not the API.
del annotations, Any, Mapping, Optional, Sequence, Union, SceneLike
