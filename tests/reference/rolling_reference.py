#!/usr/bin/env python3
"""An independent no-slip solver for Kane & Levinson's rattleback (scenes/kane-levinson.yaml,
air drag 0), in plain Python: the reference the rolling model is tested against
(Rolling.AgreesWithTheIndependentReferenceSolver, tests/theory_test.cpp).

Independent of sim/: another formulation, written from the mechanics, not from our code.
  - State in body axes: the vertical gamma (the world's up vector seen from the body) and the
    angular velocity w; our code integrates a world-frame quaternion and angular momentum.
  - Contact point of the ellipsoid x^T A^-2 x = 1 (centre c from the CM) whose outward normal
    is -gamma: r = c - A^2 gamma / sqrt(gamma^T A^2 gamma).
  - Newton-Euler about the CM with the no-slip velocity v = r x w eliminated (all in the
    rotating body frame):
        gamma' = gamma x w
        (I + M(|r|^2 1 - r r^T)) w' = -w x I w + M r x (r' x w) + M r x (w x (r x w))
                                      + M g r x gamma
    with r' = dr/dgamma gamma'.
  - Classical RK4 with a fixed step; a reversal is a sign change of n = w . gamma from the
    initial sign, located on the cubic Hermite interpolant of n(t) over the step (by bisection).
Initial state as rattleback's (sim/initial.cpp): orientation R = Rx(tilt_x) Ry(tilt_y), w =
spin along the body's z axis; gamma = R^T z.

Run:  python3 tests/reference/rolling_reference.py > tests/reference/kane-levinson.txt
(under a minute for both step sizes). Prints the first four reversal times (50 s) for two step
sizes; their difference is this solver's own error.
"""
import math
import sys

# Kane & Levinson (1982) in rattleback's body frame (scenes/kane-levinson.yaml).
SEMI = (0.03, 0.20, 0.02)
CENTRE = (0.0, 0.0, 0.01)
INERTIA = ((1.6e-3, -2.0e-5, 0.0), (-2.0e-5, 2.0e-4, 0.0), (0.0, 0.0, 1.7e-3))
MASS, G = 1.0, 9.81
SPIN, TILT_X, TILT_Y = 5.0, math.radians(0.5), math.radians(0.5)
A2 = tuple(a * a for a in SEMI)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def mat_vec(m, v):
    return tuple(dot(row, v) for row in m)


def solve3(m, b):
    """Cramer's rule for a 3x3 system."""

    def det(a):
        return (
            a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
            - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
        )

    d = det(m)
    out = []
    for col in range(3):
        mc = [list(row) for row in m]
        for row in range(3):
            mc[row][col] = b[row]
        out.append(det(mc) / d)
    return tuple(out)


def contact(gamma):
    """CM -> contact point r(gamma) and its derivative dr/dgamma (3x3)."""
    a2g = tuple(A2[i] * gamma[i] for i in range(3))
    s = math.sqrt(dot(gamma, a2g))
    r = tuple(CENTRE[i] - a2g[i] / s for i in range(3))
    # d(a2g/s)/dgamma = diag(A2)/s - a2g a2g^T / s^3
    jac = tuple(
        tuple((A2[i] if i == j else 0.0) / s - a2g[i] * a2g[j] / s**3 for j in range(3)) for i in range(3)
    )
    dr = tuple(tuple(-jac[i][j] for j in range(3)) for i in range(3))
    return r, dr


def rates(state):
    gamma, w = state[:3], state[3:]
    r, dr = contact(gamma)
    gamma_rate = cross(gamma, w)
    r_rate = mat_vec(dr, gamma_rate)
    iw = mat_vec(INERTIA, w)
    r2 = dot(r, r)
    a = tuple(
        tuple(INERTIA[i][j] + MASS * ((r2 if i == j else 0.0) - r[i] * r[j]) for j in range(3))
        for i in range(3)
    )
    terms = (cross(r, cross(r_rate, w)), cross(r, cross(w, cross(r, w))), cross(r, gamma))
    rhs = [-cross(w, iw)[i] + MASS * (terms[0][i] + terms[1][i] + G * terms[2][i]) for i in range(3)]
    w_rate = solve3(a, rhs)
    return gamma_rate + w_rate


