"""Bad input raises the command line's message, with the file, line and key apart."""

import json
import math
import os
import pickle
import subprocess
import sys

import numpy as np
import pytest

import rattleback as rb
from conftest import BIN, cli, scene_path

BAD_FRICTION = """body:
  shape: ellipsoid
  ellipsoid: {semi_axes: [0.03, 0.20, 0.02]}
  mass: 1.0
  inertia: [[1.6e-3, 0, 0], [0, 2e-4, 0], [0, 0, 1.7e-3]]
contact:
  model: smooth
  stiffness: 1.0e+5
  friction: -1
simulation: {dt: 1e-4, duration: 1}
"""


# The shipped Kane & Levinson body as a dict (scenes/kane-levinson.yaml).
DICT_SCENE = {
    "body": {
        "shape": "ellipsoid",
        "ellipsoid": {"semi_axes": [0.03, 0.20, 0.02], "center": [0.0, 0.0, 0.01]},
        "inertia": [[1.6e-3, -2.0e-5, 0.0], [-2.0e-5, 2.0e-4, 0.0], [0.0, 0.0, 1.7e-3]],
        "mass": 1.0,
    },
    "contact": {"model": "rolling"},
    "initial": {"spin": 5.0, "tilt": [0.5, 0.5]},
    "simulation": {"integrator": "rk4", "dt": 1e-4, "duration": 8.0},
}


