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

    Partials: analytic; ``sel`` and ``lmax`` of observer i depend on row i of the levels, ``sel``
    also on the durations.

    Inputs
    ------
    level : float, (num_observers, num_points), dB (units=None)
        A-weighted level at each observer from each point of the path (without ``sources``).
    {name} : float, (num_observers, width), dB (units=None)
        With ``sources`` = ((name, width), ...): the levels of consecutive points of the path
        from each source (e.g. one design condition), in path order.
    duration : float, (num_points,) or (num_observers, num_points), s
        Time share of each point (> 0); one per observer and point with
        ``duration_per_observer`` (an equivalent time that also carries the spreading over a
        leg, lpc_mdo.vehicle.footprint_path).

    Outputs
    -------
    sel : float, (num_observers,), dB (units=None)
        Sound exposure level of each observer.
    lmax : float, (num_observers,), dB (units=None)
        Smooth maximum level of each observer over the path.

    Options
    -------
    num_observers, num_points : int
        Array sizes (>= 1); with ``sources`` num_points is the sum of their widths.
    sources : sequence of (str, int) or None
        Names and widths of the level inputs (None: one input ``level``).
    duration_per_observer : bool
        Whether ``duration`` has one row per observer. Default False.
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
            desc="(name, width) of each level input, in path order (None: one input 'level')",
        )
        self.options.declare(
            "duration_per_observer",
            default=False,
            types=bool,
            desc="duration has one row per observer",
        )

    def setup(self):
        no = check_integer("num_observers", self.options["num_observers"], lower=1)
        check_number("rho", self.options["rho"], lower=0.0, lower_open=True)
        sources = self.options["sources"]
        if sources is None:
            npt = check_integer("num_points", self.options["num_points"], lower=1)
            sources = (("level", npt),)
        else:
            sources = tuple(
                (str(name), check_integer(f"width of source {name!r}", width, lower=1))
                for name, width in sources
            )
            npt = sum(width for _, width in sources)
        self._sources = sources
        self._npt = npt
        starts = np.cumsum([0] + [width for _, width in sources])
        for name, width in sources:
            self.add_input(
                name,
                np.full((no, width), 60.0),
                units=None,
                desc="A-weighted level at each observer from points of the path, dB",
            )
            rows = np.repeat(np.arange(no), width)
            cols = np.arange(no * width)
            self.declare_partials("sel", name, rows=rows, cols=cols)
            self.declare_partials("lmax", name, rows=rows, cols=cols)
        self._columns = [
            slice(start, start + width)
            for (_, width), start in zip(sources, starts[:-1], strict=True)
        ]
        per_observer = self.options["duration_per_observer"]
        self.add_input("duration", np.ones((no, npt) if per_observer else npt), units="s",
                       desc="time share of each point")  # fmt: skip
        self.add_output("sel", np.zeros(no), units=None, desc="sound exposure level, dB")
        self.add_output("lmax", np.zeros(no), units=None, desc="smooth maximum level, dB")
        rows = np.repeat(np.arange(no), npt)
        cols = np.arange(no * npt) if per_observer else np.tile(np.arange(npt), no)
        self.declare_partials("sel", "duration", rows=rows, cols=cols)

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
        level = np.concatenate([inputs[name] for name, _ in self._sources], axis=1)
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
        softmax = weights / np.sum(weights, axis=1, keepdims=True)
        for (name, _), columns in zip(self._sources, self._columns, strict=True):
            partials["sel", name] = share[:, columns].ravel()
            partials["lmax", name] = softmax[:, columns].ravel()
        duration = np.broadcast_to(inputs["duration"], share.shape)
        partials["sel", "duration"] = (DB_PER_NEPER * share / duration).ravel()
