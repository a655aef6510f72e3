"""Python and the command line draw the same pictures: a still, a frame, a surface and the
videos are the command line's bytes and files, listed alike in the folder's manifest, and the
player's data made in Python is the report's."""

import json

import numpy as np
import pytest

import rattleback as rb
from conftest import cli, scene_path


def same_still(tmp_path, scene, **given):
    """rb.still(scene, 1.0, size=(320, 180), **given), held byte for byte against `rattleback
    still` given the same as options (frame=60 as --frame 60); the image."""
    image = rb.still(scene, 1.0, size=(320, 180), **given)
    image.save(tmp_path / "py.png")
    options = [text for key, value in given.items() for text in (f"--{key}", str(value))]
    cli("still", scene, "--t", "1", "--size", "320x180", *options, "-q", "-o", str(tmp_path / "cli.png"))
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()
    return image


def test_a_still_is_the_command_lines_png(tmp_path, default_scene):
    image = same_still(tmp_path, default_scene)
    assert image.array.shape == (180, 320, 3) and image.array.dtype == np.uint8
    assert image._repr_png_() == (tmp_path / "cli.png").read_bytes()
    clear = rb.still(default_scene, 0.0, size=(64, 64), transparent=True)
    assert clear.array.shape == (64, 64, 4)
    assert clear.array[0, 0, 3] == 0  # no background where there is no body


def test_a_frame_is_the_command_lines_and_says_when_the_body_leaves_it(tmp_path, default_scene, recwarn):
    """frame= is --frame: the same picture; a frame too short for the body warns of it, as the
    command line does, pointing at the caller's line."""
    image = same_still(tmp_path, default_scene, frame=60)
    assert not [w for w in recwarn if issubclass(w.category, rb.RunWarning)]
    assert image.array.tobytes() != rb.still(default_scene, 1.0, size=(320, 180)).array.tobytes()
    with pytest.warns(rb.RunWarning, match="the body goes out of the picture") as caught:
        rb.still(default_scene, 1.0, size=(160, 96), frame=10)
    assert caught[0].message.code == "body_leaves_frame"
    assert caught[0].filename == __file__


def test_a_surface_is_the_command_lines(tmp_path, default_scene):
    """surface= is --surface: the triangles' picture, not the points'; a word that is neither is
    a SceneError naming video.surface."""
    image = same_still(tmp_path, default_scene, surface="triangles")
    assert image.array.tobytes() != rb.still(default_scene, 1.0, size=(320, 180)).array.tobytes()
    with pytest.raises(rb.SceneError) as caught:
        rb.still(default_scene, 1.0, size=(320, 180), surface="dots")
    assert caught.value.key == "video.surface"


def test_render_writes_the_videos_the_command_line_names(tmp_path, default_scene):
    files = rb.render(default_scene, tmp_path / "v", both=True, duration=1.0, size=(160, 96), fps=10)
    names = sorted(f["path"].rsplit("/", 1)[1] for f in files)
    assert names == ["v-both.mp4", "v-preferred.mp4", "v-reversed.mp4"]
    for f in files:
        assert f["frames"] == 10
        data = open(f["path"], "rb").read(12)
        assert data[4:8] == b"ftyp"  # an MP4
    spun = {f["spin"] for f in files if f["spin"] is not None}
    assert spun == {-5.0, 5.0}


def test_a_saved_still_is_listed_as_the_command_lines_still(tmp_path, default_scene):
    # It was not listed at all: the report put it under "other figures", captioned with its file
    # name, not under Stills with its view, time and spin.
    rb.still(default_scene, 0.5, view="above", spin=-4, size=(64, 48)).save(tmp_path / "py.png")
    cli(
        "still",
        default_scene,
        "--t",
        "0.5",
        "--view",
        "above",
        "--spin",
        "-4",
        "--size",
        "64x48",
        "-q",
        "-o",
        str(tmp_path / "cli.png"),
    )
    outputs = json.loads((tmp_path / "rattleback-manifest.json").read_text())["outputs"]
    by_file = {entry.pop("file"): entry for entry in outputs}
    # made_from: the scene drawn (its content and values), the same from both.
    assert len(by_file["py.png"]["made_from"]) == 16
    assert (
        by_file["py.png"]
        == by_file["cli.png"]
        == {
            "kind": "still",
            "scene": "rattleback",
            "role": "above",
            "spin": -4.0,
            "t": 0.5,
            "made_from": by_file["cli.png"]["made_from"],
            "surface": "points",  # the scene's video.surface: the report's player draws the same
        }
    )
    # An image made from an array is no still of a scene: saved, it is not listed.
    rb.Image(np.zeros((48, 64, 3), np.uint8)).save(tmp_path / "drawn.png")
    outputs = json.loads((tmp_path / "rattleback-manifest.json").read_text())["outputs"]
    assert sorted(entry["file"] for entry in outputs) == ["cli.png", "py.png"]


def test_the_players_other_spin_is_the_reports(tmp_path):
    """The player's data made in Python (make_page.py's dev page) carries the body spun the other
    way as `report`'s does: the same C++ function on the run's own model. The default body with
    its dents mirrored, spun -5 rad/s for 3 s, keeps turning; spun +5 rad/s it reverses."""
    scene = rb.Scene.from_file(scene_path("rattleback.yaml")).with_values({"body.dents.at": [-0.73, 4.5]})
    script = rb._core.player_script(scene._loaded, rb.simulate(scene, duration=3)._run, "rattleback")
    data = json.loads(script[script.index("] = ") + 4 : script.rindex(";")])
    assert data["spun"] == -5 and data["reversals"] == []
    assert data["other"]["spun"] == 5 and len(data["other"]["reversals"]) == 1
    assert data["other"]["t"][-1] == 3  # the run's duration, not the scene's 8 s
    csv_path = str(tmp_path / "rattleback.csv")
    cli(
        "simulate",
        scene_path("rattleback.yaml"),
        "--set",
        "body.dents.at=[-0.73, 4.5]",
        "--duration",
        "3",
        "-q",
        "-o",
        csv_path,
    )
    cli("report", str(tmp_path), "-q")
    if not (tmp_path / "rattleback.player.js").exists():
        pytest.skip("no player bundle in this build (no node and npm)")
    # (the run's own poses are the CSV's text in the report, the samples' doubles here)
    other = lambda text: text[text.index(',"spun":') :]
    assert other(script) == other((tmp_path / "rattleback.player.js").read_text())


def test_the_players_triangles_are_the_reports(tmp_path):
    """A scene drawn as triangles (video.surface) gives the player made in Python the same
    surface as `report`'s: the same vertices and faces, as its stills and videos draw it."""
    scene = rb.Scene.from_file(scene_path("printed.yaml"))
    script = rb._core.player_script(scene._loaded, rb.simulate(scene, duration=1)._run, "printed")
    cli("simulate", scene_path("printed.yaml"), "--duration", "1", "-q", "-o", str(tmp_path / "printed.csv"))
    cli("report", str(tmp_path), "-q")
    if not (tmp_path / "printed.player.js").exists():
        pytest.skip("no player bundle in this build (no node and npm)")
    assert '"vertices":' in script and '"faces":' in script, "the player made in Python draws points"
    surface = lambda text: text[text.index(',"vertices":') : text.index(',"radius":')]
    assert surface(script).count(",") > 5952 * 3
    assert surface(script) == surface((tmp_path / "printed.player.js").read_text())
