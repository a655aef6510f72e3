#!/usr/bin/env python3
"""The round trip of a mesh body (docs/scenes.md "A body from a mesh"): the default body exported
by `rattleback export` at a ladder of resolutions, read back as a mesh body in mm, and run as the
default scene runs (rolling, on the bottom fitted to the mesh), beside the analytic body:

  segments -> triangles -> mass-property error -> first-reversal error -> run's cost

The mass-property error is the largest relative difference of the principal moments; the
first reversal is the reversal rule's (docs/physics.md §P7), spun -5 rad/s as the scene is.
Target: a rolling run on the mesh body within 2x the analytic body's cost.
Usage: bench/mesh_round_trip.py [BUILD_DIR]. Prints figures; asserts nothing.
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build"))
rb = os.path.join(build, "app", "rattleback")
scene = os.path.join(root, "scenes", "rattleback.yaml")
work = tempfile.mkdtemp(prefix="rattleback-round-trip-")


def run(*args):
    return subprocess.run([rb, *args], capture_output=True, text=True, check=True).stdout


def analyze(path):
    return json.loads(run("analyze", "--json", path))


def simulate(path, repeats=3):
    """The run's result and the median wall time of `repeats` whole runs, s."""
    walls = []
    for _ in range(repeats):
        out = os.path.join(work, "run.csv")
        run("simulate", "-q", path, "-o", out, "--rate", "10")
        with open(out + ".json") as f:
            result = json.load(f)["result"]
        walls.append(result["wall_s"])
    return result, statistics.median(walls)


def mesh_scene(stl):
    """The default scene with the body replaced by the mesh (mm), all else as it is."""
    with open(scene) as f:
        lines = f.read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("body:"))
    end = next(i for i, l in enumerate(lines) if i > start and l and not l.startswith((" ", "#")))
    body = [
        "body:",
        "  shape: mesh",
        f"  mesh: {{file: {stl}}}",
        "  mass: 0.059",
    ]
    text = "\n".join(["units: {length: 0.001}"] + body + lines[end:]) + "\n"
    text = text.replace("units: {length: 0.01}", "")
    path = stl.replace(".stl", ".yaml")
    with open(path, "w") as f:
        f.write(text)
    return path


want = analyze(scene)
exact, exact_wall = simulate(scene)
print(f"analytic body: first reversal {exact['first_reversal_s']} s, run {exact_wall * 1e3:.2f} ms")
print(
    f"{'segments':>8} {'triangles':>9} {'mass props':>10} {'reversal s':>11} {'error s':>9} "
    f"{'run ms':>7} {'x analytic':>10}"
)
for segments in (48, 96, 192, 384):
    stl = os.path.join(work, f"body-{segments}.stl")
    run("export", scene, "-o", stl, "--segments", str(segments), "-q")
    triangles = (os.path.getsize(stl) - 84) // 50
    path = mesh_scene(stl)
    moments = float("nan")
    try:
        got = analyze(path)
        moments = max(abs(a / b - 1) for a, b in zip(got["principal_moments"], want["principal_moments"]))
        result, wall = simulate(path)
        first = result["first_reversal_s"]
        error = "" if first is None else f"{first - exact['first_reversal_s']:+.2e}"
        print(
            f"{segments:>8} {triangles:>9} {moments:>10.2e} {str(first):>11} {error:>9} "
            f"{wall * 1e3:>7.2f} {wall / exact_wall:>10.2f}"
        )
    except subprocess.CalledProcessError as e:
        print(f"{segments:>8} {triangles:>9} {moments:>10.2e}  refused: {e.stderr.strip()}")
print("target: a rolling run on the mesh body within 2x the analytic body's cost")
