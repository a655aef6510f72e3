#!/usr/bin/python3
"""Checks that the figures the pages quote from the program's output are what it prints today.

Each claim below is a phrase as it stands in a page (white space collapsed), with every number
it quotes from a run marked «so», and for each mark the value that the program gives now. A
claim fails when its phrase, with any numbers at the marks, is no longer in the page (edit the
claim with the page) or when a number the page has there differs from the program's value at
the digits quoted: «2.37» is the value rounded to
two decimals, «+3.08» also shows its sign, «−0.3243» writes minus as the page does, «6e-9» has
one significant digit, a number of more than 12 digits is Python's repr, and «ccw» is a word the program prints. The runs are the shipped scenes
and sweeps (about 10 s in all). Timings and figures dated to a commit measured by bench/ are not
claims: they belong to their commit (docs/speed.md).

Usage (from the repository's folder):
    /usr/bin/python3 docs/check_figures.py build/app/rattleback
"""
import csv
import functools
import json
import math
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


class Runs:
    """The program's output for the shipped scenes and sweeps, each run once."""

    def __init__(self, binary, folder):
        self.binary, self.folder = binary, Path(folder)
        self._tables = []

    def _run(self, *args):
        return subprocess.run(
            [self.binary, *args], cwd=ROOT, capture_output=True, text=True, check=True
        ).stdout

    @staticmethod
    def _options(spin, sets):
        """--spin and --set's KEY=VALUE, as a page's commands give them."""
        extra = ["--spin", str(spin)] if spin is not None else []
        for key_value in sets:
            extra += ["--set", key_value]
        return extra

    @functools.lru_cache(maxsize=None)
    def analyze(self, scene, spin=None, sets=()):
        """`rattleback analyze --json`."""
        return json.loads(self._run("analyze", "--json", f"scenes/{scene}.yaml", *self._options(spin, sets)))

    @functools.lru_cache(maxsize=None)
    def _simulate(self, scene, spin=None, sets=()):
        table = self.folder / f"{scene}-{len(self._tables)}.csv"
        self._tables.append(table)
        options = self._options(spin, sets)
        self._run("simulate", "-q", f"scenes/{scene}.yaml", *options, "-o", str(table))
        sidecar = json.loads(Path(str(table) + ".json").read_text())
        with open(table, newline="") as f:
            rows = list(csv.DictReader(f))
        return sidecar["result"], rows

    def simulate(self, scene, spin=None, sets=()):
        """The summary of `rattleback simulate` (its sidecar's "result")."""
        return self._simulate(scene, spin, sets)[0]

    def column(self, scene, name):
        return [float(row[name]) for row in self._simulate(scene)[1]]

    @functools.lru_cache(maxsize=None)
    def sweep(self, name):
        table = self.folder / f"sweep-{name}.csv"
        self._run("sweep", "-q", f"sweeps/{name}.yaml", "-o", str(table))
        with open(table, newline="") as f:
            return list(csv.DictReader(f))

    @functools.lru_cache(maxsize=None)
    def example(self, name):
        """The lines examples/<name>.py prints, with the Python package beside the program (a
        build tree's build/python; an installed one is on the path already)."""
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join(
            p for p in (str(Path(self.binary).parents[1] / "python"), env.get("PYTHONPATH")) if p
        )
        return subprocess.run(
            [sys.executable, f"examples/{name}.py"],
            cwd=ROOT,
            capture_output=True,
            text=True,
            check=True,
            env=env,
        ).stdout.splitlines()

    def row(self, name, **axes):
        """The sweep's row whose axes have these values (keys with dots as __: contact__air_drag)."""
        for row in self.sweep(name):
            if all(
                float(row[key.replace("__", ".").replace("_0", "[0]")]) == value
                for key, value in axes.items()
            ):
                return row
        raise KeyError(f"{name}: no row {axes}")


def energy_kept(r, scene):
    """The largest relative change of the total energy from its start, over the telemetry."""
    energy = r.column(scene, "energy")
    return max(abs(e - energy[0]) for e in energy) / abs(energy[0])


