"""``fix_modify ID temp CID`` for thermostats (temp/rescale, temp/berendsen, langevin), as LAMMPS's:
the named temperature compute's T decides, the fix's group is acted on, and a compute with a bias
(temp/partial: the components it leaves out; temp/region: the particles outside) keeps it out
(LAMMPS's remove_bias and restore_bias). A compute of another group than the fix's is warned of,
as LAMMPS warns. A fix that refuses some computes checks them in ``check_temperature``."""

from .errors import ScriptError
from .state import observables


class NamedTemperature:
    temp_id = None          # fix_modify temp: the temperature compute named instead of the group's

    def modify_param(self, sim, keyword, value):
        if keyword != "temp":
            return super().modify_param(sim, keyword, value)
        compute = sim.computes.get(value)
        if compute is None:
            raise ScriptError(f"compute {value} is not defined (temperature of fix {self.id})")
        if not type(compute).gives_temperature:
            raise ScriptError(f"compute {value} ({compute.name}) is not a temp compute, so it gives no temperature")
        self.check_temperature(value, compute)
        if compute.group != self.group:
            sim.warn(f"fix {self.id} {self.name}: temperature compute {value} is of group {compute.group}, not the "
                     f"fix's {self.group} (LAMMPS's fix_modify warns so too)")
        self.temp_id = value
        return True

    def check_temperature(self, ident, compute):
        """Refuse a temperature compute this fix cannot take (a ScriptError); all are taken by default."""

    def init_run(self, sim):
        if self.temp_id is not None and self.temp_id not in sim.computes:
            raise ScriptError(f"fix {self.id}: its temperature compute {self.temp_id} is not defined")

    def current_temperature(self, sim):
        if self.temp_id is None:
            return observables.temperature(sim, self.group)
        return float(sim.compute_value(self.temp_id))

    def thermal_velocities(self, sim):
        """The owned particles' velocities less the named compute's bias, or None where there is no
        bias (no fix_modify temp, or a compute without one: LAMMPS's tbiasflag)."""
        compute = sim.computes.get(self.temp_id) if self.temp_id is not None else None
        if not hasattr(compute, "velocity_bias"):
            return None
        p = sim.particles
        return p.v[:p.nlocal] - compute.velocity_bias(sim)

    def scale_velocities(self, sim, factor):
        p = sim.particles
        chosen = sim.groups.select(sim, self.group)
        v = p.v[:p.nlocal]
        compute = sim.computes[self.temp_id] if self.temp_id is not None else None
        if hasattr(compute, "velocity_bias"):
            bias = compute.velocity_bias(sim)[chosen]
            v[chosen] = bias + factor * (v[chosen] - bias)
        else:
            v[chosen] *= factor
