"""A sweep's line plot of first_reversal_s draws the theory's forecast_s beside it when the
table has that column (what a lab plots), read off the PNG's pixels."""

import numpy as np

from rattleback._compare import _array

from conftest import cli, scene_path

THEORY = np.array([0x00, 0x9E, 0x73])  # the forecast's colour (app/sweep.cpp plotLine)


def theory_pixels(png) -> int:
    image = _array(png)[:, :, :3].astype(int)
    return int((np.abs(image - THEORY).max(axis=2) <= 12).sum())


def test_the_forecast_is_drawn_beside_the_first_reversal_where_the_table_has_it(tmp_path):
    vary = "vary:\n  initial.spin: {from: -4, to: -1, count: 7}\n"
    base = f"base: {scene_path('rattleback.yaml')}\n"
    (tmp_path / "with.yaml").write_text(base + vary + "columns: [first_reversal_s, forecast_s]\n")
    (tmp_path / "without.yaml").write_text(base + vary + "columns: [first_reversal_s]\n")
    for name in ("with", "without"):
        cli("sweep", f"{name}.yaml", "-q", "-o", f"{name}.csv", "--plot", f"{name}.png", cwd=tmp_path)
    # Seven forecasts within the theory's range, marked by circles and joined by a dashed line:
    # 174 pixels of its colour measured here (gnuplot 5.4, pngcairo); more than half of that
    # leaves room for another build's antialiasing, and a plot without the column has none.
    assert theory_pixels(tmp_path / "with.png") > 80
    assert theory_pixels(tmp_path / "without.png") == 0
