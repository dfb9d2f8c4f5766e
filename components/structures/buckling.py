"""Skin-panel buckling of the wing box: critical stress (paper eq. 18) and buckling ratios."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import RangeCheck, check_range

PANEL_MODELS = ("curved", "flat")


class PanelBucklingComp(om.ExplicitComponent):
    """
    Critical buckling stress of the top and bottom skin panels and the ratio constraint values.

    ``panel='curved'`` (default): curved panel under axial compression after Roark, paper
    eq. 18 (docs theory/structures 'Buckling'):

        σ' = E/(6 (1 - ν²)) [ sqrt(12 (1 - ν²) (t/r)² + (π t/b)⁴) + (π t/b)² ]

    with skin thickness t, panel width b (spar to spar) and radius of curvature r of the skin
    between the spars. For r -> ∞ it reduces to the simply supported flat plate,
    σ' = (π²/3) E/(1 - ν²) (t/b)² = k π² E/(12 (1 - ν²)) (t/b)² with k = 4.

    ``panel='flat'``: σ' = k π² E/(12 (1 - ν²)) (t/b)², k = ``flat_plate_coefficient``
    (default 4, simply supported long plate; aframe's k = 6.3 in σ = k E (t/b)²/(1 - ν²)
    corresponds to 7.66 here). No radius inputs.

    Buckling ratio = -σ/σ' with σ the skin normal stress (tension positive): positive in
    compression, the constraint is ratio <= 1 (paper: no safety factor, not aggregated, the tip
    bay excluded; choose the indices when adding the constraint). Analytic diagonal partials.

    Inputs
    ------
    top_skin_stress, bottom_skin_stress : float, (num_elements,), Pa
        Skin normal stress, tension positive (BoxStressComp).
    top_skin_thickness, bottom_skin_thickness : float, (num_elements,), m
    box_width : float, (num_elements,), m
        Panel width b (spar to spar).
    top_skin_radius, bottom_skin_radius : float, (num_elements,), m
        Radius of curvature r of each skin panel (curved panels only).
    youngs_modulus : float, scalar, Pa
    poisson_ratio : float, scalar

    Outputs
    -------
    top_skin_critical_stress, bottom_skin_critical_stress : float, (num_elements,), Pa
    top_skin_buckling_ratio, bottom_skin_buckling_ratio : float, (num_elements,)

    Options
    -------
    num_elements : int
    panel : str
        'curved' (default, paper eq. 18) or 'flat'.
    flat_plate_coefficient : float
        Buckling coefficient k of the flat panel (> 0), default 4.
    """

    def initialize(self):
        self.options.declare("num_elements", types=int, lower=1, desc="Number of skin panels")
        self.options.declare(
            "panel",
            default="curved",
            values=PANEL_MODELS,
            desc="'curved' (paper eq. 18, Roark) or 'flat' plate",
        )
        self.options.declare(
            "flat_plate_coefficient",
            default=4.0,
            types=(int, float),
            check_valid=_check_positive,
            desc="Buckling coefficient k of the flat panel (> 0)",
        )

    def setup(self):
        ne = self.options["num_elements"]
        curved = self.options["panel"] == "curved"
        self._skins = ("top", "bottom")
        for skin in self._skins:
            self.add_input(
                f"{skin}_skin_stress",
                val=np.zeros(ne),
                units="Pa",
                desc=f"{skin} skin normal stress, tension positive",
            )
            self.add_input(
                f"{skin}_skin_thickness",
                val=np.full(ne, 1.5e-3),
                units="m",
                desc=f"{skin} skin thickness",
            )
            if curved:
                self.add_input(
                    f"{skin}_skin_radius",
                    val=np.full(ne, 2.0),
                    units="m",
                    desc=f"radius of curvature of the {skin} skin panel",
                )
        self.add_input(
            "box_width", val=np.full(ne, 0.5), units="m", desc="panel width b, spar to spar"
        )
        self.add_input("youngs_modulus", val=69.0e9, units="Pa", desc="Young's modulus E")
        self.add_input("poisson_ratio", val=0.33, units=None, desc="Poisson's ratio")
        for skin in self._skins:
            crit, ratio = f"{skin}_skin_critical_stress", f"{skin}_skin_buckling_ratio"
            self.add_output(
                crit,
                val=np.ones(ne),
                units="Pa",
                desc=f"critical buckling stress of the {skin} skin panel",
            )
            self.add_output(
                ratio,
                val=np.zeros(ne),
                units=None,
                desc=f"{skin} skin compressive stress over critical stress",
            )
            geo = [f"{skin}_skin_thickness", "box_width"]
            if curved:
                geo.append(f"{skin}_skin_radius")
            self.declare_partials([crit, ratio], geo, diagonal=True)
            self.declare_partials([crit, ratio], ["youngs_modulus", "poisson_ratio"])
            self.declare_partials(ratio, f"{skin}_skin_stress", diagonal=True)

    def _critical(self, t, b, r, modulus, nu):
        """σ' and its partials wrt (t, b, r, E, ν)."""
        c = modulus / (1.0 - nu**2)
        if self.options["panel"] == "flat":
            k = self.options["flat_plate_coefficient"]
            crit = k * np.pi**2 / 12.0 * c * (t / b) ** 2
            d = {
                "t": 2.0 * crit / t,
                "b": -2.0 * crit / b,
                "E": crit / modulus,
                "nu": crit * 2.0 * nu / (1.0 - nu**2),
            }
            return crit, d
        beta = np.pi * t / b
        a = t / r
        g = 12.0 * (1.0 - nu**2)
        root = np.sqrt(g * a**2 + beta**4)
        bracket = root + beta**2
        crit = c / 6.0 * bracket
        # d bracket / d(a, beta, g)
        db_da = g * a / root
        db_dbeta = 2.0 * beta**3 / root + 2.0 * beta
        db_dg = a**2 / (2.0 * root)
        d = {
            "t": c / 6.0 * (db_da / r + db_dbeta * np.pi / b),
            "b": c / 6.0 * db_dbeta * (-beta / b),
            "r": c / 6.0 * db_da * (-a / r),
            "E": crit / modulus,
            "nu": crit * 2.0 * nu / (1.0 - nu**2) + c / 6.0 * db_dg * (-24.0 * nu),
        }
        return crit, d

    def _geometry(self, inputs, skin):
        t = inputs[f"{skin}_skin_thickness"]
        b = inputs["box_width"]
        r = inputs[f"{skin}_skin_radius"] if self.options["panel"] == "curved" else None
        return t, b, r

    def compute(self, inputs, outputs):
        modulus, nu = inputs["youngs_modulus"], inputs["poisson_ratio"]
        check_range(
            "poisson_ratio",
            nu[0],
            lower=-1.0,
            upper=0.5,
            lower_open=True,
            upper_open=True,
            error=om.AnalysisError,
            where=self.msginfo,
        )
        for skin in self._skins:
            t, b, r = self._geometry(inputs, skin)
            for name, val in (
                (f"{skin}_skin_thickness", t),
                ("box_width", b),
                (f"{skin}_skin_radius", r),
            ):
                if val is not None:
                    check_range(
                        name,
                        val,
                        lower=0.0,
                        lower_open=True,
                        units="m",
                        error=om.AnalysisError,
                        where=self.msginfo,
                    )
            crit, _ = self._critical(t, b, r, modulus, nu)
            outputs[f"{skin}_skin_critical_stress"] = crit
            outputs[f"{skin}_skin_buckling_ratio"] = -inputs[f"{skin}_skin_stress"] / crit

    def compute_partials(self, inputs, partials):
        modulus, nu = inputs["youngs_modulus"], inputs["poisson_ratio"]
        for skin in self._skins:
            t, b, r = self._geometry(inputs, skin)
            crit, d = self._critical(t, b, r, modulus, nu)
            sigma = inputs[f"{skin}_skin_stress"]
            names = {
                "t": f"{skin}_skin_thickness",
                "b": "box_width",
                "r": f"{skin}_skin_radius",
                "E": "youngs_modulus",
                "nu": "poisson_ratio",
            }
            cname, rname = f"{skin}_skin_critical_stress", f"{skin}_skin_buckling_ratio"
            for key, deriv in d.items():
                partials[cname, names[key]] = deriv
                partials[rname, names[key]] = sigma / crit**2 * deriv
            partials[rname, f"{skin}_skin_stress"] = -1.0 / crit


_check_positive = RangeCheck(lower=0.0, lower_open=True, where="PanelBucklingComp")
