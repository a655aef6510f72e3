#!/usr/bin/python3
"""Opens DIR/index.html in headless Chromium (Selenium, Debian's chromium and chromium-driver)
and checks what a reader would see: the page loads with no console errors, every image decodes
(naturalWidth > 0), every video reaches readyState >= 2 with the expected duration, and its
currentTime advances when it plays; and no image or video is drawn larger than its own size.

For a classroom, at a 1280 × 720, a 1920 × 1080 and a 4:3 projector's 1024 × 768 viewport: no video has the
browser's controls (they lie over its bottom edge, where the inset is drawn) and each has the
page's own bar below it, not over it; the player's keys, P (present) among them, are listed on
the page; the player offers the body spun both ways, and its buttons and S switch the run
played; each video's bar is no wider than it; present mode (P) fills the viewport with the
picture, whole, and large read-outs that lie inside it, the title as large as they are; R there
stops at the reversal with its sense said, no empty box over the picture and the picture as
drawn whole; and Esc leaves it; full screen (F) gives the picture the height the controls
leave, and Esc leaves it too. Each player draws the body as its scene does: triangles where its
video.surface says so, else points. With SCREENSHOT_DIR, the page at its first video, the player
switched to its other spin and in present mode are saved there at both sizes (report-WxH.png,
spins-WxH.png, present-WxH.png, present-reversal-WxH.png), to look at.

Usage: check_report.py DIR EXPECTED_VIDEO_SECONDS [SCREENSHOT_DIR]
Exit status 0 when every check passes, 1 when one fails (each failure printed), 77 when
Selenium or Chromium is not installed (CTest's "skipped")."""
import pathlib
import sys
import time

try:
    import selenium  # noqa: F401  (the checks below drive it through chromium.py)
except ImportError:
    print("selenium is not installed (Debian: python3-selenium); skipped")
    sys.exit(77)

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import chromium  # noqa: E402  (tests/browser/chromium.py: one Chromium setup for the checks)


