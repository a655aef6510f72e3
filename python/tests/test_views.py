"""What a still shows, read from its pixels: the whole body in frame in every fixed view, also
for a body that slides away across the floor."""

import numpy as np
import pytest

import rattleback as rb
from conftest import scene_path

# The default body on a slippery smooth floor, spun hard: its centre of mass slides ~10 cm in
# 4 s (in `above` it would run off the frame, in `front` it was cut at the edge).
SLIDING = {
    "contact.model": "smooth",
    "contact.stiffness": 2e4,
    "contact.damping": 4,
    "contact.friction": 0.02,
    "initial.spin": -50,
    "simulation.integrator": "symplectic",
    "simulation.dt": 2e-5,
    "simulation.duration": 4,
}


def body_pixels(image: np.ndarray) -> np.ndarray:
    """Where the body is drawn: its top red, its bottom blue (the floor is grey)."""
    rgb = image[:, :, :3].astype(int)
    red = (rgb[:, :, 0] > 150) & (rgb[:, :, 1] < 90) & (rgb[:, :, 2] < 90)
    blue = (rgb[:, :, 2] > 150) & (rgb[:, :, 0] < 90)
    return red | blue


@pytest.mark.parametrize("view", ["above", "front", "side", "oblique"])
def test_a_sliding_body_stays_in_frame(view):
    scene = rb.Scene.from_file(scene_path("rattleback.yaml")).with_values(SLIDING)
    run = rb.simulate(scene, rate=50)
    assert np.hypot(run.x - run.x[0], run.y - run.y[0]).max() > 0.05  # it does slide away
    for t in (0.0, 2.0, 4.0):
        body = body_pixels(rb.still(scene, t, view=view, size=(320, 180), readouts=False).array)
        assert body.sum() > 200, f"{view} at {t} s: no body"
        edge = body[0].sum() + body[-1].sum() + body[:, 0].sum() + body[:, -1].sum()
        assert edge == 0, f"{view} at {t} s: the body touches the frame's edge"
