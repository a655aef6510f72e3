"""examples/weighted_body.py's with_weight (docs/your-own-body.md "Add a weight"): a body and a
weight given as body.mass, body.center_of_mass and body.inertia are the same body as the two
solids taken together at one density, whose exact mass properties are computed here from their
triangles (test_body_mesh.py's tetrahedra, independent of the library)."""

import importlib.util
import os
import shutil

import numpy as np

import rattleback as rb
from test_body_mesh import inertia_about_cm

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")


def example():
    spec = importlib.util.spec_from_file_location(
        "weighted_body", os.path.join(ROOT, "examples", "weighted_body.py")
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def cube(centre, side):
    """A cube's 8 corners and 12 triangles, counter-clockwise seen from outside."""
    corners = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)]) * side / 2
    faces = [[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4]]
    faces += [[2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]]
    return corners + centre, np.array(faces)


def test_a_weight_added_by_parallel_axes_is_the_body_and_weight_as_one_solid():
    printed = rb.Scene.from_file(os.path.join(ROOT, "scenes", "printed.yaml"))
    vertices, faces = printed.mesh()  # metres
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6
    density = 0.059 / volume
    # A 6 mm cube of the body's own material on its top, 70 mm out: its mass and its own
    # inertia (m s²/6 about each axis through its CM) are the weight's.
    side, at_mm = 6.0, np.array([0.0, 70.0, 8.0])
    weight = density * (side * 1e-3) ** 3
    own = weight * (side * 1e-3) ** 2 / 6 * np.eye(3)
    cube_vertices, cube_faces = cube(at_mm * 1e-3, side * 1e-3)
    # (The library refuses two solids apart as one body; the two are integrated together here.)
    com, inertia = inertia_about_cm(
        np.vstack([vertices, cube_vertices]), np.vstack([faces, cube_faces + len(vertices)]), 0.059 + weight
    )
    added = rb.analyze(example().with_weight(printed, weight, at_mm, own))
    assert abs(added["mass"] - (0.059 + weight)) <= 1e-15
    # Both are sums of the same exact integrals, taken in two orders: rounding only (1e-9 of
    # the largest moment; the CM to 1e-12 m).
    assert np.allclose(added["com"], com, rtol=0, atol=1e-12)
    assert np.allclose(added["inertia"], inertia, rtol=0, atol=1e-9 * np.abs(inertia).max())


def test_analyze_says_whose_mass_properties_it_uses():
    printed = rb.Scene.from_file(os.path.join(ROOT, "scenes", "printed.yaml"))
    assert rb.analyze(printed)["mass_properties"] == "mesh (exact for the polyhedron, uniform density)"
    weighted = example().with_weight(printed, 0.005, [0.0, 70.0, 4.0])
    assert rb.analyze(weighted)["mass_properties"] == "the scene's center_of_mass and inertia"
    moved = printed.with_values({"body.center_of_mass": [0, 5, -1]})
    assert rb.analyze(moved)["mass_properties"] == "the scene's center_of_mass, the uniform solid's inertia"


def test_a_weighted_scene_saved_as_yaml_is_the_same_scene(tmp_path):
    for name in ("printed.yaml", "printed-rattleback.stl"):
        shutil.copy(os.path.join(ROOT, "scenes", name), tmp_path / name)
    weighted = example().with_weight(rb.Scene.from_file(tmp_path / "printed.yaml"), 0.005, [0.0, 70.0, 4.0])
    # Saved beside the scene it came from (its mesh is named relative to that folder).
    (tmp_path / "weighted.yaml").write_text(weighted.to_yaml())
    again, got = rb.analyze(tmp_path / "weighted.yaml"), rb.analyze(weighted)
    for key in ("mass", "com", "inertia", "mass_properties"):
        assert again[key] == got[key], key
