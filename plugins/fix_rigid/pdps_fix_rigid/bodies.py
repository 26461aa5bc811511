r"""What the rigid-body styles share: the per-particle loops over plain arrays (numba).

Every particle of a body carries its body's index (``body``, -1 for none) and its displacement from
the body's centre of mass in the body frame (``displace``). Positions are unwrapped relative to the
body: the particle's image flags minus the body's (``image_body``), so that a body straddling a
periodic boundary is whole (LAMMPS's xcmimage). Each step:

- ``force_torque``: F = sum f_i and T = sum (r_i - X) x f_i (+ the particles' own torques for
  finite-size spheres) per body, this rank's particles (the caller sums over ranks);
- ``set_xv``: r_i = X + R d_i mapped back by the image difference, v_i = V + omega x (r_i - X);
- ``set_v``: v_i only.

The constraint virial is LAMMPS's: the force the body exerts on particle i is the velocity change the
body imposed minus the external force, f_c = m_i (v_new - v_old) / (dt/2) - f_i, and each of set_xv
and set_v adds half of r_i (x) f_c, r_i unwrapped relative to the body.
"""

import numpy as np
from numba import njit


@njit(cache=True, inline="always")
def _arm(x, image, image_body, length, xcm, i, b):
    """r_i - X: particle i's displacement from its body's centre of mass, unwrapped relative to the body."""
    return (x[i, 0] + (image[i, 0] - image_body[b, 0]) * length[0] - xcm[b, 0],
            x[i, 1] + (image[i, 1] - image_body[b, 1]) * length[1] - xcm[b, 1],
            x[i, 2] + (image[i, 2] - image_body[b, 2]) * length[2] - xcm[b, 2])


@njit(cache=True, inline="always")
def _add_inertia(out, b, m, a0, a1, a2, radius, i):
    """Particle i's part of body b's inertia tensor (xx, yy, zz, yz, xz, xy) at arm (a0, a1, a2); a
    sphere adds its own 2/5 m R^2 on the diagonal."""
    out[b, 0] += m * (a1 * a1 + a2 * a2)
    out[b, 1] += m * (a0 * a0 + a2 * a2)
    out[b, 2] += m * (a0 * a0 + a1 * a1)
    out[b, 3] -= m * a1 * a2
    out[b, 4] -= m * a0 * a2
    out[b, 5] -= m * a0 * a1
    if len(radius) > 0:
        sphere = 0.4 * m * radius[i] * radius[i]
        for d in range(3):
            out[b, d] += sphere


@njit(cache=True, inline="always")
def _to_space(ex, ey, ez, b, d0, d1, d2):
    """R d: a body-frame displacement in the space frame of body b (principal axes ex, ey, ez)."""
    return (ex[b, 0] * d0 + ey[b, 0] * d1 + ez[b, 0] * d2,
            ex[b, 1] * d0 + ey[b, 1] * d1 + ez[b, 1] * d2,
            ex[b, 2] * d0 + ey[b, 2] * d1 + ez[b, 2] * d2)


@njit(cache=True, inline="always")
def _set_velocity(v, vcm, omega, i, b, rx, ry, rz):
    """v_i = V + omega x r for particle i at space-frame arm r of body b."""
    v[i, 0] = omega[b, 1] * rz - omega[b, 2] * ry + vcm[b, 0]
    v[i, 1] = omega[b, 2] * rx - omega[b, 0] * rz + vcm[b, 1]
    v[i, 2] = omega[b, 0] * ry - omega[b, 1] * rx + vcm[b, 2]


@njit(cache=True, inline="always")
def _constraint_force(v, f, i, scale, v0, v1, v2):
    """f_c = m (v_new - v_old) / (dt/2) - f_i, ``scale`` = m / (dt/2): the force the body put on i."""
    return (scale * (v[i, 0] - v0) - f[i, 0],
            scale * (v[i, 1] - v1) - f[i, 1],
            scale * (v[i, 2] - v2) - f[i, 2])


@njit(cache=True)
def mass_and_centre(x, image, body, type_, mass, rmass, length, nlocal, nbody):
    """Per body: sum m r (unwrapped by the particle's image flags) and sum m, (nbody, 4)."""
    with_rmass = len(rmass) > 0
    out = np.zeros((nbody, 4))
    for i in range(nlocal):
        b = body[i]
        if b < 0:
            continue
        m = rmass[i] if with_rmass else mass[type_[i]]
        for d in range(3):
            out[b, d] += (x[i, d] + image[i, d] * length[d]) * m
        out[b, 3] += m
    return out


