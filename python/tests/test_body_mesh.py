"""Scene.mesh(): the body's closed surface as NumPy arrays (docs/python.md "Scenes"). Its
mass properties are computed here independently of the library (the signed tetrahedra of each
face with the origin, Tonon 2004's closed forms for a tetrahedron's second moment) and held
against analyze's continuum figures; the surface is checked closed and wound outwards by its
directed edges."""

import os

import numpy as np
import pytest

import rattleback as rb

SCENES = os.path.join(os.path.dirname(__file__), "..", "..", "scenes")


def moments(vertices, faces):
    """Volume, centroid and second moment ∫ r rᵀ dV of the solid the faces bound."""
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    det = np.einsum("ij,ij->i", a, np.cross(b, c))  # 6 × each tetrahedron's signed volume
    volume = det.sum() / 6
    centroid = (det[:, None] * (a + b + c)).sum(axis=0) / 24 / volume
    # ∫ r rᵀ over the tetrahedron (0, a, b, c) is det/120 (Σ p pᵀ + s sᵀ) with s = a + b + c.
    s = a + b + c
    second = np.einsum("i,ij,ik->jk", det, s, s)
    for p in (a, b, c):
        second += np.einsum("i,ij,ik->jk", det, p, p)
    return volume, centroid, second / 120


def inertia_about_cm(vertices, faces, mass):
    volume, com, second = moments(vertices, faces)
    c = second / volume - np.outer(com, com)
    return com, mass * (np.trace(c) * np.eye(3) - c)


def directed_edges(faces):
    return {(int(f[i]), int(f[(i + 1) % 3])) for f in faces for i in range(3)}


def closed_and_outwards(vertices, faces):
    assert vertices.dtype == np.float64 and vertices.shape[1] == 3
    assert faces.shape[1] == 3 and faces.min() == 0 and faces.max() == len(vertices) - 1
    edges = directed_edges(faces)
    # Closed and consistent: each edge walked once each way, by two faces.
    assert len(edges) == 3 * len(faces)
    assert all((j, i) in edges for i, j in edges)
    assert moments(vertices, faces)[0] > 0  # wound outwards


def test_the_default_bodys_mesh_is_closed_and_has_its_inertia():
    scene = rb.Scene.from_file(os.path.join(SCENES, "rattleback.yaml"))
    vertices, faces = scene.mesh()
    closed_and_outwards(vertices, faces)
    analysis = rb.analyze(scene)
    com, inertia = inertia_about_cm(vertices, faces, analysis["mass"])
    want = np.array(analysis["inertia"])
    # The default 192 segments: within 1e-3 of the body's continuum figures (measured 9.0e-4 in
    # tests/tessellate_test.cpp, which computes it with the library's own mesh moments).
    assert np.abs(inertia - want).max() < 1e-3 * np.abs(want).max()


def test_the_ellipsoids_volume_converges_at_second_order():
    # Kane & Levinson's scene gives the paper's inertia, not the uniform solid's: the volume is
    # what the shape alone fixes, 4/3 π abc with (a, b, c) half the box analyze gives.
    scene = rb.Scene.from_file(os.path.join(SCENES, "kane-levinson.yaml"))
    want = 4 / 3 * np.pi * np.prod(np.array(rb.analyze(scene)["size_m"]) / 2)
    errors = []
    for segments in (24, 48, 96):
        vertices, faces = scene.mesh(segments=segments)
        closed_and_outwards(vertices, faces)
        errors.append(abs(moments(vertices, faces)[0] / want - 1))
    # An inscribed polyhedron misses a smooth surface by O(h²) a cell: each halving ≈ ÷4.
    assert 3.5 < errors[0] / errors[1] < 4.5 and 3.5 < errors[1] / errors[2] < 4.5


