#!/usr/bin/python3
"""Writes a dev page for the report's 3D player into DIR, for check_player.py:

  DIR/index.html     two players (the default scene and Kane & Levinson's) and one whose run
                     is missing, with the report's markup (data-forecast: the default scene's
                     forecast applies, Kane & Levinson's is outside the theory's range)
  DIR/single.html    the default scene's player alone (keys work without focusing it)
  DIR/missing.html   one player whose run is missing, and no run data at all
  DIR/framed.html    the default scene's player with video.frame 40 (cm), twice the body
  DIR/ID.player.js   each run's data (the C++ side's player_script, through the Python package)
  DIR/ID.csv         each run's telemetry, full rate (to check the player against)
  DIR/rattleback-player.js   the bundle (player/build.sh, or --bundle FILE copied)

Usage: make_page.py DIR [--bundle FILE] [--python BUILD_PYTHON_DIR]
The package is imported from --python, else $RATTLEBACK_PYTHON, else <repo>/build/python."""
import argparse
import html
import json
import pathlib
import shutil
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parents[3]
RUNS = [("rattleback", "scenes/rattleback.yaml"), ("kl", "scenes/kane-levinson.yaml")]
MISSING = "no-such-run"


def page(title, players, scripts):
    body = "\n".join(players)
    tags = "\n".join(f'<script src="{html.escape(s)}"></script>' for s in scripts)
    return f"""<!DOCTYPE html>
<html lang="en">
<head><meta charset="utf-8"><title>{html.escape(title)}</title></head>
<body>
<h1>{html.escape(title)}</h1>
{body}
{tags}
<script src="rattleback-player.js"></script>
</body>
</html>
"""


# Each run's forecast first reversal as the report passes it (data-forecast: analyze's
# "predicted_first_reversal", here its fields the player reads; the times analyze gave for these
# scenes): the default scene's applies (a line on the plot), Kane & Levinson's is outside the
# theory's range (n²ρ/g 5.1: no line, as the report gives no time).
FORECASTS = {
    "rattleback": {"applies": True, "range": "beyond", "time_s": 2.1155056027782315, "within_s": 8.0},
    "kl": {"applies": True, "range": "outside", "time_s": 1.0968102946398548, "within_s": 8.0},
}


def player_div(run_id, heading):
    forecast = FORECASTS.get(run_id)
    data = f' data-forecast="{html.escape(json.dumps(forecast))}"' if forecast else ""
    return (
        f"<h2>{html.escape(heading)}</h2>\n"
        f'<div class="rb-player" data-run="{html.escape(run_id)}"{data}></div>'
    )


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("dir")
    parser.add_argument("--bundle", help="a built rattleback-player.js to copy (default: build it)")
    parser.add_argument("--python", help="the build's python folder (holds the rattleback package)")
    args = parser.parse_args()
    import os

    python_dir = args.python or os.environ.get("RATTLEBACK_PYTHON") or str(REPO / "build" / "python")
    sys.path.insert(0, python_dir)
    import rattleback as rb

    out = pathlib.Path(args.dir).resolve()
    out.mkdir(parents=True, exist_ok=True)
    for run_id, scene_file in RUNS:
        scene = rb.Scene.from_file(str(REPO / scene_file))
        run = rb.simulate(scene)
        (out / f"{run_id}.player.js").write_text(rb._core.player_script(scene._loaded, run._run, run_id))
        run.to_csv(str(out / f"{run_id}.csv"))
    bundle = out / "rattleback-player.js"
    if args.bundle:
        shutil.copyfile(args.bundle, bundle)
    else:
        subprocess.run([str(REPO / "player" / "build.sh"), str(bundle)], check=True)
    (out / "index.html").write_text(
        page(
            "Rattleback player: dev page",
            [
                player_div("rattleback", "Default scene"),
                player_div("kl", "Kane & Levinson"),
                player_div(MISSING, "A run whose data is missing"),
            ],
            # (no script for the missing run: a script that fails to load is the browser's own
            # console error, not the player's)
            [f"{run_id}.player.js" for run_id, _ in RUNS],
        )
    )
    (out / "single.html").write_text(
        page(
            "Rattleback player: one run",
            [player_div("rattleback", "Default scene")],
            ["rattleback.player.js"],
        )
    )
    # The default scene framed for a body twice its length (video.frame 40 cm): drawn half as
    # long as on single.html (check_player's framed()).
    framed = rb.Scene.from_file(str(REPO / "scenes/rattleback.yaml")).with_values({"video.frame": 40})
    run = rb.simulate(framed, duration=1)
    (out / "framed.player.js").write_text(rb._core.player_script(framed._loaded, run._run, "framed"))
    (out / "framed.html").write_text(
        page(
            "Rattleback player: framed for 40 cm",
            [player_div("framed", "Framed for 40 cm")],
            ["framed.player.js"],
        )
    )
    (out / "missing.html").write_text(
        page("Rattleback player: no run data", [player_div(MISSING, "A run whose data is missing")], [])
    )
    print(f"wrote {out / 'index.html'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