def classroom(driver, size, failures, screenshots):
    """The page's layout for a classroom at a viewport of `size` (module docstring)."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.keys import Keys

    w, h = size
    where = f"{w}x{h}"
    driver.execute_cdp_cmd(
        "Emulation.setDeviceMetricsOverride",
        {"width": w, "height": h, "deviceScaleFactor": 1, "mobile": False},
    )
    time.sleep(0.3)
    videos = driver.execute_script(
        """return Array.from(document.querySelectorAll('video')).map(v => {
            const r = v.getBoundingClientRect();
            const bar = v.parentElement.querySelector('.vbar');
            const b = bar && !bar.hidden ? bar.getBoundingClientRect() : null;
            const pair = v.closest('.pair');
            return {src: v.getAttribute('src'), controls: v.hasAttribute('controls'),
                    bottom: r.bottom, left: r.left, right: r.right,
                    pair: pair ? Array.from(document.querySelectorAll('.pair')).indexOf(pair) : -1,
                    bar: b && {top: b.top, height: b.height, width: b.width}};
        });"""
    )
    # Videos side by side have their bars in line (a teacher's trial: 16 px apart, where one
    # caption was longer than the other).
    for pair in {v["pair"] for v in videos if v["pair"] >= 0 and v["bar"]}:
        in_pair = [v for v in videos if v["pair"] == pair and v["bar"]]
        rows = {}
        for v in in_pair:  # the same row: videos whose bottoms are level (a wrapped pair is not)
            rows.setdefault(round(v["bottom"]), []).append(v)
        for row in rows.values():
            tops = [v["bar"]["top"] for v in row]
            heights = [v["bar"]["height"] for v in row]
            # Half a pixel: layout places boxes at fractions of a pixel; out of line was 5-16 px.
            if max(tops) - min(tops) > 0.5 or max(heights) - min(heights) > 0.5:
                failures.append(
                    f"{where}: the bars under {[v['src'] for v in row]} are not in line "
                    f"(tops {tops}, heights {heights})"
                )
    for v in videos:
        if v["controls"]:
            failures.append(f"{where}: video {v['src']} has the browser's controls, over its inset")
        if not v["bar"] or v["bar"]["height"] <= 0:
            failures.append(f"{where}: video {v['src']} has no controls of the page's own")
        elif v["bar"]["top"] < v["bottom"] - 0.5:
            failures.append(
                f"{where}: video {v['src']}: its bar (top {v['bar']['top']}) lies over it (bottom {v['bottom']})"
            )
        # The bar belongs to its video: no wider than it (a 320- or 640-wide video's slider and
        # Full screen button ran on across the page).
        elif v["bar"]["width"] > v["right"] - v["left"] + 0.5:
            failures.append(
                f"{where}: video {v['src']} is {v['right'] - v['left']:.0f} px wide, its bar "
                f"{v['bar']['width']:.0f} px"
            )
    # The page's own bar works: its play button plays the video.
    played = driver.execute_async_script(
        """const done = arguments[arguments.length - 1];
        const f = document.querySelector('figure.vid'); if (!f) { done(null); return; }
        const v = f.querySelector('video'); v.pause();
        f.querySelector('.vplay').click();
        setTimeout(() => done([!v.paused, f.querySelector('.vplay').textContent]), 500);"""
    )
    if played is None or not played[0] or "Pause" not in played[1]:
        failures.append(f"{where}: the page's play button did not play the first video ({played})")
    driver.execute_script("document.querySelectorAll('video').forEach(v => v.pause());")
    if screenshots:
        out = pathlib.Path(screenshots)
        out.mkdir(parents=True, exist_ok=True)
        driver.execute_script("document.querySelector('figure.vid').scrollIntoView({block: 'start'});")
        time.sleep(0.5)
        driver.save_screenshot(str(out / f"report-{where}.png"))
    players = driver.find_elements(By.CSS_SELECTOR, ".rb-player")
    if not players or not driver.execute_script("return !!arguments[0].rbPlayer;", players[0]):
        return
    player = players[0]
    keys = driver.execute_script(
        "return arguments[0].previousElementSibling ? arguments[0].previousElementSibling.textContent : '';",
        player,
    )
    for said in ["P present", "Esc", "F full screen", "R the next reversal", "S the other spin"]:
        if said not in keys:
            failures.append(f"{where}: the page does not say the player's key {said!r} ({keys!r})")
    driver.execute_script("arguments[0].scrollIntoView({block: 'start'});", player)
    both_spins(driver, player, where, failures, screenshots)
    player.find_element(By.CSS_SELECTOR, ".rbp-title").click()
    ActionChains(driver).send_keys("p").perform()
    time.sleep(0.8)
    got = driver.execute_script(
        """const root = arguments[0].querySelector('.rbp');
        const box = e => { const r = e.getBoundingClientRect();
                           return [r.left, r.top, r.right, r.bottom]; };
        return {present: root.classList.contains('rbp-present'),
                stage: box(root.querySelector('.rbp-stage')),
                read: box(root.querySelector('.rbp-spin')),
                side: box(root.querySelector('.rbp-side')),
                plot: box(root.querySelector('.rbp-plotbox')),
                plotPixels: root.querySelector('.rbp-plot').width / (window.devicePixelRatio || 1),
                font: parseFloat(getComputedStyle(root.querySelector('.rbp-spin')).fontSize),
                title: parseFloat(getComputedStyle(root.querySelector('.rbp-title')).fontSize),
                vw: document.documentElement.clientWidth, vh: document.documentElement.clientHeight};""",
        player,
    )
    if not got["present"]:
        failures.append(f"{where}: P did not enter present mode")
    else:
        vw, vh = got["vw"], got["vh"]
        left, top, right, bottom = got["stage"]
        inside = lambda b: b[0] >= -0.5 and b[1] >= -0.5 and b[2] <= vw + 0.5 and b[3] <= vh + 0.5
        # The picture, whole, filling the screen but for the bar and views below it (110 px)
        # and the 12 px margin, whatever the screen's shape (kept at 16:9 it left a 4:3
        # projector a blank fifth of the screen under it).
        if not inside(got["stage"]) or right - left < vw - 24 - 2 or bottom - top < vh - 110 - 2:
            failures.append(
                f"{where}: in present mode the picture is {got['stage']}, not whole in a "
                f"{vw}x{vh} viewport and {vw - 24} x {vh - 110} px"
            )
        # The read-outs over the picture, not on the margin beside it (a teacher's trial: on a
        # screen wider than 16:9 the box sat at the screen's left edge, half off the picture).
        side = got["side"]
        if not (
            side[0] >= left - 0.5
            and side[2] <= right + 0.5
            and side[1] >= top - 0.5
            and side[3] <= bottom + 0.5
        ):
            failures.append(
                f"{where}: in present mode the read-outs {side} are not over the picture {got['stage']}"
            )
        # Below 900 px high the read-outs keep to the picture's top 30 %: at 1280 x 720 their six
        # lines reached 43 % down, over the far end of a body spun -8 rad/s (a teacher's trial).
        if vh < 900 and side[3] - top > 0.3 * (bottom - top):
            failures.append(
                f"{where}: in present mode the read-outs {side} reach more than 30 % down the "
                f"picture {got['stage']}"
            )
        # The n(t) plot over the picture's bottom right (a teacher's trial: present mode dropped
        # it), scaled up where the screen is 900 px high or more (at 1280 x 720 scaled it hid
        # the spin cue's arrowhead), clear of the read-outs.
        plot = got["plot"]
        clear = plot[0] >= side[2] or plot[1] >= side[3]
        if not (
            plot[0] >= left - 0.5
            and plot[2] <= right + 0.5
            and plot[1] >= top - 0.5
            and plot[3] <= bottom + 0.5
            and plot[2] - plot[0] >= (1.5 if vh >= 900 else 1.3 if vw >= 1.6 * vh else 1) * 272
            and clear
        ):
            failures.append(
                f"{where}: in present mode the n(t) plot {plot} is not over the picture "
                f"{got['stage']}, its 272 px 1.3 times on a 16:10 screen or wider (1.5 from 900 px "
                f"high) and clear of the "
                f"read-outs {side}"
            )
        # Drawn at twice the pixel ratio, as it is scaled up.
        finer = 2
        if abs(got["plotPixels"] - finer * 270) > 1:
            failures.append(
                f"{where}: in present mode the n(t) plot is drawn {got['plotPixels']} px wide "
                f"per CSS pixel ratio, not {finer * 270} at {vw}x{vh}"
            )
        # The read-outs' type: a 28th of the screen's height, at least 26 px, no larger than
        # 2.3 % of its width (docs/commands.md), the title in the same type, read from the back of
        # a room as they are.
        size = min(max(26, vh / 28), 0.023 * vw)
        if not inside(got["read"]) or got["font"] < size - 1:
            failures.append(
                f"{where}: in present mode the spin read-out is {got['font']} px at {got['read']}"
            )
        if abs(got["title"] - size) > 1 or abs(got["title"] - got["font"]) > 0.5:
            failures.append(
                f"{where}: in present mode the title is {got['title']} px, the read-outs "
                f"{got['font']} px, not {size:.1f} px at {vw}x{vh}"
            )
        present_reversal(driver, player, where, failures, screenshots)
        if screenshots:
            driver.save_screenshot(str(pathlib.Path(screenshots) / f"present-{where}.png"))
    ActionChains(driver).send_keys(Keys.ESCAPE).perform()
    time.sleep(0.5)
    if driver.execute_script(
        "return arguments[0].querySelector('.rbp').classList.contains('rbp-present');", player
    ):
        failures.append(f"{where}: Esc did not leave present mode")
    full_screen(driver, player, where, failures, screenshots)


def full_screen(driver, player, where, failures, screenshots):
    """F: the picture takes the screen's height that the bar and views leave (a teacher's trial
    at 1280 x 720: a 16:9 picture left 120 px empty below them), and Esc leaves."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.keys import Keys

    player.find_element(By.CSS_SELECTOR, ".rbp-title").click()
    ActionChains(driver).send_keys("f").perform()
    time.sleep(0.8)
    got = driver.execute_script(
        """const root = arguments[0].querySelector('.rbp');
        const box = e => { const r = e.getBoundingClientRect();
                           return [r.left, r.top, r.right, r.bottom]; };
        const c = root.querySelector('canvas');
        return {full: document.fullscreenElement === root, stage: box(root.querySelector('.rbp-stage')),
                views: box(root.querySelector('.rbp-views')), canvas: [c.width, c.height],
                vw: document.documentElement.clientWidth, vh: document.documentElement.clientHeight};""",
        player,
    )
    if not got["full"]:
        failures.append(f"{where}: F did not make the player full screen")
        return
    vh, stage, views = got["vh"], got["stage"], got["views"]
    # Below the views' row only the page's padding (16 px) and a rounding.
    if views[3] > vh + 0.5 or vh - views[3] > 16 + 4:
        failures.append(
            f"{where}: in full screen the views' row ends at {views[3]:.0f} px of {vh}: "
            f"{vh - views[3]:.0f} px unused below the picture {stage}"
        )
    # The canvas is drawn at the stage's size, not stretched from a 16:9 one.
    w, h = stage[2] - stage[0], stage[3] - stage[1]
    if abs(got["canvas"][0] / got["canvas"][1] - w / h) > 0.02:
        failures.append(
            f"{where}: in full screen the canvas {got['canvas']} is drawn for another shape than its {w:.0f}x{h:.0f} stage"
        )
    if screenshots:
        driver.save_screenshot(str(pathlib.Path(screenshots) / f"fullscreen-{where}.png"))
    ActionChains(driver).send_keys(Keys.ESCAPE).perform()
    time.sleep(0.5)
    if driver.execute_script("return !!document.fullscreenElement;"):
        failures.append(f"{where}: Esc did not leave full screen")


