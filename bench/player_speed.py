#!/usr/bin/python3
"""How fast the report page's 3D player draws in headless Chromium on software WebGL (the target:
"the player draws at the display's rate ... at 1280×720"). Prints figures; asserts nothing.

Usage: /usr/bin/python3 bench/player_speed.py DIR [DIR…] [--seconds S] [--size WxH] [--rounds N]
                                             [--configs NAME,…]

Each DIR is a report folder (or make_page.py's dev page) whose index.html has a player; several
(e.g. the same run with an older rattleback-player.js) are measured in turn, side by side. Chromium is
started headless with a 1700×1100 window at device scale 1, in each of the configurations named
by --configs (default: both):

  swiftshader-gl  --use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader (the
                  browser tests' switches before they added --disable-gpu-compositing): WebGL on
                  SwiftShader, and Chromium's compositing too ("Compositing: Hardware
                  accelerated" in chrome://gpu, on the software GPU): about 30 ms of the GPU
                  process's CPU for each frame displayed, even of a bare canvas
  as-installed    no GL switch: Chromium's own choice on a machine without a GPU, what a user's
                  Chromium does here (chrome://gpu: "Compositing: Software only"; WebGL still on
                  SwiftShader, through ANGLE on SwiftShader's Vulkan)
  sw-compositing  swiftshader-gl with --disable-gpu-compositing: the same split as as-installed,
                  with SwiftShader asked for by name; the browser tests' switches

For each case the intervals between requestAnimationFrame callbacks are recorded for S seconds
(after 1 s to settle) and their median and 90th percentile printed, and the frames Chromium's
display compositor put on the screen in that time (Display::FrameDisplayed trace events, through
chromedriver's performance log), their rate and median interval: a page can get animation
frames at 60/s and still be displayed at far fewer (a desynchronized or OffscreenCanvas context
runs its requestAnimationFrame free of the compositor: 16.7 ms between callbacks, 50 ms between
frames shown, measured). The cases:

  raf         an empty page: the browser's own frame clock, nothing drawn
  webgl       a bare WebGL canvas of the player's size, cleared to a new colour every frame
              (Chromium's cost of presenting and compositing a canvas that changes each frame)
  desync      the same with the context attribute desynchronized: true (its animation frames
              run free of the compositor: their interval says nothing of the frames displayed)
  offscreen   the same cleared by a worker (transferControlToOffscreen; the worker's script from
              a Blob URL, as a page from file:// may load it): the page's own animation frames
              are empty, the frames displayed are the worker's
  empty       the report page with the player playing, its body, floor and shadow hidden: three.js
              clearing an empty scene each frame (plus the player's per-frame page work)
  whole       the player playing, at 1× speed, oblique view, every frame drawn whole (a
              bundle older than setDrawAll() draws every frame whole anyway: the same as player)
  player      the same, each frame drawing only the part of the picture that changed (the
              player's way: while the camera stays, only where the body and shadow are)
  follow      the player playing in the follow view: the camera moves with the body, so every
              frame is drawn whole
  paused      the same, paused (nothing changes, so nothing should be drawn)

and, for the player, the cost of one frame (the pose, read-outs and drawing) drawn and waited for
(a pixel read back), without the browser's compositing: drawn whole and drawn in part. The cases run in turn, N rounds, so that a slow moment of the machine
shows as a spread rather than as one case's figure."""
import argparse
import collections
import os
import pathlib
import shutil
import statistics
import sys
import tempfile
import time

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
except ImportError:
    print("selenium is not installed (Debian: python3-selenium)")
    sys.exit(77)

CHROMIUM = "/usr/bin/chromium"
DRIVER = "/usr/bin/chromedriver"
BASE_FLAGS = [
    "--headless=new",
    "--no-sandbox",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--force-device-scale-factor=1",
    "--window-size=1700,1100",
]
SWIFTSHADER_GL = ["--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"]
CONFIGS = {
    "swiftshader-gl": SWIFTSHADER_GL,
    "as-installed": [],
    "sw-compositing": SWIFTSHADER_GL + ["--disable-gpu-compositing"],
}
FLAGS = BASE_FLAGS + CONFIGS["sw-compositing"]  # the browser tests' (check_player.py)
TRACE_CATEGORIES = "blink.user_timing,disabled-by-default-display.framedisplayed"

FRAMES_JS = "const done = arguments[arguments.length - 1]; requestAnimationFrame(() => done(true));"

# Records requestAnimationFrame timestamps for `seconds` after `settle` seconds.
RECORD_JS = """
const [settle, seconds, mark, done] = arguments;
const stamps = [];
let startAt = null;
function tick(now) {
  if (startAt === null) startAt = now;
  if (now - startAt >= 1000 * settle) {
    if (!stamps.length) performance.mark(mark + '-start');  // in the trace: where to count
    stamps.push(now);
  }
  if (now - startAt < 1000 * (settle + seconds)) requestAnimationFrame(tick);
  else {
    performance.mark(mark + '-end');
    done(stamps);
  }
}
requestAnimationFrame(tick);
"""

