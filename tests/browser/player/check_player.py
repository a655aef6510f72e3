#!/usr/bin/python3
"""Checks the report's 3D player (player/) in headless Chromium with software WebGL.

Usage: check_player.py DIR [--screenshots OUT_DIR] [--size WxH]

DIR is a page made by make_page.py (or a report folder): DIR/index.html is opened from file://
and, for every .rb-player on it:
  - the page loads with no console errors (SEVERE), then none while it is used;
  - a player with run data is built (element.rbPlayer), one without shows a note instead;
  - the canvas shows red and blue pixels where the body is (the body's centre projects into
    their bounding box), and from above mostly red (the top is red);
  - the contact shadow darkens the floor under the body's centre and, a little, where its
    footprint ends (from above with the body hidden, against the shadow's strength set to 0);
  - the n(t) plot marks the forecast first reversal (data-forecast) with a violet line and its
    label when the forecast applies and falls within the run, and has no violet otherwise;
  - the read-outs show the time and the spin with its sense, at the slider's times ("not
    spinning" at a reversal);
  - the slider (its value set and an 'input' event dispatched) to times between samples gives
    the run's pose: the drawn quaternion equals the slerp of the data's two neighbouring samples
    (within 1e-6, up to sign) and the position their linear interpolation; the data embedded
    equals the run's CSV (DIR/ID.csv, when there) at those samples; the canvas changes;
  - play advances time, pause stops it, and the run stops at its end;
  - pause (the button; space after a click on the canvas) stops at what was shown when it
    was pressed: the time is the slider's then, and the slider, read-outs, plot cursor and
    picture stay as they were (six times, at different moments);
  - while the camera stays most frames are drawn in part (where the body and its shadow were and
    are), and the picture after playing is the one drawn whole (no pixel differs);
  - each view button moves the camera, to where the renderer puts it (render/camera.cpp): the
    oblique, above, front and side directions from the framing centre, above with +y to the
    right and +x down the screen, follow moving with the body across its long axis; a drag
    makes the view free;
  - in every view the picture drawn with the player's shortcuts (the floor without depth, the
    contact shadow alone over it) is the one drawn without them, but for at most 30 pixels more
    than 3 levels apart, and in follow both are taken;
  - the keys, with the player focused: space plays and pauses, the arrows step one sample;
  - a run with the body spun the other way ("other") has two buttons, each its spin and what its
    run did, that switch the run played (its poses, slider, ticks, R), and S switches back; a
    run without has none.
DIR/single.html (one player; the keys work unfocused) and DIR/missing.html (a player with no
run data at all: a note, no error) are checked too when there, and DIR/framed.html (the default
body framed for twice its length, video.frame: drawn half as long as on single.html).
Then the frame time at a 1280 × 720 canvas is measured and printed (frameMs() while playing,
and benchmark(): frames drawn and read back one after another), and with --screenshots the
first run's player is saved at its first reversal from the oblique and side views
(OUT_DIR/player-oblique.png, OUT_DIR/player-side.png).

Exit status 0 when every check passes, 1 when one fails (each failure printed), 77 when Selenium
or Chromium is not installed (CTest's "skipped")."""
import argparse
import csv
import json
import math
import pathlib
import re
import sys
import time

try:
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import Select
except ImportError:
    print("selenium is not installed (Debian: python3-selenium); skipped")
    sys.exit(77)

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import chromium  # noqa: E402  (tests/browser/chromium.py: one Chromium setup for the checks)

VIEWS = ["oblique", "above", "front", "side", "follow"]
ELEVATION = math.radians(10)

# Pixel statistics of a player's canvas, read back through a 2D canvas: red (the top) and blue
# (the bottom) pixels, their bounding box, and a snapshot to count changed pixels against.
PIXELS_JS = """
window.__rbPixels = function (element, snapshotName) {
  const source = element.querySelector('.rbp-stage canvas');
  const c = document.createElement('canvas');
  c.width = source.width; c.height = source.height;
  const g = c.getContext('2d');
  g.drawImage(source, 0, 0);
  const d = g.getImageData(0, 0, c.width, c.height).data;
  let red = 0, blue = 0, x0 = 1e9, y0 = 1e9, x1 = -1, y1 = -1, changed = 0, nonBackground = 0;
  window.__rbSnaps = window.__rbSnaps || {};
  const before = snapshotName ? window.__rbSnaps[snapshotName] : null;
  for (let i = 0, p = 0; i < d.length; i += 4, p++) {
    const r = d[i], gr = d[i + 1], b = d[i + 2];
    const isRed = r > 60 && r > 2 * gr && r > 2 * b;
    const isBlue = b > 60 && b > 1.6 * gr && b > 2 * r;
    if (isRed) red++;
    if (isBlue) blue++;
    if (isRed || isBlue) {
      const x = p % c.width, y = (p / c.width) | 0;
      if (x < x0) x0 = x; if (x > x1) x1 = x; if (y < y0) y0 = y; if (y > y1) y1 = y;
    }
    if (before && (Math.abs(before[i] - r) > 8 || Math.abs(before[i + 1] - gr) > 8 || Math.abs(before[i + 2] - b) > 8)) changed++;
    if (Math.abs(r - 237) + Math.abs(gr - 240) + Math.abs(b - 245) > 12) nonBackground++;
  }
  if (snapshotName) window.__rbSnaps[snapshotName] = d;
  const scale = c.width / source.clientWidth;
  return {red, blue, box: [x0 / scale, y0 / scale, x1 / scale, y1 / scale], changed: before ? changed : -1,
          total: c.width * c.height, nonBackground, width: c.width, height: c.height};
};
"""

# The n(t) plot's violet pixels (the forecast's line and label): in all, and in the canvas column
# at x (device pixels) and its neighbours, with the plot box's height for scale.
PLOT_JS = """
const element = arguments[0], x = arguments[1];
const c = element.querySelector('.rbp-plot');
const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
let all = 0, column = 0, labelBottom = -1;
for (let i = 0, p = 0; i < d.length; i += 4, p++) {
  const r = d[i], g = d[i + 1], b = d[i + 2];
  if (!(b > 120 && b > r + 40 && r > g + 25)) continue;  // violet, not the grey, orange or red
  all++;
  if (x !== null && Math.abs(p % c.width - x) <= 1) column++;
  else labelBottom = Math.max(labelBottom, Math.floor(p / c.width));
}
// the cursor line's top, in the canvas's device pixels (its box starts at the canvas's border)
const line = element.querySelector('.rbp-cursor');
const cursorTop = (parseFloat(line.style.top) - 1) * c.width / c.clientWidth;
return {all, column, height: c.height, labelBottom, cursorTop};
"""

# What a player shows at the moment pause is pressed, recorded by listeners on the window that
# capture the click on the play button and space, so run before the player's own: whether it
# was playing, the slider's value and the read-outs' and the plot cursor's text and place.
PAUSE_WATCH_JS = """
window.__rbAtPause = null;
window.__rbWatched = arguments[0];
if (!window.__rbPauseWatch) {
  window.__rbPauseWatch = true;
  const record = () => {
    const e = window.__rbWatched;
    window.__rbAtPause = window.__rbShown(e);
    window.__rbAtPause.playing = e.rbPlayer.playing();
  };
  window.addEventListener('click', (ev) => {
    if (ev.target.closest && ev.target.closest('.rbp-play')) record();
  }, true);
  window.addEventListener('keydown', (ev) => { if (ev.key === ' ') record(); }, true);
}
window.__rbShown = (e) => ({
  slider: parseFloat(e.querySelector('.rbp-slider').value),
  readouts: ['.rbp-time', '.rbp-spin', '.rbp-sense'].map((s) => e.querySelector(s).textContent),
  cursor: ['.rbp-cursor', '.rbp-dot'].map((s) => e.querySelector(s).style.transform),
});
"""

