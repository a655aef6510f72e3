#!/usr/bin/env python3
"""The speed targets (docs/speed.md), each beside its figure, measured side by side in one run on this machine.

  start-up        `simulate` of the default scene for 0.01 s against `rattleback --version`
                  (whole processes, alternating, median)                        target <= 2x
  shards          two shard processes at once (as GNU parallel runs them) + `sweep merge`,
                  against the same sweep in one process with -j2 (wall)          target <= 1.1x
  sweep           rows a second of the shipped sweeps with the shipped scene (whole process,
                  -j2), and every row's first reversal against the same sweep at tolerance
                  1e-11                                            targets >= 1000/s, <= 1e-4 s
  Kane & Levinson 20 s at tolerance 5e-7: the run's own time (in-process, median) and its
                  first reversal against dopri5 at 1e-12, and the same error at the tolerances
                  either side (3.5e-7, 7e-7: whether 5e-7's is luck)     targets <= 5 ms, 1e-5 s
  output          a 10 s run of the default scene at 10 kHz from Python: the share of
                  to_csv (formatting and writing a new file) in simulate + to_csv  target < 25 %
  --check         the check's tighter run against the run (its sidecar's cost_ratio)
                                                                                target <= 2.5x
  first run       (with --first-run) a fresh clone's `bash scripts/run.sh`, wall  target < 120 s

Usage: bench/targets.py [BUILD_DIR] [--first-run]. Prints figures; asserts nothing.
"""
import csv
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
args = [a for a in sys.argv[1:] if not a.startswith("--")]
build = os.path.abspath(args[0] if args else os.path.join(root, "build"))
rb = os.path.join(build, "app", "rattleback")
scenes = os.path.join(root, "scenes")
work = tempfile.mkdtemp(prefix="rattleback-targets-")
rows = []


def wall(argv, **kw):
    start = time.perf_counter()
    subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, **kw)
    return time.perf_counter() - start


def show(what, figure, target, met):
    rows.append((what, figure, target, "met" if met else "NOT met"))
    print(f"{what:<34} {figure:<46} {target:<14} {'met' if met else 'NOT met'}", flush=True)


