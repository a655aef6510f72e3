"""Snapshot tests of images in a pytest suite: :func:`assert_image_matches`, and a pytest plugin
(``pytest -p rattleback.testing``, or ``pytest_plugins = ["rattleback.testing"]`` in a
conftest.py) whose ``--snapshot-update`` writes the goldens instead of comparing;
:func:`suite_cases` and :func:`assert_case_matches` run a ``rattleback snapshot`` suite file's
cases as pytest tests.

A failure writes the new image, a diff image (differing pixels in magenta) and a copy of the
golden into ``snapshot-failures/`` (``--snapshot-failures DIR``, or ``failures=``) and names
them."""

from __future__ import annotations

import os
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Optional, Union

from ._compare import ImageLike, _array, _defaults, compare

PathLike = Union[str, os.PathLike]

# What the pytest plugin sets from its options (and what a caller's own arguments override).
_settings: dict[str, Any] = {"update": False, "failures": "snapshot-failures"}
# The goldens written in this session, (path, "added", "changed" or "replaced"): the plugin's summary says
# them, as `rattleback snapshot --update` does, so that an update left on in CI is seen.
_written: list[tuple[str, str]] = []


def _write(path: Path, array, drawn_by: str = "") -> None:
    from . import _draw

    path.parent.mkdir(parents=True, exist_ok=True)
    # (a temporary file renamed into place; its Software text the rasteriser, as the command
    # line writes it, so that a golden blessed by either is the same bytes)
    _draw.write_png(os.fspath(path), array, drawn_by=drawn_by)


def _written_as(result, unreadable) -> str:
    """What writing a golden did to it, as `rattleback snapshot --update` says each: one that was
    not a PNG (a Git LFS pointer) is replaced."""
    return "replaced" if unreadable is not None else "added" if result is None else "changed"


def _drawn_by(image) -> str:
    """The rasteriser that drew an rb.still image ("" for an array or a PNG's path)."""
    return (getattr(image, "_still", None) or {}).get("drawn_by", "")


def _clear_failure(*left: Path) -> None:
    """A golden that holds again: the images an earlier failure left for it would mislead, and
    a folder they leave empty would too."""
    for stale in left:
        stale.unlink(missing_ok=True)
    try:
        left[0].parent.rmdir()  # only if empty
    except OSError:
        pass


def assert_image_matches(
    image: ImageLike,
    golden_path: PathLike,
    *,
    tolerance: Optional[int] = None,
    pixels: Optional[float] = None,
    square: Optional[int] = None,
    update: Optional[bool] = None,
    failures: Optional[PathLike] = None,
) -> None:
    """Asserts that ``image`` matches the PNG at ``golden_path`` (as :func:`rattleback.compare`
    judges, with its defaults).

    With ``update`` (default: pytest's ``--snapshot-update``) the golden is written when it is
    missing or differs, and left alone when it matches. Otherwise a missing golden or a
    mismatch raises AssertionError naming the new image, the diff image and the golden's copy
    written into ``failures`` (default ``snapshot-failures``, or pytest's ``--snapshot-failures``).
    """
    __tracebackhide__ = True  # pytest shows the caller's line and the message, not this body
    golden = Path(golden_path)
    actual = _array(image)
    drawn_by = _drawn_by(image)
    tol, frac, side = _defaults(tolerance, pixels, square)
    updating = update if update is not None else _settings["update"]
    folder = Path(failures if failures is not None else _settings["failures"])
    new = folder / f"{golden.stem}-new.png"
    diff = folder / f"{golden.stem}-diff.png"
    # The golden beside them: a CI job's uploaded failures folder then holds all three to look at.
    was = folder / f"{golden.stem}-golden.png"
    result, unreadable = None, None
    if golden.is_file():
        try:
            expected = _array(golden)
        except ValueError as e:  # not a PNG (a Git LFS pointer, say): the message says which
            unreadable = e
        else:
            result = compare(actual, expected, tolerance=tol, pixels=frac, square=side)
    if updating or (result is not None and result.same):
        if updating and (result is None or not result.same):
            _write(golden, actual, drawn_by)
            _written.append((os.fspath(golden), _written_as(result, unreadable)))
        _clear_failure(new, diff, was)
        return
    _write(new, actual, drawn_by)
    if unreadable is not None:
        raise AssertionError(
            f"{unreadable}; the new image is {new} (pytest --snapshot-update, or update=True, "
            "replaces the golden with it)"
        )
    if result is None:
        raise AssertionError(
            f"{golden}: no golden image; the new image is {new} (pytest "
            "--snapshot-update, or update=True, writes it as the golden)"
        )
    hint = _other_rasteriser(golden, drawn_by)
    raise AssertionError(_differs(golden, result, (tol, frac, side), actual, expected, new, diff, was, hint))


