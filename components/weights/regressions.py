"""M4 mass-property regressions of the lift-plus-cruise fuselage, booms, empennage and wing.

The regressions (paper ref. [41], Sec. III.D) are linear in a few planform and sizing
parameters; their coefficients live in ``lpc_mdo/data/m4_regressions.toml`` (copied from
the public CADDEE_alpha code; docs theory/weights 'M4 regressions') and are read once by
:func:`m4_coefficients`. Each component returns the part's mass, its cg in the body frame and its
inertia tensor about that cg in body axes, so :class:`MassPropertiesComp` can add it as one body.
"""

import functools
import tomllib
from importlib import resources

import numpy as np
import openmdao.api as om

from lpc_mdo.components.weights.mass_properties import transport_inertia
from lpc_mdo.core.checks import RangeCheck, check_range, check_shape

# Body-frame sign of each inertia-tensor entry after the M4 -> body rotation diag(-1, 1, -1)
# (x aft -> forward, z up -> down): I_xy and I_yz change sign, I_xz does not.
_FLIP = np.array([[1.0, -1.0, 1.0], [-1.0, 1.0, -1.0], [1.0, -1.0, 1.0]])
_INERTIA_KEYS = {
    "inertia_xx": (0, 0),
    "inertia_yy": (1, 1),
    "inertia_zz": (2, 2),
    "inertia_xy": (0, 1),
    "inertia_xz": (0, 2),
    "inertia_yz": (1, 2),
}

# (name, units, description, default, lower bound, strict) of the regressors (docs theory/weights
# 'M4 regressions').
_MAIN_REGRESSORS = (
    ("wing_area", "m**2", "wing reference area S_w", 19.6, 0.0, True),
    ("wing_aspect_ratio", None, "wing aspect ratio AR", 12.12, 0.0, True),
    ("fuselage_length", "m", "fuselage length L_fus", 9.144, 0.0, True),
    ("battery_mass", "kg", "battery mass m_batt", 800.0, 0.0, False),
    ("cruise_speed", "m/s", "cruise speed V (paper: M 0.17 at 3280 ft)", 57.1897, 0.0, False),
)
_EMPENNAGE_REGRESSORS = (
    ("htail_area", "m**2", "horizontal-tail reference area S_htail", 3.7, 0.0, True),
    ("vtail_area", "m**2", "vertical-tail reference area S_vtail", 2.54, 0.0, True),
)


@functools.cache
def m4_coefficients():
    """
    Return the M4 regression data of ``lpc_mdo/data/m4_regressions.toml`` as a dict.

    Coefficient lists follow the regressor order of docs theory/weights 'M4 regressions': [S_w, AR,
    L_fus, m_batt, V, 1] (fuselage, wing, booms) or [S_htail, S_vtail, 1] (empennage).
    """
    text = resources.files("lpc_mdo").joinpath("data", "m4_regressions.toml").read_text()
    return tomllib.loads(text)


_positive = RangeCheck(lower=0.0, lower_open=True)
#: Relative round-off allowed at the edges of the regressions' data range (a value on the edge
#: that a unit conversion or the driver's scaling moved by a few ulps; 1e-12 is 4500 ulps).
ROUND_OFF = 1e-12
_fraction = RangeCheck(lower=0.0, upper=1.0)


def _point(name, value):
    check_shape(name, value, (3,))
    check_range(name, value, units="m")