BLANK_PAGE = """<!DOCTYPE html><html><head><meta charset="utf-8"><title>raf</title></head>
<body style="margin:0;background:#fff"><p>nothing drawn</p></body></html>"""

# A bare WebGL canvas, cleared to a new colour each frame: the presenting and compositing of a
# canvas that changes every frame, with nothing of the page's own.
WEBGL_PAGE = """<!DOCTYPE html><html><head><meta charset="utf-8"><title>webgl</title></head>
<body style="margin:0;background:#fff"><canvas id="c" width="%d" height="%d"
 style="display:block;width:%dpx;height:%dpx"></canvas><script>
const gl = document.getElementById('c').getContext('webgl2', {antialias: false,
  preserveDrawingBuffer: %s, powerPreference: 'low-power', desynchronized: %s});
let k = 0;
function draw() {
  k = (k + 1) %% 60;
  gl.clearColor(0.9, 0.9 + k / 600, 0.95, 1);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  requestAnimationFrame(draw);
}
requestAnimationFrame(draw);
</script></body></html>"""

# The bare canvas cleared by a worker through an OffscreenCanvas.
OFFSCREEN_PAGE = """<!DOCTYPE html><html><head><meta charset="utf-8"><title>offscreen</title></head>
<body style="margin:0;background:#fff"><canvas id="c" width="%d" height="%d"
 style="display:block;width:%dpx;height:%dpx"></canvas>
<script id="worker" type="text/plain">
onmessage = (e) => {
  const gl = e.data.getContext('webgl2', {antialias: false, powerPreference: 'low-power'});
  let k = 0;
  function draw() {
    k = (k + 1) %% 60;
    gl.clearColor(0.9, 0.9 + k / 600, 0.95, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    requestAnimationFrame(draw);
  }
  requestAnimationFrame(draw);
};
</script><script>
const canvas = document.getElementById('c').transferControlToOffscreen();
const source = new Blob([document.getElementById('worker').textContent], {type: 'text/javascript'});
new Worker(URL.createObjectURL(source)).postMessage(canvas, [canvas]);
</script></body></html>"""

# The player's cost per frame on the CPU and SwiftShader, waited for, without compositing.
DRAW_COST_JS = """
const element = arguments[0], count = arguments[1];
const p = window.RattlebackPlayer.players[0];
const gl = p.renderer.getContext();
const span = p.tEnd - p.t0;
const h = element.rbPlayer;
const pixel = new Uint8Array(4);
gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
let start = performance.now();
const costs = [];
for (const whole of [true, false]) {
  if (h.setDrawAll) h.setDrawAll(whole);
  p.render();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  let start = performance.now();
  for (let i = 0; i < count; i++) {
    p.applyTime(p.t0 + span * (0.5 + 0.2 * i / count));  // 0.2 of the run in `count` frames
    p.render();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  }
  costs.push((performance.now() - start) / count);
}
if (h.setDrawAll) h.setDrawAll(false);
return costs;
"""


def processes(root):
    """{pid: kind} of root's descendants that are Chromium's: browser, gpu-process, renderer, …"""
    children = collections.defaultdict(list)
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    fields = f.read().rsplit(")", 1)[1].split()
                children[int(fields[1])].append(int(entry))
            except OSError:
                pass
    found, todo = {}, [root]
    while todo:
        pid = todo.pop()
        for child in children[pid]:
            todo.append(child)
            try:
                with open(f"/proc/{child}/cmdline", "rb") as f:
                    args = [a for a in f.read().decode(errors="replace").split("\0") if a]
            except OSError:
                continue
            if len(args) == 1:  # a process that set its title: one string
                args = args[0].split(" ")
            if not args:
                continue
            if "chrom" not in os.path.basename(args[0]):
                continue
            kind = next((a.split("=", 1)[1] for a in args if a.startswith("--type=")), "browser")
            if kind == "utility":
                kind = next(
                    (
                        a.split("=", 1)[1].rsplit(".", 1)[-1]
                        for a in args
                        if a.startswith("--utility-sub-type=")
                    ),
                    kind,
                )
            found[child] = kind
    return found


