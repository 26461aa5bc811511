r"""Quaternion and rotation algebra of rigid bodies, as numba functions of plain arrays.

The per-step helpers take a body's arrays (bodies x 3 or x 4) and its index b, not row views: a view
made inside a numba loop costs reference counting, several times the arithmetic here.

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
def _unit(a, b, c, d):
    square = a * a + b * b + c * c + d * d
    # a body spun up to an overflowing rate: NaN, which the core's finiteness check reports by line
    norm = 1.0 / math.sqrt(square) if 0.0 < square < math.inf else math.nan
    return a * norm, b * norm, c * norm, d * norm


@njit(cache=True, inline="always")
def _axes(w, i, j, k):
    """The rotation matrix of (w, i, j, k) by columns: ex, ey, ez (9 numbers)."""
    return (w * w + i * i - j * j - k * k, 2.0 * (i * j + w * k), 2.0 * (i * k - w * j),
            2.0 * (i * j - w * k), w * w - i * i + j * j - k * k, 2.0 * (j * k + w * i),
            2.0 * (i * k + w * j), 2.0 * (j * k - w * i), w * w - i * i - j * j + k * k)


@njit(cache=True, inline="always")
def axes_from_quaternion(quat, b, ex, ey, ez):
    """Principal axes of body b in the space frame (columns of the rotation matrix of its q)."""
    r = _axes(quat[b, 0], quat[b, 1], quat[b, 2], quat[b, 3])
    ex[b, 0], ex[b, 1], ex[b, 2] = r[0], r[1], r[2]
    ey[b, 0], ey[b, 1], ey[b, 2] = r[3], r[4], r[5]
    ez[b, 0], ez[b, 1], ez[b, 2] = r[6], r[7], r[8]


@njit(cache=True)
def quaternion_from_axes(ex, ey, ez, q):
    """The unit quaternion whose rotation matrix has columns ex, ey, ez (a right-handed frame; (3,)
    and (4,) arrays, at set-up); the largest of the four squared components is taken first, so no
    division by a small number."""
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
    q[0], q[1], q[2], q[3] = _unit(q[0], q[1], q[2], q[3])


@njit(cache=True, inline="always")
def _omega(m0, m1, m2, r, i0, i1, i2):
    """Angular velocity from angular momentum and the axes r (9 numbers); a zero moment gives no
    rotation about its axis (a linear body)."""
    w0 = (m0 * r[0] + m1 * r[1] + m2 * r[2]) / i0 if i0 != 0.0 else 0.0
    w1 = (m0 * r[3] + m1 * r[4] + m2 * r[5]) / i1 if i1 != 0.0 else 0.0
    w2 = (m0 * r[6] + m1 * r[7] + m2 * r[8]) / i2 if i2 != 0.0 else 0.0
    return (w0 * r[0] + w1 * r[3] + w2 * r[6], w0 * r[1] + w1 * r[4] + w2 * r[7],
            w0 * r[2] + w1 * r[5] + w2 * r[8])


@njit(cache=True, inline="always")
def omega_from_angmom(angmom, ex, ey, ez, inertia, omega, b):
    """omega = sum_k (L . e_k / I_k) e_k of body b."""
    r = (ex[b, 0], ex[b, 1], ex[b, 2], ey[b, 0], ey[b, 1], ey[b, 2], ez[b, 0], ez[b, 1], ez[b, 2])
    w = _omega(angmom[b, 0], angmom[b, 1], angmom[b, 2], r, inertia[b, 0], inertia[b, 1], inertia[b, 2])
    omega[b, 0], omega[b, 1], omega[b, 2] = w[0], w[1], w[2]


@njit(cache=True, inline="always")
def _omega_times_q(w0, w1, w2, q0, q1, q2, q3):
    """The quaternion (0, w) q."""
    return (-w0 * q1 - w1 * q2 - w2 * q3,
            q0 * w0 + w1 * q3 - w2 * q2,
            q0 * w1 + w2 * q1 - w0 * q3,
            q0 * w2 + w0 * q2 - w1 * q1)


@njit(cache=True, inline="always")
def richardson(quat, angmom, omega, inertia, b, dtq):
    """Advance body b's q a full step (dtq = dt/2) by Richardson extrapolation; omega leaves as the
    midpoint angular velocity."""
    q0, q1, q2, q3 = quat[b, 0], quat[b, 1], quat[b, 2], quat[b, 3]
    wq = _omega_times_q(omega[b, 0], omega[b, 1], omega[b, 2], q0, q1, q2, q3)
    f = _unit(q0 + dtq * wq[0], q1 + dtq * wq[1], q2 + dtq * wq[2], q3 + dtq * wq[3])
    h = _unit(q0 + 0.5 * dtq * wq[0], q1 + 0.5 * dtq * wq[1], q2 + 0.5 * dtq * wq[2], q3 + 0.5 * dtq * wq[3])
    w = _omega(angmom[b, 0], angmom[b, 1], angmom[b, 2], _axes(h[0], h[1], h[2], h[3]),
               inertia[b, 0], inertia[b, 1], inertia[b, 2])
    omega[b, 0], omega[b, 1], omega[b, 2] = w[0], w[1], w[2]
    wq = _omega_times_q(w[0], w[1], w[2], h[0], h[1], h[2], h[3])
    h = _unit(h[0] + 0.5 * dtq * wq[0], h[1] + 0.5 * dtq * wq[1], h[2] + 0.5 * dtq * wq[2],
              h[3] + 0.5 * dtq * wq[3])
    quat[b, 0], quat[b, 1], quat[b, 2], quat[b, 3] = _unit(2.0 * h[0] - f[0], 2.0 * h[1] - f[1],
                                                           2.0 * h[2] - f[2], 2.0 * h[3] - f[3])


@njit(cache=True, inline="always")
def quaternion_times_vector(quat, b, t0, t1, t2):
    """The quaternion q_b (0, t)."""
    q0, q1, q2, q3 = quat[b, 0], quat[b, 1], quat[b, 2], quat[b, 3]
    return (-q1 * t0 - q2 * t1 - q3 * t2,
            q0 * t0 + q2 * t2 - q3 * t1,
            q0 * t1 + q3 * t0 - q1 * t2,
            q0 * t2 + q1 * t1 - q2 * t0)


@njit(cache=True, inline="always")
def conjugate_times(quat, conjqm, b):
    """The vector part of q_b* p_b."""
    q0, q1, q2, q3 = quat[b, 0], quat[b, 1], quat[b, 2], quat[b, 3]
    p0, p1, p2, p3 = conjqm[b, 0], conjqm[b, 1], conjqm[b, 2], conjqm[b, 3]
    return (-q1 * p0 + q0 * p1 + q3 * p2 - q2 * p3,
            -q2 * p0 - q3 * p1 + q0 * p2 + q1 * p3,
            -q3 * p0 + q2 * p1 - q1 * p2 + q0 * p3)


@njit(cache=True, inline="always")
def no_squish_rotate(k, conjqm, quat, inertia, b, dt):
    """Free rotation of body b about principal axis k (1, 2, 3) for a time dt: (p, q) turned by the
    angle dt (p . P_k q) / (4 I_k) in the plane of (p, P_k p), (q, P_k q)."""
    p0, p1, p2, p3 = conjqm[b, 0], conjqm[b, 1], conjqm[b, 2], conjqm[b, 3]
    q0, q1, q2, q3 = quat[b, 0], quat[b, 1], quat[b, 2], quat[b, 3]
    if k == 1:
        kq0, kq1, kq2, kq3 = -q1, q0, q3, -q2
        kp0, kp1, kp2, kp3 = -p1, p0, p3, -p2
    elif k == 2:
        kq0, kq1, kq2, kq3 = -q2, -q3, q0, q1
        kp0, kp1, kp2, kp3 = -p2, -p3, p0, p1
    else:
        kq0, kq1, kq2, kq3 = -q3, q2, -q1, q0
        kp0, kp1, kp2, kp3 = -p3, p2, -p1, p0
    phi = p0 * kq0 + p1 * kq1 + p2 * kq2 + p3 * kq3
    moment = inertia[b, k - 1]
    if moment == 0.0:
        phi = 0.0
    else:
        phi /= 4.0 * moment
    c = math.cos(dt * phi)
    s = math.sin(dt * phi)
    conjqm[b, 0], conjqm[b, 1], conjqm[b, 2], conjqm[b, 3] = (c * p0 + s * kp0, c * p1 + s * kp1,
                                                              c * p2 + s * kp2, c * p3 + s * kp3)
    quat[b, 0], quat[b, 1], quat[b, 2], quat[b, 3] = (c * q0 + s * kq0, c * q1 + s * kq1,
                                                      c * q2 + s * kq2, c * q3 + s * kq3)


def rotation_matrix(q, rot):
    """The rotation matrix of a unit quaternion (w, x, y, z) into ``rot`` (LAMMPS's quat_to_mat)."""
    w2, i2, j2, k2 = q[0] * q[0], q[1] * q[1], q[2] * q[2], q[3] * q[3]
    twoij, twoik, twojk = 2.0 * q[1] * q[2], 2.0 * q[1] * q[3], 2.0 * q[2] * q[3]
    twoiw, twojw, twokw = 2.0 * q[1] * q[0], 2.0 * q[2] * q[0], 2.0 * q[3] * q[0]
    rot[0] = w2 + i2 - j2 - k2, twoij - twokw, twojw + twoik
    rot[1] = twoij + twokw, w2 - i2 + j2 - k2, twojk - twoiw
    rot[2] = twoik - twojw, twojk + twoiw, w2 - i2 - j2 + k2


def quaternion_product(a, b, c):
    """c = a b, the turn b then a (LAMMPS's quatquat)."""
    c[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3]
    c[1] = a[0] * b[1] + b[0] * a[1] + a[2] * b[3] - a[3] * b[2]
    c[2] = a[0] * b[2] + b[0] * a[2] + a[3] * b[1] - a[1] * b[3]
    c[3] = a[0] * b[3] + b[0] * a[3] + a[1] * b[2] - a[2] * b[1]
