#!/usr/bin/python3
"""Opens DIR/index.html in headless Chromium (Selenium, Debian's chromium and chromium-driver)
and checks what a reader would see: the page loads with no console errors, every image decodes
(naturalWidth > 0), every video reaches readyState >= 2 with the expected duration, and its
currentTime advances when it plays; and no image or video is drawn larger than its own size.

Usage: check_report.py DIR EXPECTED_VIDEO_SECONDS
Exit status 0 when every check passes, 1 when one fails (each failure printed), 77 when
Selenium or Chromium is not installed (CTest's "skipped")."""
import os
import pathlib
import shutil
import sys
import tempfile
import time

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
except ImportError:
    print("selenium is not installed (Debian: python3-selenium); skipped")
    sys.exit(77)

CHROMIUM = "/usr/bin/chromium"
DRIVER = "/usr/bin/chromedriver"


def main():
    folder = pathlib.Path(sys.argv[1]).resolve()
    expected = float(sys.argv[2])
    if not (os.path.exists(CHROMIUM) and os.path.exists(DRIVER)):
        print("chromium or chromedriver is not installed; skipped")
        return 77
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    profile = tempfile.mkdtemp(prefix="rattleback-chromium-")
    for flag in [
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--autoplay-policy=no-user-gesture-required",
        f"--user-data-dir={profile}",
    ]:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(DRIVER), options=options)
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
        # The console: no errors.
        for entry in driver.get_log("browser"):
            if entry["level"] == "SEVERE":
                failures.append(f"console: {entry['message']}")
        print(f"{len(images)} images, {len(results)} videos checked")
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)  # the browser's profile: ours to remove
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
