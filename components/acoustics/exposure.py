"""Noise exposure of observers over a path: sound exposure level and a smooth maximum level."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.common import DB_PER_NEPER
from lpc_mdo.core.checks import check_integer, check_number, check_range

#: Reference duration of the sound exposure level, s (ISO 1996-1:2016, 3.1.9; 14 CFR Part 36).
REFERENCE_DURATION = 1.0


class NoiseExposureComp(om.ExplicitComponent):
    """
    Sound exposure level and smooth maximum level of each observer over the points of a path.

    See docs theory/acoustics 'Noise exposure over a path'. A path (hover, the transition
    points, a climb) is sampled at ``num_points`` points; the level L_ij (A-weighted, dB re
    20 uPa) at observer i from point j is held over that point's share of the time, its
    ``duration`` dt_j. With E = 10**(L/10):

    - the sound exposure level (ISO 1996-1:2016, 3.1.9, L_AE; 14 CFR Part 36 and ICAO Annex 16
      Vol. I, SEL): the level that, held for the reference duration t_0 = 1 s, carries the
      same A-weighted sound energy,
      sel_i = 10 log10(sum_j E(L_ij) dt_j / t_0);
    - the maximum level over the path (ISO 1996-1 L_AFmax, here of the points' levels) as a
      Kreisselmeier-Steinhauser smooth maximum with sharpness rho (per dB),
      lmax_i = m_i + ln(sum_j exp(rho (L_ij - m_i)))/rho with m_i = max_j L_ij:
      never below the largest point level and at most ln(num_points)/rho above it (0.1 dB for
      eight points at the default rho = 20).

    A steady level L over a duration T gives sel = L + 10 log10(T/t_0); a source passing at
    speed V at closest distance d with spherical spreading, L(t) = L_0 - 10 log10(1 +
    (V t/d)^2), gives sel = L_0 + 10 log10(pi d/(V t_0)) over an infinite time window.

    Partials: analytic; ``sel`` and ``lmax`` of observer i depend on its own points' levels,
    ``sel`` also on their durations.

    Inputs
    ------
    level : float, (num_observers, num_points), dB (units=None)
        A-weighted level at each observer from each point of the path (without ``sources``).
    {name} : float, (number of its points,), dB (units=None)
        With ``sources`` = ((name, observers), ...): the levels of one source's points (e.g.
        one design condition's), each heard by the observer ``observers[k]``; each observer
        may hear its own number of points (lpc_mdo.vehicle.footprint_path).
    duration : float, (num_points,), s
        Time share of each point (> 0): of each column of ``level``; with ``sources``, of every
        point in the order of the sources (an equivalent time that also carries the spreading
        over a leg).

    Outputs
    -------
    sel : float, (num_observers,), dB (units=None)
        Sound exposure level of each observer.
    lmax : float, (num_observers,), dB (units=None)
        Smooth maximum level of each observer over the path.

    Options
    -------
    num_observers, num_points : int
        Array sizes (>= 1); with ``sources`` num_points is the number of all their points.
    sources : sequence of (str, sequence of int) or None
        Name of each level input and the observer of each of its points (None: one input
        ``level``, every observer hearing every point). Every observer hears at least one point.
    rho : float
        Sharpness of the smooth maximum, per dB (> 0). Default 20.
    """

    def initialize(self):
        self.options.declare("num_observers", default=1, desc="Number of observers (>= 1)")
        self.options.declare("num_points", default=1, desc="Points of the path (>= 1)")
        self.options.declare("rho", default=20.0, desc="Smooth-maximum sharpness, 1/dB (> 0)")
        self.options.declare(
            "sources",
            default=None,
            types=(list, tuple),
            allow_none=True,
            desc="(name, observer of each point) of each level input (None: one input 'level')",
        )

    def setup(self):
        no = check_integer("num_observers", self.options["num_observers"], lower=1)
        check_number("rho", self.options["rho"], lower=0.0, lower_open=True)
        sources = self.options["sources"]
        if sources is None:
            npt = check_integer("num_points", self.options["num_points"], lower=1)
            self.add_input(
                "level", np.full((no, npt), 60.0), units=None, desc="level at each observer, dB"
            )
            self._sources = [("level", np.repeat(np.arange(no), npt))]
            self._duration_index = np.tile(np.arange(npt), no)
        else:
            self._sources = []
            for name, observers in sources:
                observers = np.asarray(observers, dtype=int).ravel()
                if observers.size == 0 or observers.min() < 0 or observers.max() >= no:
                    raise ValueError(
                        f"{self.msginfo}: the observers of source {name!r} must be at least one "
                        f"index in [0, {no - 1}], got {observers.tolist()}"
                    )
                self.add_input(
                    str(name), np.full(observers.size, 60.0), units=None, desc="levels, dB"
                )
                self._sources.append((str(name), observers))
            npt = sum(observers.size for _, observers in self._sources)
            self._duration_index = np.arange(npt)
        self._observer = np.concatenate([observers for _, observers in self._sources])
        missing = np.setdiff1d(np.arange(no), self._observer)
        if missing.size:
            raise ValueError(f"{self.msginfo}: observers {missing.tolist()} hear no point")
        self.add_input("duration", np.ones(npt), units="s", desc="time share of each point")
        self.add_output("sel", np.zeros(no), units=None, desc="sound exposure level, dB")
        self.add_output("lmax", np.zeros(no), units=None, desc="smooth maximum level, dB")
        for name, observers in self._sources:
            cols = np.arange(observers.size)
            self.declare_partials("sel", name, rows=observers, cols=cols)
            self.declare_partials("lmax", name, rows=observers, cols=cols)
        self.declare_partials("sel", "duration", rows=self._observer, cols=self._duration_index)

    def _parts(self, inputs):
        check_range(
            "duration",
            inputs["duration"],
            lower=0.0,
            lower_open=True,
            units="s",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        for name, _ in self._sources:
            check_range(name, inputs[name], error=om.AnalysisError, where=self.msginfo)
        level = np.concatenate([inputs[name].ravel() for name, _ in self._sources])
        observer = self._observer
        top = np.full(self.options["num_observers"], -np.inf)
        np.maximum.at(top, observer, level.real)
        # Energies relative to each observer's loudest point: <= 1, no overflow.
        relative = level - top[observer]
        energy = 10.0 ** (relative / 10.0) * inputs["duration"][self._duration_index]
        weights = np.exp(self.options["rho"] * relative)
        total = np.zeros(top.shape, dtype=energy.dtype)
        np.add.at(total, observer, energy)
        weight_sum = np.zeros(top.shape, dtype=weights.dtype)
        np.add.at(weight_sum, observer, weights)
        return top, energy, weights, total, weight_sum

    def compute(self, inputs, outputs):
        top, _, _, total, weight_sum = self._parts(inputs)
        outputs["sel"] = top + 10.0 * np.log10(total / REFERENCE_DURATION)
        outputs["lmax"] = top + np.log(weight_sum) / self.options["rho"]

    def compute_partials(self, inputs, partials):
        _, energy, weights, total, weight_sum = self._parts(inputs)
        observer = self._observer
        # d sel/dL_p = E_p dt_p / sum of its observer; d sel/d dt_p = (10/ln 10) E_p / sum.
        share = energy / total[observer]
        softmax = weights / weight_sum[observer]
        start = 0
        for name, observers in self._sources:
            part = slice(start, start + observers.size)
            partials["sel", name] = share[part]
            partials["lmax", name] = softmax[part]
            start += observers.size
        duration = inputs["duration"][self._duration_index]
        partials["sel", "duration"] = DB_PER_NEPER * share / duration
