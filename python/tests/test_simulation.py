"""rb.Simulation, a run stepped from Python: stepping to a time in pieces gives what one simulate
gives, a copy goes on alone, a tap changes the energy by what the impulse does, Ctrl-C raises
KeyboardInterrupt and leaves the run usable, and bad arguments are named."""

import dataclasses
import numpy as np
import pytest

import rattleback as rb
from conftest import scene_path
from test_threads_and_interrupts import ctrl_c

# The State's fields that are telemetry columns (all but t and the vectors): spin, tilt_deg, mode,
# contacts, normal_force and the energies.
COLUMNS = [
    f.name for f in dataclasses.fields(rb.State) if f.name in {c[0] for c in rb._core.telemetry_columns}
]


def same_as_simulate(scene, **settings):
    """Advances a Simulation to each of simulate's sample times, with a step and a half-way
    advance between them (pieces of any size), and compares what it reads there with the
    samples: every number equal, to the bit."""
    run = rb.simulate(scene, rate=50, **settings)
    sim = rb.Simulation(scene, **settings)
    states = []
    for k, t in enumerate(run.t):
        states.append(sim.advance(t))
        if k + 1 < len(run.t):
            sim.advance(0.5 * (t + run.t[k + 1]))
    for name in COLUMNS:
        np.testing.assert_array_equal([getattr(s, name) for s in states], run[name], name)
    np.testing.assert_array_equal([s.position for s in states], np.column_stack([run.x, run.y, run.z]))
    np.testing.assert_array_equal(
        [s.quaternion for s in states], np.column_stack([run.qw, run.qx, run.qy, run.qz])
    )
    np.testing.assert_array_equal(
        [s.angular_velocity_world for s in states], np.column_stack([run.wx, run.wy, run.wz])
    )
    assert sim.reversals == run.reversals
    # A fixed step ends on the last sample; adaptive steps end at or past it, as simulate's do.
    assert sim.t == run.t[-1] if "dt" in settings else sim.t >= run.t[-1]


def test_stepping_to_simulates_times_in_pieces_gives_its_samples_with_a_fixed_step():
    same_as_simulate(scene_path("rattleback.yaml"), dt=1e-3, duration=3.0)


def test_and_with_adaptive_steps_the_same_to_the_bit():
    # The stepper takes the same steps whatever times are asked for (a sample is read off the
    # dense output, never a step cut short), so adaptive steps agree exactly too, not only
    # within the tolerance.
    same_as_simulate(scene_path("rattleback.yaml"), duration=3.0)


def test_one_step_at_a_time_and_until_the_reversal():
    sim = rb.Simulation(scene_path("rattleback.yaml"), dt=1e-3, duration=3.0)
    for k in range(1, 4):
        assert sim.step().t == sim.t == k * 1e-3
    # The reversal rule's time: the zero crossing of n, confirmed 0.2 s later, where the run is.
    t = sim.advance(until="reversal")
    assert sim.reversals == [t] == rb.simulate(scene_path("rattleback.yaml"), dt=1e-3, duration=3.0).reversals
    assert sim.t >= t + 0.2
    assert sim.advance(until="reversal") is None and sim.t == 3.0  # none more within the run


def test_a_copy_goes_on_alone():
    scene = scene_path("rattleback.yaml")
    sim = rb.Simulation(scene, duration=3.0)
    sim.advance(1.0)
    twin = sim.copy()
    twin.set_state(angular_velocity=[0.0, 0.0, 5.0])
    twin.advance(2.0)
    sim.advance(2.0)
    alone = rb.Simulation(scene, duration=3.0)
    alone.advance(1.0)
    alone.advance(2.0)
    np.testing.assert_array_equal(sim.state.angular_velocity, alone.state.angular_velocity)
    assert sim.state.spin != twin.state.spin
    assert twin.state.spin > 0 > sim.state.spin


def inertia_and_mass(scene):
    a = rb.analyze(scene)
    return np.array(a["inertia"]), a["mass"]


