#!/usr/bin/python3
"""Every citation of the docs in the code names a page that exists and, where it names one, a
section of it: `docs/NAME.md "Heading"` must match a heading of docs/NAME.md, and
`docs/physics.md PN` a section "PN." of the physics page; and no code cites what a reader cannot
open: a "SPEC" that is not in the repository, or an "issue N" (the CHANGELOG keeps history; a
comment names the docs section that says why). Exit 1 naming each that does not.

Usage: /usr/bin/python3 docs/check_citations.py
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FOLDERS = [
    "app",
    "tasks",
    "media",
    "sim",
    "scene",
    "render",
    "util",
    "python",
    "tests",
    "bench",
    "scripts",
    "fuzz",
]
CITATION = re.compile(r'docs/([\w-]+\.md)(?:\s+"([^"]+)"|\s+(P\d+))?')
# What a reader cannot open: the SPEC that is not in the repository, an issue by its number.
UNREADABLE = re.compile(r"\bSPEC\b|\b[Ii]ssues? #?\d+")


def headings(page: Path) -> set[str]:
    found = set()
    for line in page.read_text().splitlines():
        m = re.match(r"#+\s+(.*)", line)
        if m:
            text = m.group(1).strip()
            found.add(text)
            found.add(text.replace("`", ""))
    return found


def main() -> int:
    failures = []
    cited = 0
    for folder in FOLDERS:
        for path in sorted((ROOT / folder).rglob("*")):
            if not path.is_file() or path.suffix not in {".cpp", ".hpp", ".py", ".sh", ".txt"}:
                continue
            if "node_modules" in path.parts or path.name == "check_citations.py":
                continue
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                for m in UNREADABLE.finditer(line):
                    failures.append(
                        f'{path.relative_to(ROOT)}:{number}: cites "{m.group(0)}", '
                        "which a reader cannot open: cite a docs section"
                    )
                for m in CITATION.finditer(line):
                    cited += 1
                    page = ROOT / "docs" / m.group(1)
                    where = f"{path.relative_to(ROOT)}:{number}"
                    if not page.exists():
                        failures.append(f"{where}: docs/{m.group(1)} does not exist")
                        continue
                    section = m.group(2)
                    if section and section not in headings(page):
                        failures.append(f'{where}: docs/{m.group(1)} has no section "{section}"')
                    if m.group(3) and not re.search(rf"^#+\s+{m.group(3)}\.", page.read_text(), re.M):
                        failures.append(f"{where}: docs/{m.group(1)} has no section {m.group(3)}")
    for f in failures:
        print(f)
    print(f"{cited} citations of docs/ checked, {len(failures)} broken")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
