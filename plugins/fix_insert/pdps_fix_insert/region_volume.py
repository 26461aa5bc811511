"""Uniform points in a region and the region's volume, for the region-based insertion fixes."""

import numpy as np

from pdps_core.api import ScriptError


def insertion_region(sim, name):
    """The region named, refused with side out (its extent is the inside's, not the volume inserted into)."""
    region = sim.region(name)
    if region.side_out:
        raise ScriptError(f"region {name} has side out: insertion needs a region whose inside is the "
                          "insertion volume")
    if region.dynamic:
        raise ScriptError(f"region {name} moves (move or rotate): insertion needs a still region")
    return region


def clipped_extent(region, box):
    lo, hi = region.extent()
    lo, hi = np.maximum(lo, box.lo), np.minimum(hi, box.hi)
    if (hi <= lo).any():
        raise ScriptError(f"region {region.id} does not overlap the simulation box")
    return lo, hi


def region_points(region, box, rng, n):
    """n points uniform over the part of a region inside the box (its extent tried by ``match``)."""
    lo, hi = clipped_extent(region, box)
    out = np.empty((n, 3))
    filled, tried = 0, 0
    while filled < n:
        batch = rng.uniform(lo, hi, size=(max(n - filled, 1024), 3))
        tried += len(batch)
        batch = batch[region.match(batch)]
        take = min(len(batch), n - filled)
        out[filled:filled + take] = batch[:take]
        filled += take
        if filled == 0 and tried > 10_000_000:
            raise ScriptError(f"region {region.id} holds no point of the simulation box to insert at")
    return out


def region_volume(region, box, rng, tries):
    """The volume of the region's part inside the box: the share of ``tries`` uniform points of its
    extent that ``match`` it, times the extent's volume (LIGGGHTS's ntry_mc)."""
    lo, hi = clipped_extent(region, box)
    inside = 0
    for start in range(0, tries, 1_000_000):
        batch = rng.uniform(lo, hi, size=(min(1_000_000, tries - start), 3))
        inside += int(region.match(batch).sum())
    return float(np.prod(hi - lo)) * inside / tries


def surface_clearance(region, points, reach):
    """Distance from each point to the region's surface, ``reach`` where it is farther (all_in)."""
    out = np.full(len(points), float(reach))
    rows, distance, _, _ = region.surface_contacts(points, reach)
    np.minimum.at(out, np.asarray(rows, dtype=np.int64), np.asarray(distance, dtype=np.float64))
    return out


class InRegion:
    """The insertion volume of a region-based insertion fix (``self.region``): its extent in the box,
    uniform points in it, distances to its surface."""

    def extent(self, sim):
        return clipped_extent(self.region, sim.box)

    def draw_points(self, rng, n):
        return region_points(self.region, self.sim.box, rng, n)

    def clearance(self, points, reach):
        return surface_clearance(self.region, points, reach)

    def read_border(self, args):
        """``check_dist_from_subdomain_border yes`` (default): a centre less than its radius from a
        face of the box is a failed try, as LIGGGHTS's check against its subdomain's faces (pdps's
        placement is the same on any rank count, so the faces are the box's, periodic or not)."""
        self.border = 1.0 if args.check_dist_from_subdomain_border == "yes" else -np.inf
