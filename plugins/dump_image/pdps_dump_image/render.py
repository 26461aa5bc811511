"""The renderer of dump image and movie: spheres and cylinders ray-cast into a depth-buffered picture.

This is the renderer of LIGGGHTS 3.8.0 (LAMMPS's Image class of its era), written from what its
source computes; pdps's pictures of the same scene are LIGGGHTS's, pixel for pixel (tests/).

Camera (``Camera.set``). The camera looks from ``camDir = (sin theta cos phi, sin theta sin phi,
cos theta)`` at the centre point; ``up`` is projected into the image plane (``camUp = camDir x
(up x camDir)``, normalised; theta is nudged by 1e-6 rad where up is parallel to the view). The
picture is orthographic: a pixel is ``maxdel / height / zoom`` wide, with ``maxdel`` twice the
longest box edge, so at zoom 1 the picture is twice as tall as the longest edge. The camera stands
``(maxdel / tan 30 deg + (delx camDir_x + dely camDir_y + delz camDir_z) / 2) / zoom`` from the centre,
which fixes the depths the z-buffer compares (and SSAO reads).

Shading (``_pixel``), with the surface normal n in camera space (x right, y up, z to the camera)::

    c = color (ambient + key max(0, n.k) + fill max(0, n.f) + back max(0, n.b)) + key max(0, n.h)^(16 s) s

three white lights (key 0.9 from 30 deg up, 45 deg left; fill 0.45 from 30 deg right; back 0.9 from
behind, 15 deg up), h the key light's half vector, s the shininess (``shiny``), ambient 0 (0.5 with
SSAO); each channel clamped to [0, 1] and truncated to 0..255.

Spheres are drawn over a square of pixels around their centre, the pixels whose centre falls
within the projected disc; cylinders (box edges, axes, bonds) by intersecting each pixel's ray with
the cylinder's mantle between its end caps, with a sphere on each end. A pixel keeps the nearest
surface drawn (ties: the first drawn).

SSAO (``_ssao``): for each covered pixel, ``8 + 32 f`` directions (f the ssao strength), spaced
evenly from an angle jittered by up to 15 deg with a uniform number of the dump's RanMars
generator, each marching the depth buffer over ``0.05 f maxdel`` with Bresenham's line to the
highest horizon; the colour is darkened by ``1 - ao``, ao the mean of ``clamp(sin(horizon angle) -
sin t (h . tangent))``. The generator's numbers run on from frame to frame, pixel by pixel from the
bottom row, as LIGGGHTS's on one rank.

The picture's row 0 is its bottom row; files are written from the top row down.
"""

import math

import numpy as np
from numba import njit

MY_PI = 3.14159265358979323846
EPSILON = 1.0e-6

# the camera and light parameters, one float64 array for the kernels (the slots' offsets)
RIGHT, UP, DIR, POS, CENTER = 0, 3, 6, 9, 12
TAN_PER_PIXEL, ZOOM = 15, 16
KEY, FILL, BACK, HALF, AMBIENT = 17, 20, 23, 26, 29
KEY_COLOR, FILL_COLOR, BACK_COLOR = 32, 35, 38
HARDNESS, INTENSITY = 41, 42
NPARAMS = 43


def _norm(v):
    scale = 1.0 / math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    return [v[0] * scale, v[1] * scale, v[2] * scale]


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _light(theta, phi):
    return [math.cos(theta) * math.sin(phi), math.sin(theta), math.cos(theta) * math.cos(phi)]


