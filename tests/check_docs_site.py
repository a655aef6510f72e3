#!/usr/bin/python3
"""Builds the documentation site (mkdocs build --strict, into a scratch folder) and checks that
it works offline and ships no build scripts:

- no file of the site is a script or a compiled one (.py, .pyc, .cpp, .sh, __pycache__): the
  generators and checks in docs/ stay out (scripts/mkdocs_hooks.py);
- no HTML, CSS or JS file loads anything from the web: no remote `<link href>`, `<script src>`,
  `<img src>`, `<iframe src>`, `<source src>`, `<video src|poster>`, `<audio src>`, `<embed
  src>`, `<object data>`, and no remote `@import` or `url(` in CSS, in a page's `<style>` or
  `style=`, or in JS. A link to the web (`<a href>`) is fine: it loads only when followed;
- and, where Selenium and Chromium are installed (Debian: python3-selenium, chromium,
  chromium-driver), each page opened from disk in headless Chromium requests nothing but
  file: and data: URLs (the Resource Timing entries) and logs no console error (but for the
  search index, which a page opened from disk may not fetch; 404.html, a server's page, is not
  opened).

Usage: check_docs_site.py [SOURCE_DIR]. Exit status 0 when every check passes, 1 when one
fails (each failure printed), 77 when mkdocs is not installed (CTest's "skipped").
"""
import html.parser
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

SCRIPTS = {".py", ".pyc", ".pyo", ".cpp", ".hpp", ".sh"}
# The attributes by which a tag loads what it names.
LOADS = {
    "link": ["href"],
    "script": ["src"],
    "img": ["src", "srcset"],
    "iframe": ["src"],
    "source": ["src", "srcset"],
    "video": ["src", "poster"],
    "audio": ["src"],
    "embed": ["src"],
    "object": ["data"],
    "track": ["src"],
    "input": ["src"],
}
REMOTE = re.compile(r"^\s*(https?:)?//", re.I)
# url(…) and @import in CSS (or CSS written in JS) whose address is remote.
CSS_REMOTE = re.compile(
    r"""url\(\s*['"]?\s*(?:https?:)?//[^)'"]*|@import\s+(?:url\(\s*)?['"]?\s*(?:https?:)?//[^;'")]*""",
    re.I,
)


class Tags(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.remote, self.styles, self.in_style = [], [], False

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        for name in LOADS.get(tag, []):
            value = attrs.get(name) or ""
            # A canonical link names the page's own address; the browser loads nothing from it.
            if tag == "link" and (attrs.get("rel") or "").lower() == "canonical":
                continue
            if any(REMOTE.match(part) for part in value.split(",")):
                self.remote.append(f"<{tag} {name}={value!r}>")
        if attrs.get("style"):
            self.styles.append(attrs["style"])
        self.in_style = tag == "style"

    def handle_endtag(self, tag):
        self.in_style = False

    def handle_data(self, data):
        if self.in_style:
            self.styles.append(data)


def static_failures(site):
    failures = []
    for path in sorted(site.rglob("*")):
        name = path.relative_to(site)
        if path.is_dir() and path.name == "__pycache__":
            failures.append(f"{name}: a Python cache in the site")
        elif path.is_file() and path.suffix.lower() in SCRIPTS:
            failures.append(f"{name}: a script in the site")
        elif path.suffix == ".html":
            tags = Tags()
            tags.feed(path.read_text(errors="replace"))
            failures += [f"{name}: loads {what}" for what in tags.remote]
            for style in tags.styles:
                failures += [f"{name}: style loads {m!r}" for m in CSS_REMOTE.findall(style)]
        elif path.suffix in (".css", ".js"):
            for found in CSS_REMOTE.findall(path.read_text(errors="replace")):
                failures.append(f"{name}: loads {found!r}")
    return failures


def browser_failures(site):
    """Each page in headless Chromium: what it requested and what its console said."""
    try:
        import selenium  # noqa: F401  (driven through tests/browser/chromium.py)
    except ImportError:
        print("note: selenium is not installed (python3-selenium); pages not opened in a browser")
        return []
    sys.path.insert(0, str(Path(__file__).resolve().parent / "browser"))
    import chromium  # tests/browser/chromium.py: one Chromium setup for the page checks

    if not chromium.installed():
        print("note: chromium or chromedriver is not installed; pages not opened in a browser")
        return []
    driver, profile = chromium.open_browser("--disable-gpu", prefix="rattleback-docs-chromium-")
    failures = []
    try:
        # 404.html is the server's page for a missing address: its links are from the site's root.
        for page in sorted(p for p in site.glob("*.html") if p.name != "404.html"):
            driver.get(page.as_uri())
            # Let the theme's script run (search index, fonts, anything it would fetch).
            driver.execute_async_script("const done = arguments[0]; setTimeout(done, 500);")
            requested = driver.execute_script(
                "return performance.getEntriesByType('resource').map(e => e.name);"
            )
            for url in requested:
                if not url.startswith(("file:", "data:", "blob:")):
                    failures.append(f"{page.name}: requested {url}")
            errors = [e["message"] for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
            # The search box's index is a file beside the pages, which Chromium does not let a
            # page opened from disk fetch (file:// has no CORS): search works when the site is
            # served (`mkdocs serve`, any web server) and is the one thing missing from disk.
            # Those errors, and the theme's rejected fetch of that index, are not the web's.
            if any("search/search_index.json" in m for m in errors):
                errors = [
                    m
                    for m in errors
                    if "search/search_index.json" not in m and not m.endswith("TypeError: Failed to fetch")
                ]
            failures += [f"{page.name}: console: {m}" for m in errors]
    finally:
        chromium.close(driver, profile)
    return failures


def main(argv):
    source = Path(argv[0] if argv else Path(__file__).resolve().parents[1])
    if not shutil.which("mkdocs"):
        print("mkdocs is not installed; skipped")
        return 77
    with tempfile.TemporaryDirectory() as scratch:
        site = Path(scratch) / "site"
        built = subprocess.run(
            ["mkdocs", "build", "--strict", "-q", "-f", str(source / "mkdocs.yml"), "-d", str(site)],
            cwd=source,  # where pymdownx.snippets finds the files a page includes (mkdocs.yml)
        )
        if built.returncode != 0:
            print("FAIL: mkdocs build --strict failed")
            return 1
        failures = static_failures(site)
        failures += browser_failures(site)
    for failure in failures:
        print("FAIL:", failure)
    if not failures:
        print("the site loads nothing from the web and ships no scripts")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
