"""Section lift over the section's maximum lift: how close each strip of a wing is to stall."""

import numpy as np
import openmdao.api as om

from .airfoil import get_polar


class SectionStallRatioComp(om.ExplicitComponent):
    """
    Each strip's lift coefficient over its section's maximum (positive) and minimum (negative).

    For strip j of condition i, with the VLM's sectional lift coefficient c_l,ij (paper eq. 16,
    :class:`~lpc_mdo.components.aero.vlm_sectional.VLMSectionalLiftComp`) and the airfoil
    table's maximum and minimum lift coefficients at the strip's chord Reynolds number and
    Mach number (:meth:`~lpc_mdo.components.aero.airfoil.TablePolar.max_lift_coefficients`):

        r_ij^+ = c_l,ij / c_l,max(Re_ij, M_ij),    r_ij^- = c_l,ij / c_l,min(Re_ij, M_ij).

    r^+ reaches 1 where a section reaches its positive stall, r^- (c_l,min < 0) where it reaches
    its negative stall; each is negative on the other side. Both halves go into one output row
    per condition, so one smooth maximum (KS, paper eq. 7) over the row bounds both stalls: the
    critical-section criterion of wing stall (the wing stalls when its most loaded section
    reaches the section maximum; Phillips and Alley, J. Aircraft 44(3), 2007; docs
    theory/aerodynamics 'Section lift limit').

    The section maximum varies with Reynolds number (the chord, a design variable, and the
    speed) and Mach number: the derivatives with respect to both are those of the C1 table
    interpolant. With ``speed_fraction`` f < 1 it is taken at f Re and f M, the strip's flow at
    f times the condition's speed: a limit c_l / c_l,max <= kappa f^2 then says that at the
    speed f V (the stall speed, when 1/f is the required margin over it) the section reaches
    kappa c_l,max with the Reynolds and Mach numbers it has there (c_l grows as 1/V^2 at a
    fixed lift). Outside the table's Reynolds and Mach range the lookup raises
    ``om.AnalysisError`` (the stated range of the polar; the wing tables hold for Re up to 1e7
    and M up to 0.6), never a value held at the table's edge.

    Inputs
    ------
    sectional_cl : float, (nn, ns)
        Sectional lift coefficient of each strip (left tip to right tip).
    reynolds : float, (nn * ns,)
        Chord Reynolds number of each strip, row-major over (condition, strip).
    mach : float, (nn * ns,)
        Mach number of each strip, same order.

    Outputs
    -------
    stall_ratio : float, (nn, 2 ns)
        Per condition: r^+ of the ns strips, then r^- of the ns strips.

    Options
    -------
    num_nodes : int
        Number of flight conditions nn.
    num_span_panels : int
        Number of strips ns.
    airfoil : str, Polar, array_like or dict
        The section (anything :func:`~lpc_mdo.components.aero.airfoil.get_polar` takes that
        gives a :class:`~lpc_mdo.components.aero.airfoil.TablePolar`); default 'ls413'.
    speed_fraction : float
        f in [0.1, 1]: the section maxima are those at f Re and f M (default 1).
    """

    def initialize(self):
        self.options.declare("num_nodes", default=1, types=int, lower=1, desc="conditions")
        self.options.declare("num_span_panels", types=int, lower=1, desc="strips per condition")
        self.options.declare("airfoil", default="ls413", desc="airfoil (see get_polar)")
        self.options.declare(
            "speed_fraction",
            default=1.0,
            types=float,
            lower=0.1,
            upper=1.0,
            desc="the section maximum is taken at Re and M times this (the speed where the "
            "limit applies over the condition's speed)",
        )

    def setup(self):
        nn, ns = self.options["num_nodes"], self.options["num_span_panels"]
        polar = get_polar(self.options["airfoil"])
        if not hasattr(polar, "max_lift_coefficients"):
            raise ValueError(
                f"{self.msginfo}: option 'airfoil' gives a {type(polar).__name__}, which has no "
                f"tabulated maximum lift; allowed: an airfoil name, table or file (a TablePolar)"
            )
        self._polar = polar
        n = nn * ns
        self.add_input("sectional_cl", np.zeros((nn, ns)), desc="sectional lift coefficient")
        self.add_input("reynolds", np.full(n, 1e6), desc="chord Reynolds number")
        self.add_input("mach", np.zeros(n), desc="Mach number")
        self.add_output(
            "stall_ratio",
            np.zeros((nn, 2 * ns)),
            desc="c_l over the section's c_l,max (first ns) and over its c_l,min (last ns)",
        )
        # Output (i, side, j) depends on strip (i, j) only.
        i, side, j = (
            a.ravel() for a in np.meshgrid(np.arange(nn), (0, 1), np.arange(ns), indexing="ij")
        )
        rows = (i * 2 + side) * ns + j
        cols = i * ns + j
        self.declare_partials(
            "stall_ratio", ["sectional_cl", "reynolds", "mach"], rows=rows, cols=cols
        )

    def _limits(self, inputs):
        """
        Section limits of every strip as (2, nn, ns) arrays: values, d/dRe, d/dM.

        The last real result is kept with its Reynolds and Mach numbers: the linearization at
        the point just evaluated, and every evaluation whose strips keep their Re and M (a trim
        iteration moves the angles only; Re changes with the chord), reuse it.
        """
        nn, ns = self.options["num_nodes"], self.options["num_span_panels"]
        reynolds, mach = inputs["reynolds"], inputs["mach"]
        real = not (np.iscomplexobj(reynolds) or np.iscomplexobj(mach))
        key = (reynolds.tobytes(), mach.tobytes()) if real else None
        cached = getattr(self, "_last_limits", None)
        if real and cached is not None and cached[0] == key:
            return cached[1]
        f = self.options["speed_fraction"]
        low, high, dlow_re, dhigh_re, dlow_m, dhigh_m = self._polar.max_lift_coefficients(
            f * reynolds, f * mach
        )
        limits = (
            np.stack([high, low]).reshape(2, nn, ns),
            f * np.stack([dhigh_re, dlow_re]).reshape(2, nn, ns),
            f * np.stack([dhigh_m, dlow_m]).reshape(2, nn, ns),
        )
        if real:
            self._last_limits = (key, limits)
        return limits

    def compute(self, inputs, outputs):
        limit, _, _ = self._limits(inputs)
        ratio = inputs["sectional_cl"][None] / limit  # (2, nn, ns)
        outputs["stall_ratio"] = ratio.transpose(1, 0, 2).reshape(outputs["stall_ratio"].shape)

    def compute_partials(self, inputs, partials):
        limit, dlimit_re, dlimit_m = self._limits(inputs)
        cl = inputs["sectional_cl"][None]

        def ordered(x):  # (2, nn, ns) -> the (i, side, j) order of the declared rows
            return x.transpose(1, 0, 2).ravel()

        partials["stall_ratio", "sectional_cl"] = ordered(1.0 / limit)
        dratio_dlimit = -cl / limit**2
        partials["stall_ratio", "reynolds"] = ordered(dratio_dlimit * dlimit_re)
        partials["stall_ratio", "mach"] = ordered(dratio_dlimit * dlimit_m)