class Camera:
    """The view of one picture: ``set(...)`` fills ``params`` (the kernels' array) from the view
    keywords and the box; ``ssao_radius``/``ssao_samples`` the SSAO settings."""

    def __init__(self):
        self.params = np.zeros(NPARAMS)
        self.maxdel = 1.0

    def set(self, theta, phi, up, zoom, shiny, ssao, ssao_strength, lo, hi, center, height):
        """theta, phi in radians; up (3,); lo, hi the box's corners; center the point looked at."""
        cam_dir = [math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)]
        if up[0] == 0.0 and up[1] == 0.0 and up[2] == 0.0:
            raise ValueError("the up vector is zero")
        up = _norm(up)
        self.up = up
        dot = up[0] * cam_dir[0] + up[1] * cam_dir[1] + up[2] * cam_dir[2]
        if abs(dot) > 1.0 - EPSILON:
            # up along the view: the view is tilted by EPSILON, so that pictures stay continuous
            if theta == 0.0:
                tilted = EPSILON
            elif theta == MY_PI:
                tilted = theta - EPSILON
            else:
                tilted = theta + EPSILON
            cam_dir = [math.sin(tilted) * math.cos(phi), math.sin(tilted) * math.sin(phi), math.cos(tilted)]
        cam_right = _norm(_cross(up, cam_dir))
        cam_up = _cross(cam_dir, cam_right)
        if cam_up[0] == 0.0 and cam_up[1] == 0.0 and cam_up[2] == 0.0:
            raise ValueError("the up vector is parallel to the view")
        cam_up = _norm(cam_up)
        delx, dely, delz = 2.0 * (hi[0] - lo[0]), 2.0 * (hi[1] - lo[1]), 2.0 * (hi[2] - lo[2])
        maxdel = max(max(delx, dely), delz)
        zdist = maxdel
        zdist /= math.tan(MY_PI / 6.0)
        zdist += 0.5 * (delx * cam_dir[0] + dely * cam_dir[1] + delz * cam_dir[2])
        zdist /= zoom
        p = self.params
        p[RIGHT:RIGHT + 3] = cam_right
        p[UP:UP + 3] = cam_up
        p[DIR:DIR + 3] = cam_dir
        p[POS:POS + 3] = [cam_dir[0] * zdist, cam_dir[1] * zdist, cam_dir[2] * zdist]
        p[CENTER:CENTER + 3] = center
        p[TAN_PER_PIXEL] = -(maxdel / float(height))
        p[ZOOM] = zoom
        key = _light(MY_PI / 6.0, -0.78539816339744830962)
        p[KEY:KEY + 3] = key
        p[FILL:FILL + 3] = _light(0.0, MY_PI / 6.0)
        p[BACK:BACK + 3] = _light(MY_PI / 12.0, MY_PI)
        p[HALF:HALF + 3] = _norm([0 + key[0], 0 + key[1], 1 + key[2]])
        p[AMBIENT:AMBIENT + 3] = 0.5 if ssao else 0.0
        p[KEY_COLOR:KEY_COLOR + 3] = 0.9
        p[FILL_COLOR:FILL_COLOR + 3] = 0.45
        p[BACK_COLOR:BACK_COLOR + 3] = 0.9
        p[HARDNESS] = 16.0 * shiny
        p[INTENSITY] = shiny
        self.maxdel = maxdel
        self.ssao_radius = maxdel * 0.05 * ssao_strength
        self.ssao_samples = int(8.0 + 32.0 * ssao_strength)


class Picture:
    """The buffers of one picture: depth (-1 where nothing is drawn), the surface tangent SSAO
    reads, and the RGB bytes; row 0 at the bottom."""

    def __init__(self, width, height):
        self.width, self.height = width, height
        self.depth = np.empty(width * height)
        self.surface = np.zeros(2 * width * height)
        self.rgb = np.empty(3 * width * height, dtype=np.uint8)

    def clear(self, background):
        self.depth[:] = -1.0
        self.rgb.reshape(-1, 3)[:] = background

    def rows(self):
        """The picture as (height, width, 3) bytes, top row first (as files hold it)."""
        return self.rgb.reshape(self.height, self.width, 3)[::-1]


@njit(cache=True)
def _saturate(v):
    if v < 0.0:
        return 0.0
    if v > 1.0:
        return 1.0
    return v


