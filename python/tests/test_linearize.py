"""rb.linearize: the state matrix behind analyze's eigenvalues (docs/python.md "rb.linearize")."""

import math

import numpy as np
import pytest

import rattleback as rb
from conftest import scene_path


def nearest_each(a, b):
    """The largest distance from an eigenvalue of `a` to the nearest of `b`, relative to its size."""
    return max(min(abs(x - y) for y in b) / max(1.0, abs(x)) for x in a)


def test_its_eigenvalues_are_analyzes_and_lapacks():
    scene = rb.Scene.from_file(scene_path("rattleback.yaml"))
    for spin in (-5.0, 0.0, 7.5):
        lin = rb.linearize(scene, spin=spin)
        assert lin.spin == spin
        assert lin.matrix.shape == (5, 5) and lin.states == ("u_x", "u_y", "w_x", "w_y", "w_z")
        printed = [complex(re, im) for re, im in rb.analyze(scene, spin=spin)["eigenvalues"]]
        # The bound, 1e-9: the same numbers as analyze's, not recomputed differently.
        assert nearest_each(lin.eigenvalues, printed) < 1e-9
        # LAPACK's eigenvalues of the matrix (NumPy), against the library's own solver (Eigen):
        # 1e-9, far below the finite differences' 1e-9 of the entries times the modes' size.
        assert nearest_each(np.linalg.eigvals(lin.matrix), lin.eigenvalues) < 1e-9


def test_at_rest_its_modes_rock_at_analyzes_frequencies():
    scene = rb.Scene.from_file(scene_path("rattleback.yaml"))
    lin = rb.linearize(scene, spin=0)
    hz = sorted({round(abs(l.imag) / (2 * math.pi), 9) for l in lin.eigenvalues if abs(l.imag) > 1e-6})
    quoted = rb.analyze(scene, spin=0)["frequencies_hz"]
    assert hz == pytest.approx(sorted([quoted["roll"], quoted["pitch"]]), rel=1e-8)


def test_default_spin_is_analyzes_and_the_arrays_are_read_only():
    scene = rb.Scene.from_file(scene_path("rattleback.yaml"))
    lin = rb.linearize(scene)
    assert lin.spin == rb.analyze(scene)["spin"]
    with pytest.raises(ValueError):
        lin.matrix[0, 0] = 1.0
    assert lin.units == ("1", "1", "rad/s", "rad/s", "rad/s")


def test_bad_spins_are_named():
    with pytest.raises(TypeError, match=r"^argument spin: takes a number \(rad/s\), not '5' \(str\)$"):
        rb.linearize(scene_path("rattleback.yaml"), spin="5")
    with pytest.raises(ValueError, match=r"^argument spin: must be a finite number"):
        rb.linearize(scene_path("rattleback.yaml"), spin=float("nan"))


def test_a_mesh_body_whose_bottom_is_no_bowl_has_no_linearised_model():
    # A box's bottom is flat: the fitted bottom is no bowl (docs/physics.md P11.4), so there is no
    # rocking to linearise: refused, naming why, and analyze --json's linearised is null.
    from conftest import SOURCE

    mesh = {
        "units": {"length": 0.01},
        "body": {
            "shape": "mesh",
            "mesh": {"file": str(SOURCE / "tests" / "meshes" / "box.obj")},
            "mass": 0.1,
        },
        "contact": {"model": "points", "stiffness": 20, "damping": 0.05},
        "simulation": {"dt": 1.0e-4, "duration": 0.1},
    }
    with pytest.raises(ValueError, match=r"^linearize: this mesh body's bottom does not fit .*not a bowl"):
        rb.linearize(mesh)
    assert rb.analyze(mesh)["linearised"] is None
    assert "not a bowl" in rb.analyze(mesh)["fitted_bottom"]["problem"]