def reversal(result):
    """A first reversal as a page quotes it: its time, or "none"."""
    first = result["first_reversal_s"]
    return "none" if first is None else first


# docs/getting-started.md "A body that reverses both ways": sweeps/both-ways-search.yaml's rows
# by body (the dents' place and scale), each with its two spins.
def searched(r):
    bodies = {}
    for row in r.sweep("both-ways-search"):
        body = tuple(float(row[k]) for k in ("body.dents.at[0]", "body.dents.at[1]", "body.dents.scale"))
        bodies.setdefault(body, []).append(row)
    return bodies


def exporting(r):
    return {b: rows for b, rows in searched(r).items() if all(x["exports"] == "yes" for x in rows)}


def both_ways(r):
    return {b: rows for b, rows in exporting(r).items() if all(x["first_reversal_s"] for x in rows)}


def reversing_both(r):
    """Every body, exporting or not, with a first reversal spun each way."""
    return {b: rows for b, rows in searched(r).items() if all(x["first_reversal_s"] for x in rows)}


def first_both_ways(r):
    """The printable both-ways body of the lowest row, and its rows."""
    return min((int(rows[0]["row"]), body, rows) for body, rows in both_ways(r).items())


# P8.4's runs: 30 s.
LONG = ("simulation.duration=30",)


def soonest_clockwise(r):
    """The earliest first reversal spun clockwise among the both-ways bodies, and that body."""
    return min(
        (float(x["first_reversal_s"]), body)
        for body, rows in both_ways(r).items()
        for x in rows
        if float(x["initial.spin"]) < 0
    )


def shipped_is_found(r):
    """The shipped both-ways body's dents (scenes/both-ways.yaml) among the search's both-ways ones."""
    dents = re.search(
        r"dents: \{scale: ([\d.]+), at: \[([-\d.]+), ([-\d.]+)\]",
        (ROOT / "scenes/both-ways.yaml").read_text(),
    )
    scale, x, y = (float(v) for v in dents.groups())
    return (x, y, scale) in both_ways(r)


# docs/getting-started.md "Make your own rattleback": the shipped body, mirrored, and deeper,
# as the page's commands set them.
MIRRORED = ("body.dents.at=[-0.73, 4.50]",)
DEEPER = MIRRORED + ("body.dents.scale=0.6",)
# ... and "A warning that rolling needed more friction": the same body let slip.
LETS_IT_SLIP = ("contact.model=auto", "contact.stiffness=2.0e4")


def status_count(r, name, status):
    return sum(1 for row in r.sweep(name) if row["status"].split(":")[0] == status)


def principal_difference_percent(r, scene, of):
    """The largest relative difference of two bodies' principal moments, %."""
    a, b = r.analyze(scene)["principal_moments"], r.analyze(of)["principal_moments"]
    return 100 * max(abs(x / y - 1) for x, y in zip(a, b))


def example_reversal(r, line):
    """The time (s) in line `line` of examples/weighted_body.py's output."""
    return float(re.search(r"reverses at ([0-9.]+) s", r.example("weighted_body")[line]).group(1))


