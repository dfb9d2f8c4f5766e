"""Kreisselmeier-Steinhauser (KS) constraint aggregation."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import RangeCheck

_check_positive = RangeCheck(lower=0.0, lower_open=True, where="KSComp")


class KSComp(om.ExplicitComponent):
    """
    Smooth maximum (or minimum) of each row of ``g`` by the Kreisselmeier-Steinhauser function.

    Paper eq. 7 with alpha = 1 (docs theory/structures 'KS aggregation'), in the
    numerically stable shifted form of csdl_alpha ``maximum``:

        KS_i = m_i + ln( sum_j exp(rho (g_ij - m_i)) ) / rho,   m_i = max_j Re(g_ij)

    The shift m_i cancels exactly, so it changes neither the value nor the derivatives; it only
    keeps exp() from overflowing (e.g. stresses in Pa). The real part is used for the shift alone,
    so the component stays complex-step safe. Bounds: max_j g_ij <= KS_i <= max_j g_ij +
    ln(width)/rho. With ``lower_flag`` the minimum is aggregated: KS = -KS_max(-g), so
    min_j g_ij - ln(width)/rho <= KS_i <= min_j g_ij.

    Partials: dKS_i/dg_ij = exp(rho (g_ij - m_i)) / sum_k exp(rho (g_ik - m_i)) (softmax weights,
    positive, summing to 1 over a row); output i depends on row i only (sparse).

    Inputs
    ------
    g : float, (vec_size, width), units of option ``units``
        Values to aggregate, one row per output.

    Outputs
    -------
    KS : float, (vec_size,), units of option ``units``
        Smooth maximum (minimum with ``lower_flag``) of each row of g.

    Options
    -------
    vec_size : int
        Number of independent aggregations (rows of g, e.g. flight-condition nodes). Default 1.
    width : int
        Number of values aggregated per row (>= 1). Default 1.
    rho : float
        Aggregation parameter (> 0), in 1/(units of g). Larger is closer to the true maximum
        (error at most ln(width)/rho) but less smooth. Default 50, suited to g of order one
        (normalised constraints such as sigma/sigma_allow - 1); scale g or rho for other
        magnitudes. The public LPC scripts use rho = 1 on stresses in Pa, a hard max in
        practice (docs theory/structures 'KS aggregation'): do not copy that.
    lower_flag : bool
        If True, aggregate the minimum instead of the maximum. Default False. (This is the
        ``minimum`` option of OpenMDAO's om.KSComp, whose ``lower_flag`` only flips the sign of g.)
    units : str or None
        Units of g and KS. Default None (dimensionless).
    """

    def initialize(self):
        self.options.declare(
            "vec_size",
            default=1,
            types=int,
            lower=1,
            desc="Number of independent aggregations (rows of g)",
        )
        self.options.declare(
            "width", default=1, types=int, lower=1, desc="Number of values aggregated per row"
        )
        self.options.declare(
            "rho",
            default=50.0,
            types=(int, float),
            check_valid=_check_positive,
            desc="KS aggregation parameter (> 0), in 1/(units of g)",
        )
        self.options.declare(
            "lower_flag",
            default=False,
            types=bool,
            desc="If True, aggregate the minimum instead of the maximum",
        )
        self.options.declare(
            "units",
            default=None,
            types=str,
            allow_none=True,
            desc="Units of g and KS (None: dimensionless)",
        )

    def setup(self):
        n = self.options["vec_size"]
        w = self.options["width"]
        units = self.options["units"]

        self.add_input(
            "g", val=np.zeros((n, w)), units=units, desc="Values to aggregate, one row per output"
        )
        self.add_output(
            "KS",
            val=np.zeros(n),
            units=units,
            desc="Smooth maximum (minimum if lower_flag) of each row of g",
        )

        rows = np.repeat(np.arange(n), w)
        cols = np.arange(n * w)
        self.declare_partials("KS", "g", rows=rows, cols=cols)

    def _weights(self, g):
        """Return the signed values s*g, their row shift and the exponentials."""
        sign = -1.0 if self.options["lower_flag"] else 1.0
        rho = self.options["rho"]
        sg = sign * g
        # Shift by the real row maximum: exact cancellation, so derivatives are unaffected.
        shift = np.max(sg.real, axis=1)
        expo = np.exp(rho * (sg - shift[:, np.newaxis]))
        return sign, shift, expo

    def compute(self, inputs, outputs):
        rho = self.options["rho"]
        sign, shift, expo = self._weights(inputs["g"])
        outputs["KS"] = sign * (shift + np.log(np.sum(expo, axis=1)) / rho)

    def compute_partials(self, inputs, partials):
        _, _, expo = self._weights(inputs["g"])
        # d(sign * KS_max(sign g))/dg = sign * sign * softmax = softmax.
        partials["KS", "g"] = (expo / np.sum(expo, axis=1)[:, np.newaxis]).ravel()
