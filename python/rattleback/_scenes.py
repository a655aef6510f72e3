"""Scenes: read from a file, a YAML string, a dict or a mesh's arrays, checked and compiled by
the library (the package's :class:`Scene`, and how every call takes a scene)."""

from __future__ import annotations

import json as _json
import os as _os
from collections.abc import Mapping as _Mapping
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as _np

from . import _core
from ._args import checked as _checked, refuse as _refuse
from ._errors import SceneError

SceneLike = Union["Scene", str, _os.PathLike, Mapping[str, Any]]


def _yaml_value(value: Any) -> str:
    """A Python value as YAML flow text (JSON is YAML): numbers, strings, lists, dicts."""
    if isinstance(value, _np.generic):
        value = value.item()
    if isinstance(value, _np.ndarray):
        value = value.tolist()
    return _json.dumps(value, default=_yaml_value_default)


def _mesh_arrays(vertices: Any, faces: Any, mass: float, units: float) -> tuple:
    """Scene.from_mesh's arguments checked, and its arrays as the loader takes them (float64
    and int64, contiguous); a slip is a SceneError naming the argument."""
    for argument, value in (("mass", mass), ("units", units)):
        if not (_np.isfinite(value) and value > 0):
            raise SceneError(f"from_mesh: argument {argument} must be > 0, not {value}", "from_mesh")
    vertices = _np.ascontiguousarray(vertices, dtype=_np.float64)
    faces = _np.ascontiguousarray(faces, dtype=_np.int64)
    for argument, array, rows in (("vertices", vertices, "N"), ("faces", faces, "M")):
        if array.ndim != 2 or array.shape[1] != 3:
            # (3, N) is the usual slip (a transposed array); quads are (M, 4).
            hint = "; transposed? give its .T" if array.ndim == 2 and array.shape[0] == 3 else ""
            if argument == "faces" and array.ndim == 2 and array.shape[1] == 4:
                hint = "; quads? split each into two triangles"
            raise SceneError(
                f"from_mesh: argument {argument} takes an ({rows}, 3) array, not one of shape "
                f"{array.shape}{hint}",
                "from_mesh",
            )
        if len(array) == 0:
            raise SceneError(
                f"from_mesh: argument {argument} is empty: give an ({rows}, 3) array", "from_mesh"
            )
    if not _np.isfinite(vertices).all():
        row = int(_np.argwhere(~_np.isfinite(vertices))[0][0])
        raise SceneError(f"from_mesh: argument vertices: row {row} is not finite", "from_mesh")
    outside = (faces < 0) | (faces >= len(vertices))
    if outside.any():
        row = int(_np.argwhere(outside)[0][0])
        raise SceneError(
            f"from_mesh: argument faces: row {row} names vertex {int(faces[row][outside[row]][0])}, "
            f"but vertices has {len(vertices)} rows (0 … {len(vertices) - 1})",
            "from_mesh",
        )
    return vertices, faces


