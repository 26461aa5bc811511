"""The timestep loop (LAMMPS's Verlet): setup once per run, then the hook sequence every step.

    setup:  exchange, borders, build neighbors, force_clear, pair, reverse_comm, fix setup
            (or, when nothing changed since the last run ended or since the restart it was read
            from: the lists of the last build made again, and no wrap or sort; Neighbor.can_resume)
    step:   initial_integrate, post_integrate,
            rebuild? pre_exchange, exchange, borders, pre_neighbor, build : forward_comm
            force_clear, pre_force, pair, reverse_comm, post_force, final_integrate, end_of_step,
            output when due

Energy and virial are computed only on steps where an output reads them, and always on the last
step of a run, so values read between runs are current.
"""

import time

import numpy as np
from numba import njit

from ..errors import ScriptError, SimulationError
from ..state import limits
from ..state.finite import first_non_finite
from ..styles import TALLY
from .hookspec import HOOKS, implements
from .shrink_wrap import shrink_wrap
from .timers import timed_hooks

# Where a fix grows radii past the pair's sizing, the cutoffs are widened for radii this much larger
# than the largest: fix adapt growing by 0.27 % every 40 steps (LIGGGHTS's packing tutorial) widens
# them every 36 adaptations instead of at every rebuild, for lists 1.1^3 = 1.33 times longer at most
RADIUS_HEADROOM = 0.1


@njit(cache=True)
def _clear(values):
    """values[...] = 0 (force_clear): a numba call costs half numpy's assignment on a few thousand
    rows (gran_box's forces and torques: 8.4 -> 5.1 us a step)."""
    values[:] = 0.0