def commit():
    return subprocess.run(
        ["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True
    ).stdout.strip()


print(f"rattleback targets, commit {commit()}, {os.cpu_count()} cores, {time.strftime('%Y-%m-%d')}")
print(f"{'what':<34} {'figure':<46} {'target':<14} verdict")

# 1. Start-up.
version, short = [], []
csv_out = os.path.join(work, "short.csv")
for _ in range(30):
    version.append(wall([rb, "--version"]))
    short.append(
        wall(
            [
                rb,
                "simulate",
                os.path.join(scenes, "rattleback.yaml"),
                "--duration",
                "0.01",
                "-q",
                "-o",
                csv_out,
            ]
        )
    )
v, s = statistics.median(version), statistics.median(short)
show(
    "start-up: simulate 0.01 s",
    f"{s * 1e3:.1f} ms against --version {v * 1e3:.1f} ms: {s / v:.2f}x",
    "<= 2x",
    s / v <= 2,
)

# 2. Shards + merge against one process.
sweep = os.path.join(root, "sweeps", "spin-drag.yaml")
inproc, sharded = [], []
for _ in range(5):
    inproc.append(wall([rb, "sweep", sweep, "-j2", "-q", "-o", os.path.join(work, "one.csv")]))
    start = time.perf_counter()
    shards = [
        subprocess.Popen(
            [
                rb,
                "sweep",
                sweep,
                "-j1",
                "-q",
                "--shard",
                f"{i}/2",
                "-o",
                os.path.join(work, f"s.shard-{i}-of-2.csv"),
            ],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        for i in range(2)
    ]
    for p in shards:
        p.wait()
    subprocess.run(
        [rb, "sweep", "merge", os.path.join(work, "merged.csv")]
        + [os.path.join(work, f"s.shard-{i}-of-2.csv") for i in range(2)]
        + ["-q"],
        check=True,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    sharded.append(time.perf_counter() - start)
a, b = statistics.median(inproc), statistics.median(sharded)
show(
    "shards + merge (spin-drag, 2 cores)",
    f"{b:.3f} s against one process {a:.3f} s: {b / a:.2f}x",
    "<= 1.1x",
    b / a <= 1.1,
)


# 3. Sweeps with the shipped scene, and their accuracy.
def variant(tolerance):
    """The default scene at another tolerance, beside a copy of each sweep that uses it."""
    text = open(os.path.join(scenes, "rattleback.yaml")).read()
    lines = [line for line in text.splitlines() if not line.strip().startswith("tolerance:")]
    out = "\n".join(lines).replace("simulation:\n", f"simulation:\n  tolerance: {tolerance}\n", 1)
    path = os.path.join(work, f"scene-{tolerance}.yaml")
    open(path, "w").write(out + "\n")
    return path


def sweep_copy(name, scene):
    text = open(os.path.join(root, "sweeps", name + ".yaml")).read()
    lines = [f"base: {scene}" if line.startswith("base:") else line for line in text.splitlines()]
    path = os.path.join(work, f"{name}-{os.path.basename(scene)}")
    open(path, "w").write("\n".join(lines) + "\n")
    return path


def table(path):
    return list(csv.DictReader(open(path)))


reference = variant("1.0e-11")
for name in ("spin-drag", "dents"):
    out = os.path.join(work, f"{name}.csv")
    times = [
        wall([rb, "sweep", os.path.join(root, "sweeps", name + ".yaml"), "-j2", "-q", "-o", out])
        for _ in range(3)
    ]
    ours = table(out)
    ref_out = os.path.join(work, f"{name}-ref.csv")
    subprocess.run([rb, "sweep", sweep_copy(name, reference), "-j2", "-q", "-o", ref_out], check=True)
    worst, mismatched = 0.0, 0
    for x, y in zip(ours, table(ref_out)):
        p, q = x["first_reversal_s"], y["first_reversal_s"]
        if (p == "") != (q == ""):
            mismatched += 1
        elif p:
            worst = max(worst, abs(float(p) - float(q)))
    rate = len(ours) / statistics.median(times)
    show(f"sweep {name} ({len(ours)} rows)", f"{rate:.0f} rows/s whole process", ">= 1000/s", rate >= 1000)
    show(
        f"  its accuracy against 1e-11",
        f"worst {worst:.1e} s, {mismatched} rows disagree",
        "<= 1e-4 s",
        worst <= 1e-4 and mismatched == 0,
    )


# 4. Kane & Levinson, 20 s.
def sidecar_of(argv, path):
    subprocess.run(argv + ["-q", "-o", path], check=True, stdout=subprocess.DEVNULL)
    return json.load(open(path + ".json"))


kl = os.path.join(scenes, "kane-levinson.yaml")
ref = sidecar_of(
    [rb, "simulate", kl, "--duration", "20", "--tolerance", "1e-12", "--rate", "10"],
    os.path.join(work, "kl-ref.csv"),
)["result"]
runs = [
    sidecar_of(
        [rb, "simulate", kl, "--duration", "20", "--tolerance", "5e-7", "--rate", "10"],
        os.path.join(work, "kl.csv"),
    )["result"]
    for _ in range(7)
]
cost = statistics.median(r["wall_s"] for r in runs)
error = abs(runs[0]["first_reversal_s"] - ref["first_reversal_s"])
show(
    "Kane & Levinson 20 s, tolerance 5e-7",
    f"{cost * 1e3:.1f} ms, {runs[0]['steps']} steps, {runs[0]['rejected_steps']} rejected",
    "<= 5 ms",
    cost <= 5e-3,
)
show("  its first reversal against 1e-12", f"{error:.1e} s", "<= 1e-5 s", error <= 1e-5)
# One tolerance's error can be a lucky cancellation: the same at its neighbours.
near = {
    tol: abs(
        sidecar_of(
            [rb, "simulate", kl, "--duration", "20", "--tolerance", tol, "--rate", "10"],
            os.path.join(work, "kl-near.csv"),
        )["result"]["first_reversal_s"]
        - ref["first_reversal_s"]
    )
    for tol in ("3.5e-7", "7e-7")
}
show(
    "  the same at 3.5e-7 and 7e-7",
    ", ".join(f"{e:.1e} s" for e in near.values()),
    "<= 1e-5 s",
    max(near.values()) <= 1e-5,
)

# 5. Output: the share of writing in a 10 s run at 10 kHz.
env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
code = f"""
import os, time, rattleback as rb
sims, writes, overs = [], [], []
path = {os.path.join(work, 'fast.csv')!r}
for _ in range(5):
    t0 = time.perf_counter(); run = rb.simulate({os.path.join(scenes, 'rattleback.yaml')!r}, duration=10, rate=10000)
    t1 = time.perf_counter()
    if os.path.exists(path): os.remove(path)
    t1 = time.perf_counter(); run.to_csv(path); t2 = time.perf_counter()
    run.to_csv(path); t3 = time.perf_counter()
    sims.append(t1 - t0); writes.append(t2 - t1); overs.append(t3 - t2)
sims.sort(); writes.sort(); overs.sort()
print(sims[2], writes[2], overs[2])
"""
out = subprocess.run(["/usr/bin/python3", "-c", code], env=env, capture_output=True, text=True, check=True)
sim_s, write_s, over_s = map(float, out.stdout.split())
share = write_s / (sim_s + write_s)
size = os.path.getsize(os.path.join(work, "fast.csv")) / 1e6
show(
    "output: 10 s at 10 kHz (100,001 rows)",
    f"to_csv {write_s * 1e3:.0f} ms of {(sim_s + write_s) * 1e3:.0f} ms: {share:.0%} ({size:.0f} MB)",
    "< 25 %",
    share < 0.25,
)
# The same over the file just written: ext4 allocates the new file's blocks when it is renamed
# over an old one (auto_da_alloc), so that a crash leaves the old file or the new, not an empty.
print(f"{'  (over an existing file)':<34} to_csv {over_s * 1e3:.0f} ms: " f"{over_s / (sim_s + over_s):.0%}")
# The same in C++, where the run alone is cheaper than Python's simulate (which also builds
# its arrays): the run alone against the run writing as `simulate` does (bench/output_share.cpp).
output_bench = os.path.join(build, "bench", "rattleback_output_bench")
if os.path.exists(output_bench):
    text = subprocess.run([output_bench, "11", work], capture_output=True, text=True, check=True).stdout
    alone = float(re.search(r"the run alone\s+([\d.]+) ms", text).group(1))
    going = float(re.search(r"writing as it goes \(simulate\)\s+([\d.]+) ms", text).group(1))
    show(
        "  the same as simulate writes it",
        f"run {alone:.0f} ms, writing as it goes " f"{going:.0f} ms: {(going - alone) / going:.0%}",
        "< 25 %",
        (going - alone) / going < 0.25,
    )
# The command line formats while the run goes on: its whole process at 10 kHz against 10 Hz.
scene = os.path.join(scenes, "rattleback.yaml")
fast = [
    wall(
        [
            rb,
            "simulate",
            scene,
            "--duration",
            "10",
            "--rate",
            "10000",
            "-q",
            "-o",
            os.path.join(work, "cli-fast.csv"),
        ]
    )
    for _ in range(5)
]
slow = [
    wall(
        [
            rb,
            "simulate",
            scene,
            "--duration",
            "10",
            "--rate",
            "10",
            "-q",
            "-o",
            os.path.join(work, "cli-slow.csv"),
        ]
    )
    for _ in range(5)
]
print(
    f"{'  (simulate --rate 10000, whole)':<34} {statistics.median(fast) * 1e3:.0f} ms against "
    f"--rate 10 {statistics.median(slow) * 1e3:.0f} ms"
)

# 6. --check's cost.
for name in ("rattleback", "kane-levinson"):
    ratios = [
        sidecar_of(
            [rb, "simulate", os.path.join(scenes, name + ".yaml"), "--check"], os.path.join(work, "check.csv")
        )["check"]["cost_ratio"]
        for _ in range(5)
    ]
    ratio = statistics.median(ratios)
    show(f"--check on {name}", f"the check costs {ratio:.2f}x the run", "<= 2.5x", ratio <= 2.5)

# 7. The main job's first run, from a fresh clone (minutes; only when asked).
if "--first-run" in sys.argv:
    clone = os.path.join(work, "clone")
    subprocess.run(["git", "clone", "-q", root, clone], check=True)
    seconds = wall(["bash", "scripts/run.sh"], cwd=clone)
    show(
        "first run of scripts/run.sh",
        f"{seconds:.0f} s (fresh clone, build included)",
        "< 120 s",
        seconds < 120,
    )