def _other_rasteriser(golden: Path, drawn_by: str) -> str:
    """As `rattleback snapshot` says it: a golden drawn by another rasteriser than this image is
    the likely cause of a difference."""
    from . import _draw

    then = _draw.png_drawn_by(os.fspath(golden))
    if not drawn_by or not then or then == drawn_by:
        return ""
    return f"; the golden was drawn by {then}, this by {drawn_by}: a golden holds for the rasteriser that drew it"


def _differs(golden: Path, result, tolerances, actual, expected, new: Path, diff: Path, was: Path, hint: str):
    """A mismatch's message (its figures as `rattleback snapshot` says them), having written its
    diff image (where the sizes agree) and the golden's copy beside the new image."""
    tol = tolerances[0]
    message = f"{golden}: differs: {result.describe(*tolerances)}; the new image is {new}"
    if result.same_size:
        from . import _draw

        _write(diff, _draw.diff_image(actual, expected, tol))
        message += f", the diff image {diff}"
    shutil.copyfile(golden, was)
    message += f", the golden copied as {was}{hint}"
    return message + " (pytest --snapshot-update writes the new one as the golden)"


@dataclass(frozen=True)
class SnapshotCase:
    """One case of a snapshot suite file, as ``rattleback snapshot`` reads it: the scene's path
    resolved against the suite's folder, the suite's defaults put in. ``str(case)`` is its name
    (pytest's id for it)."""

    name: str
    place: str  # "suite.yaml:7", where the case begins
    scene: str
    t: Union[float, str]  # s, or "reversal", "first_reversal", "end"
    view: Optional[str]
    size: Optional[tuple[int, int]]
    backend: Optional[str]  # None: $RATTLEBACK_BACKEND, else auto, as the command line
    title: Optional[str]  # None: the case's name
    tolerance: int
    pixels: float
    square: int
    golden: Path

    def __str__(self) -> str:
        return self.name

    def draw(self):
        """The case's image, drawn as ``rattleback snapshot`` draws it (:func:`rattleback.still`
        with the case's time, view, size, backend and title)."""
        import rattleback as rb

        backend = self.backend or os.environ.get("RATTLEBACK_BACKEND") or "auto"
        title = self.title if self.title is not None else self.name
        try:
            loaded = rb._scene(self.scene)._load(view=self.view, size=self.size)
            # Messages name the time as the suite's key t, and a run too short to reach it is
            # lengthened in the scene (a suite has no duration of its own), as the command
            # line's snapshot says.
            image, leaves = rb._drawn_still(
                loaded, self.t, True, False, backend, title, t_named="t", scene_duration_only=True
            )
        except (ValueError, RuntimeError) as e:
            # The suite's line and the case first, as the command line names them.
            e.args = (f"{self.place}: {self.name}: {e}",) + e.args[1:]
            raise
        rb._warn_leaves(loaded, leaves, stacklevel=3)
        return image


def suite_cases(path: PathLike) -> list[SnapshotCase]:
    """The cases of a snapshot suite file (docs/testing.md), read by the command line's own
    reader: a mistake in it raises :class:`rattleback.SceneError` naming its line and key. For
    ``pytest.mark.parametrize("case", suite_cases(...), ids=str)``."""
    from . import _core

    suite = _core.snapshot_suite(os.fspath(path))
    goldens = Path(suite["goldens"])
    return [SnapshotCase(golden=goldens / f"{c['name']}.png", **c) for c in suite["cases"]]


def assert_case_matches(
    case: SnapshotCase, *, update: Optional[bool] = None, failures: Optional[PathLike] = None
) -> None:
    """Draws a suite's case and asserts that it matches its golden with the case's tolerances,
    as :func:`assert_image_matches` does (and ``update``, ``failures`` as there)."""
    __tracebackhide__ = True
    assert_image_matches(
        case.draw(),
        case.golden,
        tolerance=case.tolerance,
        pixels=case.pixels,
        square=case.square,
        update=update,
        failures=failures,
    )


def pytest_addoption(parser) -> None:
    group = parser.getgroup("rattleback", "rattleback snapshot images")
    group.addoption(
        "--snapshot-update",
        action="store_true",
        default=False,
        help="write the golden images that differ or are missing instead of failing",
    )
    group.addoption(
        "--snapshot-failures",
        default="snapshot-failures",
        metavar="DIR",
        help="folder for the new and diff images of failures " "(default snapshot-failures)",
    )


def pytest_configure(config) -> None:
    _settings["update"] = bool(config.getoption("snapshot_update"))
    _settings["failures"] = config.getoption("snapshot_failures")


def pytest_terminal_summary(terminalreporter) -> None:
    if not _written:
        return
    counts = {kind: sum(1 for _, k in _written if k == kind) for kind in ("changed", "added", "replaced")}
    said = ", ".join(f"{n} {kind}" for kind, n in counts.items() if n)
    terminalreporter.section("rattleback snapshot --snapshot-update")
    terminalreporter.write_line(f"goldens written: {said}")
    for path, kind in _written:
        terminalreporter.write_line(f"  {kind:<8} {path}")
