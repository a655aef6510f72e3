"""Sweeps from Python: every scene of a sweep file, run on all cores."""

from __future__ import annotations

import json
import math
import os
import warnings
from pathlib import Path
from typing import Any, Mapping, Optional, Union

import numpy as np

from . import Scene, _core, _scene, _yaml_value_default
from ._args import checked
from ._errors import RunWarning, SceneError
from ._names import nearest


def _numbers_or_text(values: list) -> np.ndarray:
    """An axis's values as floats where every one is a number, else as text."""
    try:
        return np.array([float(v) for v in values])
    except ValueError:
        return np.array(values, dtype=object)


class SweepTable:
    """A sweep's table, one row per run in the sweep's order (first axis slowest): the same
    rows as ``rattleback sweep`` writes.

    Columns (the CSV's, same names and order): ``row``, one per varied key (floats, or text
    for values that are not numbers), ``status`` (``ok``, ``stopped`` or ``refused``: a word to
    group by), ``stop_reason`` (for a stopped run, why as a code: ``non_finite``,
    ``energy_gain``, ``on_rim``), ``first_reversal_s``, ``reversals``, ``final_spin``,
    ``max_tilt_deg``, ``energy_lost``, ``wall_s``, and ``message`` (why a run stopped or was
    refused, in words). A column is ``table["final_spin"]``, or ``table.final_spin`` where its name
    is a Python name, as a Run's. A number a run does not have is NaN; text it does not have is ``""``. The arrays are read-only, as the CSV they
    stand for is (``.copy()`` gives one to change). A sweep given ``columns`` (or a sweep file's
    ``columns:``) holds ``row``, the varied keys and those columns only, in that order (one of
    them may be ``forecast_s``, the averaged theory's first reversal, which ``analyze`` prints,
    and ``forecast_note``, a word saying why ``forecast_s`` is or is not a time).
    """

    def __init__(self, core_table):
        self._table = core_table
        columns = core_table.columns()
        for key in core_table.keys:
            columns[key] = _numbers_or_text(columns[key])
        for name, column in list(columns.items()):
            if isinstance(column, list):  # a result column of text
                columns[name] = np.array(column, dtype=object)
        # Read-only, as a Run's: the columns are the table's record, and to_csv writes the
        # rows, not the arrays (`s = table["final_spin"]; s *= 2` changed the columns and
        # to_pandas() but not the CSV).
        for column in columns.values():
            column.flags.writeable = False
        self._columns = columns

    @property
    def columns(self) -> dict[str, np.ndarray]:
        return dict(self._columns)

    @property
    def interrupted(self) -> bool:
        """True for the rows finished before Ctrl-C (``KeyboardInterrupt.table``)."""
        return bool(self._table.interrupted)

    @property
    def keys(self) -> list[str]:
        """The varied keys, in the sweep file's order."""
        return list(self._table.keys)

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self._columns:
            raise KeyError(f"{name!r} is not a column{self._nearest(name)}")
        return self._columns[name]

    def __getattr__(self, name: str) -> np.ndarray:
        columns = self.__dict__.get("_columns", {})
        if name in columns:  # as a Run's: table.first_reversal_s
            return columns[name]
        if name.startswith("_"):  # Python's and IPython's own probes: no hint to work out
            raise AttributeError(name)
        raise AttributeError(f"SweepTable has no column or attribute {name!r}{self._nearest(name)}")

    def _nearest(self, name: str) -> str:
        columns = list(self.__dict__.get("_columns", {}))
        return nearest(name, columns) + " (columns: " + ", ".join(columns) + ")"

    def __dir__(self):
        return sorted(set(super().__dir__()) | {c for c in self._columns if c.isidentifier()})

    def __len__(self) -> int:
        return len(self._columns["row"])

    def to_pandas(self):
        """The table as a ``pandas.DataFrame`` (needs pandas). A count (``reversals``) is of
        pandas' nullable integers, ``Int64``: ``<NA>`` where a refused run has none, where the
        NumPy column, float, has NaN."""
        import pandas as pd

        frame = pd.DataFrame(self._columns)
        for name in self._table.whole_columns:
            frame[name] = frame[name].astype("Int64")
        return frame

    @checked
    def to_csv(self, path: Union[str, os.PathLike]) -> None:
        """Writes the command line's table and sidecar (``path + ".json"``), each whole."""
        self._table.to_csv(os.fspath(path))

    def __repr__(self) -> str:
        part = ", interrupted" if self._table.interrupted else ""
        if "status" not in self._columns:  # a sweep whose columns do not list it
            return f"<SweepTable {self._table.file}: {len(self)} runs{part}>"
        ok = int(np.sum(self._columns["status"] == "ok"))
        return f"<SweepTable {self._table.file}: {len(self)} runs, {ok} ok{part}>"


def _value(value: Any) -> Any:
    """A value as the table will show it: a whole float as the whole number (NumPy's linspace
    gives -10.0, which the table wrote "-10.0" where a sweep file's -10 is "-10")."""
    if isinstance(value, np.generic):
        value = value.item()
    if type(value) is float and value.is_integer() and abs(value) < 1e15:
        return int(value)
    return value


def _values(values: Any) -> Any:
    """An axis's values as the sweep file's YAML (as JSON) takes them: a list, or a range."""
    if isinstance(values, Mapping):
        return dict(values)
    if isinstance(values, np.ndarray):
        values = values.tolist()
    return [_value(v) for v in values]