# (page, phrase with «numbers», one function of the runs a number)
CLAIMS = [
    (
        "docs/python.md",
        '>>> a["predicted_first_reversal"]["time_s"], a["predicted_first_reversal"]["range"] '
        "(«2.260373780590822», '«beyond»')",
        [
            lambda r: r.analyze("rattleback")["predicted_first_reversal"]["time_s"],
            lambda r: r.analyze("rattleback")["predicted_first_reversal"]["range"],
        ],
    ),
    (
        "docs/your-own-body.md",
        "The fit's RMS distance is «0.0023» % of the body's length here",
        [lambda r: 100 * r.analyze("printed")["fitted_bottom"]["rms_fraction"]],
    ),
    (
        "docs/your-own-body.md",
        "The printed body prefers «ccw» (counter-clockwise seen from above); spun clockwise at 5 "
        "rad/s it is forecast to reverse at «2.25» s and, run, reverses at «2.3175» s",
        [
            lambda r: r.analyze("printed")["preferred"],
            lambda r: r.analyze("printed")["predicted_first_reversal"]["time_s"],
            lambda r: r.simulate("printed")["first_reversal_s"],
        ],
    ),
    (
        "docs/your-own-body.md",
        "as printed spun -5 rad/s: preferred ccw, reverses at «2.32» s as printed spun +5 rad/s: "
        "preferred ccw, no reversal with the nut spun -5 rad/s: preferred ccw, reverses at «1.86» s",
        [lambda r: example_reversal(r, 0), lambda r: example_reversal(r, 2)],
    ),
    (
        "docs/scenes.md",
        "read back as a mesh body (`units.length: 0.001`); its inertia within «0.33» % of the "
        "analytic body's",
        [lambda r: principal_difference_percent(r, "printed", "rattleback")],
    ),
    (
        "docs/scenes.md",
        "spun clockwise at 5 rad/s it reverses at «2.3175» s (the analytic body at «2.3665» s",
        [
            lambda r: r.simulate("printed")["first_reversal_s"],
            lambda r: r.simulate("rattleback")["first_reversal_s"],
        ],
    ),
    (
        "README.md",
        "clockwise at 5 rad/s: at «2.37» s it has stopped rocking and spins back, to «+3.08» rad/s",
        [
            lambda r: r.simulate("rattleback")["first_reversal_s"],
            lambda r: r.simulate("rattleback")["final_spin"],
        ],
    ),
    (
        "README.md",
        "# preferred: «ccw»; roll «3.474» Hz, pitch «6.97» Hz",
        [
            lambda r: r.analyze("rattleback")["preferred"],
            lambda r: r.analyze("rattleback")["frequencies_hz"]["roll"],
            lambda r: r.analyze("rattleback")["frequencies_hz"]["pitch"],
        ],
    ),
    (
        "README.md",
        "Spun clockwise at 5 rad/s, as here, it reverses at «2.3665» s; mirror the dents "
        "(`at: [-0.73, 4.50]`) and it prefers «clockwise» instead",
        [
            lambda r: r.simulate("rattleback")["first_reversal_s"],
            lambda r: {"cw": "clockwise", "ccw": "anticlockwise"}.get(
                r.analyze("rattleback", sets=MIRRORED)["preferred"], "neither"
            ),
        ],
    ),
    ("README.md", "# first reversal «2.3665» s", [lambda r: r.simulate("rattleback")["first_reversal_s"]]),
    (
        "docs/index.md",
        "its rocking grows, passes zero at «2.37» s, and it spins back",
        [lambda r: r.simulate("rattleback")["first_reversal_s"]],
    ),
    (
        "docs/commands.md",
        "first reversal «2.3665» s (spin -5 rad/s changed sign)",
        [lambda r: r.simulate("rattleback")["first_reversal_s"]],
    ),
    (
        "docs/commands.md",
        "energy «0.00683868» J -> «0.00605795» J («-11.42» %)",
        [
            lambda r: r.simulate("rattleback")["energy_j"]["initial"],
            lambda r: r.simulate("rattleback")["energy_j"]["final"],
            lambda r: 100
            * (
                r.simulate("rattleback")["energy_j"]["final"]
                / r.simulate("rattleback")["energy_j"]["initial"]
                - 1
            ),
        ],
    ),
    (
        "docs/commands.md",
        "final spin «+3.0767» rad/s, tilt «0.76» deg",
        [
            lambda r: r.simulate("rattleback")["final_spin"],
            lambda r: r.simulate("rattleback")["final_tilt_deg"],
        ],
    ),
    (
        "docs/commands.md",
        "Richardson, order 4 reversal 1 at «2.807328» s: error about",
        [lambda r: r.simulate("kane-levinson")["first_reversal_s"]],
    ),
    (
        "docs/commands.md",
        "difference from the tighter run reversal 1 at «2.366476» s: error about",
        [lambda r: r.simulate("rattleback")["first_reversal_s"]],
    ),
    (
        "docs/commands.md",
        "roll «3.474» Hz, pitch «6.97» Hz at rest; spun −5 rad/s the pitch mode grows at «1.5655» /s "
        "(it reverses), spun +5 only the roll mode grows, at «0.1638» /s; preferred: «ccw».",
        [
            lambda r: r.analyze("rattleback")["frequencies_hz"]["roll"],
            lambda r: r.analyze("rattleback")["frequencies_hz"]["pitch"],
            lambda r: r.analyze("rattleback", -5)["growth_rates"]["pitch"],
            lambda r: r.analyze("rattleback", 5)["growth_rates"]["roll"],
            lambda r: r.analyze("rattleback")["preferred"],
        ],
    ),
    (
        "docs/physics.md",
        "roll «3.474» Hz and pitch «6.97» Hz at rest; spun −5 rad/s the pitch mode grows at «1.5655» "
        "/s (it reverses); spun +5 rad/s only the roll mode grows, at «0.1638» /s; first order: "
        "roll «+0.08051», pitch «−0.3243» per rad; preferred: «ccw».",
        [
            lambda r: r.analyze("rattleback")["frequencies_hz"]["roll"],
            lambda r: r.analyze("rattleback")["frequencies_hz"]["pitch"],
            lambda r: r.analyze("rattleback", -5)["growth_rates"]["pitch"],
            lambda r: r.analyze("rattleback", 5)["growth_rates"]["roll"],
            lambda r: r.analyze("rattleback")["first_order_growth_per_spin"]["roll"],
            lambda r: r.analyze("rattleback")["first_order_growth_per_spin"]["pitch"],
            lambda r: r.analyze("rattleback")["preferred"],
        ],
    ),
    (
        "docs/physics.md",
        "The default scene lies «beyond» the range (n²ρ/g = «0.85»): forecast at «2.12» s, it "
        "reverses at «2.37» s. Kane & Levinson's (n²ρ/g = «5.1») lies «outside» it: it takes «2.81» s",
        [
            lambda r: r.analyze("rattleback")["predicted_first_reversal"]["range"],
            lambda r: r.analyze("rattleback")["predicted_first_reversal"]["spin_parameter"],
            lambda r: r.analyze("rattleback")["predicted_first_reversal"]["time_s"],
            lambda r: r.simulate("rattleback")["first_reversal_s"],
            lambda r: r.analyze("kane-levinson")["predicted_first_reversal"]["spin_parameter"],
            lambda r: r.analyze("kane-levinson")["predicted_first_reversal"]["range"],
            lambda r: r.simulate("kane-levinson")["first_reversal_s"],
        ],
    ),
    (
        "docs/physics.md",
        "| the default scene, −5 rad/s, tilt 0.5°, with drag («2.26» s against «2.366» s) | «0.85» | «0.006» | -«4.5» % |",
        [
            lambda r: r.analyze("rattleback")["predicted_first_reversal"]["time_s"],
            lambda r: r.simulate("rattleback")["first_reversal_s"],
            lambda r: r.analyze("rattleback")["predicted_first_reversal"]["spin_parameter"],
            lambda r: r.analyze("rattleback")["predicted_first_reversal"]["energy_ratio"],
            lambda r: 100
            * (
                1
                - r.analyze("rattleback")["predicted_first_reversal"]["time_s"]
                / r.simulate("rattleback")["first_reversal_s"]
            ),
        ],
    ),
    (
        "docs/physics.md",
        "lying at 62.5° («62.49»° today)",
        [lambda r: r.simulate("seed-flip-ccw")["final_tilt_deg"]],
    ),
    (
        "docs/python.md",
        "print(run.first_reversal, run.spin.max()) # «2.36647597263203» «3.7575770895596112»",
        [
            lambda r: r.simulate("rattleback")["first_reversal_s"],
            lambda r: max(r.column("rattleback", "spin")),
        ],
    ),
    (
        "docs/commands.md",
        "dopri5, tolerance 1e-08, «2000» steps («40» rejected), 8 s simulated",
        [lambda r: r.simulate("rattleback")["steps"], lambda r: r.simulate("rattleback")["rejected_steps"]],
    ),
    (
        "docs/python.md",
        "print(pool.map(first_reversal, scenes)) # [«2.36647597263203», «2.652851022573632», "
        "«3.1372975075378924»]",
        [
            lambda r, spin=spin: float(
                r.row("spin-drag", initial__spin=spin, contact__air_drag=5.9e-6)["first_reversal_s"]
            )
            for spin in (-5, -4, -3)
        ],
    ),
    (
        "docs/python.md",
        "('«ccw»', {'pitch': «6.970009429469335», 'roll': «3.4738980805453132»})",
        [
            lambda r: r.analyze("rattleback")["preferred"],
            lambda r: r.analyze("rattleback")["frequencies_hz"]["pitch"],
            lambda r: r.analyze("rattleback")["frequencies_hz"]["roll"],
        ],
    ),
    (
        "docs/getting-started.md",
        "| shipped: `at: [0.73, 4.50]`, `scale: 0.45` | «+2.22»° | «ccw» | first reversal «2.37» s | "
        "«none» in 8 s |",
        [
            lambda r: r.analyze("rattleback")["misalignment_deg"],
            lambda r: r.analyze("rattleback")["preferred"],
            lambda r: reversal(r.simulate("rattleback")),
            lambda r: reversal(r.simulate("rattleback", 5)),
        ],
    ),
    (
        "docs/getting-started.md",
        "| mirrored: `at: [-0.73, 4.50]` | «−2.22»° | «cw» | «none» in 8 s | first reversal «2.32» s |",
        [
            lambda r: r.analyze("rattleback", sets=MIRRORED)["misalignment_deg"],
            lambda r: r.analyze("rattleback", sets=MIRRORED)["preferred"],
            lambda r: reversal(r.simulate("rattleback", -5, MIRRORED)),
            lambda r: reversal(r.simulate("rattleback", 5, MIRRORED)),
        ],
    ),
    (
        "docs/getting-started.md",
        "| mirrored and deeper: `scale: 0.6` | «−6.35»° | «cw» | first reversal «5.77» s (forecast «6.21» s) "
        "| first reversal «0.83» s |",
        [
            lambda r: r.analyze("rattleback", sets=DEEPER)["misalignment_deg"],
            lambda r: r.analyze("rattleback", sets=DEEPER)["preferred"],
            lambda r: reversal(r.simulate("rattleback", -5, DEEPER)),
            lambda r: r.analyze("rattleback", -5, DEEPER)["predicted_first_reversal"]["time_s"],
            lambda r: reversal(r.simulate("rattleback", 5, DEEPER)),
        ],
    ),
    (
        "docs/getting-started.md",
        "Its misalignment is «−2.68»°, it prefers «cw», and spun 8 rad/s it reverses either way: "
        "clockwise, the way it prefers, at «5.35» s, and counter-clockwise at «1.51» s (spun 5 rad/s it "
        "reverses counter-clockwise only).",
        [
            lambda r: r.analyze("both-ways")["misalignment_deg"],
            lambda r: r.analyze("both-ways")["preferred"],
            lambda r: reversal(r.simulate("both-ways")),
            lambda r: reversal(r.simulate("both-ways", 8)),
        ],
    ),
    (
        "docs/getting-started.md",
        "both ways «22» of «36» bodies reverse both ways (a first reversal spun each way), «5» of them "
        "exporting a solid; the first that exports: body.dents.at[0] «-1.0», body.dents.at[1] «3.0», "
        "body.dents.scale «0.48» (rows «28», «29»)",
        [
            lambda r: len(reversing_both(r)),
            lambda r: len(searched(r)),
            lambda r: len(both_ways(r)),
            lambda r: first_both_ways(r)[1][0],
            lambda r: first_both_ways(r)[1][1],
            lambda r: first_both_ways(r)[1][2],
            lambda r: first_both_ways(r)[2][0]["row"],
            lambda r: first_both_ways(r)[2][1]["row"],
        ],
    ),
    (
        "docs/getting-started.md",
        "Of the «36» bodies «19» export, and «5» of those reverse both ways; the shipped one is among "
        "them, and the soonest clockwise, at «5.17» s, has its dents at [«−1.0», «3.0»] and scale «0.5».",
        [
            lambda r: len(searched(r)),
            lambda r: len(exporting(r)),
            # "the shipped one is among them" is checked with the count
            lambda r: len(both_ways(r)) if shipped_is_found(r) else "none with the shipped body",
            lambda r: soonest_clockwise(r)[0],
            lambda r: soonest_clockwise(r)[1][0],
            lambda r: soonest_clockwise(r)[1][1],
            lambda r: soonest_clockwise(r)[1][2],
        ],
    ),
    (
        "docs/getting-started.md",
        "Spun counter-clockwise it reverses twice, at «1.51» s and again at «5.29» s",
        [
            lambda r: r.simulate("both-ways", 8)["reversals_s"][0],
            lambda r: r.simulate("both-ways", 8)["reversals_s"][1],
        ],
    ),
    (
        "docs/getting-started.md",
        "(the both-ways body spun −10 rad/s: «4.04» s rolling, «4.19» s letting it slip)",
        [
            lambda r: reversal(r.simulate("both-ways", -10)),
            lambda r: reversal(r.simulate("both-ways", -10, LETS_IT_SLIP)),
        ],
    ),
    (
        "docs/physics.md",
        "The both-ways scene spun −8 rad/s counts «6.9» where «3.0» take its «0.71»° start to 14°: it reverses "
        "at «5.35» s; spun −6 rad/s, «3.9», and reverses at «9.15» s; spun −5 rad/s, «2.6», and does not "
        "reverse in 30 s; the default body spun +5 rad/s counts «0.7», and does not reverse in 30 s, though "
        "without drag it does at «8.53» s",
        [
            lambda r: r.analyze("both-ways", -8)["either_way_efolds"],
            lambda r: math.log(14 / math.hypot(0.5, 0.5)),
            lambda r: math.hypot(0.5, 0.5),
            lambda r: reversal(r.simulate("both-ways")),
            lambda r: r.analyze("both-ways", -6)["either_way_efolds"],
            lambda r: reversal(r.simulate("both-ways", -6, LONG)),
            lambda r: r.analyze("both-ways", -5)["either_way_efolds"]
            if reversal(r.simulate("both-ways", -5, LONG)) == "none"
            else "it reverses",
            lambda r: r.analyze("rattleback", 5)["either_way_efolds"]
            if reversal(r.simulate("rattleback", 5, LONG)) == "none"
            else "it reverses",
            lambda r: reversal(r.simulate("rattleback", 5, LONG + ("contact.air_drag=0",))),
        ],
    ),
    (
        "docs/scenes.md",
        "(scale 0.48; misalignment «−2.68»°, it prefers clockwise); spun 8 rad/s it reverses either way, "
        "clockwise (the way it prefers) at «5.3502» s and counter-clockwise at «1.5062» s",
        [
            lambda r: r.analyze("both-ways")["misalignment_deg"],
            lambda r: reversal(r.simulate("both-ways")),
            lambda r: reversal(r.simulate("both-ways", 8)),
        ],
    ),
    ("docs/scenes.md", "misalignment «+2.22»°", [lambda r: r.analyze("rattleback")["misalignment_deg"]]),
    (
        "docs/scenes.md",
        "stops at «2.3665» s and spins back to «+3.08» rad/s",
        [
            lambda r: r.simulate("rattleback")["first_reversal_s"],
            lambda r: r.simulate("rattleback")["final_spin"],
        ],
    ),
    (
        "docs/scenes.md",
        "spun +5 rad/s, reverses at «2.8073» s",
        [lambda r: r.simulate("kane-levinson")["first_reversal_s"]],
    ),
    (
        "docs/scenes.md",
        "four reversals («2.81», «17.40», «31.94», «46.54» s) with the energy kept to «6e-9»",
        [
            lambda r: r.simulate("kane-levinson-long")["reversals_s"][0],
            lambda r: r.simulate("kane-levinson-long")["reversals_s"][1],
            lambda r: r.simulate("kane-levinson-long")["reversals_s"][2],
            lambda r: r.simulate("kane-levinson-long")["reversals_s"][3],
            lambda r: energy_kept(r, "kane-levinson-long"),
        ],
    ),
    (
        "docs/scenes.md",
        "n(t) swinging between ±«5.36» rad/s",
        [lambda r: max(abs(n) for n in r.column("kane-levinson-long", "spin"))],
    ),
    (
        "docs/scenes.md",
        "it rolls onto its side and ends lying at «62.49»°",
        [lambda r: r.simulate("seed-flip-ccw")["final_tilt_deg"]],
    ),
    (
        "docs/scenes.md",
        "(«115» ok, «8» stopped;",
        [lambda r: status_count(r, "spin-drag", "ok"), lambda r: status_count(r, "spin-drag", "stopped")],
    ),
    (
        "docs/scenes.md",
        "without drag «2.10» s at −8 rad/s and «3.29» s at −2.5 rad/s",
        [
            lambda r: float(r.row("spin-drag", initial__spin=-8, contact__air_drag=0)["first_reversal_s"]),
            lambda r: float(r.row("spin-drag", initial__spin=-2.5, contact__air_drag=0)["first_reversal_s"]),
        ],
    ),
    (
        "docs/scenes.md",
        "(at −5 rad/s: «2.32», «2.37» and «4.16» s for the three drags)",
        [
            lambda r, d=d: float(
                r.row("spin-drag", initial__spin=-5, contact__air_drag=d)["first_reversal_s"]
            )
            for d in (0, 5.9e-6, 5.9e-5)
        ],
    ),
    (
        "docs/scenes.md",
        "at −8 rad/s the light drag gives «1.96» s",
        [lambda r: float(r.row("spin-drag", initial__spin=-8, contact__air_drag=5.9e-6)["first_reversal_s"])],
    ),
    (
        "docs/scenes.md",
        "−5 rad/s reverses at «4.16» s",
        [lambda r: float(r.row("spin-drag", initial__spin=-5, contact__air_drag=5.9e-5)["first_reversal_s"])],
    ),
    (
        "docs/scenes.md",
        "spins of 5.5 … 8 rad/s reverse after «7.80» … «5.56» s",
        [
            lambda r: float(r.row("spin-drag", initial__spin=5.5, contact__air_drag=0)["first_reversal_s"]),
            lambda r: float(r.row("spin-drag", initial__spin=8, contact__air_drag=0)["first_reversal_s"]),
        ],
    ),
    (
        "docs/scenes.md",
        "first-order growth rate «+0.0805»·n per second",
        [lambda r: r.analyze("rattleback")["first_order_growth_per_spin"]["roll"]],
    ),
    (
        "docs/scenes.md",
        "only +10 rad/s reverses, at «7.74» s (tilt up to «33.6»°)",
        [
            lambda r: float(
                r.row("spin-drag", initial__spin=10, contact__air_drag=5.9e-6)["first_reversal_s"]
            ),
            lambda r: float(r.row("spin-drag", initial__spin=10, contact__air_drag=5.9e-6)["max_tilt_deg"]),
        ],
    ),
    (
        "docs/scenes.md",
        "(«0.57» s at at[0] = 0.75, scale 0.7;",
        [lambda r: float(r.row("dents", body__dents__at_0=0.75, body__dents__scale=0.7)["first_reversal_s"])],
    ),
    (
        "docs/scenes.md",
        "also 0.5 at −1.25 and −1, late: «7.1» and «7.9» s)",
        [
            lambda r: float(
                r.row("dents", body__dents__at_0=-1.25, body__dents__scale=0.5)["first_reversal_s"]
            ),
            lambda r: float(r.row("dents", body__dents__at_0=-1, body__dents__scale=0.5)["first_reversal_s"]),
        ],
    ),
    ("docs/scenes.md", "(«78» ok, 2.2 s on 2 threads then", [lambda r: status_count(r, "dents", "ok")]),
]


