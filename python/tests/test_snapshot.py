"""Snapshot testing from Python: rb.compare's figures, rattleback.testing.assert_image_matches,
the pytest plugin's --snapshot-update, and still(t="reversal")."""

import dataclasses
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import rattleback as rb
from rattleback.testing import assert_image_matches

from conftest import cli, scene_path

SIZE = (320, 180)


@pytest.fixture(scope="module")
def picture():
    return rb.still(scene_path("rattleback.yaml"), 1.0, size=SIZE)


def changed(image, box=(slice(40, 60), slice(100, 130)), by=60):
    """The image with a patch brightened by `by` levels: a thing changed whole."""
    array = image.array.copy() if hasattr(image, "array") else image.copy()
    patch = array[box].astype(int) + by
    array[box] = np.clip(patch, 0, 255).astype(np.uint8)
    return array


def test_compare_gives_the_figures_counted_independently(picture):
    other = changed(picture)
    result = rb.compare(picture, other)
    # Counted here with NumPy: a pixel differs when any channel differs by more than 2.
    delta = np.abs(picture.array.astype(int) - other.astype(int)).max(axis=2)
    assert result.differing == int((delta > 2).sum())
    assert result.pixels == SIZE[0] * SIZE[1]
    assert result.worst == int(delta.max())
    assert result.fraction == pytest.approx(result.differing / result.pixels)
    assert not result.same and not result
    assert rb.compare(picture, picture).same
    # A fraction allowed above the changed share still fails on the square rule; with the
    # square rule off it passes.
    assert not rb.compare(picture, other, pixels=0.5).same
    assert rb.compare(picture, other, pixels=0.5, square=0).same
    # Levels within the tolerance are no difference (one step: what another CPU moves).
    assert rb.compare(picture, changed(picture, by=1)).differing == 0


def test_compare_reads_paths_and_says_the_command_lines_verdict(tmp_path, picture):
    picture.save(tmp_path / "a.png")
    rb.Image(changed(picture)).save(tmp_path / "b.png")
    result = rb.compare(tmp_path / "a.png", str(tmp_path / "b.png"))
    said = cli("compare", str(tmp_path / "a.png"), str(tmp_path / "b.png"), check=False)
    assert said.returncode == 1 and not result.same
    assert f"{result.differing} of {result.pixels} pixels" in said.stdout
    assert f"largest channel difference {result.worst}" in said.stdout
    with pytest.raises(ValueError, match="argument tolerance"):
        rb.compare(picture, picture, tolerance=300)


def test_assert_image_matches_fails_missing_then_updates_then_passes(tmp_path, picture):
    golden = tmp_path / "goldens" / "rest.png"
    failures = tmp_path / "failures"
    with pytest.raises(AssertionError, match="no golden image") as caught:
        assert_image_matches(picture, golden, failures=failures)
    assert str(failures / "rest-new.png") in str(caught.value)
    assert not golden.exists()
    assert_image_matches(picture, golden, update=True)
    assert golden.is_file()
    before = golden.stat().st_mtime_ns
    assert_image_matches(picture, golden, failures=failures)
    assert_image_matches(picture, golden, update=True)  # matches: left alone
    assert golden.stat().st_mtime_ns == before


def test_a_mismatch_names_the_diff_image_it_wrote(tmp_path, picture):
    golden = tmp_path / "rest.png"
    picture.save(golden)
    failures = tmp_path / "failures"
    with pytest.raises(AssertionError) as caught:
        assert_image_matches(changed(picture), golden, failures=failures)
    diff = failures / "rest-diff.png"
    assert f"the diff image {diff}" in str(caught.value)
    # The golden is copied beside them, as it was (a CI job uploads the folder).
    copy = failures / "rest-golden.png"
    assert f"the golden copied as {copy}" in str(caught.value)
    assert copy.read_bytes() == golden.read_bytes()
    # The diff marks in magenta (255, 0, 255) the pixels that differ, all inside the patch.
    from rattleback import _draw

    magenta = np.all(_draw.read_png(str(diff))[..., :3] == [255, 0, 255], axis=2)
    assert magenta.sum() == rb.compare(changed(picture), golden).differing > 0
    rows, columns = np.nonzero(magenta)
    assert rows.min() >= 40 and rows.max() < 60 and columns.min() >= 100 and columns.max() < 130


