"""A value of the wrong type raises TypeError naming the argument and what it takes (it raised
pybind11's "Unable to cast Python instance to C++ type", or a TypeError showing the internal
rattleback._core signature); a value of the right type the scene cannot use is a SceneError."""

import numpy as np
import pytest

import rattleback as rb
from conftest import scene_path

SHORT = {"simulation.duration": 0.05}


@pytest.fixture(scope="module")
def scene():
    return rb.Scene.from_file(scene_path("rattleback.yaml")).with_values(SHORT)


def refused(call, message):
    with pytest.raises(TypeError) as caught:
        call()
    assert str(caught.value) == message
    # Not a ValueError: a wrong type is not a SceneError, whose attributes name a scene key.
    assert not isinstance(caught.value, ValueError)


def test_the_new_users_three_calls_name_the_argument_and_what_it_takes(scene):
    refused(
        lambda: rb.still(scene_path("rattleback.yaml"), 1, size="640x360"),
        "argument size: takes (width, height) in pixels, e.g. (640, 360), not '640x360' (str)",
    )
    refused(
        lambda: rb.simulate(scene_path("rattleback.yaml"), duration="3"),
        "argument duration: takes a number (s), not '3' (str)",
    )
    refused(
        lambda: rb.analyze(scene_path("rattleback.yaml"), spin="fast"),
        "argument spin: takes a number (rad/s), not 'fast' (str)",
    )


def test_every_public_function_checks_its_arguments(scene, tmp_path):
    refused(
        lambda: rb.simulate(scene, rate="500"),
        "argument rate: takes a number (samples per simulated second), not '500' (str)",
    )
    refused(
        lambda: rb.simulate(scene, integrator=4),
        "argument integrator: takes a name (text), e.g. 'rk4', not 4 (int)",
    )
    refused(lambda: rb.simulate(scene, check="no"), "argument check: takes True or False, not 'no' (str)")
    # Text is a moment of the run ("reversal"): a number in text is a wrong value, not type.
    with pytest.raises(
        ValueError, match="^argument t: a time in s .e.g. 1.5. or reversal, first_reversal or end, not '1'$"
    ):
        rb.still(scene, "1")
    refused(
        lambda: rb.still(scene, [1]),
        "argument t: takes a number (s), or a moment of the run: 'reversal', "
        "'first_reversal' or 'end', not [1] (list)",
    )
    refused(
        lambda: rb.still(scene, size=(640, 360, 3)),
        "argument size: takes (width, height) in pixels, e.g. (640, 360), not (640, 360, 3) " "(tuple)",
    )
    refused(
        lambda: rb.still(scene, size=(640.5, 360)),
        "argument size: takes (width, height) in pixels, e.g. (640, 360), not (640.5, 360) " "(tuple)",
    )
    refused(
        lambda: rb.still(scene, view=None, readouts="yes"),
        "argument readouts: takes True or False, not 'yes' (str)",
    )
    refused(
        lambda: rb.render(scene, tmp_path / "x.mp4", fps="30"),
        "argument fps: takes a number (frames per second), not '30' (str)",
    )
    refused(lambda: rb.render(scene, 5), "argument output: takes a path (text or os.PathLike), not 5 (int)")
    refused(lambda: rb.render(scene, crf=20.5), "argument crf: takes a whole number, not 20.5 (float)")
    refused(
        lambda: rb.sweep(scene_path("rattleback.yaml"), jobs="2"),
        "argument jobs: takes a whole number, not '2' (str)",
    )
    refused(lambda: rb.simulate(5), "argument scene: takes a Scene, a path or a dict, not 5 (int)")
    refused(
        lambda: rb.sweep(scene, {"initial.spin": 5}),
        "argument vary: initial.spin takes a list of values or a range "
        "{'from': A, 'to': B, 'count': N}, not 5 (int)",
    )
    refused(
        lambda: rb.sweep(scene, "initial.spin=5"),
        "argument vary: takes a dict of dotted keys and their values, e.g. "
        "{'initial.spin': [-5, 5]}, not 'initial.spin=5' (str)",
    )
    refused(
        lambda: rb.sweep(scene),
        "argument vary: a scene is swept along the values given as vary, e.g. "
        "vary={'initial.spin': [-5, 5]}; without it, source is a sweep file's path",
    )
    refused(
        lambda: rb.sweep("sweeps/spin-drag.yaml", duration=3),
        "argument duration: goes with vary (a sweep file sets its own: duration:)",
    )
    refused(
        lambda: scene.with_values("initial.spin=5"),
        "argument values: takes a dict of dotted keys and values, e.g. "
        "{'initial.spin': -5}, not 'initial.spin=5' (str)",
    )
    refused(
        lambda: scene.with_values({"initial.spin": object}),
        "argument values: initial.spin takes a number, text, True or False, a list or a "
        "dict, not <class 'object'> (type)",
    )
    refused(
        lambda: rb.simulate(scene).to_csv(3.5),
        "argument path: takes a path (text or os.PathLike), not 3.5 (float)",
    )
    # A long value is cut short in the message.
    with pytest.raises(TypeError) as caught:
        rb.simulate(scene, spin=list(range(1000)))
    assert len(str(caught.value)) < 120


def test_a_bool_is_not_a_number(scene):
    # True would be 1 rad/s: more likely a flag given to the wrong argument than a spin. The scene
    # file refuses `spin: true` too.
    refused(lambda: rb.simulate(scene, spin=True), "argument spin: takes a number (rad/s), not True (bool)")
    refused(lambda: rb.render(scene, crf=False), "argument crf: takes a whole number, not False (bool)")


def test_numbers_are_ints_floats_and_numpy_scalars(scene):
    base = rb.simulate(scene, spin=-4.0)
    for spin in (-4, np.float64(-4), np.float32(-4), np.int64(-4), np.int32(-4)):
        assert rb.simulate(scene, spin=spin).spin[0] == base.spin[0], type(spin)
    assert rb.analyze(scene, spin=np.float32(-4)) == rb.analyze(scene, spin=-4.0)
    assert rb.simulate(scene, check=np.bool_(False)).check is None
    image = rb.still(scene, np.float32(0.0), size=(np.int64(64), np.int32(48)))
    assert (image.width, image.height) == (64, 48)
    assert rb.still(scene, 0, size=np.array([64, 48])).width == 64
    assert rb.still(scene, 0, size=[64, 48]).width == 64
    # A 0-d array (what np.sum and friends give) is a number too, as with_values takes it
    # (simulate(spin=np.array(-4.0)) raised TypeError); not a 1-element one.
    assert rb.simulate(scene, spin=np.array(-4.0)).spin[0] == base.spin[0]
    assert rb.simulate(scene, rate=np.array(50), duration=0.2).t.size == 11
    refused(
        lambda: rb.simulate(scene, spin=np.array([-4.0])),
        "argument spin: takes a number (rad/s), not array([-4.]) (ndarray)",
    )
    refused(
        lambda: rb.render(scene, crf=np.array(2.5)),
        "argument crf: takes a whole number, not array(2.5) (ndarray)",
    )


def test_a_wrong_value_of_the_right_type_is_still_a_scene_error(scene):
    with pytest.raises(rb.SceneError):
        rb.simulate(scene, duration=-3)
    with pytest.raises(rb.SceneError):
        rb.still(scene, size=(641, 361))


def test_the_functions_keep_their_signatures_and_docstrings():
    import inspect

    assert list(inspect.signature(rb.simulate).parameters)[:3] == ["scene", "rate", "duration"]
    assert rb.still.__doc__.startswith("The scene's run drawn")
    assert rb.still.__name__ == "still"