def _columns(columns: Optional[list]) -> Optional[list]:
    """``columns`` as the core takes them: a list of names, or None for the sweep's own."""
    return None if columns is None else list(columns)


def _file_sweep(source, duration, name, jobs, kept, columns):
    """The call that runs the sweep file at ``source``."""
    if not isinstance(source, (str, os.PathLike)):
        raise TypeError(
            "argument vary: a scene is swept along the values given as vary, "
            "e.g. vary={'initial.spin': [-5, 5]}; without it, source is a "
            "sweep file's path"
        )
    for given, value in (("duration", duration), ("name", name)):
        if value is not None:
            raise TypeError(
                f"argument {given}: goes with vary (a sweep file sets its own"
                + (": duration:)" if given == "duration" else ")")
            )
    return lambda: _core.sweep(os.fspath(source), jobs, kept, columns)


def _scene_sweep(source, vary, duration, name, jobs, kept, columns):
    """The call that runs the scene ``source`` along ``vary``, as a sweep file would."""
    base = _scene(source)
    if base._mesh is not None:
        # A sweep's rows are made from the scene's text, which names the mesh by file.
        raise SceneError(
            "argument source: a Scene.from_mesh scene cannot be swept: write its mesh to an STL "
            "or OBJ file (trimesh: trimesh.Trimesh(vertices, faces).export('toy.stl')) and name it "
            "in a scene's body.mesh.file (docs/your-own-body.md)",
            "argument source",
            None,
            "body.mesh.file",
        )
    spec: dict[str, Any] = {"vary": {key: _values(v) for key, v in vary.items()}}
    if duration is not None:
        if not (math.isfinite(float(duration)) and float(duration) > 0):
            # As simulate's: a SceneError naming the key the argument sets.
            raise SceneError(
                f"argument duration: must be > 0, not {duration}",
                "argument duration",
                None,
                "simulation.duration",
            )
        spec["duration"] = float(duration)
    if name is None:
        name = (Path(base._name).stem if base._file else "scene") + "-sweep"
    text = json.dumps(spec, default=_yaml_value_default)
    return lambda: _core.sweep_of(text, name, base._yaml, base._name, list(base._values), jobs, kept, columns)


@checked
def sweep(
    source: Union[str, os.PathLike, Scene, Mapping[str, Any]],
    vary: Optional[Mapping[str, Any]] = None,
    *,
    duration: Optional[float] = None,
    jobs: int = 0,
    name: Optional[str] = None,
    resume: Optional[SweepTable] = None,
    columns: Optional[list] = None,
) -> SweepTable:
    """Runs every scene of a sweep on ``jobs`` threads (0: all cores), as ``rattleback sweep``
    does: the sweep file at ``source`` (docs/scenes.md "Sweep files": a base scene and axes of
    values), or, with ``vary``, the scene ``source`` (a Scene, a scene's path or a dict) with
    ``vary`` as a sweep file's ``vary:`` (each dotted key's values: a list or array, or a range
    ``{"from": A, "to": B, "count": N}`` with ``"scale": "log"`` if wanted), ``duration`` as its
    ``duration:`` (s, every run's), and ``name`` the table's (default: the scene file's name
    and ``-sweep``). ``resume``: a table of the same sweep kept from Ctrl-C (its rows are not
    run again, and the table returned holds them too), as ``rattleback sweep --resume`` does.
    ``columns``: the result columns to compute, as a sweep file's ``columns:`` (given with a
    sweep file, in its place): each run stops as soon as they are known (``first_reversal_s``
    once the reversal rule has confirmed it; docs/commands.md "Only the columns a table needs"),
    and the table holds only them.

    Raises :class:`SceneError` (a ``ValueError``) for a sweep that cannot be used, naming its
    file, line and key as a scene's does (an error in ``vary`` is named ``argument vary`` and
    the key); KeyboardInterrupt on Ctrl-C, whose ``table`` is a
    SweepTable of the rows finished by then (the others not run; its ``interrupted`` is True,
    and its ``to_csv`` sidecar says so). An axis the runs do not use
    (``contact.friction`` under ``rolling``: the rows along it are alike) is warned of, as
    ``rattleback sweep`` notes it (:class:`RunWarning`, code ``"axis_unused"``), and so is a
    sweep whose every run was refused (code ``"all_refused"``: ``rattleback sweep`` exits 2),
    with the first refusal's message.
    """
    kept = resume._table if resume is not None else None
    if vary is None:
        run = _file_sweep(source, duration, name, int(jobs), kept, _columns(columns))
    else:
        run = _scene_sweep(source, vary, duration, name, int(jobs), kept, _columns(columns))
    try:
        table = run()
    except KeyboardInterrupt as interrupt:
        # The rows finished before Ctrl-C, kept: `except KeyboardInterrupt as e: e.table`.
        if hasattr(interrupt, "table"):
            interrupt.table = SweepTable(interrupt.table)
        raise
    for note in table.notes:
        warnings.warn(RunWarning(note, "axis_unused"), stacklevel=3)
    result = SweepTable(table)
    if table.first_refusal is not None:
        warnings.warn(
            RunWarning(
                f"{table.file}: every run was refused; the first: {table.first_refusal}", "all_refused"
            ),
            stacklevel=3,
        )
    return result
