#!/usr/bin/python3
"""Opens a snapshot report (DIR/index.html, written by `rattleback snapshot` on failure) from disk
in headless Chromium and checks what a reviewer needs: no console errors; each failing case named
in CASES has its section with the golden, new and diff images side by side, each decoded
(naturalWidth > 0) and the three on one row; its figures (pixels differing, worst level) shown;
a case without a golden shows its new image and says --update writes it.

Usage: check_snapshot_report.py DIR DIFFERING_CASE MISSING_CASE [SCREENSHOT.png]
Exit 0 when every check passes, 1 when one fails, 77 without Selenium or Chromium (skipped)."""
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

IMAGES = """return Array.from(document.querySelectorAll('section.case img')).map(i =>
    [i.closest('section').id, i.getAttribute('src'), i.complete, i.naturalWidth,
     i.getBoundingClientRect().top]);"""


def check_case(driver, images, differing, missing, failures):
    by_case = {}
    for case, src, done, width, top in images:
        by_case.setdefault(case, []).append((src, done, width, top))
        if not done or width <= 0:
            failures.append(f"{case}: image {src} does not decode (naturalWidth {width})")
    want = {differing: ["golden", "new", "diff"], missing: ["new"]}
    for case, kinds in want.items():
        srcs = [src for src, *_ in by_case.get(case, [])]
        expected = [f"{case}-{kind}.png" for kind in kinds]
        if srcs != expected:
            failures.append(f"{case}: images {srcs}, expected {expected}")
    tops = {round(top) for _, _, _, top in by_case.get(differing, [])}
    if len(tops) != 1:
        failures.append(f"{differing}: golden, new and diff are not side by side (tops {tops})")
    text = driver.execute_script(f"return document.getElementById('{differing}').innerText;")
    for words in ["pixels differing", "worst level"]:
        if words not in text:
            failures.append(f"{differing}: the figures do not say '{words}'")
    said = driver.execute_script(f"return document.getElementById('{missing}').innerText;")
    if "--update writes it" not in said:
        failures.append(f"{missing}: does not say that --update writes its golden")


def main():
    folder = pathlib.Path(sys.argv[1]).resolve()
    differing, missing = sys.argv[2], sys.argv[3]
    if not chromium.installed():
        print("chromium or chromedriver is not installed; skipped")
        return 77
    driver, profile = chromium.open_browser("--disable-gpu", "--window-size=1400,1000")
    failures = []
    try:
        driver.get((folder / "index.html").as_uri())
        deadline = time.time() + 20
        images = driver.execute_script(IMAGES)
        while any(not done for _, _, done, _, _ in images) and time.time() < deadline:
            time.sleep(0.2)
            images = driver.execute_script(IMAGES)
        check_case(driver, images, differing, missing, failures)
        for entry in driver.get_log("browser"):
            if entry["level"] == "SEVERE":
                failures.append(f"console: {entry['message']}")
        if len(sys.argv) > 4 and sys.argv[4]:
            driver.save_screenshot(sys.argv[4])
        print(f"{len(images)} images checked")
    finally:
        chromium.close(driver, profile)
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