def ellipsoid_obj(path, semi_axes, rings=96, sectors=192):
    """A latitude-longitude mesh of the ellipsoid (corners on it, wound outwards) as OBJ."""
    a, b, c = semi_axes
    theta = np.pi * np.arange(1, rings) / rings
    phi = 2 * np.pi * np.arange(sectors) / sectors
    t, p = np.meshgrid(theta, phi, indexing="ij")
    ring = np.stack([a * np.sin(t) * np.cos(p), b * np.sin(t) * np.sin(p), -c * np.cos(t)], -1)
    vertices = np.vstack([[0, 0, -c], ring.reshape(-1, 3), [0, 0, c]])
    at = lambda i, j: 1 + i * sectors + j % sectors  # noqa: E731
    faces = []
    for j in range(sectors):
        faces.append((0, at(0, j + 1), at(0, j)))
        for i in range(rings - 2):
            faces.append((at(i, j), at(i, j + 1), at(i + 1, j + 1)))
            faces.append((at(i, j), at(i + 1, j + 1), at(i + 1, j)))
        faces.append((len(vertices) - 1, at(rings - 2, j), at(rings - 2, j + 1)))
    faces = np.array(faces)
    # Wound outwards: each face's normal away from the centre (the ellipsoid is convex).
    v = vertices[faces]
    normal = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    inward = np.einsum("ij,ij->i", normal, v.mean(axis=1)) < 0
    faces[inward] = faces[inward][:, [0, 2, 1]]
    with open(path, "w") as out:
        out.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in vertices)
        out.writelines(f"f {i + 1} {j + 1} {k + 1}\n" for i, j, k in faces)


def kane_levinson_mesh(tmp_path, rings=96, sectors=192):
    """Kane & Levinson's scene with its body a mesh of their ellipsoid (their CM and inertia)."""
    ellipsoid_obj(tmp_path / "kl.obj", (0.03, 0.20, 0.02), rings, sectors)
    return {
        "units": {"length": 1.0},
        "body": {
            "shape": "mesh",
            "mesh": {"file": str(tmp_path / "kl.obj")},
            "center_of_mass": [0.0, 0.0, -0.01],
            "inertia": [[1.6e-3, -2.0e-5, 0.0], [-2.0e-5, 2.0e-4, 0.0], [0.0, 0.0, 1.7e-3]],
            "mass": 1.0,
        },
        "contact": {"model": "rolling", "friction": 1.0},  # theirs
        "initial": {"spin": 5.0, "tilt": [0.5, 0.5]},
        "simulation": {"tolerance": 1.0e-8, "duration": 3.0},
    }


def test_a_mesh_bodys_run_states_its_fitted_bottom_in_its_sidecar(tmp_path):
    # The sidecar's model.fitted_bottom is analyze's (docs/commands.md), residual and all; a
    # 12 × 24 mesh lies 1.8e-4 of its length RMS from its fit, beside the limit 5e-4.
    import json

    scene = dict(kane_levinson_mesh(tmp_path, 12, 24), simulation={"tolerance": 1e-8, "duration": 0.2})
    rb.simulate(scene).to_csv(tmp_path / "run.csv")
    sidecar = json.loads((tmp_path / "run.csv.json").read_text())["model"]["fitted_bottom"]
    assert sidecar == rb.analyze(scene)["fitted_bottom"]
    assert 1e-5 < sidecar["rms_fraction"] < sidecar["rms_limit_fraction"] == 5e-4
    assert sidecar["problem"] is None


def test_a_mesh_of_kane_and_levinsons_ellipsoid_linearises_as_the_ellipsoid(tmp_path):
    # The rolling model on the bottom fitted to a fine mesh of their ellipsoid (the same CM and
    # inertia) is theirs: the state matrix within 1e-3 of its largest entry (the fit's radii are
    # within about 1e-4 at this mesh, docs/physics.md P11.4).
    analytic = rb.Scene.from_file(scene_path("kane-levinson.yaml"))
    scene = kane_levinson_mesh(tmp_path)
    expected = rb.linearize(analytic, spin=5.0).matrix
    got = rb.linearize(scene, spin=5.0).matrix
    assert np.abs(got - expected).max() < 1e-3 * np.abs(expected).max()
    fitted = rb.analyze(scene)["fitted_bottom"]
    assert fitted["problem"] is None and fitted["rms_fraction"] < 1e-4
