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


def test_a_mesh_body_has_no_linearised_model_yet():
    # A mesh's lowest point is a corner, with no curvature to roll on: refused, not a matrix of
    # noise (it gave eigenvalues near ±1e4 i), and analyze --json's linearised is null.
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
    with pytest.raises(ValueError, match=r"^linearize: a mesh body has no smooth bottom"):
        rb.linearize(mesh)
    assert rb.analyze(mesh)["linearised"] is None
