r"""Fix ``ave/euler``: Eulerian cell averages of granular particles on a regular grid (LIGGGHTS's
fix ave/euler).

Every NEVERY steps (and at each run's setup) the box is cut into a grid of cells and each particle
of the group is counted, whole, in the cell that holds its centre. The grid: with :math:`r_c` the
pair style's largest cutoff (LIGGGHTS's neighbor cutoff less the skin; for granular pairs twice the
largest radius, i.e. the largest diameter), the ideal cell edge is :math:`h = S\,r_c` (S =
``cell_size_relative``), and along each axis the box length :math:`L_d` holds
:math:`n_d = \lfloor L_d / h \rfloor` cells (at least 1) of edge :math:`L_d / n_d` (rounding down
makes cells larger than h). Cells are numbered :math:`i = i_z n_y n_x + i_y n_x + i_x` (row
``i + 1`` of ``f_ID[i][j]`` in LIGGGHTS's dialect). A particle on the box's faces or outside the
box is counted in no cell.

Per cell c, of volume :math:`V_c` (volume), with :math:`w_c` the part of it inside the
``basevolume_region`` (1 without one), the particles :math:`i \in c` of masses :math:`m_i` (mass),
radii :math:`r_i` (distance) and velocities :math:`v_i` (velocity):

.. math::

    N_c = \#\{i \in c\}, \qquad M_c = \sum_{i\in c} m_i, \qquad
    \bar v_c = \frac{\sum_{i\in c} m_i v_i}{M_c}\ \text{(Favre, mass average)}, \qquad
    \bar r_c = \frac{1}{N_c}\sum_{i\in c} r_i,

    \phi_c = \frac{\sum_{i\in c} \tfrac43\pi r_i^3}{w_c V_c}\ \text{(volume fraction, 1)}, \qquad
    \sigma_{c,ab} = \frac{1}{w_c V_c}\sum_{i\in c}\Big[-m_i (v_{i,a}-\bar v_{c,a})(v_{i,b}-\bar v_{c,b})
        - \tfrac12 \sum_{j} r_{ij,a} F_{ij,b}\Big], \qquad p_c = -\tfrac13 \operatorname{tr}\sigma_c

(stress and pressure in pressure units: the velocity fluctuations about the cell's mean plus each
particle's half of the virial of its contacts, :math:`r_{ij} = x_i - x_j`, :math:`F_{ij}` the
contact force on i, as LIGGGHTS's internal ``compute stress/atom pair``; times ``mvv2e`` and
``nktv2p``, 1 in si and cgs). Cells with no particle have every value 0 but their centre.

``basevolume_region R``: :math:`w_c` is estimated by Monte Carlo as LIGGGHTS's: 50 points per cell
drawn uniformly in the box by LIGGGHTS's Park-Miller generator (seed 15485863, x, y, z of each
point in turn), each point inside R adding 1/50 to its cell's weight, capped at 1; a cell whose
weight is below 1/50 has :math:`\phi_c = 0` and :math:`\sigma_c = 0` (a cell of weight 0 that holds
particles is given 1/50, as LIGGGHTS does).

Output: a global array ``f_ID[i][j]`` with a row per cell; columns (LIGGGHTS's compute_array,
numbered from 1 in its dialect): 1-3 the cell's centre, 4 :math:`\phi_c`, 5-7 :math:`\bar v_c`,
8 :math:`p_c`, 9-14 :math:`\sigma_c` xx yy zz xy xz yz, 15 :math:`\bar r_c`; and pdps's own
16 :math:`N_c` and 17 :math:`M_c`. The values are those of the last step the fix computed on.

Syntax (LIGGGHTS's, its keywords in this order)::

    fix ID GROUP ave/euler nevery N cell_size_relative S parallel yes|no [basevolume_region R]

N >= 1; S >= 1 (LIGGGHTS refuses S < 1; its manual asks for S >= 3).

Example (the volume fraction and mean vz of cell 14, and the pressure of cell 5)::

    fix eu all ave/euler nevery 100 cell_size_relative 2.7 parallel no
    thermo_style custom step f_eu[14][4] f_eu[14][7] f_eu[5][8]

Where pdps differs from LIGGGHTS 3.8.0:

- ``parallel``: pdps always averages on one grid over the whole box, summed over ranks (LIGGGHTS's
  ``parallel no``), so the values do not depend on the number of ranks; LIGGGHTS's ``parallel yes``
  gives each rank a grid over its own sub-domain, and thermo then shows rank 0's cells. On one rank
  the two are the same.
- Reading the values: LIGGGHTS's fix sets no global_freq, so its thermo (and a variable evaluated in
  a run) divides by 0 and aborts; only a variable evaluated between runs reads it, and only columns
  1-7 (it declares 7; the stress and radius reach only its dump euler/vtk). pdps's thermo, dumps and
  variables read all 17 columns at any step: the values of the last multiple of NEVERY (or of the
  run's setup). A row past the last cell is an error in pdps, 0 in LIGGGHTS.
- The contact virial is taken from the granular pair style's contacts (``ContactTable``) at the end
  of the step, with the velocities of the full step; LIGGGHTS tallies it during the step's force
  computation (half-step velocities), so the damping part of the stress differs by O(dt). A pair
  style without a contact table adds no virial (LIGGGHTS would add any pair's).
- The grid is set up again when the box's bounds have changed (LIGGGHTS: at every average when a
  fix may change the box).
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import ContactTable, Fix, ScriptError, StyleArgs, check_bins, keyword

TRIES_PER_CELL = 50
SEED = 15485863
NCOLUMNS = 17


@njit(cache=True)
def park_miller_points(seed, count, lo, hi):
    """``count`` points uniform in the box lo..hi, x, y, z in turn from LIGGGHTS's RanPark (Park and
    Miller's minimal standard generator); returns them and the generator's next seed."""
    ia, im, iq, ir = 16807, 2147483647, 127773, 2836
    am = 1.0 / im
    points = np.empty((count, 3))
    for k in range(count):
        for d in range(3):
            q = seed // iq
            seed = ia * (seed - q * iq) - ir * q
            if seed < 0:
                seed += im
            points[k, d] = lo[d] + (hi[d] - lo[d]) * (am * seed)
    return points, seed


@njit(cache=True)
def cells_of(x, count, lo, hi, inverse, dims):
    """The cell of each of the first ``count`` positions, -1 for those on or outside the box's faces
    (LIGGGHTS's coord2bin: truncation of (x - lo) / edge)."""
    cell = np.empty(count, dtype=np.int64)
    ncells = dims[0] * dims[1] * dims[2]
    for i in range(count):
        index = np.zeros(3, dtype=np.int64)
        outside = False
        for d in range(3):
            if x[i, d] <= lo[d] or x[i, d] >= hi[d]:
                outside = True
                break
            index[d] = int((x[i, d] - lo[d]) * inverse[d])
        if outside:
            cell[i] = -1
            continue
        c = index[2] * dims[1] * dims[0] + index[1] * dims[0] + index[0]
        cell[i] = c if c < ncells else -1
    return cell


@njit(cache=True)
def cell_sums(cell, chosen, v, rmass, radius, ncells):
    """Per cell: count, mass, momentum (3), sum of r^3 and sum of r of the chosen particles."""
    sums = np.zeros((ncells, 7))
    for i in range(len(cell)):
        c = cell[i]
        if c < 0 or not chosen[i]:
            continue
        m = rmass[i]
        r = radius[i]
        sums[c, 0] += 1.0
        sums[c, 1] += m
        for d in range(3):
            sums[c, 2 + d] += m * v[i, d]
        sums[c, 5] += r * r * r
        sums[c, 6] += r
    return sums


@njit(cache=True)
def cell_stress(cell, chosen, v, rmass, virial, v_av, mvv2e, nktv2p, ncells):
    """Per cell: -sum m dv_a dv_b (fluctuations about the cell's mean velocity) - sum of the
    particles' contact virials, xx yy zz xy xz yz (pressure*volume)."""
    stress = np.zeros((ncells, 6))
    pa = (0, 1, 2, 0, 0, 1)
    pb = (0, 1, 2, 1, 2, 2)
    for i in range(len(cell)):
        c = cell[i]
        if c < 0 or not chosen[i]:
            continue
        for k in range(6):
            a, b = pa[k], pb[k]
            stress[c, k] -= (mvv2e * rmass[i] * (v[i, a] - v_av[c, a]) * (v[i, b] - v_av[c, b])
                             + nktv2p * virial[i, k])
    return stress


@njit(cache=True)
def contact_virials(i_rows, j_rows, force, x, nall):
    """Each contact's virial r_ij (x) F_ij split half to i and half to j (xx yy zz xy xz yz)."""
    virial = np.zeros((nall, 6))
    pa = (0, 1, 2, 0, 0, 1)
    pb = (0, 1, 2, 1, 2, 2)
    for k in range(len(i_rows)):
        i, j = i_rows[k], j_rows[k]
        for m in range(6):
            half = 0.5 * (x[i, pa[m]] - x[j, pa[m]]) * force[k, pb[m]]
            virial[i, m] += half
            virial[j, m] += half
    return virial


class FixAveEuler(Fix):
    name = "ave/euler"
    usage = ("fix ID GROUP ave/euler nevery N cell_size_relative S parallel yes|no "
             "[basevolume_region R]")

    class Args(StyleArgs):
        nevery: int = keyword(..., ge=1, unit="1")
        cell_size_relative: float = keyword(..., ge=1.0, unit="dimensionless")
        parallel: bool = keyword(...)
        basevolume_region: str | None = keyword(None, names="region ID")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if not math.isfinite(args.cell_size_relative):
            raise ScriptError(f"fix {id} ave/euler: cell_size_relative must be finite "
                              f"(got {args.cell_size_relative})")
        if sim.dimension != 3:
            raise ScriptError(f"fix {id} ave/euler: needs a 3-d simulation (dimension {sim.dimension})")
        self.region = sim.region(args.basevolume_region) if args.basevolume_region is not None else None
        self.seed = SEED            # LIGGGHTS's generator, drawn on across runs as its is
        self.bounds = None          # the box's bounds the grid was made for
        self.values = None

    # ---- the grid -----------------------------------------------------------------------------
    def _cutoff(self, sim):
        pair = sim.pair
        cutsq = None if pair is None else getattr(pair, "cutsq", None)
        if cutsq is None:
            raise ScriptError(f"fix {self.id} ave/euler: needs a pair style (cells are cell_size_relative "
                              "times its largest cutoff)")
        cutoff = float(np.sqrt(np.max(np.asarray(cutsq)[1:, 1:])))
        if not cutoff > 0:
            raise ScriptError(f"fix {self.id} ave/euler: the pair style's largest cutoff is {cutoff:g}")
        return cutoff

    def _setup_cells(self, sim):
        box = sim.box
        lo, hi = np.array(box.lo, dtype=np.float64), np.array(box.hi, dtype=np.float64)
        ideal = self.args.cell_size_relative * self._cutoff(sim)
        for d in range(3):
            check_bins((hi[d] - lo[d]) / ideal, f"fix {self.id} ave/euler: cell edge {ideal:g} along "
                                               f"{'xyz'[d]} over the box ({lo[d]:g} to {hi[d]:g})")
        dims = np.array([max(1, int((hi[d] - lo[d]) / ideal)) for d in range(3)], dtype=np.int64)
        check_bins(int(np.prod(dims)), f"fix {self.id} ave/euler: cells of {' by '.join(map(str, dims))}")
        narrow = "".join(a for a, width in zip("xyz", hi - lo) if width < ideal)
        if narrow and sim.comm.rank == 0:
            sim.warn(f"fix {self.id} ave/euler: the box is narrower than a cell ({ideal:g}) along {narrow}: "
                     "one cell there (LIGGGHTS: number of cells was less than 1)")
        edge = (hi - lo) / dims
        self.lo, self.hi, self.dims = lo, hi, dims
        self.inverse = 1.0 / edge
        self.cell_volume = float(edge[0] * edge[1] * edge[2])
        ncells = int(np.prod(dims))
        iz, iy, ix = np.unravel_index(np.arange(ncells), (dims[2], dims[1], dims[0]))
        self.centers = np.column_stack([lo[0] + (ix + 0.5) * edge[0], lo[1] + (iy + 0.5) * edge[1],
                                        lo[2] + (iz + 0.5) * edge[2]])
        self.weight = np.ones(ncells)
        if self.region is not None:
            points, self.seed = park_miller_points(self.seed, ncells * TRIES_PER_CELL, lo, hi)
            inside = np.asarray(self.region.match(points), dtype=bool)
            cell = cells_of(points[inside], int(inside.sum()), lo, hi, self.inverse, dims)
            cell = cell[cell >= 0]
            self.weight = np.minimum(np.bincount(cell, minlength=ncells) / TRIES_PER_CELL, 1.0)
        self.bounds = (tuple(lo), tuple(hi))

    # ---- the timestep -------------------------------------------------------------------------
    def setup(self, sim):
        p = sim.particles
        if not (p.has("radius") and p.has("rmass")):
            raise ScriptError(f"fix {self.id} ave/euler: needs particles with radius and mass "
                              f"(particle_style sphere; got {sim.particle_style})")
        self._setup_cells(sim)
        self._average(sim)

    def end_of_step(self, sim):
        if sim.step % self.args.nevery:
            return
        if self.bounds != (tuple(sim.box.lo), tuple(sim.box.hi)):
            self._setup_cells(sim)
        self._average(sim)

    def _average(self, sim):
        p = sim.particles
        n = p.nlocal
        a = p.arrays
        ncells = len(self.weight)
        cell = cells_of(p.x, n, self.lo, self.hi, self.inverse, self.dims)
        chosen = sim.groups.select(sim, self.group)
        v, rmass, radius = a["v"], a["rmass"], a["radius"]
        sums = np.asarray(sim.comm.sum(cell_sums(cell, chosen, v, rmass, radius, ncells)), dtype=np.float64)
        count, mass = sums[:, 0], sums[:, 1]
        filled = count > 0
        v_av = np.zeros((ncells, 3))
        v_av[filled] = sums[filled, 2:5] / mass[filled, None]
        radius_av = np.zeros(ncells)
        radius_av[filled] = sums[filled, 6] / count[filled]
        eps = 1.0 / TRIES_PER_CELL
        # LIGGGHTS's safety: a cell the Monte Carlo missed but particles are in gets 1/50
        self.weight[(sums[:, 5] > 0) & (np.abs(self.weight) < 1e-6)] = eps
        counted = self.weight >= eps
        basis = np.where(counted, self.weight * self.cell_volume, 1.0)
        vol_fr = np.where(counted, 4.0 / 3.0 * math.pi * sums[:, 5] / basis, 0.0)
        stress = np.asarray(sim.comm.sum(cell_stress(cell, chosen, v, rmass, self._virials(sim), v_av,
                                                     sim.units.mvv2e, sim.units.nktv2p, ncells)),
                            dtype=np.float64)
        stress = np.where(counted[:, None], stress / basis[:, None], 0.0)
        pressure = -(stress[:, 0] + stress[:, 1] + stress[:, 2]) / 3.0
        self.values = np.column_stack([self.centers, vol_fr, v_av, pressure, stress, radius_av, count, mass])

    def _virials(self, sim):
        """Each owned particle's half of its contacts' virials (nlocal, 6), ghosts' halves sent home."""
        p = sim.particles
        n = p.nlocal
        pair = sim.pair
        if not isinstance(pair, ContactTable):
            return np.zeros((n, 6))
        found = pair.contacts(sim)
        virial = contact_virials(np.asarray(found["i"], dtype=np.int64), np.asarray(found["j"], dtype=np.int64),
                                 np.asarray(found["force"], dtype=np.float64), p.x, p.nall)
        owned = virial[:n]
        index, rows = sim.comm.reverse_rows(virial[n:p.nall])
        if len(index):
            np.add.at(owned, np.asarray(index, dtype=np.int64), np.asarray(rows, dtype=np.float64))
        return owned

    def array(self, sim):
        if self.values is None:
            raise ScriptError(f"fix {self.id} (ave/euler) has no cell averages before a run (run 0 first)")
        return self.values