class Scene:
    """A scene, checked and compiled: from a file, a YAML string or a dict.

    A scene is immutable; :meth:`with_values` gives a new one with keys changed. Every error
    is a :class:`SceneError` (a ``ValueError``) naming file, line and key, as the command
    line's message does.
    """

    def __init__(
        self,
        yaml: str,
        name: str,
        values: Sequence[tuple[str, str]] = (),
        _file: bool = False,
        _mesh: Optional[tuple[_np.ndarray, _np.ndarray]] = None,
    ):
        self._yaml = yaml
        self._name = name
        self._values = tuple(values)
        # Read from the file `name` (from_file); else `name` only stands for one in messages, and
        # a run's sidecar points to no file.
        self._file = _file
        # from_mesh's arrays (kept to pickle the scene) and the library's copy of them, which
        # stands for body.mesh.file's triangles in every scene made from this one.
        self._mesh = _mesh
        self._held = None if _mesh is None else _core.hold_mesh(*_mesh)
        self._loaded = _core.load(yaml, name, list(self._values), {}, _file, self._held)

    @classmethod
    @_checked
    def from_file(cls, path: Union[str, os.PathLike]) -> "Scene":
        """The scene in a YAML file (``scenes/rattleback.yaml``). A relative path that is not
        here is the installed copy's, as the command line finds it: the shipped scenes load by
        their names from any folder, and are named by the file read."""
        path = _core.find_shipped(_os.fspath(path))
        return cls(_core.read_scene_file(path), path, _file=True)

    @classmethod
    @_checked
    def from_yaml(cls, text: str, name: str = "<yaml>") -> "Scene":
        """A scene written as YAML text; ``name`` stands for the file in messages."""
        return cls(text, name)

    @classmethod
    @_checked
    def from_dict(cls, scene: Mapping[str, Any], name: str = "<dict>") -> "Scene":
        """A scene as nested dicts, keyed as the file is (``{"body": {...}, ...}``). Its errors
        name ``name`` and the key; ``line`` is None (a dict has no lines)."""
        try:
            return cls(_json.dumps(scene, default=_yaml_value_default), name)
        except SceneError as e:
            # The dict was read as one line of JSON: neither the attribute nor the message
            # names a line ("<dict>: contact is required", not "<dict>:1: …").
            raise _lineless(e, name)

    @classmethod
    @_checked
    def from_mesh(
        cls,
        vertices: Any,
        faces: Any,
        mass: float,
        units: float = 1.0,
        center_of_mass: Optional[Sequence[float]] = None,
        inertia: Any = None,
        scene: Optional[SceneLike] = None,
        name: str = "<mesh>",
    ) -> "Scene":
        """A mesh body from NumPy arrays, as ``body.shape: mesh`` reads one from a file
        (docs/scenes.md): ``vertices`` (N, 3) in ``units`` (m per unit: 0.001 for mm; the
        scene's ``units.length``), ``faces`` (M, 3) vertex indices, each counter-clockwise seen
        from outside. The mesh is checked as a file's is (closed, wound outwards, no faces of
        zero area, a toy's size), never mended. ``mass`` kg at uniform density, unless
        ``center_of_mass`` (in ``units``) and ``inertia`` (kg m², about the CM) are given.
        Contact, initial state and simulation come from ``scene`` (a Scene, a path, or a dict
        that needs no ``body``; default the shipped ``scenes/rattleback.yaml``), whose lengths
        are in ``units`` too. ``name`` stands for the scene in messages and titles; the scene's
        ``yaml`` is the whole scene, its mesh named ``<vertices, faces>``. What ``scene.mesh()``
        gives comes back: ``Scene.from_mesh(*rb.Scene.from_file("scenes/rattleback.yaml").mesh(),
        0.059)``."""
        vertices, faces = _mesh_arrays(vertices, faces, mass, units)
        if isinstance(scene, _Mapping):  # its body is from_mesh's: the dict need not have one
            base = Scene.__new__(Scene)
            base._yaml, base._name, base._values, base._file = (
                _json.dumps(scene, default=_yaml_value_default),
                "<dict>",
                (),
                False,
            )
        else:
            base = _scene("scenes/rattleback.yaml" if scene is None else scene)
        body: dict[str, Any] = {"shape": "mesh", "mesh": {"file": "<vertices, faces>"}, "mass": mass}
        if center_of_mass is not None:
            body["center_of_mass"] = center_of_mass
        if inertia is not None:
            body["inertia"] = inertia
        added = [("units.length", _yaml_value(units)), ("body", _yaml_value(body))]
        # The whole scene as one text (scene.yaml gives it, a title names no values put in).
        text = _core.yaml_with_values(base._yaml, base._name, list(base._values) + added, "from_mesh")
        try:
            return Scene(text, name, (), False, (vertices, faces))
        except SceneError as e:
            # Its lines are of a text the caller never wrote: named without them; and its way
            # out in the caller's words (arrays and arguments, not a file and its keys).
            raise _in_array_words(_lineless(e, name))

    @_checked
    def with_values(self, values: Mapping[str, Any]) -> "Scene":
        """A copy with values put at dotted keys: ``{"initial.spin": -5,
        "contact.air_drag": 1e-5, "body.dents.at[0]": 0.3}``. A wrong key or value raises
        :class:`SceneError` naming ``with_values`` and the key."""
        added = [(str(k), _yaml_value(v)) for k, v in values.items()]
        return Scene(self._yaml, self._name, self._values + tuple(added), self._file, self._mesh)

    @property
    def name(self) -> str:
        """The file (or name) the scene came from."""
        return self._name

    @property
    def values(self) -> dict[str, Any]:
        """The values put in with :meth:`with_values`, by key."""
        return {k: _json.loads(v) for k, v in self._values}

    @property
    def yaml(self) -> str:
        """The scene's YAML text, as read (before :meth:`with_values`)."""
        return self._yaml

    def to_yaml(self) -> str:
        """The whole scene as YAML text with the values :meth:`with_values` put in: what to save
        as a scene file (``Path("mine.yaml").write_text(scene.to_yaml())``). Comments and layout
        are not kept; a mesh file is named as the scene named it, relative to the scene's
        folder, so save it beside the scene it came from."""
        return _core.yaml_with_values(self._yaml, self._name, list(self._values), "with_values")

    @property
    def duration(self) -> float:
        """simulation.duration, s."""
        return self._loaded.duration

    @property
    def spin(self) -> float:
        """initial.spin, rad/s (+ counter-clockwise seen from above)."""
        return self._loaded.spin

    @_checked
    def mesh(self, segments: Optional[int] = None) -> tuple[_np.ndarray, _np.ndarray]:
        """The body's closed surface as triangles: ``(vertices, faces)``, vertices an (N, 3)
        float array in metres in the body's geometric frame (z up, the long axis along y), faces
        an (M, 3) integer array of vertex indices, each counter-clockwise seen from outside.
        What ``rattleback export`` writes as STL: the paraboloid and the ellipsoid on
        ``segments`` around (default 192; finer converges as 1/segments²), a mesh body its own
        triangles. For trimesh: ``trimesh.Trimesh(*scene.mesh())``."""
        return _core.body_mesh(self._loaded, segments)

    def _load(self, **overrides: Any):
        overrides = {k: v for k, v in overrides.items() if v is not None}
        if "size" in overrides:  # NumPy's integers too, as the ints the library casts to
            overrides["size"] = [int(side) for side in overrides["size"]]
        if not overrides:
            return self._loaded
        return _core.load(self._yaml, self._name, list(self._values), overrides, self._file, self._held)

    def __reduce__(self):
        # Pickled as what it was made of, and compiled again where it is unpickled (a worker
        # process): the compiled scene is the library's, and tens of ms to make.
        return (Scene, (self._yaml, self._name, self._values, self._file, self._mesh))

    def __repr__(self) -> str:
        extra = f", values={self.values!r}" if self._values else ""
        return f"Scene({self._name!r}{extra})"


