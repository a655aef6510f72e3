"""Sweeps from Python: every scene of a sweep file, run on all cores."""

from __future__ import annotations

import os
import warnings
from typing import Union

import numpy as np

from . import _core
from ._args import checked
from ._errors import RunWarning


def _numbers_or_text(values: list) -> np.ndarray:
    """An axis's values as floats where every one is a number, else as text."""
    try:
        return np.array([float(v) for v in values])
    except ValueError:
        return np.array(values, dtype=object)


class SweepTable:
    """A sweep's table, one row per run in the sweep's order (first axis slowest): the same
    rows as ``rattleback sweep`` writes.

    Columns: ``row``, one per varied key (floats, or text for values that are not numbers),
    ``status`` (``ok``, ``stopped`` or ``refused``), ``reason`` (why, for the others),
    ``first_reversal_s``, ``reversals``, ``final_spin``, ``max_tilt_deg``, ``energy_lost``,
    ``wall_s``. A value a run does not have is NaN. The arrays are read-only, as the CSV they
    stand for is (``.copy()`` gives one to change).
    """

    def __init__(self, core_table):
        self._table = core_table
        columns = core_table.columns()
        for key in core_table.keys:
            columns[key] = _numbers_or_text(columns[key])
        columns["status"] = np.array(columns["status"])
        columns["reason"] = np.array(columns["reason"], dtype=object)
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
    def keys(self) -> list[str]:
        """The varied keys, in the sweep file's order."""
        return list(self._table.keys)

    def __getitem__(self, name: str) -> np.ndarray:
        return self._columns[name]

    def __len__(self) -> int:
        return len(self._columns["row"])

    def to_pandas(self):
        """The table as a ``pandas.DataFrame`` (needs pandas)."""
        import pandas as pd
        return pd.DataFrame(self._columns)

    @checked
    def to_csv(self, path: Union[str, os.PathLike]) -> None:
        """Writes the command line's table and sidecar (``path + ".json"``), each whole."""
        self._table.to_csv(os.fspath(path))

    def __repr__(self) -> str:
        ok = int(np.sum(self._columns["status"] == "ok"))
        return f"<SweepTable {self._table.file}: {len(self)} runs, {ok} ok>"


@checked
def sweep(path: Union[str, os.PathLike], *, jobs: int = 0) -> SweepTable:
    """Runs every scene of the sweep file at ``path`` (docs/scenes.md "Sweep files": a base scene and axes
    of values) on ``jobs`` threads (0: all cores), as ``rattleback sweep`` does.

    Raises ValueError for a sweep file that cannot be used; KeyboardInterrupt on Ctrl-C. An
    axis the runs do not use (``contact.friction`` under ``rolling``: the rows along it are
    alike) is warned of, as ``rattleback sweep`` notes it (:class:`RunWarning`, code
    ``"axis_unused"``), and so is a sweep whose every run was refused (code
    ``"all_refused"``: ``rattleback sweep`` exits 2), with the first reason.
    """
    table = _core.sweep(os.fspath(path), int(jobs))
    for note in table.notes:
        warnings.warn(RunWarning(note, "axis_unused"), stacklevel=3)
    result = SweepTable(table)
    status = result["status"]
    if len(status) and bool(np.all(status == "refused")):
        warnings.warn(RunWarning(f"{table.file}: every run was refused; the first: "
                                 f"{result['reason'][0]}", "all_refused"), stacklevel=3)
    return result
