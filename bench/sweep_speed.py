#!/usr/bin/env python3
"""Sweep speed, side by side in one run (README "Sweeps"): start-up time and peak memory of
`rattleback --version` against rattleback-render (the program that links the renderer, as every
command did before the split), runs per second of the default scene (8 s, rolling) as one
process per run and as `rattleback sweep` with -j1 and -j2, and the integration time of one run.

Usage: bench/sweep_speed.py [BUILD_DIR] [RUNS]   (default build, 300 runs)
Prints figures; asserts nothing.
"""
import json
import os
import subprocess
import sys
import tempfile
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build"))
runs = int(sys.argv[2]) if len(sys.argv) > 2 else 300
light = os.path.join(build, "app", "rattleback")
heavy = os.path.join(build, "app", "rattleback-render")
scene = os.path.join(root, "scenes", "rattleback.yaml")


def timed(argv, repeats):
    """Median wall time (s) of `argv`, and its peak RSS (MB) as GNU time reports it (a child of
    this Python process would count Python's own pages from before its exec)."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        times.append(time.perf_counter() - start)
    times.sort()
    rss = subprocess.run(
        ["/usr/bin/time", "-f", "%M"] + argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True
    ).stderr.split()[-1]
    return times[len(times) // 2], int(rss) / 1024


def libraries(program):
    out = subprocess.run(["ldd", program], capture_output=True, text=True).stdout
    return sum(1 for line in out.splitlines() if "=>" in line or line.strip().startswith("/"))


print("== start-up: `--version`, median of 30")
print(f"{'program':<44} {'time':>9} {'peak RSS':>10} {'libraries':>10}")
for name, program in [
    ("rattleback (simulating commands)", light),
    ("rattleback-render (links the renderer)", heavy),
]:
    t, rss = timed([program, "--version"], 30)
    print(f"{name:<44} {t * 1e3:7.1f} ms {rss:7.1f} MB {libraries(program):>10}")

with tempfile.TemporaryDirectory() as work:
    # One run's integration alone: simulate's own clock (sidecar wall_s), one sample at the end.
    csv = os.path.join(work, "one.csv")
    walls = []
    for _ in range(5):
        subprocess.run([light, "simulate", scene, "-q", "--rate", "0.125", "-o", csv], check=True)
        walls.append(json.load(open(csv + ".json"))["result"]["wall_s"])
    integrate = sorted(walls)[2]
    steps = json.load(open(csv + ".json"))["result"]["steps"]
    print(f"\n== one run of {scene} (8 s simulated, rk4, {steps} steps)")
    print(f"integration alone {integrate * 1e3:.2f} ms ({integrate / steps * 1e9:.0f} ns per step)")

    print(f"\n== runs per second of that scene")
    print(f"{'how':<52} {'runs/s':>8}")
    for name, program in [
        ("one process per run: rattleback simulate", light),
        ("one process per run: the renderer-linked program", heavy),
    ]:
        n = 20
        start = time.perf_counter()
        for _ in range(n):
            subprocess.run([program, "simulate", scene, "-q", "--rate", "0.125", "-o", csv], check=True)
        print(f"{name:<52} {n / (time.perf_counter() - start):8.1f}")
    sweep = os.path.join(work, "same.yaml")
    with open(sweep, "w") as f:
        f.write(f"base: {scene}\nvary:\n  initial.spin: {{from: -5, to: -5, count: {runs}}}\n")
    for jobs in (1, 2):
        start = time.perf_counter()
        subprocess.run(
            [light, "sweep", sweep, "-q", "-j", str(jobs), "-o", os.path.join(work, f"j{jobs}.csv")],
            check=True,
        )
        elapsed = time.perf_counter() - start
        per_run = elapsed * jobs / runs
        print(
            f"{'rattleback sweep -j ' + str(jobs) + f' ({runs} runs)':<52} {runs / elapsed:8.1f}"
            f"   ({per_run * 1e3:.2f} ms per run per thread, {(per_run - integrate) * 1e3:+.2f} ms"
            f" beside integrating)"
        )