def test_advance_exactly_ends_the_step_at_t_and_a_tap_acts_there():
    # Adaptive steps end past the time asked (1.00077 s for 1 s here): exactly=True ends the last
    # step at t itself, so that a tap lands at the time asked.
    plain = rb.Simulation(scene_path("rattleback.yaml"))
    plain.advance(1.0)
    assert plain.t > 1.0
    sim = rb.Simulation(scene_path("rattleback.yaml"))
    landed = sim.advance(1.0, exactly=True)
    assert sim.t == 1.0 and landed.t == 1.0
    # The same steps up to there: the state at 1 s is the plain run's to the bit.
    np.testing.assert_array_equal(landed.angular_velocity, plain.state_at(1.0).angular_velocity)
    # From there a new stepper goes on: the first reversal moves by the integration's error
    # (5e-10 s measured at tolerance 1e-8), far inside 1e-6 s (a tenth of what the default
    # tolerance's sweep is from the converged one).
    going_on = sim.copy()
    assert abs(going_on.advance(until="reversal") - plain.advance(until="reversal")) < 1e-6
    # The tap acts at 1 s, on the state there.
    tapped = sim.set_state(angular_velocity=np.add(landed.angular_velocity, [0, 5.0, 0]))
    assert tapped.t == 1.0
    np.testing.assert_allclose(
        tapped.angular_velocity, np.add(landed.angular_velocity, [0, 5.0, 0]), rtol=0, atol=1e-12
    )
    # At the run's end it ends at the end, not past it.
    sim.advance(sim.end, exactly=True)
    assert sim.t == sim.end
    # Fixed steps end at multiples of dt: another t cannot be landed on.
    fixed = rb.Simulation(scene_path("rattleback.yaml"), dt=5e-4)
    fixed.advance(1.0, exactly=True)
    assert fixed.t == 1.0
    with pytest.raises(ValueError, match="multiple of dt"):
        fixed.advance(1.00025, exactly=True)


def test_a_tap_on_a_smooth_body_adds_the_work_of_its_angular_impulse():
    # Penalty contact: E = ½ ωᵀIω + ½ M v² + M g z + elastic. A tap changes ω alone (the pose and
    # the CM's velocity kept), so ΔE = ½ (ω+Δω)ᵀI(ω+Δω) − ½ ωᵀIω = ωᵀIΔω + ½ ΔωᵀIΔω.
    scene = rb.Scene.from_file(scene_path("rattleback.yaml")).with_values(
        {"contact.model": "smooth", "contact.stiffness": 2.0e4, "contact.damping": 4}
    )
    inertia, _ = inertia_and_mass(scene)
    sim = rb.Simulation(scene, dt=2e-5, duration=1.0)
    before = sim.advance(0.5)
    assert sim.t == 0.5
    w = before.angular_velocity
    dw = np.array([2.0, -1.0, 0.5])
    after = sim.set_state(angular_velocity=w + dw)
    np.testing.assert_array_equal(after.velocity, before.velocity)
    expected = w @ inertia @ dw + 0.5 * dw @ inertia @ dw
    # Rounding of sums of terms of the energy's size (7e-3 J): 1e-12 of it.
    assert after.energy - before.energy == pytest.approx(expected, abs=1e-12 * before.energy)


