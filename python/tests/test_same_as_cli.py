"""Python and the command line are one library: the same scene gives the same numbers, written
as the same text."""

import csv
import json
from pathlib import Path

import numpy as np
import pytest

import rattleback as rb
from conftest import cli, scene_path

# Every shipped scene, shortened (the seed's points model costs 0.7 µs a step at 10 µs steps),
# and sampled at rates that fall between steps (333 Hz) and on them.
CASES = [
    ("rattleback.yaml", 2.0, 500),
    ("rattleback.yaml", 1.5, 333),
    ("kane-levinson.yaml", 2.0, 200),
    ("seed-flip-ccw.yaml", 0.2, 1000),
    ("seed-flip-cw.yaml", 0.2, 250),
]


def sidecars_without_wall_time(tmp_path):
    """py.csv.json and cli.csv.json, each less the run's wall time (the one figure that differs)."""
    sides = [json.loads((tmp_path / f"{who}.csv.json").read_text()) for who in ("py", "cli")]
    for side in sides:
        side["result"].pop("wall_s")
    return sides


@pytest.mark.parametrize("name,duration,rate", CASES)
def test_the_csv_is_the_command_lines_text(tmp_path, name, duration, rate):
    ours = tmp_path / "py.csv"
    theirs = tmp_path / "cli.csv"
    run = rb.simulate(scene_path(name), duration=duration, rate=rate)
    run.to_csv(ours)
    cli(
        "simulate",
        scene_path(name),
        "--duration",
        str(duration),
        "--rate",
        str(rate),
        "-q",
        "-o",
        str(theirs),
    )
    assert ours.read_text() == theirs.read_text()
    a, b = sidecars_without_wall_time(tmp_path)
    assert a == b


def test_values_put_in_are_the_command_lines_set(tmp_path):
    """A scene with values put in from Python writes the CSV and sidecar that --set writes,
    the values listed in the sidecar's scene_values (report puts them in again to draw the body
    that ran)."""
    ours, theirs = tmp_path / "py.csv", tmp_path / "cli.csv"
    scene = rb.Scene.from_file(scene_path("rattleback.yaml")).with_values({"body.paraboloid.a": 1.2})
    rb.simulate(scene, duration=0.3, rate=100).to_csv(ours)
    cli(
        "simulate",
        scene_path("rattleback.yaml"),
        "--set",
        "body.paraboloid.a=1.2",
        "--duration",
        "0.3",
        "--rate",
        "100",
        "-q",
        "-o",
        str(theirs),
    )
    assert ours.read_text() == theirs.read_text()
    a, b = sidecars_without_wall_time(tmp_path)
    assert a == b
    assert a["scene_values"] == [{"key": "body.paraboloid.a", "value": "1.2"}]


def test_the_sidecar_fingerprints_the_scene_as_it_was_read(tmp_path):
    """A run written after its scene file was edited still fingerprints the scene it ran: the
    fingerprint was taken of the file as to_csv found it, so `report` drew the edited body for
    the old run without a word."""
    yaml = tmp_path / "edit.yaml"
    yaml.write_text(Path(scene_path("rattleback.yaml")).read_text())
    run = rb.simulate(str(yaml), duration=0.2, rate=100)
    run.to_csv(tmp_path / "before.csv")
    yaml.write_text(yaml.read_text().replace("a: 1.0, p: 0.5", "a: 1.2, p: 0.5"))
    run.to_csv(tmp_path / "after.csv")
    rb.simulate(str(yaml), duration=0.2, rate=100).to_csv(tmp_path / "edited.csv")

    def fingerprint(name):
        return json.loads((tmp_path / f"{name}.csv.json").read_text())["scene_fingerprint"]

    assert fingerprint("after") == fingerprint("before")
    assert fingerprint("edited") != fingerprint("before")