def present_reversal(driver, player, where, failures, screenshots):
    """In present mode, R goes to the reversal, paused: the sense's line says something (a
    blank line there was taken for a read-out gone missing), no box with a background over the
    picture is empty, and the picture drawn in part since entering present mode is the one
    drawn whole."""
    from selenium.webdriver.common.action_chains import ActionChains

    ActionChains(driver).send_keys("r").perform()
    time.sleep(0.8)
    got = driver.execute_script(
        """const e = arguments[0], root = e.querySelector('.rbp'), p = e.rbPlayer;
        const stage = root.querySelector('.rbp-stage').getBoundingClientRect();
        const empty = [];
        for (const x of root.querySelectorAll('*')) {
          const s = getComputedStyle(x), r = x.getBoundingClientRect();
          if (x instanceof SVGElement || x.tagName === 'CANVAS' || x.tagName === 'INPUT') continue;
          if (s.display === 'none' || s.visibility === 'hidden' || !(r.width > 1 && r.height > 1)) continue;
          if (r.right <= stage.left || r.left >= stage.right || r.bottom <= stage.top || r.top >= stage.bottom) continue;
          if (x.classList.contains('rbp-stage')) continue;
          // (the n(t) plot's cursor and dot mark the time on it: drawn, not empty)
          if (x.closest('.rbp-plotbox')) continue;
          const painted = s.backgroundColor !== 'rgba(0, 0, 0, 0)' && s.backgroundColor !== 'transparent';
          if (painted && !x.textContent.trim()) empty.push([x.className, Math.round(r.left), Math.round(r.top), Math.round(r.width), Math.round(r.height)]);
        }
        const grab = () => {
          const src = root.querySelector('.rbp-stage canvas'), c = document.createElement('canvas');
          c.width = src.width; c.height = src.height;
          const g = c.getContext('2d'); g.drawImage(src, 0, 0);
          return g.getImageData(0, 0, c.width, c.height).data;
        };
        const before = grab();
        // (the canvas is opaque: a part never drawn since it was resized reads black)
        let undrawn = 0;
        for (let i = 0; i < before.length; i += 4)
          if (before[i] < 8 && before[i + 1] < 8 && before[i + 2] < 8) undrawn++;
        p.renderAll();
        const after = grab();
        let differ = 0;
        for (let i = 0; i < before.length; i += 4)
          if (Math.abs(before[i] - after[i]) + Math.abs(before[i + 1] - after[i + 1]) + Math.abs(before[i + 2] - after[i + 2]) > 12) differ++;
        return {time: p.time(), reversals: p.reversals(), playing: p.playing(), empty, differ, undrawn,
                pixels: before.length / 4,
                sense: root.querySelector('.rbp-sense').textContent,
                label: root.querySelector('.rbp-reversal-label').textContent,
                labelBox: (r => [r.left, r.top, r.right, r.bottom])(root.querySelector('.rbp-reversal-label').getBoundingClientRect()),
                sideBox: (r => [r.left, r.top, r.right, r.bottom])(root.querySelector('.rbp-side').getBoundingClientRect())};""",
        player,
    )
    if not got["reversals"] or abs(got["time"] - got["reversals"][0]) > 1e-6 or got["playing"]:
        failures.append(f"{where}: in present mode R did not stop at the reversal: {got}")
        return
    if not got["sense"].strip() or "not spinning" not in got["sense"]:
        failures.append(f"{where}: at the reversal the sense's line says {got['sense']!r}")
    if got["empty"]:
        failures.append(f"{where}: at the reversal, empty boxes over the picture: {got['empty']}")
    # The reversal label clear of the read-outs (on a 4:3 projector they had covered its start).
    a, b = got["labelBox"], got["sideBox"]
    if a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]:
        failures.append(f"{where}: the reversal label {a} lies under the read-outs {b}")
    if got["undrawn"] > 0.001 * got["pixels"]:
        failures.append(f"{where}: at the reversal {got['undrawn']} pixels of the picture were never drawn")
    if got["differ"] > 0:
        failures.append(
            f"{where}: at the reversal {got['differ']} pixels differ from the picture drawn whole"
        )
    if screenshots:
        driver.save_screenshot(str(pathlib.Path(screenshots) / f"present-reversal-{where}.png"))


