"""rattleback.compare: two images compared as ``rattleback compare`` compares them."""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, Optional, Union

import numpy as np

ImageLike = Union["Image", np.ndarray, str, os.PathLike]  # noqa: F821 (rattleback.Image)


@dataclass(frozen=True)
class Comparison:
    """The figures of a comparison (``rattleback compare``'s) and its verdict.

    Attributes:
        same: whether the images match within the tolerance.
        same_size: False when the sizes differ (then no pixel was compared).
        pixels: pixels compared.
        differing: pixels with a channel beyond the tolerance.
        fraction: ``differing / pixels`` (1.0 for images of different sizes).
        worst: the largest difference of any channel anywhere, 0–255 (the worst level).
        box: (x0, y0, x1, y1), the bounding box of the differing pixels.
        square: the side of the largest square of differing pixels.
        square_failed: that square alone failed the comparison (``square`` of the tolerance).
    """

    same: bool
    same_size: bool
    pixels: int
    differing: int
    fraction: float
    worst: int
    box: tuple
    square: int
    square_failed: bool

    def __bool__(self) -> bool:
        return self.same

    def describe(self, tolerance: int, pixels: Optional[float] = None, square: Optional[int] = None) -> str:
        """One line of the figures, as ``rattleback compare`` prints them; with ``pixels`` and
        ``square`` (the tolerances judged by), as ``rattleback snapshot`` prints a case's."""
        if not self.same_size:
            return "the images have different sizes, so no pixel was compared"
        allowed = f" (allowed {100 * pixels:.4f} %)" if pixels is not None else ""
        said = (
            f"{self.differing} of {self.pixels} pixels ({100 * self.fraction:.4f} %) differ "
            f"by more than {tolerance} in a channel{allowed}; largest channel difference {self.worst}"
        )
        if square is not None and self.square_failed:
            said += f"; a square of them {self.square} px a side (square {square})"
        return said


def _array(image: Any) -> np.ndarray:
    """An image given as a rattleback.Image, an H×W×3/4 uint8 array or a PNG's path."""
    from . import Image, _draw

    if isinstance(image, Image):
        return image.array
    if isinstance(image, (str, os.PathLike)):
        return _draw.read_png(os.fspath(image))
    return Image(image).array  # (checks the array's shape and type)


def _defaults(
    tolerance: Optional[int], pixels: Optional[float], square: Optional[int]
) -> tuple[int, float, int]:
    from . import _draw

    d = _draw.default_tolerance
    return (
        d["tolerance"] if tolerance is None else int(tolerance),
        d["pixels"] if pixels is None else float(pixels),
        d["square"] if square is None else int(square),
    )


def compare(
    a: ImageLike,
    b: ImageLike,
    *,
    tolerance: Optional[int] = None,
    pixels: Optional[float] = None,
    square: Optional[int] = None,
) -> Comparison:
    """Compares two images as ``rattleback compare`` does; returns its figures and verdict.

    ``a`` and ``b`` are :class:`rattleback.Image`, arrays or PNG paths. A pixel differs when a
    channel differs by more than ``tolerance`` (0–255, default 2); the images are the same when
    at most ``pixels`` of them differ (a fraction, default 0.002) and no square of ``square``
    pixels a side all differ (default 4; 0 off). The defaults are the command line's.
    """
    from . import _draw

    tol, frac, side = _defaults(tolerance, pixels, square)
    figures = _draw.compare(_array(a), _array(b), tol, frac, side)
    figures["box"] = tuple(figures["box"])
    return Comparison(**figures)
