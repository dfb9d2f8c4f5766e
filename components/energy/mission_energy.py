"""Mission energy bookkeeping: segment energies and the paper's sizing-mission rule."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


class MissionEnergyComp(om.ExplicitComponent):
    """
    Energy drawn from the battery over the sizing mission, from per-condition electrical power.

    Each design condition i with electrical power P_i and duration t_i contributes
    E_i = P_i t_i, counted k_i times (option ``energy_multipliers``):

        E_used = sum_i k_i P_i t_i

    The paper's rule (Sec. II; docs theory/energy): the mission is flown twice plus one reserve
    cruise, with hover extended to 60 s and the outbound transition energy doubled for the
    unmodelled inbound transition,

        E_req = 2 (E_hover,60s + 2 E_transition + E_climb + E_cruise + E_descent) + E_cruise,

    i.e. k = 2 (hover, 60 s), 4 (each transition point over its own segment time), 2 (climb),
    3 (cruise), 2 (descent) and 0 for conditions that are not flown (OEI, +3g, -1g).  The
    multipliers come from the vehicle file, so another accounting needs no code change.

    A mission stated as segments (:mod:`lpc_mdo.vehicle.mission_profile`) has k = its legs and,
    with a reserve, one more term: the reserve condition r flown for t_res,

        E_used = sum_i k_i P_i t_i + P_r t_res,

    a term of its own so that a leg's duration (e.g. a cruise range) and the reserve change
    apart.

    Inputs
    ------
    electrical_power : float, (num_conditions,), W
        Battery-side electrical power in each condition (sum of motor input powers).
    duration : float, (num_conditions,), s
        Time spent in each condition.
    reserve_duration : float, scalar, s
        t_res (only with option ``reserve_index``).

    Outputs
    -------
    segment_energy : float, (num_conditions,), J
        P_i t_i (one pass).
    energy_used : float, scalar, J
        sum_i k_i P_i t_i.

    Options
    -------
    energy_multipliers : sequence of float
        k_i >= 0 per condition; its length sets num_conditions.
    reserve_index : int or None
        Index r of the reserve condition; None (default): no reserve term.
    """

    def initialize(self):
        self.options.declare(
            "energy_multipliers",
            types=(list, tuple, np.ndarray),
            desc="how many times each condition's energy counts (>= 0)",
        )
        self.options.declare(
            "reserve_index",
            default=None,
            types=int,
            allow_none=True,
            desc="condition flown in reserve (None: no reserve term)",
        )

    def setup(self):
        k = np.asarray(self.options["energy_multipliers"], dtype=float)
        if k.ndim != 1 or k.size == 0:
            raise ValueError(
                f"{self.msginfo}: 'energy_multipliers' = {k.tolist()} is not "
                "allowed: must be a non-empty 1-D sequence of numbers >= 0"
            )
        check_range("energy_multipliers", k, lower=0.0, where=self.msginfo)
        self._k = k
        n = k.size
        self.add_input(
            "electrical_power",
            np.zeros(n),
            units="W",
            desc="battery-side electrical power per condition",
        )
        self.add_input("duration", np.zeros(n), units="s", desc="time in each condition")
        self.add_output(
            "segment_energy",
            np.zeros(n),
            units="J",
            desc="energy of one pass through each condition",
        )
        self.add_output("energy_used", 0.0, units="J", desc="energy drawn over the sizing mission")
        self.declare_partials("segment_energy", ["electrical_power", "duration"], diagonal=True)
        cols = np.arange(n)
        self.declare_partials(
            "energy_used", ["electrical_power", "duration"], rows=np.zeros(n, dtype=int), cols=cols
        )
        self._reserve = self.options["reserve_index"]
        if self._reserve is not None:
            check_range("reserve_index", self._reserve, lower=0, upper=n - 1, where=self.msginfo)
            self.add_input("reserve_duration", 0.0, units="s", desc="time flown in reserve")
            self.declare_partials("energy_used", "reserve_duration")

    def compute(self, inputs, outputs):
        duration = inputs["duration"]
        if np.any(duration.real < 0.0):
            raise om.AnalysisError(f"{self.msginfo}: duration = {duration.real} s; must be >= 0.")
        energy = inputs["electrical_power"] * duration
        outputs["segment_energy"] = energy
        outputs["energy_used"] = np.dot(self._k, energy)
        if self._reserve is not None:
            reserve = inputs["reserve_duration"]
            if reserve.real < 0.0:
                raise om.AnalysisError(f"{self.msginfo}: reserve_duration = {reserve.real} s < 0")
            outputs["energy_used"] += inputs["electrical_power"][self._reserve] * reserve

    def compute_partials(self, inputs, partials):
        power = inputs["electrical_power"]
        duration = inputs["duration"]
        partials["segment_energy", "electrical_power"] = duration
        partials["segment_energy", "duration"] = power
        d_power = self._k * duration
        if self._reserve is not None:
            d_power[self._reserve] += inputs["reserve_duration"][0]
            partials["energy_used", "reserve_duration"] = power[self._reserve]
        partials["energy_used", "electrical_power"] = d_power
        partials["energy_used", "duration"] = self._k * power