def rk4(state, h):
    k1 = rates(state)
    k2 = rates(tuple(s + h / 2 * k for s, k in zip(state, k1)))
    k3 = rates(tuple(s + h / 2 * k for s, k in zip(state, k2)))
    k4 = rates(tuple(s + h * k for s, k in zip(state, k3)))
    out = tuple(s + h / 6 * (a + 2 * b + 2 * c + d) for s, a, b, c, d in zip(state, k1, k2, k3, k4))
    norm = math.sqrt(dot(out[:3], out[:3]))  # |gamma| = 1
    return tuple(x / norm for x in out[:3]) + out[3:]


def spin(state):
    return dot(state[:3], state[3:])


def spin_rate(state):
    """dn/dt = d(w.gamma)/dt = w'.gamma + w.gamma' (= w'.gamma, since gamma' is normal to w)."""
    k = rates(state)
    return dot(k[3:], state[:3]) + dot(state[3:], k[:3])


def initial():
    cx, sx, cy, sy = math.cos(TILT_X), math.sin(TILT_X), math.cos(TILT_Y), math.sin(TILT_Y)
    # R = Rx Ry; gamma = R^T z = the third row of R.
    rx = ((1, 0, 0), (0, cx, -sx), (0, sx, cx))
    ry = ((cy, 0, sy), (0, 1, 0), (-sy, 0, cy))
    r = tuple(tuple(sum(rx[i][k] * ry[k][j] for k in range(3)) for j in range(3)) for i in range(3))
    return tuple(r[2]) + (0.0, 0.0, SPIN)


def crossing(state, new, h, sign):
    """Where n(t) crosses zero within the step: the root of its cubic Hermite interpolant."""
    n0, n1 = spin(state), spin(new)
    d0, d1 = spin_rate(state) * h, spin_rate(new) * h
    lo, hi = 0.0, 1.0
    for _ in range(60):
        s = 0.5 * (lo + hi)
        value = (
            (2 * s**3 - 3 * s**2 + 1) * n0
            + (s**3 - 2 * s**2 + s) * d0
            + (-2 * s**3 + 3 * s**2) * n1
            + (s**3 - s**2) * d1
        )
        if value * sign > 0:
            lo = s
        else:
            hi = s
    return 0.5 * (lo + hi) * h


def reversals(h, duration, count):
    """Reversals as rattleback counts them (sim/rollout.hpp): a zero crossing of n against the
    current sign that goes on to reach 1 % of the initial |n| the other way before crossing
    back; the time is the crossing's. (rattleback also asks the new sign to hold for 0.2 s,
    which does not move Kane & Levinson's reversals: their spin goes on.)"""
    state, t = initial(), 0.0
    threshold = 0.01 * abs(spin(state))
    sign = 1.0 if spin(state) > 0 else -1.0
    found, pending = [], None
    for k in range(int(round(duration / h))):
        new = rk4(state, h)
        n0, n1 = spin(state), spin(new)
        if n0 * sign >= 0 and n1 * sign < 0:
            pending = t + crossing(state, new, h, sign)
        elif pending is not None and n1 * sign > 0:
            pending = None  # it crossed back before it counted
        if pending is not None and -n1 * sign >= threshold:
            found.append(pending)
            pending, sign = None, -sign
            if len(found) == count:
                break
        state, t = new, (k + 1) * h
    return found


if __name__ == "__main__":
    duration = float(sys.argv[1]) if len(sys.argv) > 1 else 50.0
    print("# Kane & Levinson (1982) rattleback, no drag, spin +5 rad/s, tilt 0.5/0.5 deg:")
    print("# reversal times [s] from tests/reference/rolling_reference.py (independent solver)")
    print("# step_s reversal_1_s reversal_2_s reversal_3_s reversal_4_s")
    for h in (2e-4, 1e-4):
        times = reversals(h, duration, 4)
        print(f"{h:g} " + " ".join(f"{x:.7f}" for x in times), flush=True)
