#!/usr/bin/env python3
"""Sweeps that compute only what their table needs (docs/commands.md "Only the columns a table
needs"), each figure beside its target, measured side by side in one run on this machine:

  200 spins       the default scene spun -8 ... -2 rad/s (its first reversal at 2.0-4.0 s of
                  the 8 s), `columns: [first_reversal_s]`, -j2: runs a second, whole process
                  (median of 5, and their spread) and the sweep's own clock, beside the
                  same sweep without columns, and the process's CPU time (what 2 idle cores
                  would take, doubled):
                                                                            target >= 3,000/s
  its accuracy    the largest difference of its first_reversal_s from the same sweep at
                  tolerance 1e-11 (converged), and whether it equals the whole runs' to the bit
                                                                            target <= 1e-4 s
  by dop853       the same 200 by the eighth-order method at DOP853_TOLERANCE: runs a second,
                  CPU, and its first reversals against the converged sweep
  regime map      100,000 runs, spin (-10 ... 10 rad/s, 50) x tilt about x (0.1 ... 5 deg, 40)
                  x air drag (0 ... 5.9e-5 N m s, 50), `columns: [first_reversal_s]`, -j2: wall
                  time of the whole process (once: it takes a minute)      target <= 40 s

Usage: bench/sweep_columns.py [BUILD_DIR] [--no-map]. Prints figures; asserts nothing. The
machine may be shared: the figures are medians, and the load average is printed beside them.
"""
import csv
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
args = [a for a in sys.argv[1:] if not a.startswith("--")]
build = os.path.abspath(args[0] if args else os.path.join(root, "build"))
rb = os.path.join(build, "app", "rattleback")
scene = os.path.join(root, "scenes", "rattleback.yaml")
work = tempfile.mkdtemp(prefix="rattleback-columns-")


def show(what, figure, target, met):
    print(f"{what:<40} {figure:<52} {target:<12} {'met' if met else 'NOT met'}", flush=True)


