"""The rolling model linearised about steady upright spin: :func:`linearize` and the
:class:`Linearization` it gives."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

import numpy as np

from . import _core
from ._args import checked


@dataclass(frozen=True)
class Linearization:
    """The rolling model linearised about steady upright spin n (docs/physics.md P8).

    The state x is the tilt u = Rᵀẑ (the world's up in body axes: ``u_x``, ``u_y``) and the
    angular velocity in body axes (``w_x``, ``w_y``, ``w_z``); near x̄ = (0, 0, 0, 0, n) it
    obeys d/dt (x − x̄) = A (x − x̄). Yaw and position drop out: the floor is the same
    everywhere and every way round.

    Attributes:
        spin: n, rad/s.
        states: the states' names, in the order of A's rows and columns.
        units: each state's unit ("1" for the tilt's components, "rad/s").
        meanings: each state in words.
        matrix: A, 5×5, 1/s (read-only).
        eigenvalues: A's eigenvalues, complex, 1/s, as ``analyze`` lists them: one is the
            spin's own (zero without air drag, as every n is steady; −σ/C with drag σ), the
            others are the roll and pitch modes; a positive real part grows.
    """

    spin: float
    states: tuple[str, ...]
    units: tuple[str, ...]
    meanings: tuple[str, ...]
    matrix: np.ndarray
    eigenvalues: np.ndarray

    @classmethod
    def _of(cls, data: dict[str, Any]) -> "Linearization":
        def frozen(a: np.ndarray) -> np.ndarray:
            a.setflags(write=False)
            return a

        states = data["states"]
        return cls(
            spin=float(data["spin"]),
            states=tuple(s["name"] for s in states),
            units=tuple(s["unit"] for s in states),
            meanings=tuple(s["meaning"] for s in states),
            matrix=frozen(np.array(data["matrix"], dtype=float)),
            eigenvalues=frozen(np.array([complex(re, im) for re, im in data["eigenvalues"]])),
        )


@checked
def linearize(scene: Any, spin: Optional[float] = None) -> Linearization:
    """The rolling model of ``scene``'s body linearised about steady upright spin ``spin``
    (rad/s; default: the scene's spin, else 5, as :func:`analyze`), whatever the scene's
    contact model: the matrix behind ``analyze``'s eigenvalues and growth rates."""
    from . import _scene  # (the package imports this module last)

    return Linearization._of(_core.linearize(_scene(scene)._load(), spin))
