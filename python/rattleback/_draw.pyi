"""Type stubs of rattleback._draw, the drawing side (see rattleback.still, rattleback.render)."""

from typing import Any, Optional

import numpy as np

from ._core import LoadedScene

presets: list[str]

def still(scene: LoadedScene, t: float | str, readouts: bool, transparent: bool,
          backend: str, title: Optional[str] = None
          ) -> tuple[np.ndarray, dict[str, Any], Optional[str]]: ...
def render(scene: LoadedScene, output: str, both: bool, crf: int, preset: str,
           backend: str) -> tuple[list[dict[str, Any]], Optional[str]]: ...
def encode_png(array: np.ndarray, drawn_by: str = "") -> bytes: ...
def write_png(path: str, array: np.ndarray,
              still: Optional[dict[str, Any]] = None) -> None: ...
def compare(a: np.ndarray, b: np.ndarray, tolerance: int, pixels: float,
            square: int) -> dict[str, Any]: ...
def diff_image(a: np.ndarray, b: np.ndarray, tolerance: int) -> np.ndarray: ...
def read_png(path: str) -> np.ndarray: ...

default_tolerance: dict[str, Any]