def test_a_passing_golden_clears_what_its_earlier_failure_left(tmp_path, picture):
    golden = tmp_path / "rest.png"
    picture.save(golden)
    failures = tmp_path / "failures"
    with pytest.raises(AssertionError):
        assert_image_matches(changed(picture), golden, failures=failures)
    left = [failures / f"rest-{what}.png" for what in ("new", "diff", "golden")]
    assert all(image.is_file() for image in left)
    assert_image_matches(picture, golden, failures=failures)
    assert not any(image.exists() for image in left)
    assert not failures.exists()  # nor the folder they left empty


def test_a_golden_that_is_not_a_png_is_said_and_update_replaces_it(tmp_path, picture):
    # What a clone without Git LFS's files holds in each PNG's place (git-lfs's pointer format).
    golden = tmp_path / "rest.png"
    golden.write_text("version https://git-lfs.github.com/spec/v1\noid sha256:00\nsize 9\n")
    failures = tmp_path / "failures"
    with pytest.raises(AssertionError, match="a Git LFS pointer, not the image") as caught:
        assert_image_matches(picture, golden, failures=failures)
    assert "--snapshot-update" in str(caught.value)
    assert (failures / "rest-new.png").is_file()
    from rattleback import testing

    written = len(testing._written)
    assert_image_matches(picture, golden, update=True, failures=failures)
    assert rb.compare(picture, golden).same
    assert not (failures / "rest-new.png").exists()
    # Listed as `rattleback snapshot --update` says it.
    assert testing._written[written:] == [(str(golden), "replaced")]


def test_the_pytest_plugin_writes_goldens_with_snapshot_update(tmp_path):
    (tmp_path / "test_mine.py").write_text(
        textwrap.dedent(
            f"""
        import rattleback as rb
        from rattleback.testing import assert_image_matches

        def test_rest():
            image = rb.still({scene_path("rattleback.yaml")!r}, 0.5, size=(320, 180))
            assert_image_matches(image, "goldens/rest.png")
        """
        )
    )
    run = [
        sys.executable,
        "-m",
        "pytest",
        "-q",
        "-p",
        "no:cacheprovider",
        "-p",
        "rattleback.testing",
        "test_mine.py",
    ]
    first = subprocess.run(run, cwd=tmp_path, capture_output=True, text=True)
    assert first.returncode == 1, first.stdout
    assert "snapshot-failures/rest-new.png" in first.stdout
    # The failure shows the test's line and the message, not the body of assert_image_matches.
    assert "updating = update if update" not in first.stdout, first.stdout
    update = subprocess.run(run + ["--snapshot-update"], cwd=tmp_path, capture_output=True, text=True)
    assert update.returncode == 0, update.stdout
    assert (tmp_path / "goldens" / "rest.png").is_file()
    # What an update wrote is said, as `rattleback snapshot --update` says it: an update left on
    # in CI passes every test, and had said nothing.
    assert "goldens written: 1 added" in update.stdout, update.stdout
    assert "added    goldens/rest.png" in update.stdout, update.stdout
    again = subprocess.run(run, cwd=tmp_path, capture_output=True, text=True)
    assert again.returncode == 0, again.stdout
    assert not (tmp_path / "snapshot-failures").exists()
    rb.still(scene_path("rattleback.yaml"), 0.5, size=(320, 180), spin=-4).save(
        tmp_path / "goldens" / "rest.png"
    )
    changed = subprocess.run(run + ["--snapshot-update"], cwd=tmp_path, capture_output=True, text=True)
    assert "goldens written: 1 changed" in changed.stdout, changed.stdout
    unchanged = subprocess.run(run + ["--snapshot-update"], cwd=tmp_path, capture_output=True, text=True)
    assert unchanged.returncode == 0 and "goldens written" not in unchanged.stdout, unchanged.stdout