@njit(cache=True)
def _pixel(p, width, depth_buf, surf_buf, rgb, ix, iy, depth, s0, s1, s2, c0, c1, c2):
    k = ix + iy * width
    if depth < 0 or (depth_buf[k] >= 0 and depth >= depth_buf[k]):
        return
    depth_buf[k] = depth
    surf_buf[2 * k] = s1
    surf_buf[2 * k + 1] = -s0
    diffuse_key = _saturate(s0 * p[KEY] + s1 * p[KEY + 1] + s2 * p[KEY + 2])
    diffuse_fill = _saturate(s0 * p[FILL] + s1 * p[FILL + 1] + s2 * p[FILL + 2])
    diffuse_back = _saturate(s0 * p[BACK] + s1 * p[BACK + 1] + s2 * p[BACK + 2])
    specular_key = _saturate(s0 * p[HALF] + s1 * p[HALF + 1] + s2 * p[HALF + 2]) ** p[HARDNESS] * p[INTENSITY]
    color = (c0, c1, c2)
    for j in range(3):
        c = color[j] * p[AMBIENT + j]
        c += color[j] * p[KEY_COLOR + j] * diffuse_key
        c += p[KEY_COLOR + j] * specular_key
        c += color[j] * p[FILL_COLOR + j] * diffuse_fill
        c += color[j] * p[BACK_COLOR + j] * diffuse_back
        rgb[3 * k + j] = np.uint8(int(_saturate(c) * 255.0))


# a centre or a half-size beyond this many pixels (a sphere far off the picture, an absurd diameter or
# zoom) is off the picture or covers it all: centres are skipped, half-sizes capped, so no loop runs on
LIMIT = 2.0 ** 30


@njit(cache=True)
def _on_screen(xf, yf):
    return abs(xf) < LIMIT and abs(yf) < LIMIT


@njit(cache=True)
def _pixels(full):
    """int(full) for a half-size in pixels, capped at LIMIT (NaN: 0)."""
    if not full < LIMIT:
        return 0 if full != full else int(LIMIT)
    return int(full)


@njit(cache=True)
def _pixel_width(p, dist):
    if p[TAN_PER_PIXEL] > 0:
        return p[TAN_PER_PIXEL] * dist
    return -p[TAN_PER_PIXEL] / p[ZOOM]


@njit(cache=True)
def _sphere(p, width, height, depth_buf, surf_buf, rgb, x0, x1, x2, c0, c1, c2, diameter):
    l0, l1, l2 = x0 - p[CENTER], x1 - p[CENTER + 1], x2 - p[CENTER + 2]
    xmap = p[RIGHT] * l0 + p[RIGHT + 1] * l1 + p[RIGHT + 2] * l2
    ymap = p[UP] * l0 + p[UP + 1] * l1 + p[UP + 2] * l2
    dist = (p[POS] * p[DIR] + p[POS + 1] * p[DIR + 1] + p[POS + 2] * p[DIR + 2]) \
        - (l0 * p[DIR] + l1 * p[DIR + 1] + l2 * p[DIR + 2])
    radius = 0.5 * diameter
    radsq = radius * radius
    pixel_width = _pixel_width(p, dist)
    xf = xmap / pixel_width
    yf = ymap / pixel_width
    if not _on_screen(xf, yf):
        return
    pixel_radius = _pixels(radius / pixel_width + 0.5) + 1
    xc = int(xf)
    yc = int(yf)
    width_error = xf - xc
    height_error = yf - yc
    xc += width // 2
    yc += height // 2
    # the square of pixels around the centre, within the picture
    for iy in range(max(yc - pixel_radius, 0), min(yc + pixel_radius, height - 1) + 1):
        for ix in range(max(xc - pixel_radius, 0), min(xc + pixel_radius, width - 1) + 1):
            s1 = ((iy - yc) - height_error) * pixel_width
            s0 = ((ix - xc) - width_error) * pixel_width
            proj = s0 * s0 + s1 * s1
            if proj > radsq:
                continue
            s2 = math.sqrt(radsq - proj)
            depth = dist - s2
            _pixel(p, width, depth_buf, surf_buf, rgb, ix, iy, depth,
                   s0 / radius, s1 / radius, s2 / radius, c0, c1, c2)