# The player's picture as drawn now, all of it (renderAll), as RGBA bytes: for the scripts below,
# which have the player as p and its hook as h.
READ_JS = """
const read = () => {
  h.renderAll();
  const c = document.createElement('canvas');
  c.width = p.canvas.width; c.height = p.canvas.height;
  const g = c.getContext('2d');
  g.drawImage(p.canvas, 0, 0);
  return g.getImageData(0, 0, c.width, c.height).data;
};
"""

# Waits for two animation frames: whatever the last change asked to be drawn is drawn.
# The contact shadow, from above with the body hidden, at the sample where the body's long axis
# is nearest 45° to the world axes: how much darker the floor is with the shadow than without
# (its strength set to 0), in grey levels, at the centre of the shadow's ellipse and at its four
# points where the footprint ends (ρ = 1: 3 % darker, the shadow fading out by ρ = 1.15). The
# shadow is a quad of its own around the body (player.js): placed or turned wrongly, it clips the
# ellipse and some of the four points are not darkened.
SHADOW_JS = (
    """
const element = arguments[0];
const p = window.RattlebackPlayer.players.find((q) => q.container === element);
const h = element.rbPlayer;
const u = p.floorMaterial.uniforms;
const before = [h.time(), h.view()];
let best = null;
for (let k = 0; k < p.n; k += Math.max(1, Math.floor(p.n / 200))) {
  h.setTime(p.run.t[k]);
  const a = u.shadowAxis.value;
  const off = Math.abs(Math.abs(Math.atan2(a.y, a.x)) % (Math.PI / 2) - Math.PI / 4);
  if (!best || off < best[1]) best = [p.run.t[k], off];
}
h.setTime(best[0]);
h.setView('above');
p.points.visible = false;
"""
    + READ_JS
    + """const strength = u.shadowStrength.value;
const on = read();
u.shadowStrength.value = 0;
const off = read();
u.shadowStrength.value = strength;
p.points.visible = true;
const c = u.shadowCenter.value, a = u.shadowAxis.value, half = u.shadowHalf.value;
const across = [a.y, -a.x];
const scale = p.canvas.width / p.width;
const darker = (x, y) => {
  const [px, py] = h.project([x, y, 0]);
  const i = 4 * (Math.round(py * scale) * p.canvas.width + Math.round(px * scale));
  return (off[i] + off[i + 1] + off[i + 2] - on[i] - on[i + 1] - on[i + 2]) / 3;
};
const ends = [[1, 0], [-1, 0], [0, 1], [0, -1]].map(([i, j]) => darker(
  c.x + i * half.x * across[0] + j * half.y * a.x, c.y + i * half.x * across[1] + j * half.y * a.y));
const result = {t: best[0], angle: Math.atan2(a.y, a.x) * 180 / Math.PI, centre: darker(c.x, c.y), ends};
h.setTime(before[0]);
h.setView(before[1]);
return result;
"""
)

# The picture the player draws with its shortcuts (the floor without depth, the points' shader
# hiding what is below it by the floor plane's depth; the contact shadow alone multiplying the
# floor) against the one drawn without them (the floor's depth, the floor's formula with the
# shadow), in each view at the given times: the pixels more than 3 levels apart, the largest
# difference, and which shortcuts were taken.
SHORTCUTS_JS = (
    """
const element = arguments[0], views = arguments[1], times = arguments[2];
const p = window.RattlebackPlayer.players.find((q) => q.container === element);
const h = element.rbPlayer;
const before = [h.time(), h.view()];
"""
    + READ_JS
    + """const out = [];
for (const view of views) {
  for (const t of times) {
    h.setTime(t);
    h.setView(view);
    h.setShortcuts(true);
    const fast = read();
    const taken = {floorWithoutDepth: !p.floorMaterial.depthTest,
                   shadowAlone: p.shadow.material === p.shadowOverMaterial};
    h.setShortcuts(false);
    const plain = read();
    h.setShortcuts(true);
    let apart = 0, worst = 0;
    for (let i = 0; i < fast.length; i += 4) {
      const d = Math.max(Math.abs(fast[i] - plain[i]), Math.abs(fast[i + 1] - plain[i + 1]),
                         Math.abs(fast[i + 2] - plain[i + 2]));
      if (d > 3) apart++;
      if (d > worst) worst = d;
    }
    out.push({view, t, apart, worst, ...taken});
  }
}
h.setTime(before[0]);
h.setView(before[1]);
return out;
"""
)

FRAMES_JS = "const done = arguments[arguments.length - 1]; requestAnimationFrame(() => requestAnimationFrame(() => done(true)));"


def slerp(a, b, u):
    """Shortest-path slerp of unit quaternions [w, x, y, z]."""
    d = sum(p * q for p, q in zip(a, b))
    if d < 0:
        b = [-q for q in b]
        d = -d
    if d > 1 - 1e-12:
        r = [p + u * (q - p) for p, q in zip(a, b)]
    else:
        theta = math.acos(min(1.0, d))
        s = math.sin(theta)
        wa, wb = math.sin((1 - u) * theta) / s, math.sin(u * theta) / s
        r = [wa * p + wb * q for p, q in zip(a, b)]
    n = math.sqrt(sum(v * v for v in r))
    return [v / n for v in r]


def quaternion_error(q, e):
    return min(max(abs(p - r) for p, r in zip(q, e)), max(abs(p + r) for p, r in zip(q, e)))


def rotate(q, v):
    """Rotates vector v by unit quaternion q = [w, x, y, z]."""
    w, x, y, z = q
    m = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]
    return [sum(m[i][k] * v[k] for k in range(3)) for i in range(3)]


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def between(t, k, u):
    return t[k] + u * (t[k + 1] - t[k])