def both_spins(driver, player, where, failures, screenshots):
    """The default scene spun -5 rad/s reverses; its player offers it spun +5 rad/s too, which
    does not: two buttons, each saying its spin and what its run did, the first pressed. A click
    on the second plays that run (its read-out, its reversals: none, the Reversal button off), at
    the same moment; S switches back."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.action_chains import ActionChains

    state = """const p = arguments[0].rbPlayer, root = arguments[0].querySelector('.rbp');
        return {labels: Array.from(root.querySelectorAll('.rbp-spun')).map(b => b.textContent),
                pressed: Array.from(root.querySelectorAll('.rbp-spun')).map(b => b.getAttribute('aria-pressed')),
                index: p.runIndex(), reversals: p.reversals(), time: p.time(), spin: p.spin(),
                readout: root.querySelector('.rbp-read.rbp-spin').textContent,
                reversalOff: root.querySelector('.rbp-reversal').disabled,
                help: root.querySelector('.rbp-help').textContent};"""
    driver.execute_script("arguments[0].rbPlayer.setTime(1.5);", player)
    got = driver.execute_script(state, player)
    first = "\u22125 rad/s: reverses at "
    if (
        len(got["labels"]) != 2
        or not got["labels"][0].startswith(first)
        or got["labels"][1] != "+5 rad/s: no reversal"
    ):
        failures.append(f"{where}: the player's spins are {got['labels']}, not −5 (reverses) and +5")
        return
    if got["pressed"] != ["true", "false"] or got["index"] != 0 or len(got["reversals"]) != 1:
        failures.append(f"{where}: the scene's own run is not the one shown first: {got}")
    # Its label is of the run's own reversal, to the hundredth.
    if got["reversals"] and got["labels"][0] != f"{first}{got['reversals'][0]:.2f} s":
        failures.append(f"{where}: the label {got['labels'][0]!r} is not its reversal {got['reversals']}")
    player.find_elements(By.CSS_SELECTOR, ".rbp-spun")[1].click()
    time.sleep(0.3)
    other = driver.execute_script(state, player)
    if (
        other["index"] != 1
        or other["pressed"] != ["false", "true"]
        or other["reversals"] != []
        or not other["reversalOff"]
        or abs(other["time"] - 1.5) > 1e-9
        or not other["spin"] > 1
        or "+" not in other["readout"]
        or "No reversal" not in other["help"]
    ):
        failures.append(f"{where}: the second spin's button did not play the run spun +5 rad/s: {other}")
    if screenshots:
        driver.save_screenshot(str(pathlib.Path(screenshots) / f"spins-{where}.png"))
    player.find_element(By.CSS_SELECTOR, ".rbp-title").click()
    ActionChains(driver).send_keys("s").perform()
    time.sleep(0.3)
    back = driver.execute_script(state, player)
    if back["index"] != 0 or back["pressed"] != ["true", "false"] or not back["spin"] < -1:
        failures.append(f"{where}: S did not switch back to the run spun -5 rad/s: {back}")


def composited_present(folder, failures):
    """What the screen shows in present mode paused at the reversal at 1920 x 1080, through
    Chromium's GPU compositor (SwiftShader, as a machine without a GPU draws a page; the checks
    above read the canvas itself, which was right): no hole in the picture. An opaque box over
    the opaque canvas let the compositor leave out the canvas under it, and with the canvas
    drawn upside down (WebGL's rows) it left out the mirror image instead, a blank box the size
    of the reversal label at the picture's bottom right (a teacher's projector showed it). The
    hole's pixels are pure white or transparent; the floor and the body have none."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By

    driver, profile = chromium.open_browser(
        "--use-gl=swiftshader", "--enable-unsafe-swiftshader", "--hide-scrollbars", "--window-size=1920,1080"
    )
    try:
        driver.set_script_timeout(30)
        driver.execute_cdp_cmd(
            "Emulation.setDeviceMetricsOverride",
            {"width": 1920, "height": 1080, "deviceScaleFactor": 1, "mobile": False},
        )
        driver.get((folder / "index.html").as_uri())
        time.sleep(2)
        canvas = driver.find_elements(By.CSS_SELECTOR, ".rbp-stage canvas")[0]
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
        canvas.click()
        # P, then the run that reverses (S switches to the other spin when this one does not),
        # then R: paused at the reversal with its label shown.
        ActionChains(driver).send_keys("P").perform()
        time.sleep(1.0)
        reverses = "return [...document.querySelectorAll('*')].find(e => e.rbPlayer).rbPlayer.reversals().length > 0;"
        if not driver.execute_script(reverses):
            ActionChains(driver).send_keys("S").perform()
            time.sleep(1.0)
        ActionChains(driver).send_keys("R").perform()
        time.sleep(1.0)
        label = driver.execute_script(
            "const l = document.querySelector('.rbp-present .rbp-reversal-label');"
            "return l && getComputedStyle(l).display !== 'none' ? l.textContent : '';"
        )
        if "reversal" not in label:
            failures.append(f"composited: present mode at the reversal shows no reversal label ({label!r})")
        boxes = driver.execute_script(
            """const root = document.querySelector('.rbp.rbp-present');
            if (!root) return null;
            const r = e => { const b = e.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
            return {stage: r(root.querySelector('.rbp-stage')),
                    over: [...root.querySelectorAll('.rbp-side, .rbp-reversal-label')].map(r)};"""
        )
        if boxes is None:
            failures.append("composited: P did not enter present mode")
            return
        # The screenshot read back in the page (a canvas decodes the PNG; no imaging module).
        counted = driver.execute_async_script(
            """const [png, stage, over, done] = arguments;
            const img = new Image();
            img.onload = () => {
              const c = document.createElement('canvas');
              c.width = img.width; c.height = img.height;
              const g = c.getContext('2d');
              g.drawImage(img, 0, 0);
              const d = g.getImageData(0, 0, c.width, c.height).data;
              let holes = 0, total = 0;
              for (let y = Math.round(stage[1]) + 2; y < Math.round(stage[3]) - 2; y += 2)
                for (let x = Math.round(stage[0]) + 2; x < Math.round(stage[2]) - 2; x += 2) {
                  if (over.some(b => b[0] - 2 <= x && x <= b[2] + 2 && b[1] - 2 <= y && y <= b[3] + 2)) continue;
                  const i = 4 * (y * c.width + x);
                  total++;
                  if (d[i + 3] === 0 || (d[i] === 255 && d[i + 1] === 255 && d[i + 2] === 255)) holes++;
                }
              done([holes, total]);
            };
            img.src = 'data:image/png;base64,' + png;""",
            driver.get_screenshot_as_base64(),
            boxes["stage"],
            boxes["over"],
        )
        holes, total = counted
        # (a label-sized hole is 1.3 % of the picture; 0.1 % leaves room for stray highlights)
        if holes > 0.001 * total:
            failures.append(
                f"composited: in present mode at the reversal {holes} of {total} sampled pixels of "
                "the picture are a hole (white or transparent)"
            )
    finally:
        chromium.close(driver, profile)