def test_a_tap_on_a_rolling_body_at_rest_adds_half_its_square_about_the_contact_point():
    # Rolling without slipping the body turns about its contact point r (body axes; upright,
    # r = (0, 0, −h) with h the CM's height): ΔE = ½ Δωᵀ I_P Δω, I_P = I + M (|r|² 1 − r rᵀ), and
    # the CM takes the velocity −Δω × r the constraint gives it.
    scene = rb.Scene.from_file(scene_path("tap-end.yaml"))
    inertia, mass = inertia_and_mass(scene)
    sim = rb.Simulation(scene.with_values({"initial.angular_velocity": [0, 0, 0]}), duration=1.0)
    before = sim.advance(0.25)
    r = np.array([0.0, 0.0, -before.position[2]])
    inertia_p = inertia + mass * (r @ r * np.eye(3) - np.outer(r, r))
    dw = np.array([3.0, 0.0, 0.0])
    after = sim.set_state(angular_velocity=dw)
    assert after.energy - before.energy == pytest.approx(0.5 * dw @ inertia_p @ dw, rel=1e-12)
    # Rounding of products of numbers of the body's size (cm, rad/s).
    np.testing.assert_allclose(after.velocity, -np.cross(dw, r), rtol=1e-12, atol=1e-15)
    # As the shipped tap scene starts: the same energy.
    assert after.energy == pytest.approx(rb.Simulation(scene).state.energy, rel=1e-12)


def test_rolling_refuses_a_velocity_that_slides_and_keeps_one_that_agrees():
    sim = rb.Simulation(scene_path("tap-end.yaml"), duration=1.0)
    sim.advance(0.3)
    state = sim.state  # at the end of the last step, where set_state acts
    with pytest.raises(ValueError) as caught:
        sim.set_state(velocity=state.velocity + [0.01, 0, 0])
    assert str(caught.value).startswith("argument velocity: slides the contact point at 0.01 m/s")
    np.testing.assert_array_equal(sim.state.velocity, state.velocity)  # refused: unchanged
    kept = sim.set_state(velocity=state.velocity * (1 + 1e-4))
    np.testing.assert_allclose(kept.velocity, state.velocity, rtol=1e-12)


def test_bad_arguments_are_named():
    scene = scene_path("rattleback.yaml")
    with pytest.raises(TypeError, match=r"^argument dt: takes a number \(s\), not '1' \(str\)$"):
        rb.Simulation(scene, dt="1")
    with pytest.raises(rb.SceneError) as caught:
        rb.Simulation(scene, duration=-3)
    assert caught.value.key == "simulation.duration"
    with pytest.raises(rb.SceneError, match=r"^argument spin: is given with " r"initial.angular_velocity"):
        rb.Simulation(scene_path("tap-end.yaml"), spin=3)
    sim = rb.Simulation(scene, duration=1.0)
    with pytest.raises(TypeError, match=r"^argument t: takes a number \(s\), not '1' \(str\)$"):
        sim.advance("1")
    with pytest.raises(TypeError, match=r"^argument angular_velocity: takes 3 numbers"):
        sim.set_state(angular_velocity=[1, 2])
    with pytest.raises(TypeError, match=r"^argument quaternion: takes 4 numbers"):
        sim.set_state(quaternion="1,0,0,0")
    with pytest.raises(ValueError, match=r"^argument until: takes 'reversal', not 'flip'$"):
        sim.advance(until="flip")
    with pytest.raises(TypeError, match=r"^advance: give t \(s\) or until='reversal'"):
        sim.advance(0.5, until="reversal")
    with pytest.raises(ValueError, match=r"^argument t: 2 s is past the run's end, 1 s"):
        sim.advance(2)
    sim.advance(0.5)
    with pytest.raises(ValueError, match=r"^argument t: 0.1 s lies before the last step"):
        sim.advance(0.1)


CHILD = r"""
import sys, time
import rattleback as rb
sim = rb.Simulation(sys.argv[1], duration=1e5)
print("started", flush=True)
try:
    sim.advance(1e5)
except KeyboardInterrupt:
    # The run is left at the step it reached, and goes on.
    t = sim.t
    assert 0 < t < 1e5 and sim.step().t > t
    print(time.monotonic(), flush=True)
    sys.exit(42)
sys.exit(0)
"""


def test_ctrl_c_raises_keyboard_interrupt_and_leaves_the_run_usable():
    out, sent = ctrl_c(CHILD, [scene_path("kane-levinson.yaml")], 1.0)
    assert float(out) - sent < 1.0  # the 20 ms look for signals, on a busy machine