def cpu_seconds(pids):
    """{pid: user + system CPU seconds so far}."""
    tick = os.sysconf("SC_CLK_TCK")
    out = {}
    for pid in pids:
        try:
            with open(f"/proc/{pid}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            out[pid] = (int(fields[11]) + int(fields[12])) / tick
        except OSError:
            pass
    return out


def stats(stamps):
    gaps = sorted(b - a for a, b in zip(stamps, stamps[1:]))
    if not gaps:
        return float("nan"), float("nan"), 0
    p90 = gaps[min(len(gaps) - 1, int(round(0.9 * (len(gaps) - 1))))]
    return statistics.median(gaps), p90, len(gaps)


def displayed(log, marks):
    """{mark: (frames displayed, their rate /s, median interval ms)} between each record's two
    marks (performance.mark), from chromedriver's performance log: the trace of the whole session,
    which chromedriver collects once, at the first get_log. A mark not in the trace is left out."""
    import json

    times, shown = {}, []
    for entry in log:
        message = json.loads(entry["message"])["message"]
        if message.get("method") != "Tracing.dataCollected":
            continue
        event = message["params"]
        name = event.get("name", "")
        if name == "Display::FrameDisplayed":
            shown.append(event["ts"] / 1000)
        elif name.startswith("rb-bench-") and event.get("ph") in ("R", "I", "n", "b", "e", "X"):
            times.setdefault(name, event["ts"] / 1000)
    shown.sort()
    out = {}
    for mark in marks:
        a, b = times.get(mark + "-start"), times.get(mark + "-end")
        if a is None or b is None:
            continue
        seen = [t for t in shown if a <= t <= b]
        gaps = sorted(y - x for x, y in zip(seen, seen[1:]))
        out[mark] = (len(seen), 1000 * len(seen) / (b - a), statistics.median(gaps) if gaps else float("nan"))
    return out


class Bench:
    def __init__(self, size, seconds, config="swiftshader-gl"):
        self.size = size
        self.seconds = seconds
        self.scratch = pathlib.Path(tempfile.mkdtemp(prefix="rattleback-player-bench-"))
        (self.scratch / "raf.html").write_text(BLANK_PAGE)
        w, h = size
        (self.scratch / "webgl.html").write_text(WEBGL_PAGE % (w, h, w, h, "false", "false"))
        (self.scratch / "desync.html").write_text(WEBGL_PAGE % (w, h, w, h, "false", "true"))
        (self.scratch / "offscreen.html").write_text(OFFSCREEN_PAGE % (w, h, w, h))
        options = webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        for flag in BASE_FLAGS + CONFIGS[config] + [f"--user-data-dir={self.scratch / 'profile'}"]:
            options.add_argument(flag)
        options.set_capability("goog:loggingPrefs", {"performance": "ALL"})
        options.add_experimental_option(
            "perfLoggingPrefs",
            {"traceCategories": TRACE_CATEGORIES, "enableNetwork": False, "enablePage": False},
        )
        self.driver = webdriver.Chrome(service=Service(DRIVER), options=options)
        self.driver.set_script_timeout(120)
        self.records = []  # [(mark, figures)]: the frames displayed filled in by collect()

    def close(self):
        self.driver.quit()
        shutil.rmtree(self.scratch, ignore_errors=True)

    def js(self, script, *args):
        return self.driver.execute_script(script, *args)

    def record(self):
        """[median, p90, intervals, {process kind: CPU ms per frame}, displayed] of the page as it
        runs; displayed: (frames, per second, median interval ms), None until collect()."""
        kinds = processes(self.driver.service.process.pid)
        self.driver.execute_async_script(FRAMES_JS)
        mark = f"rb-bench-{len(self.records)}"
        before = cpu_seconds(kinds)
        stamps = self.driver.execute_async_script(RECORD_JS, 1.0, self.seconds, mark)
        after = cpu_seconds(kinds)
        median, p90, count = stats(stamps)
        # CPU over the settling second too: per frame, counting the frames of that second alike.
        frames = max(1, count) * (1.0 + self.seconds) / self.seconds
        cpu = collections.Counter()
        for pid, kind in kinds.items():
            if pid in before and pid in after:
                cpu[kind] += 1000 * (after[pid] - before[pid]) / frames
        figures = [median, p90, count, cpu, None]
        self.records.append((mark, figures))
        return figures

    def collect(self):
        """Fills in each record's frames displayed, from the session's trace (once: at the end)."""
        shown = displayed(self.driver.get_log("performance"), [mark for mark, _ in self.records])
        for mark, figures in self.records:
            figures[4] = shown.get(mark)

    def scratch_page(self, name):
        self.driver.get((self.scratch / name).as_uri())
        return self.record()

    def open_player(self, folder):
        self.driver.get((folder / "index.html").as_uri())
        deadline = time.time() + 30
        while time.time() < deadline:
            if self.js("const e = document.querySelector('.rb-player'); return !!(e && e.rbPlayer);"):
                break
            time.sleep(0.2)
        else:
            raise RuntimeError(f"no player built on {folder / 'index.html'}")
        element = self.driver.find_element("css selector", ".rb-player")
        self.js("arguments[0].scrollIntoView({block: 'start'});", element)
        self.js(
            "const h = arguments[0].rbPlayer; h.setSize(arguments[1], arguments[2]); "
            "h.setView('oblique'); h.setSpeed(1); h.setTime(h.range()[0]);",
            element,
            *self.size,
        )
        return element

    def playing(self, element, hide, whole=False):
        self.js(
            """const p = window.RattlebackPlayer.players[0];
                   const h = arguments[0].rbPlayer;
                   if (h.setDrawAll) h.setDrawAll(arguments[2]);
                   p.points.visible = !arguments[1]; p.floor.visible = !arguments[1];
                   if (p.shadow) p.shadow.visible = !arguments[1];
                   p.setTime(p.t0, true); h.play();""",
            element,
            hide,
            whole,
        )
        result = self.record()
        self.js("arguments[0].rbPlayer.pause();", element)
        return result

    def baselines(self):
        return {name: self.scratch_page(f"{name}.html") for name in ["raf", "webgl", "desync", "offscreen"]}

    def run(self, folder):
        results = {}
        element = self.open_player(folder)
        results["empty"] = self.playing(element, True)
        results["whole"] = self.playing(element, False, True)
        results["player"] = self.playing(element, False)
        self.js("arguments[0].rbPlayer.setView('follow');", element)
        results["follow"] = self.playing(element, False)
        self.js("arguments[0].rbPlayer.setView('oblique');", element)
        self.js("arguments[0].rbPlayer.pause();", element)
        results["paused"] = self.record()
        cost = self.js(DRAW_COST_JS, element, 30)
        return results, cost


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("dirs", nargs="+", metavar="DIR")
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument(
        "--configs",
        default="swiftshader-gl,as-installed",
        help="Chromium's configurations, from: " + ", ".join(CONFIGS),
    )
    args = parser.parse_args()
    folders = [pathlib.Path(d).resolve() for d in args.dirs]
    size = [int(v) for v in args.size.split("x")]
    configs = [c for c in args.configs.split(",") if c]
    unknown = [c for c in configs if c not in CONFIGS]
    if unknown:
        parser.error(f"unknown configuration {unknown[0]!r} (known: {', '.join(CONFIGS)})")
    if not (pathlib.Path(CHROMIUM).exists() and pathlib.Path(DRIVER).exists()):
        print("chromium or chromedriver is not installed")
        return 77
    print(
        f"canvas {size[0]}×{size[1]}, {args.seconds:g} s per case; intervals between animation "
        f"frames and between frames displayed, ms; load average {open('/proc/loadavg').read().split()[0]}"
    )
    summary = collections.defaultdict(list)  # (config, where, case): [(rAF median, displayed median)]

    def line(round_, config, where, name, figures):
        median, p90, count, cpu, shown = figures
        use = ", ".join(f"{kind} {ms:.1f}" for kind, ms in cpu.most_common(3) if ms >= 0.05)
        seen = (
            f"displayed {shown[1]:5.1f}/s, median {shown[2]:6.1f}"
            if shown and shown[0] > 1
            else "displayed none"
            if shown
            else "displayed n/a"
        )
        summary[(config, where, name)].append((median, shown[2] if shown and shown[0] > 1 else float("nan")))
        print(
            f"  round {round_ + 1} {config:>14s} {where:>12s} {name:7s} rAF median {median:6.1f}  p90 {p90:6.1f}; "
            f"{seen}; CPU ms per rAF: {use}",
            flush=True,
        )

    for round_ in range(args.rounds):
        for config in configs:
            bench = Bench(size, args.seconds, config)
            try:
                cases = [("(baseline)", bench.baselines(), None)]
                for folder in folders:
                    results, cost = bench.run(folder)
                    cases.append((folder.name, results, cost))
                bench.collect()
            finally:
                bench.close()
            for where, results, cost in cases:
                for name, figures in results.items():
                    line(round_, config, where, name, figures)
                if cost:
                    print(
                        f"  round {round_ + 1} {config:>14s} {where:>12s} one frame (pose, read-outs, "
                        f"render) drawn and read back: whole {cost[0]:.1f} ms, the changed part {cost[1]:.1f} ms",
                        flush=True,
                    )
    print(f"load average {open('/proc/loadavg').read().split()[0]}")
    print("over the rounds: median (min–max) of each round's median interval, ms")
    for (config, where, name), values in summary.items():
        raf = [v[0] for v in values]
        shown = [v[1] for v in values if v[1] == v[1]]
        seen = f"{statistics.median(shown):6.1f} ({min(shown):.1f}–{max(shown):.1f})" if shown else "   n/a"
        print(
            f"  {config:>14s} {where:>12s} {name:7s} rAF {statistics.median(raf):6.1f} "
            f"({min(raf):.1f}–{max(raf):.1f})  displayed {seen}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
