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

    Partials: analytic; ``sel`` and ``lmax`` of observer i depend on row i of ``level``, ``sel``
    also on every duration.

    Inputs
    ------
    level : float, (num_observers, num_points), dB (units=None)
        A-weighted level at each observer from each point of the path.
    duration : float, (num_points,), s
        Time share of each point (> 0).

    Outputs
    -------
    sel : float, (num_observers,), dB (units=None)
        Sound exposure level of each observer.
    lmax : float, (num_observers,), dB (units=None)
        Smooth maximum level of each observer over the path.

    Options
    -------
    num_observers, num_points : int
        Array sizes (>= 1).
    rho : float
        Sharpness of the smooth maximum, per dB (> 0). Default 20.
    """

    def initialize(self):
        self.options.declare("num_observers", default=1, desc="Number of observers (>= 1)")
        self.options.declare("num_points", default=1, desc="Points of the path (>= 1)")
        self.options.declare("rho", default=20.0, desc="Smooth-maximum sharpness, 1/dB (> 0)")

    def setup(self):
        no = check_integer("num_observers", self.options["num_observers"], lower=1)
        npt = check_integer("num_points", self.options["num_points"], lower=1)
        check_number("rho", self.options["rho"], lower=0.0, lower_open=True)
        self.add_input("level", np.full((no, npt), 60.0), units=None,
                       desc="A-weighted level at each observer from each point, dB")  # fmt: skip
        self.add_input("duration", np.ones(npt), units="s", desc="time share of each point")
        self.add_output("sel", np.zeros(no), units=None, desc="sound exposure level, dB")
        self.add_output("lmax", np.zeros(no), units=None, desc="smooth maximum level, dB")
        rows = np.repeat(np.arange(no), npt)
        cols = np.arange(no * npt)
        self.declare_partials("sel", "level", rows=rows, cols=cols)
        self.declare_partials("lmax", "level", rows=rows, cols=cols)
        self.declare_partials("sel", "duration", rows=rows, cols=np.tile(np.arange(npt), no))

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
        check_range("level", inputs["level"], error=om.AnalysisError, where=self.msginfo)
        level = inputs["level"]
        top = np.max(level.real, axis=1, keepdims=True)
        # Energies relative to the loudest point: 10**((L - top)/10) <= 1, no overflow.
        energy = 10.0 ** ((level - top) / 10.0) * inputs["duration"]
        weights = np.exp(self.options["rho"] * (level - top))
        return top[:, 0], energy, weights

    def compute(self, inputs, outputs):
        top, energy, weights = self._parts(inputs)
        total = np.sum(energy, axis=1)
        outputs["sel"] = top + 10.0 * np.log10(total / REFERENCE_DURATION)
        outputs["lmax"] = top + np.log(np.sum(weights, axis=1)) / self.options["rho"]

    def compute_partials(self, inputs, partials):
        _, energy, weights = self._parts(inputs)
        share = energy / np.sum(energy, axis=1, keepdims=True)
        # d sel/dL_ij = E_ij dt_j / sum; d sel/d dt_j = (10/ln 10) E_ij / sum.
        partials["sel", "level"] = share.ravel()
        partials["sel", "duration"] = (DB_PER_NEPER * share / inputs["duration"]).ravel()
        partials["lmax", "level"] = (weights / np.sum(weights, axis=1, keepdims=True)).ravel()