def test_the_arrays_are_the_csv_columns(tmp_path, default_scene):
    run = rb.simulate(default_scene, duration=1.0)
    run.to_csv(tmp_path / "r.csv")
    with open(tmp_path / "r.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == len(run) == 501
    assert list(rows[0]) == list(run.columns)
    for name, column in run.columns.items():
        if name == "mode":
            assert [r[name] for r in rows] == list(column)
        else:
            # The CSV prints 9–10 significant digits (tilt_deg 6 decimals): what it holds is
            # the array's value rounded there.
            text = np.array([float(r[name]) for r in rows])
            np.testing.assert_allclose(column, text, rtol=1e-8, atol=1e-6 if name == "tilt_deg" else 1e-300)


def test_pandas_reads_the_csv_as_to_pandas_gives_it(tmp_path, default_scene):
    pd = pytest.importorskip("pandas")
    run = rb.simulate(default_scene, duration=1.0)
    run.to_csv(tmp_path / "r.csv")
    read = pd.read_csv(tmp_path / "r.csv", float_precision="round_trip")
    frame = run.to_pandas()
    # The count of points in contact is a whole number both ways (it was int32 from Python,
    # int64 from the CSV, and the frames did not compare equal).
    assert frame["contacts"].dtype == read["contacts"].dtype
    # Every value the same; only dtypes pandas infers from the text may differ (a column that
    # is 0 throughout, elastic under rolling, reads as whole numbers).
    pd.testing.assert_frame_equal(frame, read, check_dtype=False)


def test_the_summary_is_the_sidecars_result(default_scene):
    run = rb.simulate(default_scene)
    assert run.result["status"] == "ok"
    assert run.first_reversal == pytest.approx(2.3665, abs=5e-5)  # README: first reversal 2.3665 s
    assert run.reversals == run.result["reversals_s"]
    assert run.sidecar()["result"]["first_reversal_s"] == run.first_reversal
    # The unit alone, as an axis label takes it; what the column is apart.
    assert run.units["spin"] == "rad/s"
    assert run.meanings["spin"].startswith("n = w.z")
    assert list(run.units) == list(run.meanings) == [c["name"] for c in run.sidecar()["columns"]]


def test_analyze_is_the_command_lines_json(default_scene):
    ours = rb.analyze(default_scene)
    theirs = json.loads(cli("analyze", default_scene, "--json").stdout)
    assert ours == theirs
    assert ours["preferred"] == "ccw"
    assert rb.analyze(default_scene, spin=3)["spin"] == 3


def default_sweep(path, axes, duration):
    """A sweep file at `path` of the default scene along `axes` (its vary: lines)."""
    path.write_text(
        f"base: {scene_path('rattleback.yaml')}\nvary:\n"
        + "".join(f"  {axis}\n" for axis in axes)
        + f"duration: {duration}\n"
    )
    return path


def test_a_sweep_has_the_command_lines_rows(tmp_path):
    sweep = default_sweep(
        tmp_path / "s.yaml", ["initial.spin: [-5, 5]", "contact.air_drag: [0.0, 5.9e-5]"], 3
    )
    table = rb.sweep(sweep, jobs=2)
    table.to_csv(tmp_path / "py.csv")
    cli("sweep", str(sweep), "-q", "-o", str(tmp_path / "cli.csv"))

    def rows(path):
        with open(path, newline="") as f:
            return [{k: v for k, v in r.items() if k != "wall_s"} for r in csv.DictReader(f)]

    assert rows(tmp_path / "py.csv") == rows(tmp_path / "cli.csv")
    assert list(table["initial.spin"]) == [-5.0, -5.0, 5.0, 5.0]
    assert len(table.to_pandas()) == 4


def test_a_sweeps_count_is_whole_in_pandas(tmp_path):
    """`reversals` counts: to_pandas gives it pandas' nullable integers, <NA> for a refused
    run (a student's table showed 1.0 and NaN), where the NumPy column is float with NaN."""
    pd = pytest.importorskip("pandas")
    sweep = default_sweep(tmp_path / "s.yaml", ["body.mass: [0.059, -1]"], 3)
    table = rb.sweep(sweep, jobs=2)
    frame = table.to_pandas()
    assert str(frame["reversals"].dtype) == "Int64"
    assert list(table["status"]) == ["ok", "refused"]
    assert frame["reversals"][0] == 1 and frame["reversals"].isna().tolist() == [False, True]
    assert table["reversals"].dtype == np.float64 and np.isnan(table["reversals"][1])
    assert frame["first_reversal_s"].dtype == np.float64


def test_a_sweep_made_in_python_has_the_sweep_files_rows(tmp_path):
    sweep = default_sweep(
        tmp_path / "s.yaml",
        ["initial.spin: {from: -6, to: -2, count: 3}", "contact.air_drag: [0.0, 5.9e-5]"],
        3,
    )
    cli("sweep", str(sweep), "-q", "-o", str(tmp_path / "cli.csv"))
    table = rb.sweep(
        scene_path("rattleback.yaml"),
        {"initial.spin": {"from": -6, "to": -2, "count": 3}, "contact.air_drag": np.array([0.0, 5.9e-5])},
        duration=3,
        jobs=2,
    )
    table.to_csv(tmp_path / "py.csv")

    def rows(path):
        with open(path, newline="") as f:
            # The axes' values as numbers: Python writes 5.9e-5 as JSON does, 5.9e-05.
            return [
                {
                    k: float(v) if k in ("initial.spin", "contact.air_drag") else v
                    for k, v in r.items()
                    if k != "wall_s"
                }
                for r in csv.DictReader(f)
            ]

    assert rows(tmp_path / "py.csv") == rows(tmp_path / "cli.csv")
    assert repr(table) == "<SweepTable rattleback-sweep: 6 runs, 6 ok>"
    side = json.loads((tmp_path / "py.csv.json").read_text())
    assert side["sweep"] == "rattleback-sweep" and side["base"] == scene_path("rattleback.yaml")


def test_a_swept_array_of_whole_numbers_is_written_as_a_sweep_files(tmp_path):
    # np.linspace gives -6.0, which the table wrote "-6.0" where the file's -6 is "-6".
    table = rb.sweep(
        scene_path("rattleback.yaml"), {"initial.spin": np.linspace(-6, -5, 3)}, duration=0.1, jobs=1
    )
    table.to_csv(tmp_path / "w.csv")
    with open(tmp_path / "w.csv", newline="") as f:
        assert [r["initial.spin"] for r in csv.DictReader(f)] == ["-6", "-5.5", "-5"]


def test_a_sweep_of_a_scene_with_values_starts_from_those_values():
    changed = rb.Scene.from_file(scene_path("rattleback.yaml")).with_values({"initial.spin": -4})
    table = rb.sweep(changed, {"contact.air_drag": [0.0, 5.9e-5]}, duration=2, jobs=1)
    # The same runs with the value as an axis of one value: the base's value went into each row.
    axis = rb.sweep(
        scene_path("rattleback.yaml"),
        {"initial.spin": [-4], "contact.air_drag": [0.0, 5.9e-5]},
        duration=2,
        jobs=1,
    )
    assert list(table["final_spin"]) == list(axis["final_spin"])
    plain = rb.sweep(scene_path("rattleback.yaml"), {"contact.air_drag": [0.0]}, duration=2, jobs=1)
    assert plain["final_spin"][0] != table["final_spin"][0]  # -5 rad/s, not -4


def test_a_sweep_of_a_key_rolling_does_not_use_warns_as_the_command_line_notes(tmp_path):
    sweep = default_sweep(tmp_path / "f.yaml", ["contact.friction: [0.1, 0.5]"], 0.2)
    with pytest.warns(rb.RunWarning, match="contact.friction does not change a rolling run") as w:
        table = rb.sweep(sweep, jobs=1)
    assert w[0].message.code == "axis_unused"
    assert w[0].filename == __file__
    note = cli("sweep", str(sweep), "-o", str(tmp_path / "f.csv")).stderr
    assert note == f"rattleback: note: {w[0].message}\n"
    assert table["final_spin"][0] == table["final_spin"][1]


SLOW_BODY = """units: {length: 0.01}
body:
  shape: paraboloid
  paraboloid: {a: 1.0, p: 0.5, q: 0.0, s: 0.12, top: 0.5}
  dents: {scale: 0.5, at: [0.8, 2.0]}
  grid: {dx: 0.05, dy: 0.05, dz: 0.05}
  mass: 0.03
contact: {model: rolling}
gravity: 9.81
initial: {spin: -1.0, tilt: [0.5, 0.5]}
simulation: {tolerance: 1.0e-8, duration: 8.0}
"""


def test_a_sweep_whose_every_run_is_refused_warns_as_the_command_line_exits_two(tmp_path):
    sweep = default_sweep(tmp_path / "r.yaml", ["contact.air_drag: [-1.0, -2.0]"], 0.1)
    with pytest.warns(rb.RunWarning, match="every run was refused; the first: ") as caught:
        table = rb.sweep(sweep, jobs=1)
    assert caught[-1].message.code == "all_refused"
    assert list(table["status"]) == ["refused", "refused"]
    done = cli("sweep", str(sweep), "-q", "-o", str(tmp_path / "r.csv"), check=False)
    assert done.returncode == 2
    # The same reason; the command line, for which it is bad input, writes nothing.
    said = str(caught[-1].message).replace("refused; the first", "refused, nothing written; the first")
    assert done.stderr == f"{said}\n"
    assert not (tmp_path / "r.csv").exists()


def test_analyze_looks_as_far_as_its_duration(tmp_path):
    """A 10 cm body spun -1 rad/s is forecast to reverse after its scene's 8 s: none within
    them, one within 60 (--duration 60 shows it without an edit of the scene)."""
    scene = tmp_path / "slow.yaml"
    scene.write_text(SLOW_BODY)
    near = rb.analyze(scene)["predicted_first_reversal"]
    far = rb.analyze(scene, duration=60)["predicted_first_reversal"]
    assert near["time_s"] is None
    assert 8 < far["time_s"] < 60
    out = cli("analyze", str(scene), "--duration", "60", "--json").stdout
    assert json.loads(out)["predicted_first_reversal"]["time_s"] == far["time_s"]


def test_the_attitude_quaternion_is_unit_and_gives_the_tilt(default_scene):
    # Body to world, scalar first: the body's z axis in world axes is R e_z, whose vertical
    # part is R[2][2] = 1 − 2(qx² + qy²) = cos(tilt).
    run = rb.simulate(default_scene, duration=3)
    norm = run.qw**2 + run.qx**2 + run.qy**2 + run.qz**2
    # (Normalised in C++ before sampling: a few rounding steps of 1e-16 each.)
    np.testing.assert_allclose(norm, 1.0, atol=1e-12)
    tilt = np.degrees(np.arccos(np.clip(1 - 2 * (run.qx**2 + run.qy**2), -1, 1)))
    # (The same rotation through another formula: arccos near 0.7° loses ~1e-12 of a degree.)
    np.testing.assert_allclose(tilt, run.tilt_deg, atol=1e-9)
    # The yaw rate of the quaternion is the spin: d/dt of the heading of the body's x axis
    # (R e_x projected on the floor) follows n, here within 1 % over the first second.
    heading = np.unwrap(
        np.arctan2(2 * (run.qx * run.qy + run.qw * run.qz), 1 - 2 * (run.qy**2 + run.qz**2))
    )
    rate = np.gradient(heading, run.t)
    first = run.t < 1
    # (1 %: the heading of the tilted x axis turns at n only to first order in the 0.7° tilt, and
    # np.gradient at 2 ms differentiates the 7 Hz wobble to ~0.3 %.)
    np.testing.assert_allclose(rate[first][5:-5].mean(), run.spin[first][5:-5].mean(), rtol=0.01)
    # Continuous in time: no sample jumps to −q.
    q = np.stack([run.qw, run.qx, run.qy, run.qz], axis=1)
    # (2 ms at 5 rad/s turns 0.01 rad: neighbouring unit quaternions have q·q' ≈ 1; a flip to
    # −q would give ≈ −1.)
    assert (np.sum(q[1:] * q[:-1], axis=1) > 0.9).all()


def test_python_lists_its_files_in_the_folders_manifest_as_the_command_line_does(tmp_path):
    """Each file a run writes is listed with the scene it was made from (its content and the
    values put in), the same as simulate -o lists its own: the report tells files of an edited
    scene from the run's by it."""
    scene = rb.Scene.from_file(scene_path("rattleback.yaml")).with_values({"body.paraboloid.a": 1.2})
    run = rb.simulate(scene, duration=0.2)
    run.to_csv(tmp_path / "mine.csv")
    run.to_npz(tmp_path / "mine.npz")
    run.to_hdf5(tmp_path / "mine.h5")
    cli(
        "simulate",
        scene_path("rattleback.yaml"),
        "--set",
        "body.paraboloid.a=1.2",
        "--duration",
        "0.2",
        "-q",
        "-o",
        "theirs.csv",
        cwd=tmp_path,
    )
    outputs = json.loads((tmp_path / "rattleback-manifest.json").read_text())["outputs"]
    theirs = [o for o in outputs if o["file"] == "theirs.csv"]
    assert len(theirs) == 1 and len(theirs[0]["made_from"]) == 16
    for name in ("mine.csv", "mine.npz", "mine.h5"):
        assert [o for o in outputs if o["file"] == name] == [{**theirs[0], "file": name}]


def test_check_is_the_command_lines_check(tmp_path, default_scene):
    """simulate(check=True) estimates the same errors as ``simulate --check``, in the same
    sidecar."""
    run = rb.simulate(scene_path("kane-levinson.yaml"), duration=3.0, check=True)
    run.to_csv(tmp_path / "py.csv")
    cli(
        "simulate",
        scene_path("kane-levinson.yaml"),
        "--duration",
        "3",
        "--check",
        "-q",
        "-o",
        str(tmp_path / "cli.csv"),
    )
    ours = json.loads((tmp_path / "py.csv.json").read_text())["check"]
    theirs = json.loads((tmp_path / "cli.csv.json").read_text())["check"]
    for side in (ours, theirs):
        side.pop("cost_ratio")  # wall times
    assert ours == theirs
    assert {k: v for k, v in run.check.items() if k != "cost_ratio"} == ours
    assert run.check["method"] == "Richardson, order 4"
    assert len(run.check["reversal_errors_s"]) == len(run.result["reversals_s"]) == 1
    assert 0 < abs(run.check["reversal_errors_s"][0]) < 1e-7  # rk4 at 0.1 ms: ~1e-9 s
    assert rb.simulate(default_scene, duration=0.1).check is None


def test_a_runs_arrays_are_read_only(tmp_path, default_scene):
    """A run's columns are what its CSV holds: `s = run.spin; s *= 2` changed run.spin,
    run.columns and to_pandas() but not what to_csv wrote. A copy is the caller's to change."""
    run = rb.simulate(default_scene, duration=0.2, rate=100)
    first = run.spin[0]
    for name, column in run.columns.items():
        assert not column.flags.writeable, name
        with pytest.raises(ValueError):
            column[0] = column[1]
    s = run.spin
    with pytest.raises(ValueError):
        s *= 2
    assert run.spin[0] == run["spin"][0] == first
    mine = run.spin.copy()
    mine *= 2
    assert mine[0] == 2 * first
    pd = pytest.importorskip("pandas")
    frame = run.to_pandas()
    frame["spin"] *= 2  # the frame is the caller's
    assert run.spin[0] == first


def test_a_sweep_tables_arrays_are_read_only(tmp_path):
    """As a run's: `s = table["final_spin"]; s *= 2` changed the table's columns and
    to_pandas() but not what to_csv wrote. A copy is the caller's to change."""
    sweep = default_sweep(tmp_path / "s.yaml", ["initial.spin: [-5, 5]"], 0.2)
    table = rb.sweep(sweep, jobs=1)
    first = table["initial.spin"][0]
    for name, column in table.columns.items():
        assert not column.flags.writeable, name
        with pytest.raises(ValueError):
            column[0] = column[1]
    s = table["initial.spin"]
    with pytest.raises(ValueError):
        s *= 2
    assert table["initial.spin"][0] == table.columns["initial.spin"][0] == first
    mine = table["initial.spin"].copy()
    mine *= 2
    assert mine[0] == 2 * first
    pytest.importorskip("pandas")
    frame = table.to_pandas()
    frame["initial.spin"] *= 2  # the frame is the caller's
    assert table["initial.spin"][0] == first


def test_a_shipped_scene_is_found_from_any_folder_as_the_command_line_finds_it(tmp_path, monkeypatch):
    """`rb.simulate("scenes/rattleback.yaml")` from another folder said "cannot open the scene
    file", while `rattleback simulate scenes/rattleback.yaml` there found the installed copy
    (tasks::findShipped). The installed assets folder is stood for by one holding the build
    tree's assets and the source's scenes and sweeps."""
    assets = tmp_path / "share"
    assets.mkdir()
    built = Path(rb.__file__).resolve().parents[2] / "share" / "rattleback"
    for entry in built.iterdir():
        (assets / entry.name).symlink_to(entry)
    for folder in ("scenes", "sweeps"):
        (assets / folder).symlink_to(Path(scene_path("rattleback.yaml")).parents[1] / folder)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.setenv("RATTLEBACK_ASSETS", str(assets))
    monkeypatch.chdir(elsewhere)

    shipped = str(assets / "scenes" / "rattleback.yaml")
    scene = rb.Scene.from_file("scenes/rattleback.yaml")
    assert scene.name == shipped  # named as the command line names it, by the file it read
    run = rb.simulate("scenes/rattleback.yaml", duration=0.2, rate=100)
    run.to_csv("py.csv")
    cli("simulate", "scenes/rattleback.yaml", "--duration", "0.2", "--rate", "100", "-q", "-o", "cli.csv")
    assert Path("py.csv").read_text() == Path("cli.csv").read_text()
    a, b = sidecars_without_wall_time(elsewhere)
    assert a == b and a["scene_path"] == shipped
    assert rb.analyze("scenes/rattleback.yaml")["preferred"] == "ccw"
    assert rb.still("scenes/rattleback.yaml", size=(64, 48)).width == 64
    assert len(rb.sweep("sweeps/spin-drag.yaml", jobs=1)) > 0
    # A file of that name here is the one read, as for the command line.
    (elsewhere / "scenes").mkdir()
    (elsewhere / "scenes" / "rattleback.yaml").write_text(Path(shipped).read_text())
    assert rb.Scene.from_file("scenes/rattleback.yaml").name == "scenes/rattleback.yaml"


@pytest.mark.parametrize("there", ["kane-levinson.yaml", "rattleback.yaml"])
def test_a_run_of_a_scene_with_no_file_points_to_none(tmp_path, there):
    """A run of a scene made from text is of no file: its sidecar named <cwd>/other.yaml, and
    `report` took whatever file sat there for its scene, drawing that body in the 3D player
    (the same text) or saying the file "has changed since this run" (another)."""
    text = Path(scene_path("rattleback.yaml")).read_text()
    run = rb.simulate(rb.Scene.from_yaml(text, name="other.yaml"), duration=0.5)
    run.to_csv(tmp_path / "other.csv")
    sidecar = json.loads((tmp_path / "other.csv.json").read_text())
    assert sidecar["scene"] == "other.yaml" and sidecar["scene_path"] is None
    assert run.sidecar() == {**sidecar, "result": run.sidecar()["result"]}
    # Its fingerprint is of the text run, as a file's is of the file's text.
    ran = rb.simulate(scene_path("rattleback.yaml"), duration=0.5).sidecar()
    assert sidecar["scene_fingerprint"] == ran["scene_fingerprint"]
    (tmp_path / "other.yaml").write_text(Path(scene_path(there)).read_text())
    report = cli("report", str(tmp_path))
    assert "other.yaml" not in report.stderr
    assert not (tmp_path / "other.player.js").exists()
    page = (tmp_path / "index.html").read_text()
    assert "rb-player" not in page and "averaged theory" not in page


def test_a_scene_with_no_file_gets_a_default_name_of_a_file(tmp_path, monkeypatch):
    """A dict's or unnamed text's video was out/<dict>.mp4 (out/<yaml>.mp4): a name in angle
    brackets, which a shell takes for redirections. Such a scene's outputs are named "scene"."""
    monkeypatch.chdir(tmp_path)
    text = Path(scene_path("rattleback.yaml")).read_text()
    for scene in (rb.Scene.from_yaml(text), rb.Scene.from_yaml(text, name="mine.yaml")):
        [video] = rb.render(scene, duration=0.2, size=(64, 48), fps=10)
        assert video["path"] == ("out/mine.mp4" if scene.name == "mine.yaml" else "out/scene.mp4")
    both = rb.render(rb.Scene.from_yaml(text), both=True, duration=0.2, size=(64, 48), fps=10)
    assert sorted(f["path"] for f in both) == [
        "out/scene-both.mp4",
        "out/scene-preferred.mp4",
        "out/scene-reversed.mp4",
    ]
    listed = json.loads((tmp_path / "out" / "rattleback-manifest.json").read_text())
    assert "<yaml>" not in json.dumps(listed)


def test_a_sweep_given_columns_holds_them_with_the_command_lines_values(tmp_path):
    """columns= is a sweep file's columns: (docs/commands.md "Only the columns a table needs"): the
    table holds the row, the varied keys and those columns, the command line's values (runs
    stopped once their first reversal is confirmed give the whole run's to the bit), and a
    sweep file's own columns: are kept."""
    base = scene_path("rattleback.yaml")
    vary = {"initial.spin": [-5, -3, 4]}
    whole = rb.sweep(base, vary, duration=4, jobs=1)
    listed = rb.sweep(base, vary, duration=4, jobs=2, columns=["first_reversal_s", "forecast_s"])
    assert list(listed.columns) == ["row", "initial.spin", "first_reversal_s", "forecast_s"]
    assert np.array_equal(listed["first_reversal_s"], whole["first_reversal_s"], equal_nan=True)
    assert int(np.sum(np.isfinite(listed["first_reversal_s"]))) == 2  # -5 and -3 reverse
    sweep = tmp_path / "s.yaml"
    sweep.write_text(
        f"base: {base}\nvary:\n  initial.spin: [-5, -3, 4]\nduration: 4\ncolumns: [forecast_s]\n"
    )
    own = rb.sweep(str(sweep), jobs=1)
    assert list(own.columns) == ["row", "initial.spin", "forecast_s"]
    assert np.array_equal(own["forecast_s"], listed["forecast_s"], equal_nan=True)
    with pytest.raises(
        rb.SceneError,
        match="argument columns: forcast_s is not a column of the table; did you mean forecast_s",
    ):
        rb.sweep(base, vary, columns=["forcast_s"])
    # A table without status still warns when every run was refused (the CLI exits 2).
    with pytest.warns(rb.RunWarning, match="every run was refused; the first: argument vary: body.mass"):
        rb.sweep(base, {"body.mass": [-1.0]}, duration=0.1, columns=["first_reversal_s"])