@njit(cache=True)
def inertia_sums(x, image, body, type_, mass, rmass, radius, length, xcm, image_body, nlocal, nbody):
    """Per body: the inertia tensor about the centre of mass (xx, yy, zz, yz, xz, xy); spheres add
    2/5 m R^2 on the diagonal."""
    with_rmass = len(rmass) > 0
    out = np.zeros((nbody, 6))
    for i in range(nlocal):
        b = body[i]
        if b < 0:
            continue
        dx, dy, dz = _arm(x, image, image_body, length, xcm, i, b)
        m = rmass[i] if with_rmass else mass[type_[i]]
        _add_inertia(out, b, m, dx, dy, dz, radius, i)
    return out


@njit(cache=True)
def body_frame(x, image, body, type_, mass, rmass, radius, length, xcm, image_body, ex, ey, ez,
               displace, nlocal, nbody):
    """Set each particle's body-frame displacement; return the inertia tensor recomputed from them
    (diagonal: the principal moments, off-diagonal: 0, when the axes are right)."""
    with_rmass = len(rmass) > 0
    out = np.zeros((nbody, 6))
    for i in range(nlocal):
        b = body[i]
        if b < 0:
            continue
        dx, dy, dz = _arm(x, image, image_body, length, xcm, i, b)
        d0 = ex[b, 0] * dx + ex[b, 1] * dy + ex[b, 2] * dz
        d1 = ey[b, 0] * dx + ey[b, 1] * dy + ey[b, 2] * dz
        d2 = ez[b, 0] * dx + ez[b, 1] * dy + ez[b, 2] * dz
        displace[i, 0], displace[i, 1], displace[i, 2] = d0, d1, d2
        m = rmass[i] if with_rmass else mass[type_[i]]
        _add_inertia(out, b, m, d0, d1, d2, radius, i)
    return out


@njit(cache=True)
def momenta(x, v, omega_atom, image, body, type_, mass, rmass, radius, length, xcm, image_body,
            nlocal, nbody):
    """Per body: linear momentum sum m v and angular momentum about the centre of mass
    sum (r - X) x m v (+ 2/5 m R^2 omega of spheres), (nbody, 6)."""
    with_rmass = len(rmass) > 0
    out = np.zeros((nbody, 6))
    for i in range(nlocal):
        b = body[i]
        if b < 0:
            continue
        m = rmass[i] if with_rmass else mass[type_[i]]
        dx, dy, dz = _arm(x, image, image_body, length, xcm, i, b)
        out[b, 0] += v[i, 0] * m
        out[b, 1] += v[i, 1] * m
        out[b, 2] += v[i, 2] * m
        out[b, 3] += dy * m * v[i, 2] - dz * m * v[i, 1]
        out[b, 4] += dz * m * v[i, 0] - dx * m * v[i, 2]
        out[b, 5] += dx * m * v[i, 1] - dy * m * v[i, 0]
        if len(radius) > 0 and len(omega_atom) > 0:
            sphere = 0.4 * m * radius[i] * radius[i]
            for d in range(3):
                out[b, 3 + d] += sphere * omega_atom[i, d]
    return out


@njit(cache=True)
def force_torque(x, f, torque_atom, image, body, length, xcm, image_body, nlocal, out):
    """Per body into ``out`` (nbody, 6), zeroed here: total force and torque about the centre of mass
    of this rank's particles (spheres' own torques added)."""
    out[:] = 0.0
    with_torque = len(torque_atom) > 0
    for i in range(nlocal):
        b = body[i]
        if b < 0:
            continue
        out[b, 0] += f[i, 0]
        out[b, 1] += f[i, 1]
        out[b, 2] += f[i, 2]
        dx, dy, dz = _arm(x, image, image_body, length, xcm, i, b)
        out[b, 3] += dy * f[i, 2] - dz * f[i, 1]
        out[b, 4] += dz * f[i, 0] - dx * f[i, 2]
        out[b, 5] += dx * f[i, 1] - dy * f[i, 0]
    if not with_torque:
        return
    # the spheres' own torques after all arms, in a second pass as LAMMPS sums them (the same
    # total to round-off; in LAMMPS's order a body's spin noise is LAMMPS's to the bit)
    for i in range(nlocal):
        b = body[i]
        if b < 0:
            continue
        out[b, 3] += torque_atom[i, 0]
        out[b, 4] += torque_atom[i, 1]
        out[b, 5] += torque_atom[i, 2]


@njit(cache=True, inline="always")
def _add_virial(virial, w0, w1, w2, w3, w4, w5):
    virial[0] += w0
    virial[1] += w1
    virial[2] += w2
    virial[3] += w3
    virial[4] += w4
    virial[5] += w5


