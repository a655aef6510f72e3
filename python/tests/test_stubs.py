"""The .pyi stubs name what the extension modules hold, so editors and help() know every
function (a function added to a module and not to its stub fails here)."""

import ast
from pathlib import Path

import rattleback
from rattleback import _core, _draw

PACKAGE = Path(rattleback.__file__).parent


def stubbed(module_name):
    tree = ast.parse((PACKAGE / f"{module_name}.pyi").read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    return names


def held(module):
    return {n for n in dir(module) if not n.startswith("__")}


def test_the_core_stub_names_everything_the_module_holds():
    assert stubbed("_core") == held(_core)


def test_the_draw_stub_names_everything_the_module_holds():
    assert stubbed("_draw") == held(_draw)


def test_every_public_function_has_a_docstring():
    for name in rattleback.__all__:
        obj = getattr(rattleback, name)
        if callable(obj):
            assert obj.__doc__ and len(obj.__doc__) > 40, name