def write(name, text):
    path = os.path.join(work, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def children_cpu():
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    return used.ru_utime + used.ru_stime


def sweep(path, out, jobs=2):
    """Whole-process wall time, s, the sweep's own (its summary's `wall time` line) and the
    process's CPU time, s (user + system: what the load of other work moves least)."""
    start, cpu = time.perf_counter(), children_cpu()
    done = subprocess.run(
        [rb, "sweep", path, f"-j{jobs}", "-o", out], check=True, capture_output=True, text=True
    )
    whole = time.perf_counter() - start
    inside = float(re.search(r"wall time\s+([\d.]+) s", done.stdout).group(1))
    return whole, inside, children_cpu() - cpu


def column(path, name):
    return [row[name] for row in csv.DictReader(open(path))]


def scene_at(tolerance, integrator=None):
    """The default scene at another tolerance, and integrator when given (its simulation block
    has the line `  tolerance: 1.0e-8`)."""
    text = open(scene).read()
    assert "  tolerance: 1.0e-8" in text
    line = (
        f"tolerance: {tolerance}" if not integrator else f"integrator: {integrator}\n  tolerance: {tolerance}"
    )
    return write(f"scene-{integrator}-{tolerance}.yaml", text.replace("tolerance: 1.0e-8", line, 1))


# The eighth-order method (sim/dop853.hpp) at the loosest tolerance that holds every first
# reversal of the 200 within 1e-4 s of the converged sweep (docs/speed.md).
DOP853_TOLERANCE = "1.0e-9"


print(
    f"rattleback sweep columns, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}, {time.strftime('%Y-%m-%d %H:%M')}"
)
print(f"{'what':<40} {'figure':<52} {'target':<12} verdict")

spins = "initial.spin: {from: -8, to: -2, count: 200}"
listed = write("listed.yaml", f"base: {scene}\nvary:\n  {spins}\ncolumns: [first_reversal_s]\n")
whole = write("whole.yaml", f"base: {scene}\nvary:\n  {spins}\n")
converged = write("converged.yaml", f"base: {scene_at('1.0e-11')}\nvary:\n  {spins}\n")
eighth = write(
    "dop853.yaml",
    f"base: {scene_at(DOP853_TOLERANCE, 'dop853')}\nvary:\n  {spins}\ncolumns: [first_reversal_s]\n",
)

runs = {"listed": [], "whole": [], "dop853": []}
for _ in range(5):  # alternating, so that a busy moment falls on all alike
    runs["listed"].append(sweep(listed, os.path.join(work, "listed.csv")))
    runs["whole"].append(sweep(whole, os.path.join(work, "whole.csv")))
    runs["dop853"].append(sweep(eighth, os.path.join(work, "dop853.csv")))
rate = {k: 200 / statistics.median(w for w, _, _ in v) for k, v in runs.items()}
# The spread of the five, beside the median: on 2 cores a figure within it of the target is the
# machine's moment as much as the program's.
spread = {k: (200 / max(w for w, _, _ in v), 200 / min(w for w, _, _ in v)) for k, v in runs.items()}
inner = {k: 200 / statistics.median(s for _, s, _ in v) for k, v in runs.items()}
cpu = {k: statistics.median(c for _, _, c in v) for k, v in runs.items()}
show(
    "200 spins, columns: [first_reversal_s]",
    f"{rate['listed']:.0f} runs/s whole process ({spread['listed'][0]:.0f}-{spread['listed'][1]:.0f}; "
    f"{inner['listed']:.0f} in-sweep)",
    ">= 3000/s",
    rate["listed"] >= 3000,
)
print(
    f"{'  the same without columns:':<40} {rate['whole']:.0f} runs/s whole process ({inner['whole']:.0f} in-sweep): "
    f"{rate['listed'] / rate['whole']:.2f}x"
)
# The CPU a process takes moves little with the load; half of it is the wall time 2 idle cores
# would take at best (the start-up runs on one of them, so a little more in truth).
print(
    f"{'  CPU of the process, with / without:':<40} {cpu['listed']:.3f} s / {cpu['whole']:.3f} s: "
    f"on 2 idle cores at most {400 / cpu['listed']:.0f} / {400 / cpu['whole']:.0f} runs/s"
)

show(
    f"  the same by dop853 at {DOP853_TOLERANCE}",
    f"{rate['dop853']:.0f} runs/s whole process ({spread['dop853'][0]:.0f}-{spread['dop853'][1]:.0f}; "
    f"{inner['dop853']:.0f} in-sweep), CPU {cpu['dop853']:.3f} s",
    ">= 3000/s",
    rate["dop853"] >= 3000,
)

sweep(converged, os.path.join(work, "converged.csv"))
ours = column(os.path.join(work, "listed.csv"), "first_reversal_s")
full = column(os.path.join(work, "whole.csv"), "first_reversal_s")
ref = column(os.path.join(work, "converged.csv"), "first_reversal_s")


def against_converged(what, values):
    missing = sum((a == "") != (b == "") for a, b in zip(values, ref))
    worst = max(abs(float(a) - float(b)) for a, b in zip(values, ref) if a and b)
    show(
        what,
        f"largest difference {worst:.1e} s, {missing} rows disagree on none",
        "<= 1e-4 s",
        worst <= 1e-4 and missing == 0,
    )


against_converged("  its first reversals against 1e-11", ours)
against_converged(f"  dop853's against 1e-11", column(os.path.join(work, "dop853.csv"), "first_reversal_s"))
print(
    f"{'  equal to the whole runs to the bit:':<40} {ours == full} ({sum(1 for a in ours if a)} of 200 reverse)"
)

if "--no-map" not in sys.argv:
    regime = write(
        "regime.yaml",
        f"base: {scene}\nvary:\n  initial.spin: {{from: -10, to: 10, count: 50}}\n"
        "  initial.tilt[0]: {from: 0.1, to: 5, count: 40}\n"
        "  contact.air_drag: {from: 0, to: 5.9e-5, count: 50}\ncolumns: [first_reversal_s]\n",
    )
    out = os.path.join(work, "regime.csv")
    seconds, inside, used = sweep(regime, out)
    cells = column(out, "first_reversal_s")
    show(
        "regime map, 100,000 runs (spin x tilt x drag)",
        f"{seconds:.1f} s whole process ({inside:.1f} s in-sweep), {sum(1 for c in cells if c)} reverse",
        "<= 40 s",
        seconds <= 40,
    )
    print(f"{'  its CPU:':<40} {used:.1f} s: on 2 idle cores at least {used / 2:.1f} s")
print(f"load average after: {os.getloadavg()[0]:.1f}")