# Scenes the pages show as a shipped scene's (page, the heading the ```yaml block follows, the
# scene file): the block must be that file's scene, key for key and value for value (comments and
# layout aside), so that the figures quoted beside it are its figures.
SCENES = [
    ("README.md", "## Scene files", "scenes/rattleback.yaml"),
    ("docs/your-own-body.md", "## A scene for the mesh", "scenes/printed.yaml"),
]


def numbers_as_floats(value):
    if isinstance(value, dict):
        return {k: numbers_as_floats(v) for k, v in value.items()}
    if isinstance(value, list):
        return [numbers_as_floats(v) for v in value]
    if isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    return value


def check_scenes():
    try:
        import yaml
    except ImportError:
        return ["PyYAML is missing (Debian: python3-yaml; scripts/setup.sh installs it)"]
    failures = []
    for page, heading, scene in SCENES:
        text = (ROOT / page).read_text()
        found = re.search(re.escape(heading) + r"\n.*?```yaml\n(.*?)```", text, re.S)
        if not found:
            failures.append(f"{page}: no ```yaml block after {heading!r}")
            continue
        shown_scene = numbers_as_floats(yaml.safe_load(found.group(1)))
        shipped = numbers_as_floats(yaml.safe_load((ROOT / scene).read_text()))
        if shown_scene != shipped:
            differ = sorted(
                key for key in set(shown_scene) | set(shipped) if shown_scene.get(key) != shipped.get(key)
            )
            failures.append(
                f"{page}: the scene after {heading!r} is not {scene}'s: they differ in {', '.join(differ)}"
            )
    return failures