def surfaces(driver, failures):
    """Each player draws the body as its scene's stills and videos do: a scene whose data has
    the surface's faces (video.surface: triangles) drawn as those triangles and no points, any
    other as its points (three.js's own count of what the picture drew, the floor's and the
    shadow's triangles among it). The page must have one of each."""
    drawn = driver.execute_script(
        """return Array.from(document.querySelectorAll('.rb-player')).filter(e => e.rbPlayer).map(e => {
            const p = e.rbPlayer, run = window.RATTLEBACK_RUNS[p.id];
            p.renderAll();
            const d = p.drawn();
            return {id: p.id, faces: run.faces ? run.faces.length / 3 : 0,
                    points: (run.top.length + run.bottom.length) / 3, drawn: d};
        });"""
    )
    for d in drawn:
        got = d["drawn"]
        if d["faces"]:
            if got["body"] != "triangles" or got["faces"] != d["faces"] or got["points"] != 0:
                failures.append(
                    f"player {d['id']}: its scene draws {d['faces']} triangles, the player drew {got}"
                )
            elif got["triangles"] < d["faces"]:
                failures.append(
                    f"player {d['id']}: {got['triangles']} triangles drawn, fewer than its {d['faces']}"
                )
        elif got["body"] != "points" or got["points"] != d["points"]:
            failures.append(f"player {d['id']}: its scene draws {d['points']} points, the player drew {got}")
    kinds = {bool(d["faces"]) for d in drawn}
    if kinds != {True, False}:
        failures.append(f"the page should have a player of triangles and one of points: {drawn}")


