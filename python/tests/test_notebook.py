"""The tour notebook runs from start to end (nbclient), so the example never rots."""

import os
import shutil

import nbformat
from nbclient import NotebookClient

from conftest import SOURCE


def run_notebook(name, folder):
    """examples/NAME run from start to end in `folder` (beside a link to the shipped scenes, as a
    user's copy would be): its code cells' outputs, none an error, and their printed text."""
    (folder / "scenes").symlink_to(SOURCE / "scenes")
    shutil.copy(SOURCE / "examples" / name, folder / name)
    nb = nbformat.read(folder / name, as_version=4)
    NotebookClient(
        nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(folder)}}
    ).execute()
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    return outputs, "".join(o.get("text", "") for o in outputs if o.output_type == "stream")


def test_the_tour_runs_and_shows_its_plot_and_still(tmp_path):
    outputs, text = run_notebook("tour.ipynb", tmp_path)
    pngs = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(pngs) >= 3  # the n(t) plot, the sweep's and the still
    assert "first reversal at 2.36" in text
    assert "<SweepTable rattleback-sweep: 45 runs, 45 ok>" in text
    assert (tmp_path / "out" / "tour.mp4").stat().st_size > 10_000


def test_the_laboratory_runs_steps_taps_keeps_hdf5_and_checks_the_growth(tmp_path):
    """examples/laboratory.ipynb: its own asserts hold the stepped reversal to simulate's, the
    run's growth to the linearised model's (3 %) and a columns: sweep's first reversals to the
    whole runs'; here, that it ran and said what it found."""
    outputs, text = run_notebook("laboratory.ipynb", tmp_path)
    # the tap, the pair, the regime map
    assert len([o for o in outputs if "image/png" in o.get("data", {})]) == 3
    assert "opposite directions: True" in text
    assert "read back equal: True" in text
    assert "growth: eigenvalue" in text
    assert "equal to the whole runs: True" in text