def shown(value, quoted):
    """`value` written as `quoted` is: the same digits, sign style and notation."""
    if isinstance(value, str):
        return value
    if len(re.sub(r"[^0-9]", "", quoted.split("e")[0]).lstrip("0")) > 12:
        return repr(value)  # all the digits, as Python prints a float: its shortest round trip
    minus = "−" if "−" in quoted else "-"
    plain = quoted.replace("−", "-")
    if "e" in plain:
        digits = len(plain.split("e")[0].lstrip("+-").replace(".", "")) - 1
        mantissa, exponent = f"{abs(value):.{digits}e}".split("e")
        text = f"{mantissa}e{int(exponent)}"
    else:
        decimals = len(plain.split(".")[1]) if "." in plain else 0
        text = f"{abs(value):.{decimals}f}"
    if value < 0 and float(text.replace("e", "E")) != 0:
        return minus + text
    return ("+" if plain.startswith("+") else "") + text


def pattern(phrase):
    """A regular expression for the phrase with any number (or word) where it has «…»."""
    parts = re.split("«[^»]*»", " ".join(phrase.split()))
    return r"([+−-]?[0-9][0-9.]*(?:e[+−-]?[0-9]+)?|[a-z]+)".join(re.escape(p) for p in parts)


def check(runs):
    failures = []
    pages = {}
    for page, phrase, values in CLAIMS:
        if page not in pages:
            pages[page] = " ".join((ROOT / page).read_text().split())
        assert len(re.findall("«[^»]*»", phrase)) == len(values), phrase
        found = re.search(pattern(phrase), pages[page])
        if not found:
            text = " ".join(phrase.split())
            failures.append(f"{page}: the phrase is no longer there: {text!r} (edit the claim)")
            continue
        for number, value in zip(found.groups(), values):
            actual = shown(value(runs), number)
            if actual != number:
                failures.append(
                    f"{page}: {found.group(0)!r} quotes {number}; the program gives "
                    f"{actual} ({value(runs)!r})"
                )
    return failures


def main(argv):
    if len(argv) != 1:
        print(__doc__)
        return 2
    with tempfile.TemporaryDirectory() as folder:
        failures = check(Runs(str(Path(argv[0]).resolve()), folder)) + check_scenes()
    for failure in failures:
        print(failure)
    count = sum(len(values) for _, _, values in CLAIMS)
    print(
        f"{len(failures)} problems among {count} quoted figures and {len(SCENES)} quoted scenes"
        if failures
        else f"all {count} quoted figures are the program's output, and the {len(SCENES)} quoted "
        "scenes the shipped ones"
    )
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
