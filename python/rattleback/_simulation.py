"""A run stepped from Python: :class:`Simulation` and the :class:`State` it reads."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from . import _core
from ._args import checked


@dataclass(frozen=True)
class State:
    """The state of a run at one time, SI units (arrays are read-only copies).

    Attributes:
        t: s.
        position: the centre of mass, world axes, m (z up, the floor at z = 0).
        quaternion: the attitude, body to world, unit, scalar first (w, x, y, z).
        velocity: the centre of mass's velocity, world axes, m/s.
        angular_velocity: ω in body axes (x short, y long, z up), rad/s.
        angular_velocity_world: ω in world axes, rad/s.
        spin: n = ω·ẑ, rad/s (+ counter-clockwise seen from above).
        tilt_deg: the body's z axis from the vertical, degrees.
        mode: the contact model being integrated (under ``auto``: ``rolling`` or ``smooth``).
        contacts: points below the floor (the telemetry's ``contacts``).
        normal_force: the floor's normal force, N.
        kinetic, potential, elastic, energy: J, as the telemetry's columns.
    """

    t: float
    position: np.ndarray
    quaternion: np.ndarray
    velocity: np.ndarray
    angular_velocity: np.ndarray
    angular_velocity_world: np.ndarray
    spin: float
    tilt_deg: float
    mode: str
    contacts: int
    normal_force: float
    kinetic: float
    potential: float
    elastic: float
    energy: float

    @classmethod
    def _of(cls, fields: dict) -> "State":
        # The library gives every telemetry column at t (one table): the State keeps its own.
        fields = {f.name: fields[f.name] for f in dataclasses.fields(cls)}
        for name in ("position", "quaternion", "velocity", "angular_velocity", "angular_velocity_world"):
            array = np.array(fields[name], dtype=float)
            array.flags.writeable = False
            fields[name] = array
        return cls(**fields)


class Simulation:
    """A run you step: the library's rollout, as ``simulate`` and the command line drive it.

    ``Simulation(scene, duration=…, spin=…, dt=…, tolerance=…, integrator=…)`` starts the
    scene's run (the keywords as :func:`simulate`'s). Read :attr:`state`, go on with
    :meth:`step` or :meth:`advance`, change the state with :meth:`set_state` (a tap), and
    :meth:`copy` the run to try two futures. Stepping to the sample times of ``simulate`` and
    taking :meth:`advance`'s states gives its samples: the same steps (fixed ``dt``: the same
    doubles). Steps release the GIL; Ctrl-C raises ``KeyboardInterrupt`` and leaves the run at
    the step it reached. A run that stops by itself raises :class:`RunStopped`.
    """

    @checked
    def __init__(
        self,
        scene,
        *,
        duration: Optional[float] = None,
        spin: Optional[float] = None,
        dt: Optional[float] = None,
        tolerance: Optional[float] = None,
        integrator: Optional[str] = None,
    ):
        from . import _scene  # (the package imports this module last)

        loaded = _scene(scene)._load(
            duration=duration, spin=spin, dt=dt, tolerance=tolerance, integrator=integrator
        )
        self._run = _core.Simulation(loaded)

    @property
    def t(self) -> float:
        """The run's time: the end of its last step, s."""
        return self._run.t

    @property
    def end(self) -> float:
        """The run's end, s (simulation.duration, or ``duration=``)."""
        return self._run.end

    @property
    def steps(self) -> int:
        """Steps taken so far."""
        return self._run.steps

    @property
    def reversals(self) -> list[float]:
        """The spin reversals so far, s (the reversal rule, docs/physics.md P7)."""
        return list(self._run.reversals)

    @property
    def scene(self) -> str:
        return self._run.scene

    @property
    def state(self) -> State:
        """The state at :attr:`t`."""
        return State._of(self._run.state())

    @checked
    def state_at(self, t: float) -> State:
        """The state at time ``t`` (s) within the last step, on its interpolant (the dense
        output, or a cubic Hermite one for fixed steps), as ``simulate`` samples it."""
        return State._of(self._run.state_at(float(t)))

    def step(self) -> State:
        """Takes one step (``dt``, or the adaptive stepper's next) and returns the state at
        its end."""
        return State._of(self._run.step())

    @checked
    def advance(self, t: Optional[float] = None, *, until: Optional[str] = None, exactly: bool = False):
        """Steps on to time ``t`` (s) and returns the state at ``t``; or, with
        ``until="reversal"``, steps until the reversal rule confirms the next reversal.

        With ``t``: the run takes the steps ``simulate`` takes to reach ``t`` (with a fixed
        ``dt`` its last step ends at ``t`` when ``t`` is a multiple of it; adaptive steps end at
        or past ``t``: :attr:`t` tells), and the state returned is the one at ``t`` on the
        last step's interpolant, as ``simulate`` samples it.

        With ``exactly=True`` the last step ends at ``t`` itself (the adaptive stepper starts
        again there), so :attr:`t` is ``t`` and a :meth:`set_state` acts at ``t``: a tap at
        the time asked. The steps after it then differ from ``simulate``'s within the
        tolerance. With fixed steps ``t`` must be a multiple of ``dt``.

        With ``until="reversal"``: the run stops at the step where the rule confirms a
        reversal — the spin has crossed zero, gone on to 1 % of the initial spin the new way and
        held there 0.2 s (docs/physics.md P7) — so :attr:`t` is 0.2 s or more past it. Returns
        that reversal's time: its zero crossing of n, located on the step it fell in (the time
        ``Run.reversals`` lists); None when the run reaches its end first. A run started with no
        spin (n = 0 at the start) counts no reversal.
        """
        if (t is None) == (until is None):
            raise TypeError("advance: give t (s) or until='reversal', one of them")
        if until is not None:
            if until != "reversal":
                raise ValueError(f"argument until: takes 'reversal', not {until!r}")
            return self._run.advance_to_reversal()
        return State._of(self._run.advance_to(float(t), bool(exactly)))

    @checked
    def set_state(
        self,
        *,
        position: Optional[Sequence[float]] = None,
        quaternion: Optional[Sequence[float]] = None,
        velocity: Optional[Sequence[float]] = None,
        angular_velocity: Optional[Sequence[float]] = None,
    ) -> State:
        """Changes the state at :attr:`t` and goes on from there (a tap, a push, a new pose);
        returns the state the run goes on from.

        Each part given replaces the run's: ``position`` (m) and ``velocity`` (m/s) of the
        centre of mass in world axes, ``quaternion`` (w, x, y, z; normalised here),
        ``angular_velocity`` in body axes (rad/s, as ``initial.angular_velocity``). Turned by
        a ``quaternion`` alone the body keeps its ω in body axes.

        Under ``contact.model: rolling`` the state is put back on the constraint: the height
        of ``position`` and the velocity follow from the pose and ω (a ``velocity`` given must
        agree with rolling without slipping, v = −ω × r, within 1e-3 of it, or ValueError names
        the one it needs). Under ``auto`` the mode is chosen again, as at the start (a
        velocity that slides starts the smooth contact). The adaptive stepper starts afresh, and
        the run's watch for energy from nowhere measures from the new state's energy.
        """
        return State._of(
            self._run.set_state(
                _listed(position), _listed(quaternion), _listed(velocity), _listed(angular_velocity)
            )
        )

    def copy(self) -> "Simulation":
        """An independent run from here: the same state, steps, stepper and reversals, each
        going on alone."""
        twin = Simulation.__new__(Simulation)
        twin._run = self._run.copy()
        return twin

    def __copy__(self) -> "Simulation":
        return self.copy()

    def __deepcopy__(self, memo) -> "Simulation":
        return self.copy()

    def __repr__(self) -> str:
        return f"<Simulation {self.scene}: t = {self.t:.6g} s of {self.end:.6g} s>"


def _listed(value) -> Optional[list[float]]:
    return None if value is None else [float(v) for v in value]