@njit(cache=True)
def _cylinder(p, width, height, depth_buf, surf_buf, rgb, x, y, c0, c1, c2, diameter, sflag):
    if sflag % 2:
        _sphere(p, width, height, depth_buf, surf_buf, rgb, x[0], x[1], x[2], c0, c1, c2, diameter)
    if sflag // 2:
        _sphere(p, width, height, depth_buf, surf_buf, rgb, y[0], y[1], y[2], c0, c1, c2, diameter)
    radius = 0.5 * diameter
    radsq = radius * radius
    z0, z1, z2 = y[0] - x[0], y[1] - x[1], y[2] - x[2]
    raster_width = abs(z0 * p[RIGHT] + z1 * p[RIGHT + 1] + z2 * p[RIGHT + 2]) + diameter
    raster_height = abs(z0 * p[UP] + z1 * p[UP + 1] + z2 * p[UP + 2]) + diameter
    m0 = (y[0] + x[0]) * 0.5 - p[CENTER]
    m1 = (y[1] + x[1]) * 0.5 - p[CENTER + 1]
    m2 = (y[2] + x[2]) * 0.5 - p[CENTER + 2]
    length = math.sqrt(z0 * z0 + z1 * z1 + z2 * z2)
    if length == 0.0:
        return
    inverse = 1.0 / length
    z0, z1, z2 = z0 * inverse, z1 * inverse, z2 * inverse
    length *= 0.5
    zmax, zmin = length, -length
    xmap = p[RIGHT] * m0 + p[RIGHT + 1] * m1 + p[RIGHT + 2] * m2
    ymap = p[UP] * m0 + p[UP + 1] * m1 + p[UP + 2] * m2
    dist = (p[POS] * p[DIR] + p[POS + 1] * p[DIR + 1] + p[POS + 2] * p[DIR + 2]) \
        - (m0 * p[DIR] + m1 * p[DIR + 1] + m2 * p[DIR + 2])
    pixel_width = _pixel_width(p, dist)
    xf = xmap / pixel_width
    yf = ymap / pixel_width
    if not _on_screen(xf, yf):
        return
    xc = int(xf)
    yc = int(yf)
    width_error = xf - xc
    height_error = yf - yc
    xc += width // 2
    yc += height // 2
    half_width = _pixels((raster_width * 0.5) / pixel_width + 0.5)
    half_height = _pixels((raster_height * 0.5) / pixel_width + 0.5)
    d0, d1, d2 = p[DIR], p[DIR + 1], p[DIR + 2]
    if (z0 == d0 and z1 == d1 and z2 == d2) or (z0 == -d0 and z1 == -d1 and z2 == -d2):
        return
    # the cylinder's frame: zaxis along it, yaxis = zaxis x camDir, xaxis = yaxis x zaxis
    ya0, ya1, ya2 = z1 * d2 - z2 * d1, z2 * d0 - z0 * d2, z0 * d1 - z1 * d0
    scale = 1.0 / math.sqrt(ya0 * ya0 + ya1 * ya1 + ya2 * ya2)
    ya0, ya1, ya2 = ya0 * scale, ya1 * scale, ya2 * scale
    xa0, xa1, xa2 = ya1 * z2 - ya2 * z1, ya2 * z0 - ya0 * z2, ya0 * z1 - ya1 * z0
    scale = 1.0 / math.sqrt(xa0 * xa0 + xa1 * xa1 + xa2 * xa2)
    xa0, xa1, xa2 = xa0 * scale, xa1 * scale, xa2 * scale
    ld0 = d0 * xa0 + d1 * xa1 + d2 * xa2
    ld1 = 0.0
    ld2 = d0 * z0 + d1 * z1 + d2 * z2
    r0, r1, r2 = p[RIGHT], p[RIGHT + 1], p[RIGHT + 2]
    lr0 = r0 * xa0 + r1 * xa1 + r2 * xa2
    lr1 = r0 * ya0 + r1 * ya1 + r2 * ya2
    lr2 = r0 * z0 + r1 * z1 + r2 * z2
    scale = 1.0 / math.sqrt(lr0 * lr0 + lr1 * lr1 + lr2 * lr2)
    lr0, lr1, lr2 = lr0 * scale, lr1 * scale, lr2 * scale
    u0, u1, u2 = p[UP], p[UP + 1], p[UP + 2]
    lu0 = u0 * xa0 + u1 * xa1 + u2 * xa2
    lu1 = u0 * ya0 + u1 * ya1 + u2 * ya2
    lu2 = u0 * z0 + u1 * z1 + u2 * z2
    scale = 1.0 / math.sqrt(lu0 * lu0 + lu1 * lu1 + lu2 * lu2)
    lu0, lu1, lu2 = lu0 * scale, lu1 * scale, lu2 * scale
    a = ld0 * ld0
    for iy in range(max(yc - half_height, 0), min(yc + half_height, height - 1) + 1):
        for ix in range(max(xc - half_width, 0), min(xc + half_width, width - 1) + 1):
            sy = ((iy - yc) - height_error) * pixel_width
            sx = ((ix - xc) - width_error) * pixel_width
            s0 = lr0 * sx + lu0 * sy
            s1 = lr1 * sx + lu1 * sy
            s2 = lr2 * sx + lu2 * sy
            b = 2 * ld0 * s0
            c = s0 * s0 + s1 * s1 - radsq
            partial = b * b - 4 * a * c
            if partial < 0:
                continue
            partial = math.sqrt(partial)
            t = (-b + partial) / (2 * a)
            t2 = (-b - partial) / (2 * a)
            if t2 > t:
                t = t2
            s0 += t * ld0
            s1 += t * ld1
            s2 += t * ld2
            if s2 > zmax or s2 < zmin:
                continue
            n0 = s0 / radius
            n1 = s1 / radius
            n2 = 0.0
            _pixel(p, width, depth_buf, surf_buf, rgb, ix, iy, dist - t,
                   n0 * lr0 + n1 * lr1 + n2 * lr2, n0 * lu0 + n1 * lu1 + n2 * lu2,
                   n0 * ld0 + n1 * ld1 + n2 * ld2, c0, c1, c2)


