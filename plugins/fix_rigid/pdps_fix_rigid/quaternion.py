r"""Quaternion and rotation algebra of rigid bodies, as numba functions of plain arrays.

A body's orientation is the unit quaternion q = (w, i, j, k) that turns body-frame vectors into space-
frame ones; its principal axes ex, ey, ez (the columns of the rotation matrix) follow from q. The
conventions are LAMMPS's math_extra (the ones fix rigid's Richardson and no-squish updates are written
in), so that a body set up from the same particles turns the same way:

- ``omega_from_angmom``: omega = sum_k (L . e_k / I_k) e_k, with 0 for a zero principal moment;
- ``richardson``: dq/dt = omega q / 2 advanced a full step directly and as two half steps with omega
  re-evaluated at the midpoint from L and the half-step q; q = 2 q_half - q_full, normalised
  (Richardson extrapolation; fix rigid);
- ``no_squish_rotate``: the free rotation about principal axis k of the symplectic splitting of
  Miller et al., J. Chem. Phys. 116, 8649 (2002) (NO_SQUISH), in the conjugate quaternion momentum
  p = 2 S(q) (0, L_body) of Kamberaj, Low and Neal, J. Chem. Phys. 122, 224114 (2005) (fix rigid/nve).
"""

import math

from numba import njit


@njit(cache=True, inline="always")
def normalize4(q):
    square = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]
    # a body spun up to an overflowing rate: NaN, which the core's finiteness check reports by line
    norm = 1.0 / math.sqrt(square) if 0.0 < square < math.inf else math.nan
    q[0] *= norm
    q[1] *= norm
    q[2] *= norm
    q[3] *= norm


@njit(cache=True, inline="always")
def axes_from_quaternion(q, ex, ey, ez):
    """Principal axes in the space frame (columns of the rotation matrix of q)."""
    w, i, j, k = q[0], q[1], q[2], q[3]
    ex[0] = w * w + i * i - j * j - k * k
    ex[1] = 2.0 * (i * j + w * k)
    ex[2] = 2.0 * (i * k - w * j)
    ey[0] = 2.0 * (i * j - w * k)
    ey[1] = w * w - i * i + j * j - k * k
    ey[2] = 2.0 * (j * k + w * i)
    ez[0] = 2.0 * (i * k + w * j)
    ez[1] = 2.0 * (j * k - w * i)
    ez[2] = w * w - i * i - j * j + k * k


@njit(cache=True)
def quaternion_from_axes(ex, ey, ez, q):
    """The unit quaternion whose rotation matrix has columns ex, ey, ez (a right-handed frame); the
    largest of the four squared components is taken first, so no division by a small number."""
    q0sq = 0.25 * (ex[0] + ey[1] + ez[2] + 1.0)
    q1sq = q0sq - 0.5 * (ey[1] + ez[2])
    q2sq = q0sq - 0.5 * (ex[0] + ez[2])
    q3sq = q0sq - 0.5 * (ex[0] + ey[1])
    if q0sq >= 0.25:
        q[0] = math.sqrt(q0sq)
        q[1] = (ey[2] - ez[1]) / (4.0 * q[0])
        q[2] = (ez[0] - ex[2]) / (4.0 * q[0])
        q[3] = (ex[1] - ey[0]) / (4.0 * q[0])
    elif q1sq >= 0.25:
        q[1] = math.sqrt(q1sq)
        q[0] = (ey[2] - ez[1]) / (4.0 * q[1])
        q[2] = (ey[0] + ex[1]) / (4.0 * q[1])
        q[3] = (ex[2] + ez[0]) / (4.0 * q[1])
    elif q2sq >= 0.25:
        q[2] = math.sqrt(q2sq)
        q[0] = (ez[0] - ex[2]) / (4.0 * q[2])
        q[1] = (ey[0] + ex[1]) / (4.0 * q[2])
        q[3] = (ez[1] + ey[2]) / (4.0 * q[2])
    else:
        q[3] = math.sqrt(q3sq)
        q[0] = (ex[1] - ey[0]) / (4.0 * q[3])
        q[1] = (ez[0] + ex[2]) / (4.0 * q[3])
        q[2] = (ez[1] + ey[2]) / (4.0 * q[3])
    normalize4(q)


