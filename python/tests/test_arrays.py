"""Telemetry as arrays (docs/commands.md "Telemetry as arrays"): `simulate -o RUN.npz` and
`-o RUN.h5`, and Python's to_npz / to_hdf5, read with the tools researchers use (np.load, h5py),
hold the run's own doubles: the CSV's text read back exactly (its numbers are shortest
round-trip text), each column in its kind (float64, int64 counts, the mode as text), its unit
beside it, and the sidecar the CSV has."""

import json
import time

import h5py
import numpy as np
import pandas as pd
import pytest

import rattleback as rb
from conftest import cli, scene_path

# An auto run: the mode column changes (rolling, then smooth), so that the text column is tried
# with more than one word.
SCENE = scene_path("rattleback.yaml")
SHORT = ["--duration", "0.5", "--rate", "2000"]


def csv_columns(path):
    # pandas' default float parser is not round-trip; the CSV's text is.
    return pd.read_csv(path, float_precision="round_trip")


def kinds():
    """Each column's expected dtype kind, from the sidecar's declaration of the columns (not
    from the files under test): counts are whole numbers, the mode a word, the rest doubles."""
    return {
        name: ("i" if name == "contacts" else "U" if name == "mode" else "f")
        for name, _, _ in rb._core.telemetry_columns
    }


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    folder = tmp_path_factory.mktemp("arrays")
    for ext in ("csv", "npz", "h5"):
        cli("simulate", SCENE, *SHORT, "-q", "-o", str(folder / f"run.{ext}"))
    return folder


def test_npz_holds_the_csvs_numbers_exactly_in_each_columns_kind(written):
    table = csv_columns(written / "run.csv")
    with np.load(written / "run.npz") as npz:  # allow_pickle stays False: no object arrays
        assert [c for c in npz.files if c not in ("columns", "units")] == list(table.columns)
        for name, kind in kinds().items():
            assert npz[name].dtype.kind == kind, name
            assert npz[name].shape == (len(table),)
            if kind == "U":
                assert list(npz[name]) == list(table[name]), name
            else:
                assert np.array_equal(npz[name], table[name].to_numpy()), name
        units = dict(zip(npz["columns"], npz["units"]))
    sidecar = json.loads((written / "run.csv.json").read_text())
    assert units == {c["name"]: c["unit"] for c in sidecar["columns"]}


def test_hdf5_holds_the_csvs_numbers_exactly_with_unit_and_meaning(written):
    table = csv_columns(written / "run.csv")
    sidecar = json.loads((written / "run.csv.json").read_text())
    with h5py.File(written / "run.h5", "r") as f:
        assert sorted(f.keys()) == sorted(table.columns)
        # h5py lists datasets by name; the root's `columns` keeps the CSV's order.
        assert list(f.attrs["columns"]) == list(table.columns)
        for column in sidecar["columns"]:
            data = f[column["name"]]
            assert data.attrs["unit"] == column["unit"]
            assert data.attrs["meaning"] == column["meaning"]
            if column["name"] == "mode":
                assert list(data.asstr()[:]) == list(table["mode"])
            else:
                assert data.dtype.kind == kinds()[column["name"]]
                assert np.array_equal(data[:], table[column["name"]].to_numpy()), column["name"]


def test_the_sidecar_is_the_csvs(written):
    # The same run: all but the time it took.
    sidecars = [json.loads((written / f"run.{ext}.json").read_text()) for ext in ("csv", "npz", "h5")]
    for s in sidecars:
        s.pop("wall_s", None)
        s.get("result", {}).pop("wall_s", None)
    assert sidecars[0] == sidecars[1] == sidecars[2]


def test_a_run_written_twice_gives_the_same_bytes(tmp_path):
    # No time of writing inside (a ZIP's dates, HDF5's object times): a file under version
    # control or in a cache stays the same.
    # (A second apart: HDF5 keeps its times to the second.)
    for name in ("a", "b"):
        for ext in ("npz", "h5"):
            cli("simulate", SCENE, *SHORT, "-q", "-o", str(tmp_path / f"{name}.{ext}"))
        time.sleep(1.1 if name == "a" else 0)
    for ext in ("npz", "h5"):
        assert (tmp_path / f"a.{ext}").read_bytes() == (tmp_path / f"b.{ext}").read_bytes(), ext


def test_pythons_to_npz_and_to_hdf5_hold_the_runs_arrays(tmp_path):
    run = rb.simulate(SCENE, duration=0.5, rate=2000)
    run.to_npz(tmp_path / "run.npz")
    run.to_hdf5(tmp_path / "run.hdf5")
    with np.load(tmp_path / "run.npz") as npz, h5py.File(tmp_path / "run.hdf5") as f:
        for name in run.columns:
            if name == "mode":
                assert list(npz[name]) == list(f[name].asstr()[:]) == list(run[name])
            else:
                assert np.array_equal(npz[name], run[name]) and np.array_equal(f[name][:], run[name])
    assert json.loads((tmp_path / "run.npz.json").read_text())["rows"] == len(run["t"])


def test_a_name_of_another_format_is_refused_and_nothing_is_written(tmp_path):
    run = rb.simulate(SCENE, duration=0.05)
    for method, name, said in [
        (run.to_npz, "x.h5", "x.h5: writes NumPy arrays; give a name " "ending in .npz"),
        (run.to_hdf5, "x.npz", "give a name ending in .h5"),
        (run.to_csv, "x.npz", "give a name ending in .csv"),
        (run.to_npz, "x.png", "give a name ending in .npz"),
        (run.to_csv, "x.npy", "writes a CSV table (.csv), NumPy arrays (.npz) or HDF5 (.h5)"),
    ]:
        with pytest.raises(ValueError) as caught:
            method(tmp_path / name)
        assert str(caught.value).startswith(method.__name__ + " ") and said in str(caught.value)
    assert list(tmp_path.iterdir()) == []


def test_the_report_lists_arrays_beside_the_csv_and_alone(tmp_path):
    # The page reads a CSV's rows: a run kept only as arrays is linked, not read as a CSV.
    folder = tmp_path / "out"
    cli("simulate", SCENE, "--duration", "0.2", "-q", "-o", str(folder / "rattleback.npz"))
    page = cli("report", str(folder))
    assert page.returncode == 0
    html = (folder / "index.html").read_text()
    assert '<a href="rattleback.npz">rattleback.npz</a>' in html and "(CSV)" not in html
    cli("simulate", SCENE, "--duration", "0.2", "-q", "-o", str(folder / "rattleback.csv"))
    cli("report", str(folder))
    html = (folder / "index.html").read_text()
    assert '<a href="rattleback.npz">rattleback.npz</a>' in html
    assert '<a href="rattleback.csv">telemetry (CSV)</a>' in html


def test_the_command_line_refuses_a_name_of_a_format_it_does_not_write(tmp_path):
    # -o x.npy wrote CSV text, which np.load then called pickled data.
    for name in ("x.npy", "x.parquet", "x.mat"):
        result = cli("simulate", SCENE, "--duration", "0.05", "-q", "-o", str(tmp_path / name), check=False)
        assert result.returncode == 2
        assert "-o " in result.stderr and "NumPy arrays (.npz) or HDF5 (.h5)" in result.stderr
    assert list(tmp_path.iterdir()) == []