def test_a_still_at_the_reversal_is_at_the_runs_first_reversal():
    scene = scene_path("rattleback.yaml")
    reversal = rb.simulate(scene).first_reversal
    image = rb.still(scene, "reversal", size=SIZE)
    assert image.t == reversal
    assert np.array_equal(image.array, rb.still(scene, reversal, size=SIZE).array)
    assert rb.still(scene, "end", size=SIZE).t == 8.0  # the scene's simulation.duration
    with pytest.raises(ValueError, match="argument t: a time in s"):
        rb.still(scene, "soon")


def test_a_titled_still_does_not_depend_on_the_scene_files_name(tmp_path):
    text = open(scene_path("rattleback.yaml")).read()
    (tmp_path / "one.yaml").write_text(text)
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "other-name.yaml").write_text(text)
    a = rb.still(tmp_path / "one.yaml", 0.5, size=SIZE, title="case")
    b = rb.still(tmp_path / "sub" / "other-name.yaml", 0.5, size=SIZE, title="case")
    assert np.array_equal(a.array, b.array)
    # Untitled, the file's name is drawn into the title: the pictures differ.
    assert not np.array_equal(
        rb.still(tmp_path / "one.yaml", 0.5, size=SIZE).array,
        rb.still(tmp_path / "sub" / "other-name.yaml", 0.5, size=SIZE).array,
    )


