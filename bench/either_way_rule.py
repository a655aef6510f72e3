#!/usr/bin/env python3
"""How often analyze's `either way` rule (docs/physics.md P8.4) agrees with a run: 36 bodies
(the default body's dents at three places across, three along, four depths), each spun its
preferred way at 4, 6, 8 and 10 rad/s for 30 s, from tilts of 0.1, 0.5 and 2 degrees about each
axis; a run agrees where `grows_either_way` is whether it reversed. Prints the agreement per tilt
(the page quotes it); asserts nothing. About a minute on 2 cores.

Usage: bench/either_way_rule.py [BUILD_DIR]
"""
import itertools
import json
import os
import subprocess
import sys
import tempfile

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build"))
rb = os.path.join(build, "app", "rattleback")
scene = os.path.join(root, "scenes", "rattleback.yaml")
table = os.path.join(tempfile.mkdtemp(prefix="rattleback-either-way-"), "run.csv")


def run(*args):
    return subprocess.run([rb, *args], capture_output=True, text=True)


for tilt in (0.1, 0.5, 2.0):
    agree = total = 0
    misses = []
    for x, y, scale in itertools.product((-1.25, -1.0, -0.75), (3.0, 3.5, 4.0), (0.40, 0.44, 0.48, 0.52)):
        sets = ["--set", f"body.dents={{scale: {scale}, at: [{x}, {y}], inset: 0.1}}"]
        sets += ["--set", f"initial.tilt=[{tilt}, {tilt}]"]
        for speed in (4, 6, 8, 10):
            theory = json.loads(run("analyze", scene, *sets, "--spin", str(speed), "--json").stdout)
            if theory["preferred"] not in ("cw", "ccw"):
                continue
            spin = speed if theory["preferred"] == "ccw" else -speed
            ran = run("simulate", scene, *sets, "--spin", str(spin), "--duration", "30", "-q", "-o", table)
            reversed_ = (
                ran.returncode == 0
                and json.load(open(table + ".json"))["result"]["first_reversal_s"] is not None
            )
            total += 1
            if theory["grows_either_way"] == reversed_:
                agree += 1
            else:
                misses.append(f"({x}, {y}) {scale} at {spin}: counts {theory['either_way_efolds']}")
    print(f"tilt {tilt}° about each axis: the rule agrees with {agree} of {total} runs", flush=True)
    for miss in misses:
        print("   ", miss)
