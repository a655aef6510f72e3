"""A weight glued to a printed rattleback: the keys body.mass, body.center_of_mass and
body.inertia for the body and the weight together, and what the weight does to the reversal
(docs/your-own-body.md "Add a weight").

Run from the repository's folder, or anywhere rattleback is installed:
    python3 examples/weighted_body.py
"""

import numpy as np

import rattleback as rb


def with_weight(scene, mass, at, own_inertia=None):
    """`scene`'s body with a weight of `mass` kg whose CM is at `at` (the mesh's frame, in the
    scene's file units), of inertia `own_inertia` about its own CM (kg m²; a point's, zero, when
    not given). The two are added about their common CM by the parallel-axis rule."""
    body = rb.analyze(scene)
    unit = body["length_unit_m"]  # m per file unit
    m0, c0, i0 = body["mass"], np.array(body["com"]), np.array(body["inertia"])  # kg, m, kg m²
    pw = np.asarray(at, dtype=float) * unit
    m = m0 + mass
    c = (m0 * c0 + mass * pw) / m

    def shifted(point_mass, d):  # a mass's inertia about a point d from it
        return point_mass * (d @ d * np.eye(3) - np.outer(d, d))

    inertia = i0 + shifted(m0, c0 - c) + shifted(mass, pw - c)
    if own_inertia is not None:
        inertia = inertia + np.asarray(own_inertia, dtype=float)
    return scene.with_values(
        {"body.mass": m, "body.center_of_mass": (c / unit).tolist(), "body.inertia": inertia.tolist()}
    )


if __name__ == "__main__":
    printed = rb.Scene.from_file("scenes/printed.yaml")
    # A 5 g nut glued on the top, 70 mm out along the long axis (the mesh is in mm, z up).
    weighted = with_weight(printed, 0.005, [0.0, 70.0, 4.0])
    for name, scene in (("as printed", printed), ("with the nut", weighted)):
        theory = rb.analyze(scene)
        for spin in (-5.0, 5.0):
            run = rb.simulate(scene, spin=spin)
            first = run.first_reversal
            print(
                f"{name:13} spun {spin:+.0f} rad/s: preferred {theory['preferred']}, "
                + ("no reversal" if first is None else f"reverses at {first:.2f} s")
            )