@njit(cache=True, inline="always")
def omega_from_angmom(m, ex, ey, ez, moments, w):
    """Angular velocity from angular momentum in the space frame; a zero moment gives no rotation
    about its axis (a linear body)."""
    w0 = (m[0] * ex[0] + m[1] * ex[1] + m[2] * ex[2]) / moments[0] if moments[0] != 0.0 else 0.0
    w1 = (m[0] * ey[0] + m[1] * ey[1] + m[2] * ey[2]) / moments[1] if moments[1] != 0.0 else 0.0
    w2 = (m[0] * ez[0] + m[1] * ez[1] + m[2] * ez[2]) / moments[2] if moments[2] != 0.0 else 0.0
    for d in range(3):
        w[d] = w0 * ex[d] + w1 * ey[d] + w2 * ez[d]


@njit(cache=True, inline="always")
def _omega_times_q(w, q):
    """The quaternion (0, w) q."""
    return (-w[0] * q[1] - w[1] * q[2] - w[2] * q[3],
            q[0] * w[0] + w[1] * q[3] - w[2] * q[2],
            q[0] * w[1] + w[2] * q[1] - w[0] * q[3],
            q[0] * w[2] + w[0] * q[2] - w[1] * q[1])


@njit(cache=True)
def richardson(q, m, w, moments, dtq, half, full, ex, ey, ez):
    """Advance q a full step (dtq = dt/2) by Richardson extrapolation; w leaves as the midpoint
    angular velocity. ``half``, ``full`` (4,) and ``ex``, ``ey``, ``ez`` (3,) are scratch."""
    wq = _omega_times_q(w, q)
    for c in range(4):
        full[c] = q[c] + dtq * wq[c]
        half[c] = q[c] + 0.5 * dtq * wq[c]
    normalize4(full)
    normalize4(half)
    axes_from_quaternion(half, ex, ey, ez)
    omega_from_angmom(m, ex, ey, ez, moments, w)
    wq = _omega_times_q(w, half)
    for c in range(4):
        half[c] += 0.5 * dtq * wq[c]
    normalize4(half)
    for c in range(4):
        q[c] = 2.0 * half[c] - full[c]
    normalize4(q)


@njit(cache=True, inline="always")
def quaternion_times_vector(q, b):
    """The quaternion q (0, b)."""
    return (-q[1] * b[0] - q[2] * b[1] - q[3] * b[2],
            q[0] * b[0] + q[2] * b[2] - q[3] * b[1],
            q[0] * b[1] + q[3] * b[0] - q[1] * b[2],
            q[0] * b[2] + q[1] * b[1] - q[2] * b[0])


@njit(cache=True, inline="always")
def conjugate_times(q, p):
    """The vector part of q* p (two quaternions)."""
    return (-q[1] * p[0] + q[0] * p[1] + q[3] * p[2] - q[2] * p[3],
            -q[2] * p[0] - q[3] * p[1] + q[0] * p[2] + q[1] * p[3],
            -q[3] * p[0] + q[2] * p[1] - q[1] * p[2] + q[0] * p[3])


@njit(cache=True)
def no_squish_rotate(k, p, q, moments, dt):
    """Free rotation about principal axis k (1, 2, 3) for a time dt: (p, q) turned by the angle
    dt (p . P_k q) / (4 I_k) in the plane of (p, P_k p), (q, P_k q)."""
    if k == 1:
        kq0, kq1, kq2, kq3 = -q[1], q[0], q[3], -q[2]
        kp0, kp1, kp2, kp3 = -p[1], p[0], p[3], -p[2]
    elif k == 2:
        kq0, kq1, kq2, kq3 = -q[2], -q[3], q[0], q[1]
        kp0, kp1, kp2, kp3 = -p[2], -p[3], p[0], p[1]
    else:
        kq0, kq1, kq2, kq3 = -q[3], q[2], -q[1], q[0]
        kp0, kp1, kp2, kp3 = -p[3], p[2], -p[1], p[0]
    phi = p[0] * kq0 + p[1] * kq1 + p[2] * kq2 + p[3] * kq3
    if moments[k - 1] == 0.0:
        phi = 0.0
    else:
        phi /= 4.0 * moments[k - 1]
    c = math.cos(dt * phi)
    s = math.sin(dt * phi)
    p[0], p[1], p[2], p[3] = c * p[0] + s * kp0, c * p[1] + s * kp1, c * p[2] + s * kp2, c * p[3] + s * kp3
    q[0], q[1], q[2], q[3] = c * q[0] + s * kq0, c * q[1] + s * kq1, c * q[2] + s * kq2, c * q[3] + s * kq3
