"""Headless Chromium for the page checks (report, player, snapshot report, docs site): one
place for where it is and the flags every check needs; each check adds its own (a window size,
software WebGL, autoplay)."""

import os
import shutil
import tempfile

CHROMIUM = "/usr/bin/chromium"
DRIVER = "/usr/bin/chromedriver"

# No sandbox (CI runs as root), no first-run, update or sync traffic: the checks see only the
# requests the page makes.
FLAGS = [
    "--headless=new",
    "--no-sandbox",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def installed():
    """Whether Chromium and chromedriver are there (Debian: chromium, chromium-driver)."""
    return os.path.exists(CHROMIUM) and os.path.exists(DRIVER)


def open_browser(*flags, prefix="rattleback-chromium-"):
    """A driver for a headless Chromium with FLAGS, `flags` and a profile of its own (a temporary
    folder, returned beside it for close()), logging the console (goog:loggingPrefs)."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    profile = tempfile.mkdtemp(prefix=prefix)
    for flag in [*FLAGS, *flags, f"--user-data-dir={profile}"]:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(DRIVER), options=options), profile


def close(driver, profile):
    """Ends the browser and removes its profile (ours to remove)."""
    driver.quit()
    shutil.rmtree(profile, ignore_errors=True)
