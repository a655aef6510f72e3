"""The package's namespace is its API: what `dir(rattleback)` and IPython's completion of `rb.`
list is `__all__`, and docs/python.md ("What the package holds") documents each name of it, and
no other `rb.` name.

Stated exactly: in a fresh interpreter (nothing else imported), the names of
`dir(rattleback)` that do not start with `_` are `__all__` less `__version__`; names that start
with `_` are the package's own (its modules `_core`, `_draw`, … and helpers). A submodule
(`rattleback.testing`) joins the namespace once imported, as any package's does.
"""

import re
import subprocess
import sys

import pytest
import rattleback
from conftest import SOURCE

PAGE = SOURCE / "docs" / "python.md"


def public_names_in_a_fresh_interpreter():
    code = "import rattleback as rb; print(' '.join(n for n in dir(rb) if not n.startswith('_')))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return out.stdout.split()


def test_dir_lists_the_api_and_nothing_else():
    listed = public_names_in_a_fresh_interpreter()
    assert sorted(listed) == sorted(set(rattleback.__all__) - {"__version__"})


def test_every_name_in_all_is_there():
    for name in rattleback.__all__:
        assert hasattr(rattleback, name), name
    assert len(set(rattleback.__all__)) == len(rattleback.__all__)


def test_star_import_gives_the_api():
    names = {}
    exec("from rattleback import *", names)
    assert set(names) - {"__builtins__"} == set(rattleback.__all__)


def documented_table():
    """The names of the table under "What the package holds" in docs/python.md."""
    text = PAGE.read_text()
    section = text.split("## What the package holds", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"^\| `rb\.(\w+)` \|", section, re.M)


def test_the_docs_table_is_all():
    table = documented_table()
    assert len(table) == len(set(table)), table
    assert set(table) == set(rattleback.__all__)


def test_every_rb_name_the_docs_use_is_in_all():
    # rb.X anywhere on the page (not "/tmp/rb.mp4"): a name the docs use is one users can reach.
    used = set(re.findall(r"(?<![\w/.])rb\.(\w+)", PAGE.read_text()))
    assert used, "no rb. names found on the page"
    assert used - set(rattleback.__all__) - {"__all__"} == set()


def test_ipython_completes_the_api():
    # What a notebook's Tab after `rb.` lists, with Jedi (IPython's default) and without.
    pytest.importorskip("IPython")
    code = """if True:
        from IPython.core.interactiveshell import InteractiveShell
        from IPython.core.completer import provisionalcompleter
        shell = InteractiveShell.instance()
        shell.run_cell("import rattleback as rb")
        for jedi in (True, False):
            shell.Completer.use_jedi = jedi
            with provisionalcompleter():
                found = shell.Completer.completions("rb.", 3)
                print(" ".join(sorted({c.text.rsplit(".", 1)[-1] for c in found})))
    """
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    lines = out.stdout.strip().splitlines()
    assert len(lines) == 2, out.stdout + out.stderr
    for line in lines:
        assert sorted(line.split()) == sorted(set(rattleback.__all__) - {"__version__"})