def test_the_command_lines_junit_says_each_cases_verdict_as_the_terminal_does(tmp_path):
    """`rattleback snapshot --junit FILE` writes JUnit XML (what a CI's test view reads): a
    missing golden and one that differs are failures whose messages are the terminal's words;
    after --update every case passes, saying what its golden became."""
    import shutil
    import xml.etree.ElementTree as ET

    (tmp_path / "suite.yaml").write_text(
        f"size: 160x90\ncases:\n  - {{name: rest, scene: {scene_path('rattleback.yaml')}}}\n"
        f"  - {{name: later, scene: {scene_path('rattleback.yaml')}, t: 1}}\n"
    )
    cli("snapshot", "suite.yaml", "--update", "-q", cwd=tmp_path)
    shutil.copy(tmp_path / "goldens" / "rest.png", tmp_path / "goldens" / "later.png")
    (tmp_path / "goldens" / "rest.png").unlink()
    run = cli("snapshot", "suite.yaml", "--junit", "out/j.xml", cwd=tmp_path, check=False)
    assert run.returncode == 1, run.stderr
    root = ET.parse(tmp_path / "out" / "j.xml").getroot()
    assert root.tag == "testsuites" and root.attrib["tests"] == "2" and root.attrib["failures"] == "2"
    cases = {c.attrib["name"]: c for c in root.iter("testcase")}
    assert set(cases) == {"rest", "later"}
    assert cases["rest"].attrib["file"] == "suite.yaml" and cases["rest"].attrib["line"] == "3"
    missing, differs = cases["rest"].find("failure"), cases["later"].find("failure")
    assert missing.attrib["type"] == "missing" and "--update writes it" in missing.attrib["message"]
    said = next(line for line in run.stdout.splitlines() if line.startswith("DIFFERS  later  "))
    assert differs.attrib["message"] == "differs: " + said.removeprefix("DIFFERS  later  ")
    assert differs.text == "report: snapshot-report/index.html#later"

    cli("snapshot", "suite.yaml", "--update", "-q", "--junit", "out/j.xml", cwd=tmp_path)
    root = ET.parse(tmp_path / "out" / "j.xml").getroot()
    assert root.attrib["failures"] == "0" and root.attrib["errors"] == "0"
    out = {c.attrib["name"]: c.find("system-out").text for c in root.iter("testcase")}
    assert out == {"rest": "golden added: goldens/rest.png", "later": "golden changed: goldens/later.png"}
    # A golden that is not a PNG is an error of the check, and replaced by --update.
    (tmp_path / "goldens" / "rest.png").write_text("version https://git-lfs.github.com/spec/v1\n")
    run = cli("snapshot", "suite.yaml", "-q", "--junit", "out/j.xml", cwd=tmp_path, check=False)
    assert run.returncode == 2
    error = ET.parse(tmp_path / "out" / "j.xml").getroot().find("testsuite/testcase[@name='rest']/error")
    assert "a Git LFS pointer, not the image" in error.attrib["message"]
    cli("snapshot", "suite.yaml", "--update", "-q", "--junit", "out/j.xml", cwd=tmp_path)
    root = ET.parse(tmp_path / "out" / "j.xml").getroot()
    assert root.attrib["errors"] == "0"
    assert (
        root.find("testsuite/testcase[@name='rest']/system-out").text == "golden replaced: goldens/rest.png"
    )

    refused = cli("snapshot", "suite.yaml", "--junit", "j.png", cwd=tmp_path, check=False)
    assert refused.returncode == 2 and "--junit j.png: writes JUnit XML" in refused.stderr
    assert not (tmp_path / "j.png").exists()

    # A suite that cannot run replaces the last run's XML with one error at the line at fault (it
    # had been left as it was: green cases in the CI's view of a job that failed), for a key
    # misspelt, for a case whose scene is missing and for one whose scene has a mistake.
    good = (tmp_path / "suite.yaml").read_text()
    for broken, line, words in (
        (good.replace("t: 1}", "tt: 1}"), "4", "cases[1].tt is not a key of a case"),
        (
            good.replace("t: 1}", "t: 1}\n  - {name: gone, scene: nope.yaml}"),
            "5",
            "gone: nope.yaml: cannot open",
        ),
        # A scene with a mistake of its own: the case's line, the scene's line in the message.
        (
            good.replace("t: 1}", "t: 1}\n  - {name: typo, scene: typo.yaml}"),
            "5",
            "typo: typo.yaml:2: simulation.durration",
        ),
    ):
        (tmp_path / "typo.yaml").write_text("simulation:\n  durration: 3\n")
        (tmp_path / "suite.yaml").write_text(broken)
        run = cli("snapshot", "suite.yaml", "-q", "--junit", "out/j.xml", cwd=tmp_path, check=False)
        assert run.returncode == 2, run.stderr
        root = ET.parse(tmp_path / "out" / "j.xml").getroot()
        assert (root.attrib["tests"], root.attrib["errors"], root.attrib["failures"]) == ("1", "1", "0")
        case = root.find("testsuite/testcase")
        assert (case.attrib["name"], case.attrib["file"], case.attrib["line"]) == (
            "suite",
            "suite.yaml",
            line,
        )
        assert words in case.find("error").attrib["message"]


def test_a_suite_files_cases_run_in_pytest_draw_what_the_command_line_draws(tmp_path):
    """rattleback.testing.suite_cases reads a `rattleback snapshot` suite file as the command
    line does (paths from the suite's folder, the top's defaults in each case), and each case
    drawn from Python is the command line's image to the pixel on this machine (the same
    program and rasteriser: no tolerance is needed), so its golden holds under
    assert_case_matches. Titles, times and views each change the picture, so a case drawn with
    any of them lost would differ."""
    from rattleback.testing import assert_case_matches, suite_cases

    (tmp_path / "cases").mkdir()
    (tmp_path / "cases" / "suite.yaml").write_text(
        f"size: 320x180\nsquare: 0\ncases:\n  - {{name: rest, scene: {scene_path('rattleback.yaml')}}}\n"
        f"  - {{name: turned, scene: {scene_path('rattleback.yaml')}, t: reversal, view: above,"
        " title: turned back, tolerance: 5}\n"
    )
    cli("snapshot", "cases/suite.yaml", "--update", "-q", cwd=tmp_path)
    cases = suite_cases(tmp_path / "cases" / "suite.yaml")
    assert [str(c) for c in cases] == ["rest", "turned"]
    rest, turned = cases
    assert rest.golden == tmp_path / "cases" / "goldens" / "rest.png"
    assert rest.place.endswith("suite.yaml:4") and rest.size == (320, 180) and rest.t == 0.0
    assert (turned.t, turned.view, turned.title, turned.tolerance, turned.square) == (
        "reversal",
        "above",
        "turned back",
        5,
        0,
    )
    for case in cases:
        drawn = rb.compare(case.draw(), case.golden, tolerance=0, pixels=0.0, square=0)
        assert drawn.differing == 0, (case.name, drawn)
        assert_case_matches(case, failures=tmp_path / "failures")
    # Another time is another picture: the case's golden no longer holds for it.
    other = dataclasses.replace(rest, t=2.0)
    with pytest.raises(AssertionError, match="differs"):
        assert_case_matches(other, failures=tmp_path / "failures")

    # A mistake in the suite is the command line's message, with its line and key.
    (tmp_path / "bad.yaml").write_text(f"cases:\n  - {{name: a, scene: x.yaml, tme: 1}}\n")
    with pytest.raises(rb.SceneError) as caught:
        suite_cases(tmp_path / "bad.yaml")
    assert caught.value.line == 2 and "cases[0].tme is not a key of a case" in str(caught.value)