@njit(cache=True)
def draw_spheres(p, width, height, depth_buf, surf_buf, rgb, x, colors, diameters):
    """Spheres at x (n, 3) in colors (n, 3), of diameters (n,), in order; a diameter <= 0 draws none."""
    for i in range(x.shape[0]):
        if diameters[i] > 0.0:
            _sphere(p, width, height, depth_buf, surf_buf, rgb, x[i, 0], x[i, 1], x[i, 2],
                    colors[i, 0], colors[i, 1], colors[i, 2], diameters[i])


@njit(cache=True)
def draw_cylinders(p, width, height, depth_buf, surf_buf, rgb, ends, colors, diameters):
    """Cylinders from ends[i, 0] to ends[i, 1] ((n, 2, 3)), each with a sphere on both ends."""
    for i in range(ends.shape[0]):
        _cylinder(p, width, height, depth_buf, surf_buf, rgb, ends[i, 0], ends[i, 1],
                  colors[i, 0], colors[i, 1], colors[i, 2], diameters[i], 3)


@njit(cache=True)
def map_colors(values, kind, fractional, lo, hi, binsize, entries, entry_colors, out):
    """Each value's color under a color map (colors.ColorMap.table: kind 0 continuous, 1 discrete,
    2 sequential); a value matching no entry keeps the map's last color."""
    n = entries.shape[0]
    inverse = 1.0 / binsize
    for i in range(values.shape[0]):
        value = values[i]
        value = value if value > lo else lo
        value = value if value < hi else hi
        low = lo
        if fractional:
            value = 0.0 if lo == hi else (value - lo) / (hi - lo)
            low = 0.0
        for j in range(3):
            out[i, j] = entry_colors[n - 1, j]
        if kind == 0:
            for k in range(n - 1):
                if value >= entries[k, 0] and value <= entries[k + 1, 0]:
                    fraction = (value - entries[k, 0]) / (entries[k + 1, 0] - entries[k, 0])
                    for j in range(3):
                        out[i, j] = entry_colors[k, j] + fraction * (entry_colors[k + 1, j] - entry_colors[k, j])
                    break
        elif kind == 1:
            for k in range(n):
                if value >= entries[k, 0] and value <= entries[k, 1]:
                    for j in range(3):
                        out[i, j] = entry_colors[k, j]
                    break
        else:
            b = int((value - low) * inverse) % n
            for j in range(3):
                out[i, j] = entry_colors[b, j]