# The mesh checks' words for a file, and from_mesh's for the arrays it was given.
_ARRAY_WORDS = (
    ("body.mesh.file <vertices, faces>: ", "vertices, faces: "),
    ("flip them (Blender: Mesh > Normals > Flip) and export again", "flip them (faces[:, ::-1])"),
    (" and export again", " and give the arrays again"),
    ("units.length: ", "units="),
)


def _in_array_words(e: SceneError) -> SceneError:
    """`e`, raised for from_mesh's arrays, worded for them."""
    message = str(e)
    for file_words, array_words in _ARRAY_WORDS:
        message = message.replace(file_words, array_words)
    e.args = (message,)
    return e


def _lineless(e: SceneError, name: str) -> SceneError:
    """`e` without a line where it is in the text of `name`, which the caller did not write as
    lines (a dict's JSON, from_mesh's scene)."""
    if e.file == name:
        located = f"{name}:{e.line}: "
        message = str(e)
        if e.line is not None and message.startswith(located):
            e.args = (f"{name}: " + message[len(located) :],)
        e.line = None
    return e


def _yaml_value_default(value: Any) -> Any:
    if isinstance(value, _np.generic):
        return value.item()
    if isinstance(value, _np.ndarray):
        return value.tolist()
    raise TypeError(f"{type(value).__name__} is not a scene value")


def _scene(scene: SceneLike) -> Scene:
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, _Mapping):
        return Scene.from_dict(scene)
    if isinstance(scene, (str, _os.PathLike)):
        return Scene.from_file(scene)
    _refuse("scene", scene)