class _M4RegressionComp(om.ExplicitComponent):
    """
    Shared machinery: a part made of K sub-parts k with mass fractions w_k.

    With the regressors x~ = [x, 1]:

    - m = f c_m . x~                                   (f = option mass_factor)
    - p_k = n + S C_k x~,  S = diag(-k_x, 1, -1)       (M4 frame -> body frame, n = nose)
    - cg = sum_k w_k p_k  (y set to 0 if several sub-parts, as coded; symmetric vehicle)
    - I = sum_k [ f L_k x~ + w_k m P(p_k - cg) ]      (parallel axis, docs theory/weights 'Mass
      properties'; not docs theory/weights 'Public-code compatibility')

    L_k x~ is the sub-part's own inertia regression rotated to body axes. The inertia is the
    exact inertia of the sub-parts about ``cg``. All partials are analytic; only the inertia's
    are not constant.
    """

    _regressors = _MAIN_REGRESSORS
    _prefix = ""
    _what = ""

    def initialize(self):
        data = m4_coefficients()
        self.options.declare(
            "mass_factor",
            default=1.0,
            types=(int, float),
            check_valid=_positive,
            desc="factor on the regression mass and own inertias (> 0); "
            "paper 1.0, public run scripts 1.3",
        )
        self.options.declare(
            "nose",
            default=tuple(data["frame"]["nose"]),
            types=(list, tuple, np.ndarray),
            check_valid=_point,
            desc="fuselage nose (body-frame origin) in the M4 frame, m",
        )

    def _fixed_cg_length(self):
        """Fuselage length (m) at which the cg's x is evaluated, or None (the regression's L)."""
        return None

    def _sub_parts(self):
        """Return [(mass fraction, {'cg_x': coeffs, ...}, cg_x_factor)] of the sub-parts."""
        raise NotImplementedError

    def _mass_coefficients(self):
        raise NotImplementedError

    def setup(self):
        nx = len(self._regressors)
        for name, units, desc, default, _, _ in self._regressors:
            self.add_input(name, default, units=units, desc=desc)
        prefix = self._prefix
        self.add_output(
            f"{prefix}_mass",
            100.0,
            units="kg",
            desc=f"mass of the {self._what} (M4 regression)",
        )
        self.add_output(
            f"{prefix}_cg", np.zeros(3), units="m", desc=f"cg of the {self._what}, body frame"
        )
        self.add_output(
            f"{prefix}_inertia",
            np.eye(3),
            units="kg*m**2",
            desc=f"inertia tensor of the {self._what} about its cg, body axes",
        )

        factor = float(self.options["mass_factor"])
        nose = np.asarray(self.options["nose"], dtype=float)
        parts = self._sub_parts()
        k = len(parts)
        self._weights = np.array([w for w, _, _ in parts])
        self._cg_map = np.zeros((k, 3, nx + 1))  # p_k = cg_map[k] @ x~
        self._own = np.zeros((k, 3, 3, nx + 1))  # own inertia (body axes) = own[k] @ x~
        for i, (_, coeffs, kx) in enumerate(parts):
            for axis, sign in ((0, -kx), (1, 1.0), (2, -1.0)):
                key = "cg_" + "xyz"[axis]
                if key in coeffs:
                    self._cg_map[i, axis] = sign * np.asarray(coeffs[key])
                self._cg_map[i, axis, -1] += nose[axis]
            for key, (a, b) in _INERTIA_KEYS.items():
                if key in coeffs:
                    entry = factor * _FLIP[a, b] * np.asarray(coeffs[key])
                    self._own[i, a, b] = entry
                    self._own[i, b, a] = entry
        names = [r[0] for r in self._regressors]
        fixed = self._fixed_cg_length()
        if fixed is not None:
            # The cg at the fixed length: the L column moves into the constant.
            j = names.index("fuselage_length")
            self._cg_map[:, :, -1] += fixed * self._cg_map[:, :, j]
            self._cg_map[:, :, j] = 0.0
        self._length_range = None
        if "fuselage_length" in names:
            self._length_range = tuple(m4_coefficients()["data_range"]["fuselage_length"])
        self._mass_map = factor * np.asarray(self._mass_coefficients(), dtype=float)
        self._cg_total = np.einsum("k,kan->an", self._weights, self._cg_map)
        if k > 1:
            self._cg_total[1] = 0.0

        for j, (name, *_) in enumerate(self._regressors):
            self.declare_partials(f"{prefix}_mass", name, val=self._mass_map[j])
            if np.any(self._cg_total[:, j]):  # a cg at a fixed fuselage length has none
                self.declare_partials(f"{prefix}_cg", name, val=self._cg_total[:, j : j + 1])
            self.declare_partials(f"{prefix}_inertia", name)

    def _evaluate(self, inputs):
        """Return x~, mass, sub-part cgs (K, 3) and offsets r_k = p_k - cg (K, 3)."""
        values = []
        for name, units, _, _, lower, strict in self._regressors:
            value = inputs[name][0]
            check_range(
                name,
                value,
                lower=lower,
                lower_open=strict,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
            values.append(value)
        if self._length_range is not None:
            lower, upper = self._length_range
            length = inputs["fuselage_length"][0]
            # A design variable on its bound (the range's edges are the reference file's
            # bounds) comes back from the driver's scaling a few ulps outside: that is the edge.
            slack = ROUND_OFF * upper
            if not lower - slack <= np.real(length) <= upper + slack:
                check_range(
                    "fuselage_length",
                    length,
                    lower=lower,
                    upper=upper,
                    units="m",
                    error=om.AnalysisError,
                    where=self.msginfo,
                )
        xt = np.array(values + [1.0])
        mass = self._mass_map @ xt
        if mass.real <= 0.0:
            raise om.AnalysisError(
                f"{self.msginfo}: {self._prefix}_mass = {mass.real} kg from the M4 regression "
                f"at {dict(zip([r[0] for r in self._regressors], xt.real[:-1], strict=True))}; "
                "must be > 0 (inputs far outside the regression's data)."
            )
        points = self._cg_map @ xt
        return xt, mass, points, points - self._cg_total @ xt

    def compute(self, inputs, outputs):
        xt, mass, _, r = self._evaluate(inputs)
        p, _ = transport_inertia(r)
        inertia = np.einsum("kabn,n->ab", self._own, xt) + mass * np.einsum(
            "k,kab->ab", self._weights, p
        )
        if np.any(np.diag(inertia).real < 0.0):
            raise om.AnalysisError(
                f"{self.msginfo}: {self._prefix}_inertia diagonal = "
                f"{np.diag(inertia).real.tolist()} kg*m**2 from the M4 regression; must be >= 0 "
                "(inputs far outside the regression's data)."
            )
        prefix = self._prefix
        outputs[f"{prefix}_mass"] = mass
        outputs[f"{prefix}_cg"] = self._cg_total @ xt
        outputs[f"{prefix}_inertia"] = inertia

    def compute_partials(self, inputs, partials):
        xt, mass, _, r = self._evaluate(inputs)
        p, dp = transport_inertia(r)
        nx = len(self._regressors)
        dr = self._cg_map[:, :, :nx] - self._cg_total[None, :, :nx]  # (K, 3, nx)
        jac = (
            self._own[..., :nx].sum(axis=0)
            + np.einsum("k,kab,n->abn", self._weights, p, self._mass_map[:nx])
            + mass * np.einsum("k,kabl,kln->abn", self._weights, dp, dr)
        )
        jac = jac.reshape(9, nx)
        for j, (name, *_) in enumerate(self._regressors):
            partials[f"{self._prefix}_inertia", name] = jac[:, j : j + 1]


class _SinglePartRegressionComp(_M4RegressionComp):
    """A part that is one body with its own cg factor k_x (the coefficients under ``_prefix``)."""

    def initialize(self):
        super().initialize()
        k_x = m4_coefficients()[self._prefix]["cg_x_factor"]
        self.options.declare(
            "cg_x_factor",
            default=k_x,
            types=(int, float),
            check_valid=_positive,
            desc=f"k_x in x_cg = x_nose - k_x cg_X (> 0); {k_x} as coded",
        )

    def _sub_parts(self):
        return [(1.0, m4_coefficients()[self._prefix], float(self.options["cg_x_factor"]))]

    def _mass_coefficients(self):
        return m4_coefficients()[self._prefix]["mass"]


class FuselageRegressionComp(_SinglePartRegressionComp):
    """
    Fuselage structural mass, cg and inertia from the M4 regression.

    Implements docs theory/weights 'M4 regressions' (paper Sec. III.D and eq. 32; CADDEE_alpha
    ``m4_nasa_lpc.py``): q = c . [S_w, AR, L_fus, m_batt, V, 1] for the mass, cg_X, cg_Z, Ixx, Iyy,
    Izz and Ixz; body-frame cg = (x_n - k_x cg_X, 0, z_n - cg_Z) with
    k_x = 0.88 as coded (docs theory/weights 'M4 regressions') and (x_n, z_n) the nose in the M4
    frame (CAD (2.464, 5.113) ft). The inertia is the regression's own (local) tensor rotated to
    body axes (I_xz keeps its
    sign), times ``mass_factor``.

    Inputs
    ------
    wing_area : float, (1,), m**2
        Wing reference area (> 0). Default 19.6.
    wing_aspect_ratio : float, (1,), unitless
        Wing aspect ratio (> 0). Default 12.12.
    fuselage_length : float, (1,), m
        Fuselage length, within the regressions' data range [6.4008, 11.8872] m
        (``lpc_mdo/data/m4_regressions.toml`` ``[data_range]``; docs theory/weights 'M4
        regressions'). Default 9.144.
    battery_mass : float, (1,), kg
        Battery mass (>= 0). Default 800.
    cruise_speed : float, (1,), m/s
        Cruise speed (>= 0). Default 57.1897 (paper M 0.17 at 3280 ft; code 61.2476).

    Outputs
    -------
    fuselage_mass : float, (1,), kg
        Fuselage structural mass.
    fuselage_cg : float, (3,), m
        Fuselage cg, body frame.
    fuselage_inertia : float, (3, 3), kg*m**2
        Inertia tensor about ``fuselage_cg``, body axes.

    Options
    -------
    mass_factor : float
        Factor (> 0) on mass and own inertia. Default 1.0 (paper); the run scripts use 1.3.
    cg_x_factor : float
        k_x (> 0). Default 0.88 (as coded; 1.0 takes the regression cg as it is).
    nose : sequence of 3 float
        Body-frame origin in the M4 frame, m. Default (0.7510272, 0, 1.5584424).

    Raises
    ------
    om.AnalysisError
        If an input is outside its range (the fuselage length outside the data range) or the
        regression gives a mass <= 0 or a negative moment of inertia.
    """

    _prefix = "fuselage"
    _what = "fuselage"


class WingRegressionComp(_SinglePartRegressionComp):
    """
    Wing structural mass, cg and inertia from the M4 regression (public-code alternative).

    The paper's wing mass comes from the wing-box beam (eq. 32); this regression
    (docs theory/weights 'M4 regressions') is the older public-code estimate, kept as an alternative
    and as the placeholder wing mass of the W_other calibration until the beam model is connected.
    Same form as :class:`FuselageRegressionComp` with k_x = 0.9.

    Inputs
    ------
    wing_area, wing_aspect_ratio, fuselage_length, battery_mass, cruise_speed : float, (1,)
        As :class:`FuselageRegressionComp` (m**2, -, m, kg, m/s).

    Outputs
    -------
    wing_mass : float, (1,), kg
    wing_cg : float, (3,), m
        Body frame.
    wing_inertia : float, (3, 3), kg*m**2
        About ``wing_cg``, body axes.

    Options
    -------
    mass_factor : float
        Factor (> 0) on mass and own inertia. Default 1.0.
    cg_x_factor : float
        k_x (> 0). Default 0.9 (as coded).
    nose : sequence of 3 float
        Body-frame origin in the M4 frame, m.

    Raises
    ------
    om.AnalysisError
        As :class:`FuselageRegressionComp`.
    """

    _prefix = "wing"
    _what = "wing"


class BoomRegressionComp(_M4RegressionComp):
    """
    Mass, cg and inertia of the 8 lift-rotor booms from the M4 regressions.

    Implements docs theory/weights 'M4 regressions': the total boom mass regression, split equally
    over the 4 boom groups (inner/outer, port/starboard; each carries a front and a rear rotor),
    each with its own cg and local Ixx, Iyy, Izz regressions. The
    total cg is the mass-weighted mean with y set to 0 (as coded; the vehicle is symmetric). The
    inertia about that cg uses the parallel-axis theorem with each group's own offset,
    I = sum_g [I_g + (m/4) P(cg_g - cg)], the project default of docs theory/weights 'Public-code
    compatibility' (the public code uses P(cg_total) for every group instead, which is not
    reproduced).

    Inputs
    ------
    wing_area, wing_aspect_ratio, fuselage_length, battery_mass, cruise_speed : float, (1,)
        As :class:`FuselageRegressionComp` (m**2, -, m, kg, m/s).

    Outputs
    -------
    boom_mass : float, (1,), kg
        Total mass of the 8 booms.
    boom_cg : float, (3,), m
        Their cg, body frame.
    boom_inertia : float, (3, 3), kg*m**2
        Their inertia tensor about ``boom_cg``, body axes.

    Options
    -------
    mass_factor : float
        Factor (> 0) on mass and own inertias. Default 1.0 (paper); run scripts 1.3.
    nose : sequence of 3 float
        Body-frame origin in the M4 frame, m.
    cg_fuselage_length : float or None
        Fuselage length (m) at which the cg regressions are evaluated; None (default) takes the
        ``fuselage_length`` input, as coded. The M4 models scale the wing's station, and with
        it the booms', with the fuselage length (the wing and boom cg regressions both move
        0.26 m aft and 0.04 m up per metre of fuselage); where the wing keeps its station when
        the fuselage is stretched (lpc-mdo: the stretch goes into the tail cone, docs
        theory/geometry 'Fuselage zones'), the booms keep theirs: evaluate their cg at the
        vehicle's reference length. Mass and inertias still take the input.

    Raises
    ------
    om.AnalysisError
        As :class:`FuselageRegressionComp`.
    """

    _prefix = "boom"
    _what = "8 booms"
    groups = ("in_port", "out_port", "in_star", "out_star")

    def initialize(self):
        super().initialize()
        self.options.declare(
            "cg_fuselage_length",
            default=None,
            types=(int, float),
            allow_none=True,
            lower=0.0,
            desc="fuselage length (m) of the cg's x; None = the input fuselage_length",
        )

    def _fixed_cg_length(self):
        return self.options["cg_fuselage_length"]

    def _sub_parts(self):
        data = m4_coefficients()["booms"]
        return [(0.25, data[g], 1.0) for g in self.groups]

    def _mass_coefficients(self):
        return m4_coefficients()["booms"]["mass"]


class EmpennageRegressionComp(_M4RegressionComp):
    """
    Mass, cg and inertia of the empennage (horizontal + vertical tail) from the M4 regressions.

    Implements docs theory/weights 'M4 regressions' with the regressors [S_htail, S_vtail, 1]: total
    mass regression; h-tail and v-tail cg and local inertia regressions; the cg weights the h-tail
    by w_h = 0.65 and the v-tail by 0.35 (as coded),
    taken as their mass fractions, with y set to 0. The inertia about that cg is the
    parallel-axis sum I = I_h + I_v + w_h m P(cg_h - cg) + (1 - w_h) m P(cg_v - cg), the same
    correction as for the booms (docs theory/weights 'Public-code compatibility'; the code adds m
    P(cg) about the origin instead).

    Inputs
    ------
    htail_area : float, (1,), m**2
        Horizontal-tail area (> 0). Default 3.7.
    vtail_area : float, (1,), m**2
        Vertical-tail area (> 0). Default 2.54.

    Outputs
    -------
    empennage_mass : float, (1,), kg
    empennage_cg : float, (3,), m
        Body frame.
    empennage_inertia : float, (3, 3), kg*m**2
        About ``empennage_cg``, body axes.

    Options
    -------
    mass_factor : float
        Factor (> 0) on mass and own inertias. Default 1.0 (paper); run scripts 1.3.
    htail_mass_fraction : float
        w_h in [0, 1]. Default 0.65 (as coded).
    nose : sequence of 3 float
        Body-frame origin in the M4 frame, m.

    Raises
    ------
    om.AnalysisError
        As :class:`FuselageRegressionComp`.
    """

    _regressors = _EMPENNAGE_REGRESSORS
    _prefix = "empennage"
    _what = "empennage"

    def initialize(self):
        super().initialize()
        self.options.declare(
            "htail_mass_fraction",
            default=m4_coefficients()["empennage"]["htail_mass_fraction"],
            types=(int, float),
            check_valid=_fraction,
            desc="h-tail share of the empennage mass in [0, 1]; 0.65 as coded",
        )

    def _sub_parts(self):
        data = m4_coefficients()["empennage"]
        wh = float(self.options["htail_mass_fraction"])
        return [(wh, data["htail"], 1.0), (1.0 - wh, data["vtail"], 1.0)]

    def _mass_coefficients(self):
        return m4_coefficients()["empennage"]["mass"]
