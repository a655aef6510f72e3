"""The way out of a name that is not there, for the messages of what a user reads by name."""

from __future__ import annotations

import difflib
from typing import Any, Iterable


def nearest(name: str, names: Iterable[str]) -> str:
    """``"; did you mean 'x'?"`` for the nearest of ``names``, or ``""``."""
    near = difflib.get_close_matches(name, [n for n in names if isinstance(n, str)], n=1)
    return f"; did you mean {near[0]!r}?" if near else ""


class Keyed(dict):
    """A result's dict (``analyze``'s, as ``analyze --json`` prints it; nested ones too) whose
    missing key says where it is: the nearest key (``misalignment`` for ``misalignment_deg``),
    or the dict within that has it (``time_s`` is ``["predicted_first_reversal"]["time_s"]``).
    Otherwise a plain dict: ``json.dumps``, ``==`` and pickling are a dict's."""

    @classmethod
    def of(cls, value: Any) -> Any:
        if isinstance(value, dict):
            return cls({k: cls.of(v) for k, v in value.items()})
        return value

    def __missing__(self, key: Any) -> Any:
        if not isinstance(key, str):
            raise KeyError(key)
        within = [k for k, v in self.items() if isinstance(v, dict) and key in v]
        if within:
            raise KeyError(f"{key!r} is a key of [{within[0]!r}]: [{within[0]!r}][{key!r}]")
        raise KeyError(f"{key!r} is not a key{nearest(key, self)} (keys: {', '.join(sorted(self))})")

    def __reduce__(self):  # pickled as the plain dict it stands for
        return (dict, (dict(self),))
