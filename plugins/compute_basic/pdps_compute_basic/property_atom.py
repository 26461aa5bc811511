r"""Compute ``property/atom``: attributes of each particle as per-atom values, for ``dump custom``
and ``compute reduce`` (LAMMPS's compute property/atom).

With one attribute the values are a per-atom vector (``c_ID``); with several, a per-atom array whose
column k (0-based, in the order given) is ``c_ID[k]``. Particles outside the group get 0.

Attributes, in the run's units:

- ``id``, ``type``; ``mass`` (per-particle ``rmass`` when present, else the type's);
- ``x y z`` positions wrapped into the box, ``xu yu zu`` unwrapped through periodic images
  (:math:`x + n_x L_x`), ``ix iy iz`` image counts;
- ``vx vy vz`` velocities, ``fx fy fz`` forces;
- with ``particle_style sphere``: ``radius``, ``diameter``, ``omegax omegay omegaz`` angular
  velocities, ``tqx tqy tqz`` torques.

It has no global value: read it through ``dump custom`` or ``compute reduce``.

Syntax::

    compute ID GROUP property/atom attribute...

Example::

    compute p all property/atom xu vz radius
    dump 1 all custom 100 grains.dump id c_p[0] c_p[1] c_p[2]
    compute top all reduce max c_p[1]
"""

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, param

from .peratom import ATTRIBUTES, attribute, check_attribute


class ComputePropertyAtom(Compute):
    name = "property/atom"
    usage = "compute ID GROUP property/atom attribute... (" + " ".join(ATTRIBUTES) + ")"

    class Args(StyleArgs):
        attributes: list[str] = param(min_length=1, names="attribute")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        for name in args.attributes:
            check_attribute(sim, name, f"compute {id} property/atom")

    def peratom(self, sim):
        chosen = sim.groups.select(sim, self.group)
        columns = [np.where(chosen, attribute(sim, name), 0.0) for name in self.args.attributes]
        return columns[0] if len(columns) == 1 else np.column_stack(columns)

    def _per_atom_only(self, sim):
        raise ScriptError(f"compute {self.id} (property/atom) has per-atom values only: read them with "
                          f"dump custom (c_{self.id}) or compute reduce")

    scalar = vector = array = _per_atom_only
