"""Time in each condition where an optimized speed flies a stated distance."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


class FlightTimeComp(om.ExplicitComponent):
    """
    Durations of the mission's conditions when some fly their distances at a design speed.

    A level segment stated as a distance d takes t = d / V. Where a condition's speed V is a
    design variable (``speed_rule = "optimized"``), its time per leg is

        t_i = t_i,0 + d_i / V_i,

    with d_i the distance its distance segments state (``level_distance``) and t_i,0 the time
    of its other segments; a reserve stated as a distance d_res at such a condition takes
    t_res = d_res / V_r. The energy P_i t_i = P_i(V) t_i,0 + d_i P_i(V) / V is then smallest at
    the speed of least power per speed, the best-range speed (at most P/V: the tangent from the
    origin to the power curve; Raymer, Aircraft Design: A Conceptual Approach, 5th ed., Sec.
    17.2.7), and over a duration at the speed of least power (best endurance); the optimizer
    finds it with the rest of the design. The other conditions keep their times.

    Inputs
    ------
    {condition}_speed : float, (1,), m/s
        V_i of each condition named in option ``speed_conditions``.
    distance : float, (num_conditions,), m
        d_i (default: option ``distance``; used where the speed is optimized), an input so that
        the post-optimal sensitivity to a cruise range is a total derivative.

    Outputs
    -------
    duration : float, (num_conditions,), s
        t_i of every condition of the mission (in option order).
    reserve_duration : float, (1,), s
        t_res (only with option ``reserve_time``).

    Options
    -------
    fixed_time : sequence of float
        t_i,0 (s) per condition; its length sets num_conditions.
    distance : sequence of float
        Default d_i (m) per condition (0 where its speed is fixed).
    speed_conditions : dict
        Condition name -> its index among the conditions, for each optimized speed.
    reserve_time : float or None
        t_res (s) of a reserve flown for a time; None: no reserve output.
    reserve_distance : float
        d_res (m) of a reserve flown over a distance at ``reserve_condition``'s speed (then
        ``reserve_time`` is not used), else 0.
    reserve_condition : str or None
        The condition of ``speed_conditions`` whose speed flies the reserve distance.
    """

    def initialize(self):
        self.options.declare("fixed_time", types=(list, tuple, np.ndarray))
        self.options.declare("distance", types=(list, tuple, np.ndarray))
        self.options.declare("speed_conditions", types=dict)
        self.options.declare("reserve_time", default=None, allow_none=True)
        self.options.declare("reserve_distance", default=0.0)
        self.options.declare("reserve_condition", default=None, allow_none=True)

    def setup(self):
        opt = self.options
        self._t0 = np.asarray(opt["fixed_time"], dtype=float)
        self._d = np.asarray(opt["distance"], dtype=float)
        n = self._t0.size
        if self._d.shape != (n,) or np.any(self._d < 0.0) or np.any(self._t0 < 0.0):
            raise ValueError(
                f"FlightTimeComp: fixed_time and distance must be {n} non-negative values, got "
                f"{list(self._t0)} and {list(self._d)}"
            )
        self._reserve = opt["reserve_time"] is not None
        self.add_input("distance", val=self._d.copy(), units="m", desc="Distance per leg")
        self.add_output("duration", val=self._t0.copy(), units="s", desc="Time per leg")
        if self._reserve:
            self.add_output(
                "reserve_duration", val=float(opt["reserve_time"]), units="s", desc="Reserve time"
            )
        free = list(opt["speed_conditions"].values())
        self.declare_partials("duration", "distance", rows=free, cols=free)
        # The condition whose speed flies the reserve distance, if any.
        reserve_speed = opt["reserve_condition"] if opt["reserve_distance"] else None
        self._reserve_speed = (
            reserve_speed if self._reserve and reserve_speed in opt["speed_conditions"] else None
        )
        for name, i in opt["speed_conditions"].items():
            self.add_input(f"{name}_speed", val=50.0, units="m/s", desc=f"Speed of {name}")
            self.declare_partials("duration", f"{name}_speed", rows=[i], cols=[0])
        if self._reserve_speed is not None:
            self.declare_partials("reserve_duration", f"{self._reserve_speed}_speed")

    def _speed(self, inputs, name):
        speed = inputs[f"{name}_speed"]
        check_range(
            f"{name}_speed",
            speed,
            lower=0.0,
            lower_open=True,
            units="m/s",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        return speed[0]

    def compute(self, inputs, outputs):
        opt = self.options
        duration = self._t0 + np.zeros_like(outputs["duration"])  # complex under cs
        distance = inputs["distance"]
        for name, i in opt["speed_conditions"].items():
            duration[i] += distance[i] / self._speed(inputs, name)
        outputs["duration"] = duration
        if self._reserve_speed is not None:
            speed = self._speed(inputs, self._reserve_speed)
            outputs["reserve_duration"] = opt["reserve_distance"] / speed
        elif self._reserve:
            outputs["reserve_duration"] = opt["reserve_time"]

    def compute_partials(self, inputs, partials):
        opt = self.options
        distance = inputs["distance"]
        per_distance = []
        for name, i in opt["speed_conditions"].items():
            speed = self._speed(inputs, name)
            partials["duration", f"{name}_speed"] = -distance[i] / speed**2
            per_distance.append(1.0 / speed)
            if name == self._reserve_speed:
                partials["reserve_duration", f"{name}_speed"] = -opt["reserve_distance"] / speed**2
        partials["duration", "distance"] = per_distance