def test_a_file_error_names_file_line_and_key_as_the_command_line_does(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text(BAD_FRICTION)
    with pytest.raises(rb.SceneError) as caught:
        rb.Scene.from_file(path)
    e = caught.value
    assert isinstance(e, ValueError)
    assert (e.file, e.line, e.key) == (str(path), 9, "contact.friction")
    line = cli("simulate", str(path), check=False)
    assert line.returncode == 2
    assert str(e) == line.stderr.strip()


def test_a_yaml_string_and_a_dict_are_named_in_their_errors():
    with pytest.raises(rb.SceneError) as caught:
        rb.Scene.from_yaml(BAD_FRICTION, name="mine")
    assert (caught.value.file, caught.value.line, caught.value.key) == ("mine", 9, "contact.friction")
    with pytest.raises(rb.SceneError) as caught:
        rb.Scene.from_dict(DICT_SCENE | {"gravity": -9.81})
    assert caught.value.file == "<dict>" and caught.value.key == "gravity"
    assert caught.value.line is None  # a dict has no lines
    assert str(caught.value).startswith("<dict>: gravity must be")
    run = rb.simulate(rb.Scene.from_dict(DICT_SCENE), duration=0.5)
    assert len(run) == 251 and run.result["status"] == "ok"


def test_with_values_checks_each_key_and_value():
    scene = rb.Scene.from_file(scene_path("rattleback.yaml"))
    assert rb.simulate(scene.with_values({"initial.spin": 5}), duration=0.1).spin[0] > 0
    with pytest.raises(rb.SceneError) as caught:
        scene.with_values({"initial.spn": 1})
    assert (caught.value.file, caught.value.key) == ("with_values", "initial.spn")
    assert "not a known key" in str(caught.value)
    with pytest.raises(rb.SceneError) as caught:
        scene.with_values({"contact.air_drag": -1})
    assert str(caught.value).startswith("with_values: contact.air_drag must be")
    with pytest.raises(rb.SceneError) as caught:
        scene.with_values({"body.dents.at[7]": 0.5})
    assert "does not have" in str(caught.value)
    # The scene it came from is unchanged.
    assert scene.spin == -5 and scene.values == {}


def test_a_bad_argument_is_named_as_the_argument():
    with pytest.raises(rb.SceneError) as caught:
        rb.simulate(scene_path("rattleback.yaml"), dt=-1)
    assert str(caught.value) == "argument dt: must be > 0, not -1"
    assert caught.value.key == "simulation.dt"
    with pytest.raises(ValueError, match="argument dt and argument tolerance"):
        rb.simulate(scene_path("rattleback.yaml"), dt=1e-3, tolerance=1e-6)
    with pytest.raises(ValueError, match="rate"):
        rb.simulate(scene_path("rattleback.yaml"), rate=0)


@pytest.mark.parametrize("argument", ["dt", "tolerance", "duration"])
@pytest.mark.parametrize("value, shown", [(math.nan, "nan"), (math.inf, "inf"), (-math.inf, "-inf")])
def test_a_non_finite_step_tolerance_or_duration_is_said_to_be(argument, value, shown):
    # A NaN dt read "argument dt: or simulation.tolerance is required" (NaN is the scene's "not
    # given"); the command line's --dt nan reads the same as this.
    with pytest.raises(rb.SceneError) as caught:
        rb.simulate(scene_path("rattleback.yaml"), **{argument: value})
    assert str(caught.value) == f"argument {argument}: must be a finite number, not {shown}"
    assert caught.value.key == f"simulation.{argument}"


def test_a_stills_time_is_named_as_the_argument():
    # It was the command line's "--t must be a time ≥ 0 s", an option Python has not.
    scene = scene_path("rattleback.yaml")
    with pytest.raises(ValueError) as caught:
        rb.still(scene, t=-1)
    assert str(caught.value) == "argument t: must be a time ≥ 0 s, not -1"
    with pytest.raises(ValueError) as caught:
        rb.still(scene, t=1e9)
    assert str(caught.value).startswith("argument t: 1e+09 s is past the longest run")


def test_a_missing_file_is_a_scene_error():
    with pytest.raises(rb.SceneError, match="cannot open the scene file"):
        rb.simulate("no/such/scene.yaml")


def test_a_relative_scene_not_found_says_where_it_was_looked_for(tmp_path, monkeypatch):
    # A new user's first paste, scenes/rattleback.yaml, run from a folder of their own with a
    # build tree's package (which has no installed scenes to fall back on).
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("RATTLEBACK_ASSETS", str(tmp_path / "no-assets"))
    with pytest.raises(rb.SceneError) as caught:
        rb.Scene.from_file("scenes/mine.yaml")
    assert f"(looked for in {tmp_path}; an installed rattleback also finds its shipped" in str(caught.value)
    assert "else give the file's full path)" in str(caught.value)


def test_an_unknown_keyword_names_the_nearest_one():
    with pytest.raises(
        TypeError, match=r"^analyze\(\) got an unexpected keyword argument 'spinn'; did you mean 'spin'\?$"
    ):
        rb.analyze(scene_path("rattleback.yaml"), spinn=3)
    # Without a near one, Python's own message.
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'colour'$"):
        rb.analyze(scene_path("rattleback.yaml"), colour=3)
    # n, the theory's name for the spin; a scene key's last word, which the scene gives (each had
    # a bare message).
    with pytest.raises(TypeError, match=r"argument 'n'; did you mean 'spin'\?$"):
        rb.linearize(scene_path("rattleback.yaml"), n=3)
    with pytest.raises(TypeError, match=r"argument 'omega'; did you mean 'angular_velocity'\?$"):
        rb.Simulation(scene_path("rattleback.yaml")).set_state(omega=[0, 1, 0])
    with pytest.raises(
        TypeError, match=r"'tilt': initial.tilt is a scene key, .*with_values\(\{'initial.tilt'"
    ):
        rb.simulate(scene_path("rattleback.yaml"), tilt=[1, 0])


def test_reading_outside_the_last_step_says_the_way_out():
    sim = rb.Simulation(scene_path("rattleback.yaml"), duration=1.0)
    sim.advance(0.5)
    with pytest.raises(ValueError, match=r"advance\(t\) goes on to a later time; copy\(\) before"):
        sim.state_at(0.1)


def test_a_run_that_stops_itself_raises_run_stopped():
    # Forward Euler at 5 ms on the rolling body gains energy until the watchdog stops it
    # (README: euler trips the 10 % energy bound at steps ≥ 0.5 ms).
    with pytest.raises(rb.RunStopped) as caught:
        rb.simulate(scene_path("rattleback.yaml"), integrator="euler", dt=5e-3)
    assert caught.value.reason == "energy_gain"
    assert 0 < caught.value.t < 8


def test_a_stopped_run_names_its_values_and_carries_the_run_as_far_as_it_went():
    # A student's Pool over spins: one run tipped over, and the error named only the file, with
    # nothing to plot of the 0.9 s before. The message names the values put in; .run is the Run
    # up to the stop, its result "stopped", its samples those of an unstopped run's start.
    import pickle

    scene = rb.Scene.from_file(scene_path("rattleback.yaml")).with_values({"initial.spin": -20})
    with pytest.raises(rb.RunStopped) as caught:
        rb.simulate(scene)
    stopped = caught.value
    assert str(stopped).startswith(
        scene_path("rattleback.yaml") + " (initial.spin = -20): "
        "the run stopped: the body tipped onto the edge of its top"
    )
    assert "use contact.model auto, smooth or points" in str(stopped)
    assert stopped.reason == "on_rim" and isinstance(stopped.run, rb.Run)
    assert stopped.run.result["status"] == "stopped"
    assert stopped.run.t[-1] <= stopped.t < stopped.run.t[-1] + 1 / stopped.run.rate
    start = rb.simulate(scene, duration=0.5)
    n = len(start)
    assert np.array_equal(stopped.run.spin[:n], start.spin)  # the same run, as far as both go
    back = pickle.loads(pickle.dumps(stopped))  # from a Pool's worker
    assert back.reason == "on_rim" and np.array_equal(back.run.spin, stopped.run.spin)

    # A key put in twice is named once, at the value it has; a long value is cut short (a weight
    # added twice had named the body's mass, CM and nine-number inertia twice before the cause).
    twice = scene.with_values({"initial.spin": -30, "initial.tilt": [0.123456789012345678] * 2})
    twice = twice.with_values({"initial.spin": -20, "initial.tilt": [0.5000000000000001] * 2})
    with pytest.raises(rb.RunStopped) as caught:
        rb.simulate(twice)
    assert str(caught.value).startswith(
        scene_path("rattleback.yaml") + " (initial.spin = -20, initial.tilt = "
        "[0.5000000000000001, 0.5000000000000001]): the run stopped"
    ), str(caught.value)
    long = scene.with_values({"initial.tilt": [0.123456789012345678, 0.2345678901234567]})
    with pytest.raises(rb.RunStopped) as caught:
        rb.simulate(long)
    assert "initial.tilt = [0.12345678901234568, 0.2345678901234567…): the run" in str(caught.value)


def test_a_bad_video_argument_is_a_scene_error_naming_the_argument():
    scene = rb.Scene.from_file(scene_path("rattleback.yaml"))
    with pytest.raises(rb.SceneError) as caught:
        rb.still(scene, size=(641, 361))
    assert str(caught.value).startswith("argument size: sides must be even")
    assert (caught.value.file, caught.value.line, caught.value.key) == ("argument size", None, "video.size")
    with pytest.raises(rb.SceneError) as caught:
        rb.still(scene, view="top")
    assert caught.value.key == "video.view"


@pytest.mark.parametrize(
    "fps, message",
    [
        (29.97, "argument fps: must be a whole number of frames per second (24, 25, 30, 60 …), not 29.97"),
        (0, "argument fps: must be within 1 … 240, not 0"),
    ],
)
def test_a_bad_fps_is_a_scene_error_as_the_other_video_arguments(tmp_path, fps, message):
    # It was a plain ValueError, while a bad view, size or playback is a SceneError (as
    # docs/python.md lists fps among them).
    scene = rb.Scene.from_file(scene_path("rattleback.yaml"))
    with pytest.raises(rb.SceneError) as caught:
        rb.render(scene, tmp_path / "x.mp4", fps=fps, duration=0.1, size=(64, 48))
    assert str(caught.value) == message
    assert (caught.value.file, caught.value.line, caught.value.key) == ("argument fps", None, "video.fps")
    assert not (tmp_path / "x.mp4").exists()


def test_the_librarys_messages_name_pythons_arguments_not_the_command_lines_options(tmp_path):
    # The library names an argument as the front end that called it does (util/arguments.hpp):
    # these read "--crf", "--preset", "--both … (--spin", "(or --dt)" to a Python user.
    scene = rb.Scene.from_file(scene_path("rattleback.yaml"))
    calls = [
        (lambda: rb.render(scene, tmp_path / "x.mp4", crf=60), "argument crf: must be within 1 … 51"),
        (lambda: rb.render(scene, tmp_path / "x.mp4", preset="bogus"), "argument preset: must be one of"),
        (
            lambda: rb.render(scene.with_values({"initial.spin": 0}), tmp_path / "x.mp4", both=True),
            "argument both renders the spin and its reverse",
        ),
        (lambda: rb.simulate(scene, integrator="rk4"), "give simulation.dt (or argument dt)"),
    ]
    for call, said in calls:
        with pytest.raises(ValueError) as caught:
            call()
        assert said in str(caught.value)
        assert "--" not in str(caught.value), str(caught.value)
    assert "give a spin (argument spin, or initial.spin" in str(pytest.raises(ValueError, calls[2][0]).value)
    assert not list(tmp_path.iterdir())


def test_a_dict_has_no_line():
    with pytest.raises(rb.SceneError) as caught:
        rb.Scene.from_dict(DICT_SCENE | {"gravity": -9.81})
    assert caught.value.line is None
    # Nor does its message print one (it said "<dict>:1: contact is required").
    without_contact = {k: v for k, v in DICT_SCENE.items() if k != "contact"}
    with pytest.raises(rb.SceneError) as caught:
        rb.Scene.from_dict(without_contact)
    assert caught.value.line is None
    assert str(caught.value).startswith("<dict>: contact is required, e.g. ")
    with pytest.raises(rb.SceneError) as caught:
        rb.Scene.from_dict(without_contact, name="mine")
    assert str(caught.value).startswith("mine: contact is required, e.g. ")


def test_an_unwritable_output_gives_the_way_out_in_pythons_terms(tmp_path):
    # A file where a folder of the path should be, and a folder nothing can be written in: the
    # way out names the method, not the command line's -o.
    (tmp_path / "afile").write_text("a file, not a folder")
    run = rb.simulate(rb.Scene.from_dict(DICT_SCENE), duration=0.1)
    with pytest.raises(ValueError) as caught:
        run.to_csv(tmp_path / "afile" / "x.csv")
    message = str(caught.value)
    assert "is a file, not a folder (give to_csv another path)" in message
    assert "give -o" not in message
    with pytest.raises(ValueError) as caught:
        run.to_csv("/proc/x.csv")
    assert str(caught.value).startswith("/proc/x.csv: cannot write a file in /proc: ")
    assert str(caught.value).endswith("(give to_csv a path in a folder you can write)")
    image = rb.still(rb.Scene.from_dict(DICT_SCENE), t=0.0, size=(64, 48))
    with pytest.raises(ValueError) as caught:
        image.save("/proc/x.png")
    assert str(caught.value).startswith("/proc/x.png: cannot write a file in /proc: ")
    assert str(caught.value).endswith("(give save a path in a folder you can write)")


def test_to_csv_does_not_write_over_its_scene_nor_as_a_picture(tmp_path):
    # A student's run.to_csv("mine.yaml") replaced the scene with telemetry, where the command
    # line refuses the same: ValueError, the scene (or sweep file) unchanged.
    mine = tmp_path / "mine.yaml"
    mine.write_text(open(scene_path("rattleback.yaml")).read())
    text = mine.read_text()
    run = rb.simulate(str(mine), duration=0.1)
    table = rb.sweep(str(mine), {"initial.spin": [-5]}, duration=0.1)
    for write in (run.to_csv, table.to_csv):
        with pytest.raises(ValueError) as caught:
            write(str(mine))
        assert "is one of its own inputs, which it would replace with a CSV table" in str(caught.value)
        with pytest.raises(ValueError) as caught:
            write(str(tmp_path / "t.png"))
        assert str(caught.value).endswith("writes a CSV table, not a .png file; give a name ending in .csv")
    assert mine.read_text() == text
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine.yaml"]


def test_a_write_the_machine_cannot_finish_is_an_os_error_not_bad_input():
    # A full disk (/dev/full refuses every write) is the machine's failure: OSError, as the
    # command line's exit status 4, not the ValueError of a bad path or scene.
    run = rb.simulate(rb.Scene.from_dict(DICT_SCENE), duration=0.1)
    with pytest.raises(OSError) as caught:
        run.to_csv("/dev/full")
    assert not isinstance(caught.value, ValueError)
    assert str(caught.value) == "/dev/full: writing failed: No space left on device"


def test_a_package_whose_modules_are_not_built_says_how_to_build_them(tmp_path):
    # The layout right after configuring (or after scripts/run.sh, which builds only the
    # command): the package's Python files without its compiled modules. The import names the
    # build command; it had imported an empty namespace package, and `rb.simulate` failed with
    # "module 'rattleback' has no attribute 'simulate'".
    import shutil

    package = tmp_path / "rattleback"
    package.mkdir()
    for source in os.scandir(os.path.dirname(rb.__file__)):
        if source.name.endswith((".py", ".pyi")):
            shutil.copy(source.path, package / source.name)
    result = subprocess.run(
        [sys.executable, "-c", "import rattleback"],
        capture_output=True,
        text=True,
        env=dict(os.environ, PYTHONPATH=str(tmp_path)),
    )
    assert result.returncode == 1
    last = result.stderr.strip().splitlines()[-1]
    assert last == (
        f"ImportError: rattleback's compiled modules are not built in {package}: "
        "build them with `bash scripts/build.sh rattleback_python` "
        "(scripts/run.sh builds only the command)"
    ), result.stderr


def test_a_video_name_of_another_kind_is_named_as_python_names_it(tmp_path):
    # The command line's "-o": in Python the argument is render's output.
    path = tmp_path / "v.avi"
    with pytest.raises(ValueError) as caught:
        rb.render(scene_path("rattleback.yaml"), path, duration=0.1)
    assert str(caught.value) == (f"render's output {path}: writes MP4 video; " "give a name ending in .mp4")
    assert not path.exists()


@pytest.mark.parametrize(
    "array,given,way_out",
    [
        # A float image in 0…1 (matplotlib's) was cast to 0 or 1: black; 300 as int64 wrapped to 44.
        (np.full((4, 6, 3), 0.5), "float64", "np.clip(a * 255, 0, 255).astype(np.uint8)"),
        (np.full((4, 6, 3), 300), "int64", "np.clip(a, 0, 255).astype(np.uint8)"),
        (np.zeros((4, 6, 3), bool), "bool", "a.astype(np.uint8) * 255"),
    ],
)
def test_an_image_of_another_dtype_than_uint8_is_refused(array, given, way_out):
    with pytest.raises(ValueError) as caught:
        rb.Image(array)
    assert str(caught.value) == (
        f"argument array: an image is an H×W×3 or H×W×4 uint8 array, " f"not {given} (give {way_out})"
    )


def test_an_image_of_another_shape_is_refused_when_made():
    with pytest.raises(ValueError) as caught:
        rb.Image(np.zeros((4, 6), np.uint8))
    assert str(caught.value) == (
        "argument array: an image is an H×W×3 or H×W×4 uint8 array, " "not of shape (4, 6)"
    )
    assert rb.Image(np.zeros((4, 6, 4), np.uint8)).png().startswith(b"\x89PNG")


def test_an_empty_output_name_is_refused_as_the_argument(tmp_path, monkeypatch):
    # to_csv("") said ": cannot move the finished file into place: No such file or directory",
    # and render(output="") wrote out/<scene>.mp4 as if no name had been given.
    monkeypatch.chdir(tmp_path)
    run = rb.simulate(rb.Scene.from_dict(DICT_SCENE), duration=0.1)
    with pytest.raises(ValueError) as caught:
        run.to_csv("")
    assert str(caught.value) == "argument path: '' names no file; give a file name"
    with pytest.raises(ValueError, match="^argument path: '' names no file"):
        rb.Image(np.zeros((4, 6, 3), np.uint8)).save("")
    with pytest.raises(ValueError) as caught:
        rb.render(rb.Scene.from_dict(DICT_SCENE), "", duration=0.1)
    assert str(caught.value) == (
        "argument output: '' names no file; give a file name, or None " "for the default"
    )
    assert list(tmp_path.iterdir()) == []


def test_an_image_name_of_another_kind_is_refused_as_still_refuses_it(tmp_path):
    # save("x.jpg") wrote PNG data under a .jpg name; `rattleback still -o y.jpg` refuses it.
    image = rb.Image(np.zeros((4, 6, 3), np.uint8))
    for name in ("x.jpg", "x"):
        path = tmp_path / name
        with pytest.raises(ValueError) as caught:
            image.save(path)
        assert str(caught.value) == f"save's path {path}: writes PNG; give a name ending in .png"
        assert not path.exists()
    image.save(tmp_path / "x.PNG")  # as the command line takes it, in any case
    theirs = cli("still", scene_path("rattleback.yaml"), "-o", str(tmp_path / "y.jpg"), check=False)
    assert theirs.returncode != 0 and "writes PNG; give a name ending in .png" in theirs.stderr


@pytest.mark.parametrize("playback, given", [(0, "0"), (-1, "-1"), (float("nan"), "nan")])
def test_a_bad_playback_says_the_value_given(tmp_path, playback, given):
    # It said "must be a speed > 0 (…)" without the value, where other arguments end "not X".
    scene = rb.Scene.from_file(scene_path("rattleback.yaml"))
    with pytest.raises(rb.SceneError) as caught:
        rb.render(scene, tmp_path / "x.mp4", playback=playback, duration=0.1, size=(64, 48))
    assert str(caught.value) == (
        "argument playback: must be a speed > 0 (1 real time, "
        "0.5 slow motion, 2 twice as fast), not " + given
    )
    assert not (tmp_path / "x.mp4").exists()


def test_a_runs_warnings_are_python_warnings(recwarn):
    """What simulate's summary warns of is a RunWarning in Python, pointing at the caller's line
    (a mass typed in grams would run in silence in a notebook); a run without one
    warns of nothing."""
    rb.simulate(scene_path("rattleback.yaml"), duration=0.2)
    assert not [w for w in recwarn if issubclass(w.category, rb.RunWarning)]
    grams = rb.Scene.from_file(scene_path("rattleback.yaml")).with_values({"body.mass": 59})
    with pytest.warns(rb.RunWarning, match="denser than any solid") as caught:
        run = rb.simulate(grams, duration=0.2)
    assert caught[0].message.code == "implausible_mass"
    assert caught[0].filename == __file__
    assert run.result["warnings"][0]["code"] == "implausible_mass"


def test_a_sweep_files_errors_name_its_file_line_and_key(tmp_path):
    """A sweep file's error is a SceneError naming the file, the line and the key, as a scene's
    is (docs/commands.md "Messages"), with the same message as the command line."""
    sweep = tmp_path / "bad.yaml"
    sweep.write_text(f"base: {scene_path('rattleback.yaml')}\nvary:\n  initial.spin: []\n")
    with pytest.raises(rb.SceneError) as caught:
        rb.sweep(str(sweep), jobs=1)
    assert str(caught.value) == f"{sweep}:3: initial.spin has no values"
    assert (caught.value.file, caught.value.line, caught.value.key) == (str(sweep), 3, "initial.spin")
    said = cli("sweep", str(sweep), "-o", str(tmp_path / "t.csv"), check=False)
    assert (said.returncode, said.stderr) == (2, f"{caught.value}\n")
    sweep.write_text("vary: {initial.spin: [1]}\n")
    with pytest.raises(rb.SceneError) as caught:
        rb.sweep(str(sweep), jobs=1)
    assert (caught.value.line, caught.value.key) == (1, "base")
    with pytest.raises(rb.SceneError) as caught:
        rb.sweep(str(tmp_path / "none.yaml"), jobs=1)
    assert (caught.value.line, caught.value.key) == (None, None)


def test_a_sweep_made_in_python_names_argument_vary_and_the_key():
    base = scene_path("rattleback.yaml")
    for vary, message in [
        (
            {"initial.spn": [1, 2]},
            "argument vary: initial.spn is not a known key; did you mean spin? "
            "(known here: spin, angular_velocity, tilt, height, velocity)",
        ),
        ({"initial.spin": []}, "argument vary: initial.spin has no values"),
        (
            {"video.fps": [30]},
            "argument vary: video.fps: a sweep only simulates; video keys do not change a run",
        ),
        (
            {"initial.tilt": [0.5, 1.0]},
            "argument vary: initial.tilt is a list (the base scene's is [0.5, 0.5]): give lists as "
            "its values, e.g. [[0.5, 0.5]], or vary one element, as initial.tilt[0]",
        ),
        (
            {"body.dents.at[5]": [1]},
            "argument vary: body.dents.at[5]: the base scene has no list body.dents.at with an " "element 5",
        ),
    ]:
        with pytest.raises(rb.SceneError) as caught:
            rb.sweep(base, vary, jobs=1)
        assert str(caught.value) == message
        assert caught.value.file == "argument vary" and caught.value.line is None
    with pytest.raises(rb.SceneError, match=r"^argument duration: must be > 0, not -1$") as e:
        rb.sweep(base, {"initial.spin": [1]}, duration=-1)
    assert e.value.key == "simulation.duration"  # as simulate's
    # A quoted number is refused before anything runs, as a scene refuses it (it ran as the
    # number; then its row was refused, which a heatmap shows as "no reversal").
    with pytest.raises(ValueError) as caught:
        rb.sweep(base, {"initial.spin": [-5, "-4"]}, duration=0.1, jobs=1)
    assert str(caught.value) == (
        'argument vary: initial.spin has the quoted string "-4": write ' "the number without quotes (-4)"
    )
    # So is a word where the base has a number (a unit written in), in the scene's words.
    with pytest.raises(ValueError) as caught:
        rb.sweep(base, {"initial.spin": ["5 rad/s", 4]}, duration=0.1, jobs=1)
    assert str(caught.value) == (
        "argument vary: initial.spin must be a number, not the quoted " 'string "5 rad/s"'
    )
    # A value no scene can take refuses its row, named as the argument's (a file's names its line).
    table = rb.sweep(base, {"body.mass": [-1, 0.059]}, duration=0.1, jobs=1)
    assert list(table["status"]) == ["refused", "ok"]
    assert table["message"][0] == "argument vary: body.mass must be > 0, not -1"


def test_a_name_a_run_does_not_have_says_the_way_to_it():
    # A student's first tries: the sidecar's key as an attribute, a typo'd column by key.
    run = rb.simulate(scene_path("rattleback.yaml"), duration=1)
    with pytest.raises(AttributeError, match=r"did you mean run\.first_reversal "):
        run.first_reversal_s
    with pytest.raises(AttributeError, match=r"a key of the run's result: run\.result\['final_spin'\]"):
        run.final_spin
    with pytest.raises(KeyError, match="did you mean 'spin'"):
        run["spn"]
    with pytest.raises(AttributeError, match="did you mean 'spin'"):
        run.spn
    assert not hasattr(run, "_repr_html_")  # IPython's probe: a plain AttributeError
    with pytest.raises(AttributeError, match=r"did you mean 't' \(the time, s\)"):
        run.time


def test_a_name_an_analysis_or_a_sweep_table_does_not_have_says_the_way_to_it():
    # A student's tries: analyze's keys by a name near theirs, a key of a dict within it, a
    # sweep table's column as an attribute (as a run's) and by a typo.
    a = rb.analyze(scene_path("rattleback.yaml"))
    with pytest.raises(KeyError, match="did you mean 'misalignment_deg'"):
        a["misalignment"]
    with pytest.raises(KeyError, match="did you mean 'predicted_first_reversal'"):
        a["predicted_reversal"]
    with pytest.raises(KeyError, match=r"a key of \['predicted_first_reversal'\]"):
        a["time_s"]
    with pytest.raises(KeyError, match="did you mean 'time_s'"):
        a["predicted_first_reversal"]["time"]
    # Otherwise the dict analyze --json prints: equal to it, and JSON and pickles as a dict.
    assert isinstance(a, dict) and json.loads(json.dumps(a)) == a
    assert type(pickle.loads(pickle.dumps(a))) is dict
    table = rb.sweep(scene_path("rattleback.yaml"), {"initial.spin": [-5, 5]}, duration=0.5)
    np.testing.assert_array_equal(table.status, table["status"])
    assert "final_spin" in dir(table)
    with pytest.raises(AttributeError, match="did you mean 'first_reversal_s'"):
        table.first_reversal
    with pytest.raises(KeyError, match="did you mean 'status'"):
        table["stauts"]
    assert not hasattr(table, "_repr_html_")