def test_a_mesh_bodys_own_triangles_come_back_in_metres(tmp_path):
    box = np.array([[x, y, z] for z in (0, 20) for y in (0, 40) for x in (0, 100)], float)
    # The box's 12 triangles, counter-clockwise seen from outside.
    faces = np.array(
        [
            [0, 2, 3],
            [0, 3, 1],
            [4, 5, 7],
            [4, 7, 6],
            [0, 1, 5],
            [0, 5, 4],
            [2, 6, 7],
            [2, 7, 3],
            [0, 4, 6],
            [0, 6, 2],
            [1, 3, 7],
            [1, 7, 5],
        ]
    )
    with open(tmp_path / "box.obj", "w") as out:
        out.writelines(f"v {x} {y} {z}\n" for x, y, z in box)
        out.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
    scene = rb.Scene.from_dict(
        {
            "units": {"length": 0.001},
            "body": {"shape": "mesh", "mesh": {"file": str(tmp_path / "box.obj")}, "mass": 0.2},
            "contact": {"model": "points", "stiffness": 20},
            "simulation": {"dt": 1e-4, "duration": 0.1},
        }
    )
    vertices, got = scene.mesh()
    # The same triangles, corner by corner (the reader numbers the vertices as it meets them).
    assert np.allclose(vertices[got], box[faces] / 1000, rtol=0, atol=1e-15)


def test_bad_segments_and_dents_through_the_bottom_are_refused():
    scene = rb.Scene.from_file(os.path.join(SCENES, "rattleback.yaml"))
    with pytest.raises(ValueError, match="argument segments: must be 8 to 4096, not 5"):
        scene.mesh(segments=5)
    with pytest.raises(TypeError, match="argument segments: takes a whole number"):
        scene.mesh(segments=5.5)
    with pytest.raises(rb.SceneError, match="body.dents cut through the bottom"):
        scene.with_values({"body.dents.scale": 0.9}).mesh()


BOX_FACES = np.array(
    [[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4]]
    + [[2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]]
)


def box_in_mm(a, b, c):
    """A box a × b × c mm about its centre, vertex k at (±a/2, ±b/2, ±c/2) by k's bits."""
    return np.array([[x, y, z] for z in (-c / 2, c / 2) for y in (-b / 2, b / 2) for x in (-a / 2, a / 2)])


POINTS = {"contact": {"model": "points", "stiffness": 20}, "simulation": {"dt": 1e-4, "duration": 0.1}}


def test_from_mesh_gives_a_box_its_closed_form_inertia():
    # A solid box of mass m and sides a, b, c: I = m (b² + c²) / 12 about x, and so on.
    a, b, c, mass = 100.0, 40.0, 20.0, 0.2
    scene = rb.Scene.from_mesh(box_in_mm(a, b, c) + [3, -5, 10], BOX_FACES, mass, units=1e-3, scene=POINTS)
    inertia = np.array(rb.analyze(scene)["inertia"])
    sides = np.array([a, b, c]) * 1e-3
    expected = (
        mass
        / 12
        * np.diag(
            [sides[1] ** 2 + sides[2] ** 2, sides[0] ** 2 + sides[2] ** 2, sides[0] ** 2 + sides[1] ** 2]
        )
    )
    # The divergence theorem is exact for a polyhedron: only rounding is left (1e-12 of I).
    assert np.allclose(inertia, expected, rtol=0, atol=1e-12 * expected.max())