@njit(cache=True)
def set_xv(x, v, f, omega_atom, image, body, displace, type_, mass, rmass, length, xcm, vcm, omega,
           ex, ey, ez, image_body, nlocal, dtf, virial, tally):
    """Positions and velocities of the particles from their bodies; with ``tally``, half the
    constraint virial added to ``virial`` (6,)."""
    with_rmass = len(rmass) > 0
    with_omega = len(omega_atom) > 0
    tally = tally and dtf != 0.0
    w0 = w1 = w2 = w3 = w4 = w5 = 0.0
    for i in range(nlocal):
        b = body[i]
        if b < 0:
            continue
        sx = (image[i, 0] - image_body[b, 0]) * length[0]
        sy = (image[i, 1] - image_body[b, 1]) * length[1]
        sz = (image[i, 2] - image_body[b, 2]) * length[2]
        x0, x1, x2 = x[i, 0] + sx, x[i, 1] + sy, x[i, 2] + sz
        v0, v1, v2 = v[i, 0], v[i, 1], v[i, 2]
        d0, d1, d2 = displace[i, 0], displace[i, 1], displace[i, 2]
        rx, ry, rz = _to_space(ex, ey, ez, b, d0, d1, d2)
        _set_velocity(v, vcm, omega, i, b, rx, ry, rz)
        x[i, 0] = rx + xcm[b, 0] - sx
        x[i, 1] = ry + xcm[b, 1] - sy
        x[i, 2] = rz + xcm[b, 2] - sz
        if with_omega:
            for d in range(3):
                omega_atom[i, d] = omega[b, d]
        m = rmass[i] if with_rmass else mass[type_[i]]
        if not tally:
            continue
        fc0, fc1, fc2 = _constraint_force(v, f, i, m / dtf, v0, v1, v2)
        w0 += 0.5 * x0 * fc0
        w1 += 0.5 * x1 * fc1
        w2 += 0.5 * x2 * fc2
        w3 += 0.5 * x0 * fc1
        w4 += 0.5 * x0 * fc2
        w5 += 0.5 * x1 * fc2
    _add_virial(virial, w0, w1, w2, w3, w4, w5)


@njit(cache=True)
def set_v(x, v, f, omega_atom, image, body, displace, type_, mass, rmass, length, vcm, omega,
          ex, ey, ez, image_body, nlocal, dtf, virial, tally):
    """Velocities of the particles from their bodies; with ``tally``, half the constraint virial
    added."""
    with_rmass = len(rmass) > 0
    with_omega = len(omega_atom) > 0
    tally = tally and dtf != 0.0
    w0 = w1 = w2 = w3 = w4 = w5 = 0.0
    for i in range(nlocal):
        b = body[i]
        if b < 0:
            continue
        d0, d1, d2 = displace[i, 0], displace[i, 1], displace[i, 2]
        rx, ry, rz = _to_space(ex, ey, ez, b, d0, d1, d2)
        v0, v1, v2 = v[i, 0], v[i, 1], v[i, 2]
        _set_velocity(v, vcm, omega, i, b, rx, ry, rz)
        if with_omega:
            for d in range(3):
                omega_atom[i, d] = omega[b, d]
        m = rmass[i] if with_rmass else mass[type_[i]]
        if not tally:
            continue
        fc0, fc1, fc2 = _constraint_force(v, f, i, m / dtf, v0, v1, v2)
        x0 = x[i, 0] + (image[i, 0] - image_body[b, 0]) * length[0]
        x1 = x[i, 1] + (image[i, 1] - image_body[b, 1]) * length[1]
        x2 = x[i, 2] + (image[i, 2] - image_body[b, 2]) * length[2]
        w0 += 0.5 * x0 * fc0
        w1 += 0.5 * x1 * fc1
        w2 += 0.5 * x2 * fc2
        w3 += 0.5 * x0 * fc1
        w4 += 0.5 * x0 * fc2
        w5 += 0.5 * x1 * fc2
    _add_virial(virial, w0, w1, w2, w3, w4, w5)


@njit(cache=True)
def remap_centres(xcm, image_body, lo, hi, length, periodic):
    """Centres of mass back into the periodic box, the bodies' image flags counting the shifts."""
    for b in range(xcm.shape[0]):
        for d in range(3):
            if not periodic[d] or not np.isfinite(xcm[b, d]):
                continue
            shift = np.floor((xcm[b, d] - lo[d]) / length[d])
            if shift != 0.0:
                xcm[b, d] -= shift * length[d]
                image_body[b, d] += int(shift)
            # round-off of the shift may leave it a hair outside
            if xcm[b, d] < lo[d]:
                xcm[b, d] += length[d]
                image_body[b, d] -= 1
            elif xcm[b, d] >= hi[d]:
                xcm[b, d] -= length[d]
                image_body[b, d] += 1
