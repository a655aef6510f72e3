#!/usr/bin/env python3
"""The size bounds of docs/design.md "Small rooms": no function of a front end (app/, python/)
over 60 lines, and no product source file over 600. Prints each one over, and exits 1 if any.

A C++ function is a definition at the file's outer level (namespaces are not indented):
from the first line of its signature to its closing brace at column 0, lambdas inside it
counted with it. A Python function is ast's, decorators left out, its docstring in.

Usage: tests/check_lengths.py [SOURCE_DIR]
"""
import ast
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
FRONT_ENDS = ("app", "python")
PRODUCT = ("app", "python", "sim", "tasks", "render", "scene", "util", "media", "player/src")
SOURCES = (".cpp", ".hpp", ".py", ".js")
FUNCTION_LINES = 60
FILE_LINES = 600
NOT_FUNCTIONS = re.compile(
    r"^(namespace|struct|class|enum|union|extern|template\s*<[^>]*>\s*(struct|class))\b"
)


def files(folders):
    for folder in folders:
        for base, dirs, names in os.walk(os.path.join(root, folder)):
            dirs[:] = [d for d in dirs if d not in ("tests", "node_modules", "__pycache__")]
            for name in sorted(names):
                if name.endswith(SOURCES):
                    yield os.path.join(base, name)


def cpp_functions(lines):
    """(signature, first line, last line) of each outer-level definition, 1-based."""
    i = 0
    while i < len(lines):
        if lines[i].endswith("{") and not re.search(r"=\s*\{$", lines[i]):
            first = i
            while (
                first > 0
                and lines[first - 1][:1] not in ("", "#", "/", "}")
                and not lines[first - 1].rstrip().endswith((";", "{", "}", ":"))
            ):
                first -= 1
            if lines[first][:1] not in (" ", "/", "#") and not NOT_FUNCTIONS.match(lines[first]):
                last = i + 1
                while last < len(lines) and not re.match(r"^\}\s*;?\s*(//.*)?$", lines[last]):
                    last += 1
                yield lines[first].strip(), first + 1, last + 1
                i = last
        i += 1


def python_functions(text):
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield node.name, node.lineno, node.end_lineno


over = []
for path in files(PRODUCT):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    lines = text.split("\n")
    name = os.path.relpath(path, root)
    count = len(lines) - (1 if text.endswith("\n") else 0)
    if count > FILE_LINES:
        over.append(f"{name}: {count} lines (at most {FILE_LINES} a file)")
    if not name.startswith(FRONT_ENDS):
        continue
    found = (
        python_functions(text)
        if path.endswith(".py")
        else cpp_functions(lines)
        if path.endswith((".cpp", ".hpp"))
        else ()
    )
    for what, first, last in found:
        if last - first + 1 > FUNCTION_LINES:
            over.append(
                f"{name}:{first}: {what[:60]}: {last - first + 1} lines (at most {FUNCTION_LINES} a function)"
            )

for line in over:
    print(line)
print(
    f"check_lengths: {len(over)} over the bounds"
    if over
    else "check_lengths: every file and function within its bound"
)
sys.exit(1 if over else 0)