def test_from_mesh_of_the_default_body_rolls_and_reverses_as_it_does():
    body = rb.Scene.from_file(os.path.join(SCENES, "rattleback.yaml"))
    vertices, faces = body.mesh()
    scene = rb.Scene.from_mesh(vertices, faces, 0.059, scene=body)
    # Its inertia: the mesh's own, computed here, to rounding.
    _, inertia = inertia_about_cm(vertices, faces, 0.059)
    got = np.array(rb.analyze(scene)["inertia"])
    assert np.allclose(got, inertia, rtol=0, atol=1e-9 * np.abs(inertia).max())
    # And it reverses within 0.01 s of the analytic body (docs/scenes.md's round-trip table:
    # 3.1e-3 s apart at the default 192 segments).
    run, analytic = rb.simulate(scene, duration=4), rb.simulate(body, duration=4)
    assert abs(run.first_reversal - analytic.first_reversal) < 0.01
    # The scene keeps its mesh through with_values and pickling (a worker process).
    import pickle

    again = pickle.loads(pickle.dumps(scene.with_values({"initial.spin": -4})))
    assert rb.simulate(again, duration=1).spin[-1] == rb.simulate(scene, duration=1, spin=-4).spin[-1]
    # The same mesh in mm with units=1e-3 is the same body.
    in_mm = rb.Scene.from_mesh(vertices * 1000, faces, 0.059, units=1e-3, scene=body)
    assert np.allclose(rb.analyze(in_mm)["inertia"], got, rtol=0, atol=1e-12 * np.abs(got).max())


def test_from_mesh_checks_the_mesh_as_a_file_is_checked():
    box = box_in_mm(100, 40, 20)

    def refused(match, vertices=box, faces=BOX_FACES, file="from_mesh", **kw):
        kw.setdefault("units", 1e-3)
        with pytest.raises(rb.SceneError, match=match) as e:
            rb.Scene.from_mesh(vertices, faces, 0.2, scene=POINTS, **kw)
        assert e.value.file == file and e.value.line is None
        return e.value

    # The library's checks, as a file's: the scene named by from_mesh's name, with no line.
    # Their ways out in the arrays' words: no file to export again, `units=` for the unit.
    closed = "^<mesh>: vertices, faces: the mesh is not closed: 3 open edges"
    e = refused(closed, faces=BOX_FACES[:-1], file="<mesh>")
    assert e.key == "body.mesh.file" and str(e).endswith("and give the arrays again")
    refused(
        r"the mesh is inside out.*flip them \(faces\[:, ::-1\]\)$", faces=BOX_FACES[:, ::-1], file="<mesh>"
    )
    refused(r"with units=1, .*in mm\? units=0.001 makes it 0.1 m", units=1.0, file="<mesh>")
    refused("^toy: vertices, faces", faces=BOX_FACES[:-1], file="toy", name="toy")
    # The arrays' own faults, named as arguments.
    refused("argument faces: row 0 names vertex 8, but vertices has 8 rows", faces=BOX_FACES + 8)
    refused(
        "argument vertices: row 3 is not finite", vertices=np.where(np.arange(8)[:, None] == 3, np.nan, box)
    )
    refused(
        r"argument vertices takes an \(N, 3\) array, not one of shape \(3, 8\); transposed", vertices=box.T
    )
    refused(r"argument faces takes an \(M, 3\) array, not one of shape \(36,\)", faces=BOX_FACES.ravel())
    with pytest.raises(rb.SceneError, match="^from_mesh: argument mass must be > 0, not -1"):
        rb.Scene.from_mesh(box, BOX_FACES, -1, units=1e-3, scene=POINTS)
    with pytest.raises(TypeError, match=r"argument faces: takes an \(M, 3\) array of whole numbers"):
        rb.Scene.from_mesh(box, BOX_FACES.astype(float), 0.2)
    # A dict with no contact: named without the line of a text the caller never wrote.
    with pytest.raises(rb.SceneError, match="^<mesh>: contact is required") as e:
        rb.Scene.from_mesh(box, BOX_FACES, 0.2, units=1e-3, scene={"initial": {"spin": 5}})
    assert e.value.line is None
    # The scene's text is the whole scene, and a title names no values put in.
    scene = rb.Scene.from_mesh(box, BOX_FACES, 0.2, units=1e-3, scene=POINTS, name="box")
    assert "shape: mesh" in scene.yaml and scene.values == {} and scene.name == "box"
    with pytest.raises(rb.SceneError, match="cannot be swept: write its mesh to an STL or OBJ file"):
        rb.sweep(scene, vary={"initial.spin": [1, 2]})