class Checker:
    def __init__(self, driver, folder):
        self.driver = driver
        self.folder = folder
        self.failures = []
        self.checks = 0

    def check(self, ok, what):
        self.checks += 1
        if not ok:
            self.failures.append(what)
            print("FAIL:", what)
        return ok

    def js(self, script, *args):
        return self.driver.execute_script(script, *args)

    def frames(self):
        self.driver.execute_async_script(FRAMES_JS)

    def until(self, element, condition, seconds=10):
        """Waits until the JS `condition` (h: the player's hook) holds, or `seconds` pass."""
        deadline = time.time() + seconds
        while time.time() < deadline:
            if self.js(f"const h = arguments[0].rbPlayer; return !!({condition});", element):
                return True
            time.sleep(0.02)
        return False

    def console(self, where):
        for entry in self.driver.get_log("browser"):
            if entry["level"] == "SEVERE":
                self.check(False, f"{where}: console error: {entry['message']}")

    def open(self, name):
        self.driver.get((self.folder / name).as_uri())
        deadline = time.time() + 30
        while time.time() < deadline:
            state = self.js(
                """return Array.from(document.querySelectorAll('.rb-player')).map(
                e => [e.getAttribute('data-run'), !!e.rbPlayer, e.rbPlayerError || null]);"""
            )
            if state and all(built or error for _, built, error in state):
                break
            time.sleep(0.2)
        self.js(PIXELS_JS)
        self.frames()
        return state

    def element(self, index):
        return self.driver.find_elements(By.CSS_SELECTOR, ".rb-player")[index]

    def hook(self, element, call, *args):
        return self.js(f"return arguments[0].rbPlayer.{call};", element, *args)

    def pixels(self, element, snapshot=None):
        return self.js("return window.__rbPixels(arguments[0], arguments[1]);", element, snapshot)

    def slider_to(self, element, t):
        self.js(
            """const s = arguments[0].querySelector('.rbp-slider');
                   s.value = String(arguments[1]);
                   s.dispatchEvent(new Event('input', {bubbles: true}));""",
            element,
            t,
        )
        self.frames()

    # ------------------------------------------------------------------------------------------
    def player(self, element, run_id):
        where = f"run {run_id}"
        self.js("arguments[0].scrollIntoView({block: 'start'});", element)
        self.frames()
        run = self.js(
            """const r = window.RATTLEBACK_RUNS[arguments[0]];
            return {t: r.t, x: r.x, y: r.y, z: r.z, qw: r.qw, qx: r.qx, qy: r.qy, qz: r.qz,
                    spin: r.spin, reversals: r.reversals, reach: r.reach};""",
            run_id,
        )
        t = run["t"]
        n = len(t)
        quat = lambda k: [run["qw"][k], run["qx"][k], run["qy"][k], run["qz"][k]]
        pos = lambda k: [run["x"][k], run["y"][k], run["z"][k]]
        center = pos(0)
        self.hook(element, "pause()")

        # The embedded samples are the run's own (its CSV, full rate) at the same times.
        csv_path = self.folder / f"{run_id}.csv"
        rows = {}
        if csv_path.exists():
            with open(csv_path) as f:
                for row in csv.DictReader(f):
                    rows[round(float(row["t"]), 6)] = row
            if not rows or max(rows) < round(t[-1], 6) or min(rows) > round(t[0], 6):
                print(
                    f"note: {csv_path.name} does not cover the player's run "
                    f"[{t[0]}, {t[-1]}]: not compared"
                )
                rows = {}
        # The run's (t, n) at the CSV's full rate, for the read-outs.
        series = sorted((float(r["t"]), float(r["spin"])) for r in rows.values())
        if rows:
            worst = 0.0
            missing = 0
            for k in range(0, n, max(1, n // 50)):
                row = rows.get(round(t[k], 6))
                if row is None:
                    missing += 1
                    continue
                for key in ["x", "y", "z", "qw", "qx", "qy", "qz", "spin"]:
                    worst = max(worst, abs(float(row[key]) - run[key][k]))
            self.check(missing == 0, f"{where}: {missing} player samples have no row in {csv_path.name}")
            self.check(worst < 1e-6, f"{where}: player data differs from {csv_path.name} by {worst}")

        # As loaded (the oblique view at the start): the body is drawn, its top red.
        px = self.pixels(element)
        self.check(px["red"] > 100, f"{where}: as loaded the canvas shows {px['red']} red pixels")
        # The forecast first reversal (data-forecast, when it applies and falls within the run): a
        # violet line across the n(t) plot at its time; none otherwise.
        forecast = self.js("return arguments[0].getAttribute('data-forecast');", element)
        forecast = json.loads(forecast) if forecast else None
        expect = (
            forecast["time_s"]
            if forecast
            and forecast.get("applies") is True
            and forecast.get("range") != "outside"
            and isinstance(forecast.get("time_s"), (int, float))
            and t[0] <= forecast["time_s"] <= t[-1]
            else None
        )
        got = self.hook(element, "forecast()")
        self.check(
            got == expect, f"{where}: the plot's forecast is {got}, not {expect} (data-forecast {forecast})"
        )
        plot = self.js(PLOT_JS, element, self.hook(element, "forecastX()"))
        if expect is None:
            self.check(
                plot["all"] == 0, f"{where}: no forecast, yet {plot['all']} violet pixels on the n(t) plot"
            )
        else:
            # the line spans the plot box (130 − 28 px tall at 1 px per CSS px)
            self.check(
                plot["column"] >= 0.6 * plot["height"],
                f"{where}: the forecast line at t = {expect:.3f} s has {plot['column']} violet pixels "
                f"in its column of the n(t) plot ({plot['height']} tall)",
            )
            self.check(
                plot["all"] > plot["column"] + 20,
                f"{where}: the forecast line has no label ({plot['all'] - plot['column']} violet pixels beside it)",
            )
            # the cursor's line runs below the label: near the reversal it covered it (a
            # teacher's trial)
            self.check(
                plot["cursorTop"] > plot["labelBottom"],
                f"{where}: the plot's cursor starts at device row {plot['cursorTop']:.0f}, over "
                f"the forecast's label (down to row {plot['labelBottom']})",
            )

        # Colours where the body is, from the side at the start: red top and blue bottom.
        self.hook(element, "setTime(arguments[1])", t[0])
        self.click_view(element, "side")
        self.frames()
        px = self.pixels(element)
        self.check(px["red"] > 100, f"{where}: side view shows {px['red']} red pixels")
        self.check(px["blue"] > 100, f"{where}: side view shows {px['blue']} blue pixels")
        cm = self.hook(element, "project(arguments[1])", self.hook(element, "position()"))
        box = px["box"]
        self.check(
            box[0] - 2 <= cm[0] <= box[2] + 2 and box[1] - 2 <= cm[1] <= box[3] + 2,
            f"{where}: the coloured pixels {box} do not surround the body's centre {cm}",
        )
        self.check(
            px["nonBackground"] > 0.2 * px["total"],
            f"{where}: the floor is not visible ({px['nonBackground']} of {px['total']} pixels)",
        )
        self.click_view(element, "above")
        self.frames()
        px = self.pixels(element)
        self.check(
            px["red"] > 100 and px["red"] > 3 * px["blue"],
            f"{where}: from above the top should be red: {px['red']} red, {px['blue']} blue",
        )

        # The contact shadow: under the body and as wide as its footprint (SHADOW_JS).
        shadow = self.js(SHADOW_JS, element)
        self.check(
            shadow["centre"] > 40,
            f"{where}: the contact shadow darkens the floor under the body's "
            f"centre by {shadow['centre']:.1f} levels (t = {shadow['t']:.2f} s)",
        )
        self.check(
            min(shadow["ends"]) >= 2,
            f"{where}: where the footprint ends (long axis at "
            f"{shadow['angle']:.0f}°, t = {shadow['t']:.2f} s) the contact shadow darkens the floor "
            f"by {[round(v, 1) for v in shadow['ends']]} levels",
        )

        # The slider: poses between samples, as slerp / lerp of the neighbouring samples.
        self.click_view(element, "oblique")
        picks = [(max(1, n // 7), 0.37), (n // 2, 0.5), (n - 3, 0.81)]
        reversals = run["reversals"] or []
        times = [between(t, k, u) for k, u in picks] + [r for r in reversals if t[0] < r < t[-1]][:1]
        self.slider_to(element, t[0])
        self.pixels(element, f"{run_id}-slider")
        for target in times:
            self.slider_to(element, target)
            got_t = self.hook(element, "time()")
            self.check(abs(got_t - target) < 1e-9, f"{where}: slider to t = {target} gave time {got_t}")
            k = max(i for i in range(n - 1) if t[i] <= got_t)
            u = (got_t - t[k]) / (t[k + 1] - t[k])
            expected = slerp(quat(k), quat(k + 1), u)
            got = self.hook(element, "quaternion()")
            err = quaternion_error(got, expected)
            self.check(
                err < 1e-6,
                f"{where}: at t = {got_t} the drawn quaternion {got} is not the slerp "
                f"{expected} of samples {k} and {k + 1} (error {err:.3g})",
            )
            expected_p = [a + u * (b - a) for a, b in zip(pos(k), pos(k + 1))]
            got_p = self.hook(element, "position()")
            err_p = max(abs(a - b) for a, b in zip(got_p, expected_p))
            self.check(
                err_p < 1e-9,
                f"{where}: at t = {got_t} the drawn position {got_p} is not "
                f"{expected_p} (error {err_p:.3g})",
            )
            # The run's n at got_t, on the straight line between its CSV's samples where there is
            # a CSV (at 500 a second, its full rate), else between the player's poses. Neither
            # line is n between samples: the CSV's misses Kane & Levinson's n, which swings with
            # its 17 Hz pitch, by up to 0.034 rad/s (measured against every other sample), so the
            # read-out (a cubic between poses) is allowed 0.05 of it. Where n is known exactly,
            # at a counted reversal (0), the read-out is held to 0.01 below.
            spin, room = run["spin"][k] + u * (run["spin"][k + 1] - run["spin"][k]), 0.05
            if series:
                c = max(i for i in range(len(series) - 1) if series[i][0] <= got_t)
                w = (got_t - series[c][0]) / (series[c + 1][0] - series[c][0])
                spin = series[c][1] + w * (series[c + 1][1] - series[c][1])
            shown_t = self.js("return arguments[0].querySelector('.rbp-time').textContent;", element)
            shown_n = self.js(
                "return arguments[0].querySelector('.rbp-spin').textContent + ' ' + "
                "arguments[0].querySelector('.rbp-sense').textContent;",
                element,
            )
            self.check(f"{got_t:.2f} s" in shown_t, f"{where}: at t = {got_t} the read-out says {shown_t!r}")
            said = re.search(r"([+-]) *(\d+\.\d\d) rad/s", shown_n)
            said_n = (-1 if said and said.group(1) == "-" else 1) * float(said.group(2)) if said else math.nan
            # (The read-out rounds to 0.01: half of that, and the interpolation's room.)
            self.check(
                abs(said_n - spin) <= 0.005 + room,
                f"{where}: at t = {got_t} (n = {spin:+.4f}) the read-out says {shown_n!r}",
            )
            if target in reversals:
                # n passes 0 there: the read-out rounds to 0.01, and the poses kept replay n
                # within 0.005 rad/s (tasks::kPlayerSpin). A teacher's trial: the Reversal button
                # read +0.04 on Kane & Levinson, whose poses at 100 a second missed its n.
                self.check(
                    abs(said_n) <= 0.01,
                    f"{where}: at the reversal, t = {got_t}, the " f"read-out says {shown_n!r}, not ±0.00",
                )
                # The sense's line says so, not a blank line where the words were.
                self.check(
                    "(not spinning)" in shown_n,
                    f"{where}: at the reversal, t = {got_t}, the sense's line says {shown_n!r}",
                )
            if said and abs(spin) > 0.05 + room:
                sense = "(counter-clockwise)" if spin > 0 else "(clockwise)"
                self.check(
                    sense in shown_n,
                    f"{where}: at t = {got_t} (n = {spin:+.4f}) the read-out " f"says {shown_n!r}",
                )
            px = self.pixels(element, f"{run_id}-slider")
            self.check(
                px["changed"] > 50,
                f"{where}: moving the slider to t = {target:.4f} changed " f"{px['changed']} pixels",
            )

        # Play, pause, and the end of the run.
        play = element.find_element(By.CSS_SELECTOR, ".rbp-play")
        self.hook(element, "setSpeed(1)")
        self.hook(element, "setTime(arguments[1])", t[0] + 0.1 * (t[-1] - t[0]))
        start = self.hook(element, "time()")
        self.pixels(element, f"{run_id}-play")
        play.click()
        time.sleep(1.0)
        now = self.hook(element, "time()")
        self.check(self.hook(element, "playing()"), f"{where}: the play button does not play")
        self.check(now > start + 0.3, f"{where}: playing for 1 s moved time from {start} to {now}")
        self.check(
            self.pixels(element, f"{run_id}-play")["changed"] > 50, f"{where}: playing changed no pixels"
        )
        play.click()
        # (A click returns before the page has handled it on a loaded machine: wait for it.)
        self.until(element, "!h.playing()")
        paused = self.hook(element, "time()")
        time.sleep(0.3)
        self.check(
            not self.hook(element, "playing()") and self.hook(element, "time()") == paused,
            f"{where}: the pause button does not stop time",
        )
        self.pause_holds(element, where, run_id)
        # While the camera stays, a frame redraws only the part where the body and its shadow
        # were and are; the picture then must be the one drawn whole.
        partial, drawn = self.hook(element, "drawCounts()")
        self.check(
            drawn > 10 and partial > 0.5 * drawn,
            f"{where}: only {partial} of {drawn} frames were drawn in part in a fixed view",
        )
        for view in ["oblique", "side"]:
            self.click_view(element, view)
            self.hook(element, "play()")
            time.sleep(0.5)
            self.hook(element, "pause()")
            self.frames()
            self.pixels(element, f"{run_id}-part")
            self.hook(element, "renderAll()")
            px = self.pixels(element, f"{run_id}-part")
            self.check(
                px["changed"] == 0,
                f"{where}: after playing in the {view} view, drawing the "
                f"picture whole changed {px['changed']} pixels",
            )
        self.click_view(element, "oblique")
        self.hook(element, "setTime(arguments[1])", t[-1] - 0.1)
        self.hook(element, "play()")
        time.sleep(0.6)
        self.check(
            not self.hook(element, "playing()") and self.hook(element, "time()") == t[-1],
            f"{where}: playback does not stop at the end of the run "
            f"(playing {self.hook(element, 'playing()')}, t = {self.hook(element, 'time()')})",
        )
        self.hook(element, "pause()")

        # The views: each button moves the camera to the renderer's place for it.
        self.hook(element, "setTime(arguments[1])", times[0])
        previous = None
        expected_dirs = {
            "oblique": unit([0.75, -0.55, 0.55]),
            "above": [0, 0, 1],
            "front": [0, -math.cos(ELEVATION), math.sin(ELEVATION)],
            "side": [math.cos(ELEVATION), 0, math.sin(ELEVATION)],
        }
        for view in VIEWS:
            self.click_view(element, view)
            self.check(
                self.hook(element, "view()") == view,
                f"{where}: the {view} button gave view " f"{self.hook(element, 'view()')}",
            )
            cam = self.hook(element, "cameraPosition()")
            if previous is not None:
                self.check(
                    max(abs(a - b) for a, b in zip(cam, previous)) > 1e-4,
                    f"{where}: the {view} button did not move the camera ({cam})",
                )
            previous = cam
            if view in expected_dirs:
                d = unit([a - b for a, b in zip(cam, center)])
                err = max(abs(a - b) for a, b in zip(d, expected_dirs[view]))
                self.check(
                    err < 1e-3,
                    f"{where}: the {view} camera looks from {d}, " f"expected {expected_dirs[view]}",
                )
            if view == "above":
                c0 = self.hook(element, "project(arguments[1])", center)
                cy = self.hook(element, "project(arguments[1])", [center[0], center[1] + 0.01, center[2]])
                cx = self.hook(element, "project(arguments[1])", [center[0] + 0.01, center[1], center[2]])
                self.check(
                    cy[0] > c0[0] + 5 and abs(cy[1] - c0[1]) < 1,
                    f"{where}: from above +y does not point right ({c0} -> {cy})",
                )
                self.check(
                    cx[1] > c0[1] + 5 and abs(cx[0] - c0[0]) < 1,
                    f"{where}: from above +x does not point down the screen ({c0} -> {cx})",
                )
            if view == "follow":
                follow = []
                for target in times[:2]:
                    self.hook(element, "setTime(arguments[1])", target)
                    cam = self.hook(element, "cameraPosition()")
                    body = self.hook(element, "position()")
                    q = self.hook(element, "quaternion()")
                    away = [a - b for a, b in zip(cam, body)]
                    axis = rotate(q, [0, 1, 0])
                    flat = unit([away[0], away[1], 0])
                    along = abs(flat[0] * axis[0] + flat[1] * axis[1]) / max(
                        1e-12, math.hypot(axis[0], axis[1])
                    )
                    self.check(
                        along < 1e-3,
                        f"{where}: the follow camera is not across the long axis "
                        f"at t = {target} ({along})",
                    )
                    follow.append((cam, math.sqrt(sum(a * a for a in away))))
                self.check(
                    max(abs(a - b) for a, b in zip(follow[0][0], follow[1][0])) > 1e-3,
                    f"{where}: the follow camera does not move with the body",
                )
                self.check(
                    abs(follow[0][1] - follow[1][1]) < 0.01 * follow[0][1],
                    f"{where}: the follow camera's distance changes ({follow})",
                )
        # The shortcuts (the floor without depth, the shadow alone) draw the picture drawn
        # without them: a row of a sphere at the contact may differ, where its depth ties the
        # floor's, and the shadow by a level or two (the floor is rounded before it is darkened).
        # In follow both are taken.
        shortcut_times = [times[0], times[-1]]
        for r in self.js(SHORTCUTS_JS, element, VIEWS, shortcut_times):
            self.check(
                r["apart"] <= 30,
                f"{where}: in the {r['view']} view at t = {r['t']:.3f} s the picture "
                f"drawn with the shortcuts differs from the one without in {r['apart']} pixels by more "
                f"than 3 levels (at most {r['worst']}; floor without depth {r['floorWithoutDepth']}, "
                f"shadow alone {r['shadowAlone']})",
            )
            if r["view"] == "follow":
                self.check(
                    r["floorWithoutDepth"] and r["shadowAlone"],
                    f"{where}: in follow at t = {r['t']:.3f} s a shortcut was not taken ({r})",
                )
        # A drag makes the view free and moves the camera.
        self.click_view(element, "oblique")
        before = self.hook(element, "cameraPosition()")
        canvas = element.find_element(By.CSS_SELECTOR, ".rbp-stage canvas")
        ActionChains(self.driver).move_to_element(canvas).click_and_hold().move_by_offset(
            80, 30
        ).move_by_offset(40, 10).release().perform()
        after = self.hook(element, "cameraPosition()")
        self.check(
            self.hook(element, "view()") == "free",
            f"{where}: a drag left the view " f"{self.hook(element, 'view()')}, not free",
        )
        self.check(
            max(abs(a - b) for a, b in zip(before, after)) > 1e-4, f"{where}: a drag did not move the camera"
        )
        self.click_view(element, "oblique")

        # Keys, with the player focused (a click on its read-outs).
        self.hook(element, "pause()")
        element.find_element(By.CSS_SELECTOR, ".rbp-title").click()
        self.check(
            self.js("return arguments[0].contains(document.activeElement);", element),
            f"{where}: a click on the player does not focus it",
        )
        self.keys(element, where, run)
        self.speed_menu(element, where, run)
        self.teacher_controls(element, where, run)
        self.spin_cue(element, where, run)
        self.spins(element, where, run_id)

    def pause_holds(self, element, where, run_id):
        # Pause stops at what is shown when it is pressed: the time, the slider, the read-outs,
        # the plot's cursor and the picture stay there, none moves on a frame after (playback
        # applies a pose a frame before it shows it). Paused with the button, and with space
        # after a click on the canvas (which focuses the player), three times each at different
        # moments.
        play = element.find_element(By.CSS_SELECTOR, ".rbp-play")
        canvas = element.find_element(By.CSS_SELECTOR, ".rbp-stage canvas")
        t0, t1 = self.hook(element, "range()")
        # At 1× a short run reaches its end (and stops by itself) in under 3 s of wall time,
        # which a loaded machine spends between two presses: at 0.25× it takes four times as long.
        speed = self.hook(element, "speed()")
        self.hook(element, "setSpeed(arguments[1])", 0.25)
        for attempt in range(6):
            by_key = attempt % 2 == 1
            how = "space after a click on the canvas" if by_key else "the button"
            self.hook(element, "pause()")
            self.hook(element, "setTime(arguments[1])", t0 + 0.1 * (t1 - t0))
            self.js(PAUSE_WATCH_JS, element)
            # A click or key returns before the page has handled it on a loaded machine: each
            # step waits for the player to be seen playing, then paused, and the state at the
            # press is the one recorded at the press that paused it.
            if by_key:
                self.hook(element, "play()")
                ActionChains(self.driver).move_to_element(canvas).click().perform()
                self.until(element, "h.playing()")
                time.sleep(0.2 + 0.04 * attempt)
                self.js("window.__rbAtPause = null;")
                ActionChains(self.driver).send_keys(Keys.SPACE).perform()
            else:
                play.click()
                self.until(element, "h.playing()")
                time.sleep(0.3 + 0.04 * attempt)
                self.js("window.__rbAtPause = null;")
                play.click()
            self.until(element, "window.__rbAtPause && !h.playing()")
            at = self.js("return window.__rbAtPause;")
            now = self.hook(element, "time()")
            if not self.check(
                at and at["playing"] and not self.hook(element, "playing()"),
                f"{where}: pausing with {how} was not seen ({at})",
            ):
                continue
            self.frames()
            self.pixels(element, f"{run_id}-pause")
            time.sleep(0.6)
            later = self.hook(element, "time()")
            shown = self.js("return window.__rbShown(arguments[0]);", element)
            # (The slider holds its value to 15 significant digits.)
            self.check(
                abs(now - at["slider"]) < 1e-9 and later == now,
                f"{where}: paused with {how} at t = {at['slider']} (the slider), the time is "
                f"{now} right after and {later} 0.6 s later",
            )
            for key in ["slider", "readouts", "cursor"]:
                self.check(
                    shown[key] == at[key],
                    f"{where}: paused with {how}, the {key} showed "
                    f"{at[key]!r} and 0.6 s later {shown[key]!r}",
                )
            px = self.pixels(element, f"{run_id}-pause")
            self.check(
                px["changed"] == 0,
                f"{where}: paused with {how}, the picture changed " f"{px['changed']} pixels after",
            )
            # ... and it is the picture of the time paused at.
            self.hook(element, "renderAll()")
            px = self.pixels(element, f"{run_id}-pause")
            self.check(
                px["changed"] == 0,
                f"{where}: paused with {how}, the picture is not the one "
                f"of t = {later} ({px['changed']} pixels differ)",
            )
        self.hook(element, "setSpeed(arguments[1])", speed)
        self.click_view(element, "oblique")

    def speed_menu(self, element, where, run):
        # A speed chosen from the menu with the pointer gives the keys back to the player (they
        # went to the menu: → chose the next speed, space did nothing); tabbed to, the menu's
        # own arrows still choose speeds.
        t = run["t"]
        k = len(t) // 3
        self.hook(element, "pause()")
        menu = element.find_element(By.CSS_SELECTOR, ".rbp-speed")
        Select(menu).select_by_value("0.5")
        self.check(self.hook(element, "speed()") == 0.5, f"{where}: the menu did not set 0.5×")
        self.hook(element, "setTime(arguments[1])", between(t, k, 0.4))
        ActionChains(self.driver).send_keys(Keys.ARROW_RIGHT).perform()
        speed, got = self.hook(element, "speed()"), self.hook(element, "time()")
        self.check(
            speed == 0.5 and got == t[k + 1],
            f"{where}: → after choosing 0.5× made the speed {speed}× and the time {got}, "
            f"not 0.5× and {t[k + 1]}",
        )
        ActionChains(self.driver).send_keys(Keys.SPACE).perform()
        time.sleep(0.3)
        self.check(self.hook(element, "playing()"), f"{where}: space after choosing a speed does not play")
        self.hook(element, "pause()")
        self.js("document.activeElement && document.activeElement.blur(); arguments[0].focus();", menu)
        ActionChains(self.driver).send_keys(Keys.ARROW_DOWN).perform()
        speed = self.hook(element, "speed()")
        self.check(
            speed == 1 and self.js("return document.activeElement === arguments[0];", menu),
            f"{where}: ↓ on the focused menu made the speed {speed}×, not 1×, or moved the focus",
        )
        ActionChains(self.driver).send_keys(Keys.ARROW_DOWN).perform()
        speed = self.hook(element, "speed()")
        self.check(speed == 2, f"{where}: ↓ again on the menu made the speed {speed}×, not 2×")
        self.hook(element, "setSpeed(1)")

    def keys(self, element, where, run):
        t = run["t"]
        n = len(t)
        k = n // 3
        self.hook(element, "setTime(arguments[1])", between(t, k, 0.4))
        ActionChains(self.driver).send_keys(Keys.SPACE).perform()
        time.sleep(0.3)
        self.check(self.hook(element, "playing()"), f"{where}: space does not play")
        ActionChains(self.driver).send_keys(Keys.SPACE).perform()
        self.check(self.until(element, "!h.playing()"), f"{where}: space again does not pause")

        # (Each key is waited for: on a loaded machine it returns before the page handles it.)
        def key(k, expect):
            ActionChains(self.driver).send_keys(k).perform()
            self.until(element, f"h.time() === {expect!r}", 5)
            return self.hook(element, "time()")

        self.hook(element, "setTime(arguments[1])", between(t, k, 0.4))
        got = key(Keys.ARROW_RIGHT, t[k + 1])
        self.check(
            got == t[k + 1], f"{where}: → from between samples {k} and {k + 1} went to {got}, not {t[k + 1]}"
        )
        got = key(Keys.ARROW_RIGHT, t[k + 2])
        self.check(got == t[k + 2], f"{where}: → again went to {got}, not {t[k + 2]}")
        key(Keys.ARROW_LEFT, t[k + 1])
        got = key(Keys.ARROW_LEFT, t[k])
        self.check(got == t[k], f"{where}: ← twice went to {got}, not {t[k]}")
        # A time a hair before a sample (paused at 1.4999 s) counts as that sample: → goes on
        # to the next one; it went to 1.50, the same picture and read-out, and seemed dead.
        self.hook(element, "setTime(arguments[1])", between(t, k, 0.99))
        got = key(Keys.ARROW_RIGHT, t[k + 2])
        self.check(
            got == t[k + 2],
            f"{where}: → from just before sample {k + 1} went to {got}, " f"not on to {t[k + 2]}",
        )
        self.hook(element, "setTime(arguments[1])", between(t, k, 0.01))
        got = key(Keys.ARROW_LEFT, t[k - 1])
        self.check(
            got == t[k - 1],
            f"{where}: ← from just after sample {k} went to {got}, " f"not back to {t[k - 1]}",
        )

    def teacher_controls(self, element, where, run):
        # What a lesson needs (a teacher's trial): the moment the spin passes zero at a button
        # or R, the start and end at Home and End, the floor's scale beside the picture, an
        # orbit that stays above the floor, full screen.
        reversals = run.get("reversals") or []
        button = element.find_element(By.CSS_SELECTOR, ".rbp-reversal")
        t0, t1 = self.hook(element, "range()")
        if reversals:
            self.hook(element, "setTime(arguments[1])", t0)
            button.click()
            self.check(
                self.until(element, f"h.time() === {reversals[0]!r}"),
                f"{where}: the reversal button went to {self.hook(element, 'time()')}, "
                f"not the first reversal {reversals[0]}",
            )
            self.check(not self.hook(element, "playing()"), f"{where}: the reversal button left it playing")
            shown = element.find_element(By.CSS_SELECTOR, ".rbp-spin").text
            self.check("0.0" in shown, f"{where}: at the reversal the spin read-out says {shown!r}")
            element.find_element(By.CSS_SELECTOR, ".rbp-title").click()
            ActionChains(self.driver).send_keys("r").perform()
            expect = reversals[1] if len(reversals) > 1 else reversals[0]
            self.check(
                self.until(element, f"h.time() === {expect!r}", 5),
                f"{where}: R went to {self.hook(element, 'time()')}, not {expect}",
            )
        else:
            self.check(
                not button.is_enabled(), f"{where}: a run without reversals has the reversal button on"
            )
        element.find_element(By.CSS_SELECTOR, ".rbp-title").click()
        ActionChains(self.driver).send_keys(Keys.END).perform()
        self.check(
            self.until(element, f"h.time() === {t1!r}", 5),
            f"{where}: End went to {self.hook(element, 'time()')}",
        )
        ActionChains(self.driver).send_keys(Keys.HOME).perform()
        self.check(
            self.until(element, f"h.time() === {t0!r}", 5),
            f"{where}: Home went to {self.hook(element, 'time()')}",
        )
        help_text = element.find_element(By.CSS_SELECTOR, ".rbp-help").text
        said = f"{len(reversals)} reversal" if reversals else "No reversal in this run"
        self.check(said in help_text, f"{where}: the help says {help_text!r}, not {said!r}")
        # The scale: a length, four times deeper in the side view.
        self.click_view(element, "oblique")
        oblique = element.find_element(By.CSS_SELECTOR, ".rbp-scale").text
        self.click_view(element, "side")
        side = element.find_element(By.CSS_SELECTOR, ".rbp-scale").text
        pattern = re.compile(r"^floor squares (\d+(?:\.\d+)?) (mm|cm|m)$")
        a, b = pattern.match(oblique), pattern.match(side)
        unit = {"mm": 1e-3, "cm": 1e-2, "m": 1.0}
        self.check(
            bool(a and b) and abs(float(b[1]) * unit[b[2]] - 4 * float(a[1]) * unit[a[2]]) < 1e-9,
            f"{where}: the floor's scale reads {oblique!r} in oblique and {side!r} in side",
        )
        # A long drag down orbits towards the floor and stops above it.
        self.click_view(element, "oblique")
        canvas = element.find_element(By.CSS_SELECTOR, ".rbp-stage canvas")
        # (Up the canvas is down towards the floor: a drag of its whole height turns the camera
        # by a full turn, so two-fifths of it twice is far past the horizon.)
        h = canvas.size["height"]
        ActionChains(self.driver).move_to_element_with_offset(
            canvas, 0, int(0.45 * h)
        ).click_and_hold().move_by_offset(0, -int(0.4 * h)).move_by_offset(
            0, -int(0.4 * h)
        ).release().perform()
        eye, target = self.hook(element, "cameraPosition()"), self.hook(element, "cameraTarget()")
        self.check(
            eye[2] > target[2] and eye[2] > 0,
            f"{where}: an orbit down took the camera to " f"{eye}, below the floor or the target {target}",
        )
        self.click_view(element, "oblique")
        # Full screen: the player fills the screen and F (or the button) leaves it.
        self.js("arguments[0].querySelector('.rbp-full').click();", element)
        time.sleep(0.5)
        is_full = self.js(
            "return document.fullscreenElement === arguments[0].querySelector('.rbp');", element
        )
        self.check(is_full, f"{where}: the full-screen button did not fill the screen")
        if is_full:
            self.js("document.exitFullscreen();")
            time.sleep(0.3)

    def spin_cue(self, element, where, run):
        # The spin cue over the picture, as the videos draw it (docs/commands.md "The spin cue"):
        # at a sample where n < -0.05 an arrow in bluish green whose head is left of the arc's
        # middle (a clockwise turn seen from above moves the side nearer the camera to the
        # viewer's left), where n > 0.05 orange with its head on the right; none where |n| is
        # below 0.05; "reversal at T s" from each reversal on for 1.5 s, and not before it.
        t, spin = run["t"], run["spin"]
        self.click_view(element, "oblique")
        picks = {}
        for k in range(len(t)):
            if spin[k] < -0.5 and -1 not in picks:
                picks[-1] = t[k]
            if spin[k] > 0.5 and 1 not in picks:
                picks[1] = t[k]
        colours = {1: "#e69f00", -1: "#009e73"}
        for sense, at in picks.items():
            self.hook(element, "setTime(arguments[1])", at)
            self.frames()
            cue = self.hook(element, "cue()")
            geometry = self.js(
                """const svg = arguments[0].querySelector('.rbp-cue');
                const d = svg.querySelector('path:nth-of-type(2)').getAttribute('d');
                const points = d.slice(1).split('L').map(p => p.split(',').map(Number));
                const tip = svg.querySelector('polygon:last-of-type').getAttribute('points')
                    .split(' ')[0].split(',').map(Number);
                return {middle: points[points.length >> 1], tip,
                        shown: getComputedStyle(svg).display !== 'none'};""",
                element,
            )
            self.check(
                cue["sense"] == sense and cue["color"] == colours[sense] and geometry["shown"],
                f"{where}: at t = {at} (n {'>' if sense > 0 else '<'} 0) the cue is {cue}",
            )
            right = geometry["tip"][0] > geometry["middle"][0]
            self.check(
                right == (sense > 0),
                f"{where}: at t = {at} the arrow's head {geometry['tip']} is on the "
                f"{'right' if right else 'left'} of its middle {geometry['middle']}",
            )
        slow = [t[k] for k in range(len(t)) if abs(spin[k]) < 0.02]
        if slow:
            self.hook(element, "setTime(arguments[1])", slow[0])
            self.frames()
            self.check(self.hook(element, "cue()")["sense"] == 0, f"{where}: an arrow at n ≈ 0")
        t0, t1 = self.hook(element, "range()")
        for r in run.get("reversals") or []:
            for offset, expect in [(-0.1, False), (0.1, True), (1.4, True), (1.6, False)]:
                at = r + offset
                if not t0 <= at <= t1 or any(0 < at - q < 1.5 for q in run["reversals"] if q != r):
                    continue
                self.hook(element, "setTime(arguments[1])", at)
                self.frames()
                label = self.hook(element, "cue()")["label"]
                self.check(
                    (label == f"reversal at {r:.2f} s") == expect and (bool(label) == expect),
                    f"{where}: at t = {at:.3f} ({offset:+} s from the reversal at {r}) the label "
                    f"reads {label!r}",
                )
        ticks = self.js(
            """const s = arguments[0].querySelector('.rbp-slider');
            return s.list ? Array.from(s.list.options).map(o => +o.value) : [];""",
            element,
        )
        self.check(
            ticks == list(run.get("reversals") or []),
            f"{where}: the time slider's ticks {ticks} are not the reversals {run.get('reversals')}",
        )

    def spins(self, element, where, run_id):
        """A run whose data carries the body spun the other way ("other") is played either way:
        two buttons, each its spin and what its run did (from its own reversals), the first
        pressed; the second plays the other run (its poses between samples, the slider's span
        and ticks, R to its first reversal), at the same moment, and S switches back. A run
        without one has no buttons, and S does nothing."""
        data = self.js(
            """const r = window.RATTLEBACK_RUNS[arguments[0]]; const o = r.other;
            return {spun: r.spun, reversals: r.reversals, other: o ? {spun: o.spun, t: o.t,
                    qw: o.qw, qx: o.qx, qy: o.qy, qz: o.qz, reversals: o.reversals} : null};""",
            run_id,
        )
        buttons = lambda: self.js(
            """return Array.from(arguments[0].querySelectorAll('.rbp-spun')).map(
                b => [b.textContent, b.getAttribute('aria-pressed')]);""",
            element,
        )
        other = data["other"]
        # The default scene prefers counter-clockwise: its run (on the dev page, Python's
        # player_script; in a report, `report`'s) comes with the other spin.
        self.check(
            bool(other) or run_id != "rattleback", f"{where}: the default scene's data has no other spin"
        )
        if not other:
            self.check(buttons() == [], f"{where}: one run, and spin buttons {buttons()}")
            element.find_element(By.CSS_SELECTOR, ".rbp-title").click()
            ActionChains(self.driver).send_keys("s").perform()
            time.sleep(0.2)
            self.check(self.hook(element, "runIndex()") == 0, f"{where}: S switched a run alone")
            return

        def label(spun, reversals):
            did = f"reverses at {reversals[0]:.2f} s" if reversals else "no reversal"
            if len(reversals) > 1:
                did += f" ({len(reversals)} reversals)"
            sign = "\u2212" if spun < 0 else "+"  # (U+2212, the minus sign of print)
            return f"{sign}{float(f'{abs(spun):.4g}'):g} rad/s: {did}"

        expected = [
            label(data["spun"], data["reversals"] or []),
            label(other["spun"], other["reversals"] or []),
        ]
        self.check(
            buttons() == [[expected[0], "true"], [expected[1], "false"]],
            f"{where}: the spin buttons are {buttons()}, not {expected} with the first pressed",
        )
        self.check(data["spun"] == -other["spun"] != 0, f"{where}: spun {data['spun']} and {other['spun']}")
        t = other["t"]
        n = len(t)
        self.hook(element, "setTime(arguments[1])", 1.0)
        element.find_elements(By.CSS_SELECTOR, ".rbp-spun")[1].click()
        self.frames()
        self.check(
            self.hook(element, "runIndex()") == 1 and abs(self.hook(element, "time()") - 1.0) < 1e-9,
            f"{where}: the second spin's button gave run {self.hook(element, 'runIndex()')} at "
            f"t = {self.hook(element, 'time()')}, not run 1 at 1 s",
        )
        self.check(
            buttons() == [[expected[0], "false"], [expected[1], "true"]],
            f"{where}: after the click the spin buttons are {buttons()}",
        )
        span = self.js(
            """const s = arguments[0].querySelector('.rbp-slider');
            return [+s.min, +s.max, s.list ? Array.from(s.list.options).map(o => +o.value) : []];""",
            element,
        )
        self.check(
            span == [t[0], t[-1], list(other["reversals"] or [])],
            f"{where}: the other spin's slider is {span}, not [{t[0]}, {t[-1]}] with its reversals",
        )
        for k, u in [(n // 3, 0.3), (n - 2, 0.7)]:
            self.slider_to(element, between(t, k, u))
            got_t = self.hook(element, "time()")
            k = max(i for i in range(n - 1) if t[i] <= got_t)
            u = (got_t - t[k]) / (t[k + 1] - t[k])
            q = lambda i: [other["qw"][i], other["qx"][i], other["qy"][i], other["qz"][i]]
            err = quaternion_error(self.hook(element, "quaternion()"), slerp(q(k), q(k + 1), u))
            self.check(
                err < 1e-6, f"{where}: spun the other way, at t = {got_t} the drawn pose is {err:.3g} off"
            )
        element.find_element(By.CSS_SELECTOR, ".rbp-title").click()
        if other["reversals"]:
            self.hook(element, "setTime(arguments[1])", t[0])
            ActionChains(self.driver).send_keys("r").perform()
            self.check(
                self.until(element, f"h.time() === {other['reversals'][0]!r}", 5),
                f"{where}: R spun the other way went to {self.hook(element, 'time()')}, not its reversal",
            )
        ActionChains(self.driver).send_keys("s").perform()
        self.check(self.until(element, "h.runIndex() === 0", 5), f"{where}: S did not switch back")
        self.hook(element, "setTime(arguments[1])", 1.0)
        run = self.js("return window.RATTLEBACK_RUNS[arguments[0]].t;", run_id)
        self.check(
            self.hook(element, "range()") == [run[0], run[-1]],
            f"{where}: switched back, the span is {self.hook(element, 'range()')}",
        )

    def click_view(self, element, view):
        button = element.find_element(By.CSS_SELECTOR, f".rbp-view-{view}")
        button.click()
        self.frames()

    # ------------------------------------------------------------------------------------------
    def page(self, name, expect_missing):
        state = self.open(name)
        self.console(f"{name} on load")
        self.check(bool(state), f"{name}: no .rb-player on the page")
        for index, (run_id, built, error) in enumerate(state or []):
            has_data = self.js(
                "return !!(window.RATTLEBACK_RUNS && window.RATTLEBACK_RUNS[arguments[0]]);", run_id
            )
            element = self.element(index)
            if not has_data:
                text = element.text.strip()
                self.check(
                    not built and error and text,
                    f"{name}: the player of missing run {run_id} shows {text!r} (built {built}, error {error})",
                )
                expect_missing -= 1
                continue
            if not self.check(built, f"{name}: no player for run {run_id} ({error})"):
                continue
            self.player(element, run_id)
            self.console(f"{name}, run {run_id}")
        self.check(expect_missing <= 0, f"{name}: expected a player with a missing run")
        return state

    def single(self):
        # One player on the page: its keys work with nothing focused.
        state = self.open("single.html")
        self.console("single.html on load")
        element = self.element(0)
        run_id = state[0][0]
        run = self.js("return {t: window.RATTLEBACK_RUNS[arguments[0]].t};", run_id)
        self.js("document.activeElement && document.activeElement.blur();")
        self.check(
            self.js("return document.activeElement === document.body;"), "single.html: something has focus"
        )
        self.keys(element, "single.html (unfocused)", run)
        self.console("single.html")

    def framed(self):
        # A scene's video.frame frames the player's views for a body that long, as its stills
        # (render_test.cpp's OneFrameDrawsBodiesAtOneScale): the default body (20 cm) framed for
        # 40 cm is drawn half as long from above as framed for itself, and the floor's squares
        # follow the frame (2 cm, against 1 cm). Lengths are the red and blue pixels' extent
        # across the canvas (+y, the long axis at t = 0, to the right): each end is uncertain by
        # a sphere's edge, a pixel or two of the hundreds: 5 %.
        widths, labels = {}, {}
        for name in ("single.html", "framed.html"):
            self.open(name)
            element = self.element(0)
            self.hook(element, "setView('above')")
            self.hook(element, "setTime(0)")
            self.frames()
            box = self.pixels(element)["box"]
            widths[name] = box[2] - box[0]
            labels[name] = self.js("return arguments[0].querySelector('.rbp-scale').textContent;", element)
            self.console(name)
        ratio = widths["framed.html"] / widths["single.html"]
        self.check(
            abs(ratio - 0.5) < 0.05 * 0.5,
            f"framed.html: framed for 40 cm the 20 cm body is "
            f"{widths['framed.html']:.0f} px long from above, {ratio:.3f} of its "
            f"{widths['single.html']:.0f} px framed for itself, not half",
        )
        self.check(
            "2 cm" in labels["framed.html"] and "1 cm" in labels["single.html"],
            f"the floor's squares read {labels['single.html']!r} and {labels['framed.html']!r}, "
            "not 1 and 2 cm",
        )

    def measure(self, screenshots, size):
        self.open("single.html" if (self.folder / "single.html").exists() else "index.html")
        element = self.element(0)
        self.js("arguments[0].scrollIntoView({block: 'start'});", element)
        self.hook(element, "setSize(arguments[1], arguments[2])", *size)
        self.hook(element, "setView('oblique')")
        self.hook(element, "setSpeed(1)")
        self.hook(element, "setTime(0)")
        self.hook(element, "play()")
        time.sleep(4)
        frame = self.hook(element, "frameMs()")
        render = self.hook(element, "renderMs()")
        self.hook(element, "pause()")
        bench = self.hook(element, "benchmark(30)")
        print(
            f"frame time at {size[0]}x{size[1]}: {frame:.1f} ms between drawn frames while playing "
            f"({1000 / frame:.0f} fps); {bench:.1f} ms per frame drawn and read back; "
            f"{render:.1f} ms CPU per render call"
        )
        self.check(math.isfinite(frame) and frame > 0, f"frameMs() is {frame}")
        if screenshots:
            run = self.js(
                "return window.RATTLEBACK_RUNS[arguments[0]].reversals;",
                self.js("return arguments[0].getAttribute('data-run');", element),
            )
            t_rev = run[0] if run else 0
            out = pathlib.Path(screenshots)
            out.mkdir(parents=True, exist_ok=True)
            for view in ["oblique", "side"]:
                self.hook(element, "setView(arguments[1])", view)
                self.hook(element, "setTime(arguments[1])", t_rev)
                self.frames()
                root = element.find_element(By.CSS_SELECTOR, ".rbp")
                self.js("arguments[0].scrollIntoView({block: 'start'});", root)
                root.screenshot(str(out / f"player-{view}.png"))
                print(f"saved {out / f'player-{view}.png'} (t = {t_rev:.4f} s, {view})")
        self.console("measuring")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("dir")
    parser.add_argument("--screenshots", help="save player-oblique.png and player-side.png here")
    parser.add_argument("--size", default="1280x720", help="the canvas size to measure the frame time at")
    args = parser.parse_args()
    folder = pathlib.Path(args.dir).resolve()
    size = [int(v) for v in args.size.split("x")]
    if not chromium.installed():
        print("chromium or chromedriver is not installed; skipped")
        return 77
    driver, profile = chromium.open_browser(
        "--disable-quic",
        # WebGL on the CPU (SwiftShader through ANGLE): no GPU needed; the page
        # composited on the CPU, as Chromium does by itself on a machine without a GPU
        # (compositing on SwiftShader instead cost ~30 ms of CPU a frame, whole window:
        # bench/player_speed.py's swiftshader-gl against as-installed)
        "--use-gl=angle",
        "--use-angle=swiftshader",
        "--enable-unsafe-swiftshader",
        "--disable-gpu-compositing",
        "--force-device-scale-factor=1",
        "--window-size=1700,1100",
    )
    checker = Checker(driver, folder)
    try:
        driver.set_script_timeout(60)
        checker.page(
            "index.html", expect_missing=1 if "no-such-run" in (folder / "index.html").read_text() else 0
        )
        if (folder / "missing.html").exists():
            state = checker.page("missing.html", expect_missing=1)
            checker.check(state and not state[0][1], "missing.html: a player was built with no data")
        if (folder / "single.html").exists():
            checker.single()
        if (folder / "framed.html").exists():
            checker.framed()
        checker.measure(args.screenshots, size)
    except Exception as e:  # a check that could not run is a failure, not a crash
        checker.check(False, f"the check stopped: {type(e).__name__}: {e}")
    finally:
        chromium.close(driver, profile)
    failed = len(checker.failures)
    print(f"{checker.checks - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
