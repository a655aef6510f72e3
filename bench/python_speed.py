#!/usr/bin/python3
"""What Python adds to the library (docs/python.md "Speed"): the per-call overhead of simulate()
over the same C++ run, the cost of the columns per sample, and sweep throughput from Python
against the command line. Prints figures; asserts nothing.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/python_speed.py [RATTLEBACK_BINARY]
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import rattleback as rb

ROOT = Path(__file__).resolve().parents[1]
BIN = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build" / "app" / "rattleback")
SCENE = str(ROOT / "scenes" / "rattleback.yaml")


def median_seconds(call, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def call_overhead():
    # A run so short that the call is all there is: 2 ms simulated, 2 samples.
    scene = rb.Scene.from_file(SCENE).with_values({"simulation.duration": 0.002})
    native = rb._core._native_seconds(scene._loaded, 500.0, 2001)
    python = median_seconds(lambda: rb.simulate(scene), 2001)
    print(
        f"simulate, 2 ms simulated (2 samples): C++ {1e6 * native:8.1f} µs, from Python "
        f"{1e6 * python:8.1f} µs: overhead {1e6 * (python - native):6.1f} µs per call "
        f"(target ≤ 50 µs)"
    )
    # The default scene whole (8 s, 4001 samples): the overhead plus the columns.
    scene = rb.Scene.from_file(SCENE)
    native = rb._core._native_seconds(scene._loaded, 500.0, 21)
    python = median_seconds(lambda: rb.simulate(scene), 21)
    samples = len(rb.simulate(scene))
    print(
        f"simulate, default scene (8 s, {samples} samples): C++ {1e3 * native:7.2f} ms, from "
        f"Python {1e3 * python:7.2f} ms: {1e3 * (python - native):5.2f} ms more, "
        f"{1e9 * (python - native) / samples:6.0f} ns per sample for 21 columns"
    )


def sweep_throughput():
    sweep = ROOT / "sweeps" / "spin-drag.yaml"
    rows = len(rb.sweep(sweep))  # warm (and the row count)
    with tempfile.TemporaryDirectory() as out:
        cli = median_seconds(
            lambda: subprocess.run(
                [BIN, "sweep", str(sweep), "-q", "-o", os.path.join(out, "t.csv")], check=True
            ),
            5,
        )
    python = median_seconds(lambda: rb.sweep(sweep), 5)
    print(
        f"sweep {sweep.name} ({rows} runs, all cores): command line {rows / cli:6.1f} runs/s "
        f"(whole process), Python {rows / python:6.1f} runs/s: Python/CLI "
        f"{cli / python:5.2f}× (target 1 within noise)"
    )


if __name__ == "__main__":
    print(f"rattleback {rb.__version__}, {os.cpu_count()} cores, median of repeated calls")
    call_overhead()
    sweep_throughput()