def test_a_suite_case_in_pytest_says_what_the_command_line_says(tmp_path):
    """A golden blessed from pytest is the command line's bytes (its PNG names the rasteriser,
    as the command line's does), a mismatch gives the allowed share and a golden drawn by
    another rasteriser is said, and a case that cannot be drawn is named by its suite line with
    the suite's words for the way out."""
    from rattleback import _draw
    from rattleback.testing import assert_case_matches, suite_cases

    ccw = tmp_path / "ccw.yaml"
    ccw.write_text(open(scene_path("rattleback.yaml")).read().replace("spin: -5.0", "spin: 5.0"))
    assert "spin: 5.0" in ccw.read_text()
    (tmp_path / "suite.yaml").write_text(
        f"size: 320x180\ncases:\n  - {{name: rest, scene: {scene_path('rattleback.yaml')}}}\n"
    )
    (tmp_path / "late.yaml").write_text("cases:\n  - {name: ccw, scene: ccw.yaml, t: reversal}\n")
    cli("snapshot", "suite.yaml", "--update", "-q", cwd=tmp_path)
    (rest,) = suite_cases(tmp_path / "suite.yaml")
    (ccw_case,) = suite_cases(tmp_path / "late.yaml")
    by_cli = rest.golden.read_bytes()
    rest.golden.unlink()
    assert_case_matches(rest, update=True)
    assert rest.golden.read_bytes() == by_cli

    # Another picture against it: the figures with the allowed share, as the command line's.
    other = dataclasses.replace(rest, t=2.0)
    with pytest.raises(AssertionError) as caught:
        assert_case_matches(other, failures=tmp_path / "failures")
    assert "differ by more than 2 in a channel (allowed 0.2000 %); largest" in str(caught.value)
    # A golden drawn elsewhere: both rasterisers named.
    _draw.write_png(str(rest.golden), _draw.read_png(str(rest.golden)), drawn_by="NVIDIA GeForce")
    with pytest.raises(AssertionError) as caught:
        assert_case_matches(other, failures=tmp_path / "failures")
    assert "; the golden was drawn by NVIDIA GeForce, this by " in str(caught.value)

    # Spun its preferred way it does not reverse in 8 s: the suite's line, the case, and a
    # longer run in the scene (a suite has no duration of its own).
    with pytest.raises(ValueError) as caught:
        assert_case_matches(ccw_case)
    said = str(caught.value)
    assert said.startswith(f"{ccw_case.place}: ccw: t reversal: the run has no reversal"), said
    assert "simulation.duration: a longer one in the scene" in said
    # The command line's snapshot says the same line, as a case it cannot draw (status 2).
    by_cli = cli("snapshot", "late.yaml", "-q", cwd=tmp_path, check=False)
    # (The suite named as given: here by its folder.)
    assert by_cli.returncode == 2 and by_cli.stderr == said.replace(f"{tmp_path}/", "") + "\n"