def main():
    folder = pathlib.Path(sys.argv[1]).resolve()
    expected = float(sys.argv[2])
    if not chromium.installed():
        print("chromium or chromedriver is not installed; skipped")
        return 77
    driver, profile = chromium.open_browser(
        "--disable-gpu", "--disable-quic", "--autoplay-policy=no-user-gesture-required"
    )
    failures = []
    try:
        driver.set_script_timeout(30)
        driver.get((folder / "index.html").as_uri())
        # Images: every one decoded.
        images = driver.execute_script(
            "return Array.from(document.images).map(i => [i.getAttribute('src'), i.complete, i.naturalWidth]);"
        )
        deadline = time.time() + 20
        while any(not done for _, done, _ in images) and time.time() < deadline:
            time.sleep(0.2)
            images = driver.execute_script(
                "return Array.from(document.images).map(i => [i.getAttribute('src'), i.complete, i.naturalWidth]);"
            )
        if not images:
            failures.append("the page has no images")
        for src, done, width in images:
            if not done or width <= 0:
                failures.append(f"image {src} does not decode (naturalWidth {width})")
        # Videos: loaded, the right duration, and playing moves them on.
        results = driver.execute_async_script(
            """
            const done = arguments[arguments.length - 1];
            const videos = Array.from(document.querySelectorAll('video'));
            const one = v => new Promise(resolve => {
              const report = extra => resolve(Object.assign({src: v.getAttribute('src'),
                  readyState: v.readyState, duration: v.duration, error: v.error && v.error.code}, extra));
              const ready = () => {
                const before = v.currentTime;
                v.muted = true;
                v.play().then(() => setTimeout(() => report({before, after: v.currentTime}), 1000),
                              e => report({playError: String(e)}));
              };
              if (v.readyState >= 2) ready();
              else { v.addEventListener('loadeddata', ready, {once: true});
                     v.addEventListener('error', () => report({}), {once: true});
                     v.load(); }
              setTimeout(() => report({timeout: true}), 20000);
            });
            Promise.all(videos.map(one)).then(done);
        """
        )
        if not results:
            failures.append("the page has no videos")
        for r in results:
            name = r["src"]
            if r.get("timeout") or r.get("error"):
                failures.append(f"video {name} did not load: {r}")
                continue
            if r["readyState"] < 2:
                failures.append(f"video {name}: readyState {r['readyState']} < 2")
            if abs(r["duration"] - expected) > 0.05:
                failures.append(f"video {name}: duration {r['duration']} s, expected {expected} s")
            if "playError" in r:
                failures.append(f"video {name} does not play: {r['playError']}")
            elif not r["after"] > r["before"]:
                failures.append(f"video {name}: currentTime did not advance ({r['before']} -> {r['after']})")
        # Nothing drawn larger than it is: a 320 × 180 video or still keeps its own size on a
        # wide page (blown up, its pixels blur), and a large one shrinks to fit.
        sizes = driver.execute_script(
            """
            return Array.from(document.querySelectorAll('img, video')).map(e =>
                [e.getAttribute('src'), e.clientWidth, e.naturalWidth || e.videoWidth || 0]);"""
        )
        for src, shown, natural in sizes:
            if natural > 0 and shown > natural + 1:
                failures.append(f"{src} is drawn {shown} px wide, larger than its own {natural} px")
        for size in [(1280, 720), (1920, 1080), (1024, 768)]:
            classroom(driver, size, failures, sys.argv[3] if len(sys.argv) > 3 else "")
        surfaces(driver, failures)
        # The console: no errors.
        for entry in driver.get_log("browser"):
            if entry["level"] == "SEVERE":
                failures.append(f"console: {entry['message']}")
        print(f"{len(images)} images, {len(results)} videos checked")
    finally:
        chromium.close(driver, profile)
    composited_present(folder, failures)
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