@njit(cache=True)
def ssao(p, width, height, depth_buf, surf_buf, rgb, radius, samples, state, indices):
    """Darken each covered pixel by its ambient occlusion (module docstring); ``state``/``indices``
    are the RanMars generator's (ranmars.py), advanced by one number per covered pixel."""
    del_theta = 2.0 * MY_PI / samples
    pixel_width = p[TAN_PER_PIXEL] if p[TAN_PER_PIXEL] > 0 else -p[TAN_PER_PIXEL] / p[ZOOM]
    pixel_radius = _pixels(radius / pixel_width + 0.5)
    jitter = MY_PI / 12
    npixels = width * height
    index = 0
    for y in range(height):
        for x in range(width):
            cdepth = depth_buf[index]
            if cdepth < 0:
                index += 1
                continue
            sx = surf_buf[index * 2]
            sy = surf_buf[index * 2 + 1]
            sin_t = -math.sqrt(sx * sx + sy * sy)
            theta = _uniform(state, indices) * jitter
            ao = 0.0
            for s in range(samples):
                hx = math.cos(theta)
                hy = math.sin(theta)
                theta += del_theta
                scaled_sin_t = sin_t * (hx * sy + hy * sx)
                dx = int(hx * pixel_radius)
                dy = int(hy * pixel_radius)
                ex = min(max(x + dx, 0), width - 1)
                ey = min(max(y + dy, 0), height - 1)
                if abs(hx) > abs(hy):
                    small = 1 if hx > 0 else -1
                    large = width if hy > 0 else -width
                    delta = abs(hy / hx)
                else:
                    small = width if hy > 0 else -width
                    large = 1 if hx > 0 else -1
                    delta = abs(hx / hy)
                length_step = math.sqrt(1 + delta * delta) * pixel_width
                end = ex + ey * width
                ind = index + small
                length = length_step
                err = delta
                if err >= 1.0:
                    ind += large
                    err -= 1.0
                min_peak = -1.0
                peak_length = 0.0
                while (small > 0 and ind <= end) or (small < 0 and ind >= end):
                    if ind < 0 or ind >= npixels:
                        break
                    if min_peak < 0 or (depth_buf[ind] >= 0 and depth_buf[ind] < min_peak):
                        min_peak = depth_buf[ind]
                        peak_length = length
                    ind += small
                    length += length_step
                    err += delta
                    if err >= 1.0:
                        ind += large
                        err -= 1.0
                if peak_length > 0:
                    h = math.atan((cdepth - min_peak) / peak_length)
                    ao += _saturate(math.sin(h) - scaled_sin_t)
                else:
                    ao += _saturate(-scaled_sin_t)
            ao /= samples
            for j in range(3):
                c = float(rgb[index * 3 + j])
                c *= (1.0 - ao)
                rgb[index * 3 + j] = np.uint8(int(c))
            index += 1


@njit(cache=True)
def _uniform(state, indices):
    """RanMars's next uniform number (ranmars.py holds the same generator for Python callers)."""
    u = state
    uni = u[indices[0]] - u[indices[1]]
    if uni < 0.0:
        uni += 1.0
    u[indices[0]] = uni
    indices[0] -= 1
    if indices[0] == 0:
        indices[0] = 97
    indices[1] -= 1
    if indices[1] == 0:
        indices[1] = 97
    u[98] -= u[99]
    if u[98] < 0.0:
        u[98] += u[100]
    uni -= u[98]
    if uni < 0.0:
        uni += 1.0
    return uni