class Verlet:
    setup_hook = "setup"            # what fixes are called with after the setup forces

    def __init__(self, sim):
        self.sim = sim
        self.hooks = {}
        self.forward = ("x",)
        self.reverse = ("f",)
        self.warned_overrun = False
        self.contributing = []
        self.tally_atom = []
        self.sized_radius = None        # per type, the radii the pair's cutoffs cover (radii that vary)
        self.bond_forces = None         # the bond styles' loops (pdps_core/bond_loop.py), when bonds are computed

    # ---- setup ----------------------------------------------------------------------------------
    def _register_hooks(self):
        """hook -> the methods of the styles joining it, in script order, each timing itself
        (hookspec.py says why a tuple)."""
        sim = self.sim
        styles = list(sim.fixes.values()) + list(sim.analyzes.values())
        timed = [timed_hooks(style, sim.timers, [h for h in HOOKS if implements(style, h)]) for style in styles]
        self.hooks = {}
        for hook in HOOKS:
            functions = tuple(getattr(proxy, hook) for proxy in timed if hasattr(proxy, hook))
            if functions:
                self.hooks[hook] = functions

    def _call(self, hook):
        functions = self.hooks.get(hook)
        if functions is not None:
            t0 = time.perf_counter()
            sim = self.sim
            for function in functions:
                function(sim)
            sim.timers.stage["Modify"] += time.perf_counter() - t0

    def setup(self):
        sim = self.sim
        particles = sim.particles
        styles = [s for s in [sim.pair, *sim.fixes.values(), *sim.computes.values(),
                              *sim.analyzes.values()] if s is not None]
        for style in styles:
            particles.request_all(style.per_atom)
        ghost_velocity = sim.system.ghost_velocity or any(s.ghost_velocity for s in styles)
        forward = ["x"] + (["v"] if ghost_velocity else [])
        for style in styles:
            forward += [name for name in style.ghost_fields if name not in forward]
        self.forward = tuple(forward)
        self.reverse = ("f", "torque") if particles.has("torque") else ("f",)
        sim.neighbor.clear_requests()
        sim.neighbor.exclusions(sim.ntypes, sim.groups)
        self.bond_forces = self._bond_setup()
        sim.neighbor.special_exclusions(particles, sim.system.topology)
        sim.box.lost = sim.output.thermo.lost_policy()
        sim.neighbor.overrun = 0.0
        sim.neighbor.once_overrun = 0.0
        sim.styles.pair_list = None
        if sim.pair is not None:
            cutoff = sim.pair.init(sim.ntypes)
            sim.pair.cutsq = cutoff * cutoff        # for computes that evaluate pairs themselves (Pair.single)
            sim.styles.pair_list = sim.neighbor.request(sim.pair.neighbor_list, cutoff,
                                                 direct_ok=getattr(sim.pair, "cell_loops", False))
        radii_vary = any(fix.varies_radius for fix in sim.fixes.values())
        sim.neighbor.radii_vary = radii_vary
        self.sized_radius = None
        if radii_vary and sim.pair is not None and sim.pair.cutoff_from_radii:
            self.sized_radius = np.maximum(self._largest_radii(), [
                max([0.0] + [fix.inserted_radius(t) for fix in sim.fixes.values()]) for t in range(sim.ntypes + 1)])
        # styles ask for neighbor lists (and prepare per-run state) before ghosts are sized
        sim.run_state.in_init = True
        try:
            for style in styles:
                if style is not sim.pair and callable(getattr(style, "init_run", None)):
                    style.init_run(sim)
        finally:
            sim.run_state.in_init = False
        sim.groups.update(sim)
        self._register_hooks()
        self.contributing = [fix for fix in sim.fixes.values() if fix.thermo_energy or fix.thermo_virial]
        self.tally_atom = [c for c in sim.computes.values() if c.peratom_tally]
        if self.tally_atom:
            particles.request(TALLY, 7, ghost=False, replicate="copy")
        if self.tally_atom and sim.pair is not None and not sim.pair.peratom_tally:
            c = self.tally_atom[0]
            raise ScriptError(f"compute {c.id} ({c.name}) needs per-particle energies and virials, which pair "
                              f"style {sim.pair.name} does not tally")

        sim.run_state.box_changed = False
        trial = sim.neighbor.skin_trial
        if trial is not None and not trial.done:
            if sim.neighbor.requests:
                trial.begin(max(float(r.cutoff.max()) for r in sim.neighbor.requests))
            else:
                sim.neighbor.skin_trial = None
        if self.bond_forces is not None and not sim.neighbor.requests:
            raise ScriptError("bonds are computed between particles and their ghosts, and no neighbor list "
                              "makes ghosts here: define a pair style (pair_style zero CUTOFF, as long as the "
                              "longest bond, if the scene has no other)")
        limits.check_images(sim.box, sim.neighbor.ghost_cutoff())
        limits.check_ghosts(sim.box, sim.neighbor.ghost_cutoff(), int(sim.comm.sum(particles.nlocal)))
        # a shrink-wrapped box is fitted to the particles at every run's start, as LAMMPS's is
        resume = not sim.system.shrink_faces and not sim.dialect.rebuild_at_setup
        if resume and sim.neighbor.can_resume(particles, sim.box, sim.comm, wrap=sim.dialect.wrap_at_setup):
            self._resume_lists()
        else:
            shrink_wrap(sim)
            sim.comm.exchange(particles, sim.box, sim.step)
            self._reneighbor()
        # styles with history read it without advancing it during the setup forces (LAMMPS setupflag)
        sim.run_state.in_setup = True
        try:
            self._forces(eflag=True, vflag=True)
            self._call(self.setup_hook)
            self._fix_contributions()
            self._fix_contributions("final_integrate")
        finally:
            sim.run_state.in_setup = False
        self._check_finite()

    def _reneighbor(self):
        sim, particles = self.sim, self.sim.particles
        t0 = time.perf_counter()
        if self.sized_radius is not None:
            self._widen_for_radii()
        sim.neighbor.choose_skin(sim.box)
        if sim.neighbor.sort_due(sim.step):
            particles.keep(sim.neighbor.spatial_order(particles, sim.box, sim.step))
        sim.comm.borders(particles, sim.box, sim.neighbor.ghost_cutoff())
        sim.timers.stage["Comm"] += time.perf_counter() - t0
        self._call("pre_neighbor")
        t1 = time.perf_counter()
        sim.neighbor.build(particles, sim.box)
        if self.bond_forces is not None:
            sim.system.topology.build_bond_list(sim)
        t2 = time.perf_counter()
        sim.timers.stage["Neigh"] += t2 - t1
        self._call("post_neighbor")

    def _largest_radii(self):
        """The largest radius of each type (index 0 unused) over every rank."""
        sim, p = self.sim, self.sim.particles
        largest = np.zeros(sim.ntypes + 1)
        np.maximum.at(largest, p.type[:p.nlocal], p.radius[:p.nlocal])
        return sim.comm.max(largest)

    def _widen_for_radii(self):
        """At a rebuild where a fix grew radii (fix adapt) past those the pair's cutoffs were sized for
        (a granular pair: the largest radius of type i plus that of type j), the cutoffs grow by the
        excess, and RADIUS_HEADROOM beyond it, so that the lists see every contact; the pair is not
        asked again (its init makes the run's contact laws)."""
        sim = self.sim
        largest = self._largest_radii()
        if not (largest > self.sized_radius).any():
            return
        wanted = np.where(largest > self.sized_radius, largest * (1.0 + RADIUS_HEADROOM), self.sized_radius)
        extra = wanted - self.sized_radius
        self.sized_radius = wanted
        pair_list = sim.styles.pair_list
        pair_list.cutoff = pair_list.cutoff + extra[:, None] + extra[None, :]
        sim.pair.cutsq = pair_list.cutoff * pair_list.cutoff
        limits.check_images(sim.box, sim.neighbor.ghost_cutoff())

    def _resume_lists(self):
        """The lists of the last build, made again from the positions they were built with (xhold),
        then the current positions put back: the run goes on as if the previous one had not ended."""
        sim, particles = self.sim, self.sim.particles
        n = particles.nlocal
        t0 = time.perf_counter()
        current = particles.x[:n].copy()
        particles.x[:n] = sim.neighbor.xhold
        sim.comm.borders(particles, sim.box, sim.neighbor.ghost_cutoff())
        sim.neighbor.build(particles, sim.box, resume=True)
        if self.bond_forces is not None:
            sim.system.topology.build_bond_list(sim)
        particles.x[:n] = current
        sim.comm.forward_comm(particles, self.forward)
        sim.neighbor.refresh(particles, sim.box)
        sim.timers.stage["Neigh"] += time.perf_counter() - t0
        self._call("pre_neighbor")
        self._call("post_neighbor")

    def _forces(self, eflag, vflag):
        # the parts themselves, not the facade's names: this runs every step
        sim = self.sim
        particles, run, pair = sim.system.particles, sim.run_state, sim.styles.pair
        run.eflag, run.vflag = bool(eflag), bool(vflag)
        # per-particle energies and virials only on steps that read energies or virials
        run.tally_atom = bool(self.tally_atom) and (run.eflag or run.vflag)
        if run.tally_atom:
            particles.arrays[TALLY][:] = 0.0
        arrays = particles.arrays
        _clear(arrays["f"])
        if "torque" in arrays:
            _clear(arrays["torque"])
        self._call("pre_force")
        if pair is not None:
            t0 = time.perf_counter()
            pair.energy = 0.0
            full_list = pair.neighbor_list != "half"
            if vflag and full_list:
                pair.virial = None
            pair.compute(sim, sim.styles.pair_list, eflag, vflag)
            if vflag and full_list:
                if pair.virial is None:
                    raise SimulationError(f"pair style {pair.name} uses a full neighbor list and set no "
                                          f"virial at step {run.step} (a style on a full list tallies it: "
                                          "Pair.virial)")
                run.virial[:] = pair.virial
            elif vflag:
                x, f = particles.x, particles.f
                run.virial[:] = (np.einsum("ij,ij->j", x, f).tolist()
                                 + [float(x[:, 0] @ f[:, 1]), float(x[:, 0] @ f[:, 2]),
                                    float(x[:, 1] @ f[:, 2])])
            sim.timers.stage["Pair"] += time.perf_counter() - t0
            self._bond_forces(eflag, vflag)
            self._call("pre_reverse")
            t0 = time.perf_counter()
            sim.comm.reverse_comm(particles, self.reverse + ((TALLY,) if run.tally_atom else ()))
            sim.timers.stage["Comm"] += time.perf_counter() - t0
        else:
            if vflag:
                run.virial[:] = 0.0
            self._bond_forces(eflag, vflag)
            self._call("pre_reverse")
            if self.bond_forces is not None:
                sim.comm.reverse_comm(particles, self.reverse)
        if eflag:
            run.evdwl = pair.energy if pair is not None else 0.0
            run.pe = run.evdwl + run.ebond
            run.energy_step = run.step
        if vflag:
            run.pair_virial[:] = run.virial
            if self.bond_forces is not None:
                run.virial += self.bond_forces.virial
            run.virial_step = run.step
        if run.tally_atom:
            run.tally_step = run.step

    def interaction_energy(self):
        """The pair and bond energy of the particles where they stand now, summed over ranks, with
        the neighbor lists of the last build; the forces are computed afresh into f (the caller
        keeps and restores the step's). No fix hook runs (LAMMPS's FixNumDiff::update_energy)."""
        sim = self.sim
        particles, run, pair = sim.system.particles, sim.run_state, sim.styles.pair
        _clear(particles.arrays["f"])
        # the step's own tallies (pair.energy, per-particle energies) stay as they were
        tally_atom, run.tally_atom = run.tally_atom, False
        energy = 0.0
        try:
            if pair is not None:
                kept = pair.energy
                pair.energy = 0.0
                pair.compute(sim, sim.styles.pair_list, True, False)
                energy += pair.energy
                pair.energy = kept
            if self.bond_forces is not None:
                energy += self.bond_forces.compute(sim, True)
        finally:
            run.tally_atom = tally_atom
        return float(sim.comm.sum(energy))

    def _bond_setup(self):
        """The bond loops of this run, or None where no bond is computed (no bonds, bond_style none);
        bonds with no bond style are ignored with LAMMPS's warning."""
        sim = self.sim
        topology, styles = sim.system.topology, sim.styles.bond
        self.sim.run_state.ebond = 0.0
        if not topology.has_bonds(sim.particles):
            return None
        if styles is None:
            if int(sim.comm.sum(int(sim.particles.num_bond[:sim.particles.nlocal].sum()))) > 0:
                sim.warn("Bonds are defined but no bond style is set: no bond forces are computed")
            return None
        from ..bond_loop import BondForces
        styles.check_set(topology.nbondtypes)
        forces = BondForces(sim)
        return forces if forces.parts else None

    def _bond_forces(self, eflag, vflag):
        """The bonds' forces (before ghosts' forces are summed back), energy and virial when asked."""
        if self.bond_forces is None:
            return
        sim = self.sim
        t0 = time.perf_counter()
        run = sim.run_state
        tally = bool(eflag or vflag)
        energy = self.bond_forces.compute(sim, tally)
        if eflag:
            run.ebond = energy
        sim.timers.stage["Bond"] += time.perf_counter() - t0

    def _fix_contributions(self, stage="post_force"):
        """Fix energies and virials, where switched on, join the pair's: after post_force, when the
        fixes' forces are known, or, for a fix whose virial is complete only then (``virial_after =
        "final_integrate"``: fix rigid's constraint forces of set_v), after final_integrate."""
        sim = self.sim
        for fix in self.contributing:
            if stage == "post_force" and sim.eflag and fix.thermo_energy:
                sim.run_state.pe += float(fix.compute_energy(sim))
            if sim.vflag and fix.thermo_virial and fix.virial_after == stage:
                sim.run_state.virial += np.asarray(fix.compute_virial(sim), dtype=np.float64)

    def _check_finite(self):
        particles = self.sim.particles
        n = particles.nlocal
        message = None
        for name in ("x", "f"):
            values = particles.arrays[name]
            i = first_non_finite(values, n)
            if i >= 0:
                what = "position" if name == "x" else "force"
                message = (f"particle {int(particles.tag[i])} has a non-finite {what} "
                           f"({', '.join(f'{c:.6g}' for c in values[i])}) at step {self.sim.step}; "
                           "the run is unstable (time step too large or particles overlapping?)")
                break
        self.sim.comm.agree(message)

    def _check_runaway(self, step):
        """A particle that crossed half the box between two neighbor decisions has no meaningful
        trajectory left (its pairs and its image are guesses): stop rather than print garbage."""
        sim = self.sim
        half_box = 0.5 * float(sim.box.length[: sim.dimension].min())
        # every rank knows the largest move of all (the rebuild decision's maximum): the ranks
        # agree on a message only when there is one, not with a collective on every rebuild
        if sim.neighbor.moved_at_build <= half_box:
            return
        distance, i = sim.neighbor.moved(sim.particles)
        message = None
        if distance > half_box and i >= 0:
            message = (f"particle {int(sim.particles.tag[i])} moved {distance:.3g} since the last neighbor "
                       f"list build, more than half the box ({half_box:g}), at step {step}: the run has "
                       "blown up (time step too large or forces too strong?)")
        sim.comm.agree(message)

    def _skin_trial(self, step):
        """neighbor auto: the skin this step switches to while the trial lasts (None: no change)."""
        trial = self.sim.neighbor.skin_trial
        if trial is None or trial.done:
            return None
        skin = trial.next_skin(self.sim.neighbor, step, self.sim.comm)
        if trial.done:
            self.sim.neighbor.skin_trial = None
            self.sim.info(trial.report(skin))
        return skin

    # ---- steps ----------------------------------------------------------------------------------
    def run(self, nsteps):
        sim = self.sim
        particles, run, fixes = sim.particles, sim.run_state, sim.fixes
        last = run.step + nsteps
        for _ in range(nsteps):
            run.step += 1
            run.time += run.dt
            step = run.step
            eflag, vflag = sim.output.flags(step, last)
            new_skin = self._skin_trial(step)
            self._call("initial_integrate")
            self._call("post_integrate")
            rebuild = sim.neighbor.decide(particles, sim.comm)
            if sim.neighbor.once_overrun and not self.warned_overrun:
                self.warned_overrun = True
                sim.warn(f"neigh_modify once yes: a particle moved {sim.neighbor.once_overrun:.3g} since the "
                         f"run's neighbor list build, more than half the skin {sim.neighbor.skin:g}, at step {step}: "
                         "interactions may be missed from now on (LAMMPS builds no list either)")
            if new_skin is not None:
                sim.neighbor.skin = new_skin
                sim.neighbor.moved_at_build = 0.0       # moves under the old skin are not the new one's
                rebuild = True
                limits.check_images(sim.box, sim.neighbor.ghost_cutoff())
            # a box changed since the last decision (barostat, deform) shifts every periodic image:
            # wrap and make the ghosts again with the new lengths (sim.change_box)
            if run.box_changed:
                rebuild, run.box_changed = True, False
                limits.check_images(sim.box, sim.neighbor.ghost_cutoff())
            # a fix inserting or deleting particles asks for this step's rebuild (LAMMPS's
            # force_reneighbor / next_reneighbor); every rank's fixes agree on the step
            if not rebuild and any(fix.next_reneighbor == step for fix in fixes.values()):
                rebuild = True
            if rebuild:
                self._check_runaway(step)
                if sim.neighbor.overrun and not self.warned_overrun:
                    self.warned_overrun = True
                    sim.warn(f"a particle moved {sim.neighbor.overrun:.3g} between neighbor list builds, "
                             f"more than the skin {sim.neighbor.skin:g}, at step {step}: interactions may "
                             "have been missed (time step too large or velocities too high?)")
                self._call("pre_exchange")
                t0 = time.perf_counter()
                shrink_wrap(sim)
                sim.comm.exchange(particles, sim.box, step)
                sim.timers.stage["Comm"] += time.perf_counter() - t0
                self._reneighbor()
            else:
                t0 = time.perf_counter()
                sim.comm.forward_comm(particles, self.forward)
                t1 = time.perf_counter()
                sim.neighbor.refresh(particles, sim.box)
                sim.timers.stage["Comm"] += t1 - t0
                sim.timers.stage["Neigh"] += time.perf_counter() - t1
            self._forces(eflag, vflag)
            self._call("post_force")
            self._fix_contributions()
            self._check_finite()
            self._call("final_integrate")
            self._fix_contributions("final_integrate")
            self._call("end_of_step")
            sim.output.write(step, last)
            if run.restart_output is not None:
                t0 = time.perf_counter()
                run.restart_output.write(sim, step)
                sim.timers.stage["Output"] += time.perf_counter() - t0
        sim.neighbor.mark_current(particles)
        self._call("post_run")
