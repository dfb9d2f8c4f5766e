"""Thin-walled box cross-section of the wing box: area, bending inertias and torsion constant."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range

TORSION_FORMULAS = ("polar", "bredt")


class BoxSectionComp(om.ExplicitComponent):
    """
    Section properties of a rectangular box beam, per element.

    See docs theory/structures 'Box section'.

    The box has outer width w (spar to spar) and height h, skins t_top, t_bot and two webs
    (spars) t_front, t_rear. As in the reference model the beam uses one web thickness, the mean
    of the two spars: t_web = (t_front + t_rear)/2.

    - A = w h - (w - 2 t_web)(h - t_top - t_bot)
    - Neutral-axis shift (as coded): z_c = (t_top - t_bot)(w - 2 t_web)/w
    - I_y (vertical bending) = Σ_skins [w t³/12 + w t d²] + 2 [t_web h_w³/12 + t_web h_w z_c²],
      d_top = h/2 - t_top/2 - z_c, d_bot = -h/2 + t_bot/2 - z_c, h_w = h - t_top - t_bot
    - I_z (in-plane bending) = (t_top + t_bot) w³/12
      + 2 [h_w t_web³/12 + h_w t_web (w/2 - t_web/2)²]
    - Torsion constant J, option ``torsion_formula``:

      * ``'polar'`` (default): J = I_y + I_z, the polar moment of area. This is the form the
        reference model uses (the validation case of docs theory/structures 'Validation' depends on
        it), so the defaults reproduce the reference numbers. It treats the box like a solid section
        and is several
        times stiffer in torsion than a closed thin-walled box (about 9x for the docs
        theory/structures 'Validation' root bay).
      * ``'bredt'``: Bredt-Batho closed thin-walled section, J = 4 A_m² / ∮ ds/t with the
        mid-line box A_m = w_m h_m, w_m = w - t_web, h_m = h - (t_top + t_bot)/2 and
        ∮ ds/t = w_m/t_top + w_m/t_bot + h_m/t_front + h_m/t_rear (each wall its own thickness).
        This is the physically right torsion constant of a single-cell box; with equal skins and
        equal webs it equals the Bredt form quoted (commented out in aframe) in docs
        theory/structures 'Box section'.

    The neutral-axis shift z_c is the reference model's approximation (kept as the default, docs
    theory/structures 'Box section'). All partials are analytic and diagonal over elements.

    Inputs
    ------
    box_width : float, (num_elements,), m
        Outer width w, spar to spar.
    box_height : float, (num_elements,), m
        Outer height h, skin to skin.
    top_skin_thickness : float, (num_elements,), m
    bottom_skin_thickness : float, (num_elements,), m
    front_spar_thickness : float, (num_elements,), m
    rear_spar_thickness : float, (num_elements,), m

    Outputs
    -------
    area : float, (num_elements,), m**2
    bending_inertia_vertical : float, (num_elements,), m**4
        I_y, bending in the vertical (local x-z) plane.
    bending_inertia_inplane : float, (num_elements,), m**4
        I_z, chord-wise bending.
    torsion_constant : float, (num_elements,), m**4
    web_thickness : float, (num_elements,), m
        Mean spar thickness used by the beam and the stress recovery.

    Options
    -------
    num_elements : int
        Number of beam elements (>= 1).
    torsion_formula : str
        'polar' (default, as the reference model) or 'bredt'.
    """

    def initialize(self):
        self.options.declare("num_elements", types=int, lower=1, desc="Number of beam elements")
        self.options.declare(
            "torsion_formula",
            default="polar",
            values=TORSION_FORMULAS,
            desc="Torsion constant: 'polar' (J = I_y + I_z, reference model) or "
            "'bredt' (closed thin-walled box)",
        )

    def setup(self):
        ne = self.options["num_elements"]
        self.add_input(
            "box_width", val=np.full(ne, 0.5), units="m", desc="outer box width, spar to spar"
        )
        self.add_input(
            "box_height", val=np.full(ne, 0.15), units="m", desc="outer box height, skin to skin"
        )
        for name, what in (
            ("top_skin_thickness", "top skin"),
            ("bottom_skin_thickness", "bottom skin"),
            ("front_spar_thickness", "front spar web"),
            ("rear_spar_thickness", "rear spar web"),
        ):
            self.add_input(name, val=np.full(ne, 1.5e-3), units="m", desc=f"{what} thickness")
        self.add_output("area", val=np.ones(ne), units="m**2", desc="cross-section area")
        self.add_output(
            "bending_inertia_vertical",
            val=np.ones(ne),
            units="m**4",
            desc="second moment of area for vertical bending (I_y)",
        )
        self.add_output(
            "bending_inertia_inplane",
            val=np.ones(ne),
            units="m**4",
            desc="second moment of area for in-plane bending (I_z)",
        )
        self.add_output(
            "torsion_constant", val=np.ones(ne), units="m**4", desc="torsion constant J"
        )
        self.add_output(
            "web_thickness", val=np.full(ne, 1.5e-3), units="m", desc="mean spar web thickness"
        )
        ar = np.arange(ne)
        self.declare_partials(
            ["area", "bending_inertia_vertical", "bending_inertia_inplane", "torsion_constant"],
            "*",
            rows=ar,
            cols=ar,
        )
        self.declare_partials(
            "web_thickness",
            ["front_spar_thickness", "rear_spar_thickness"],
            rows=ar,
            cols=ar,
            val=0.5,
        )

    def _check(self, w, h, tt, tb, tf, tr):
        for name, val in (
            ("box_width", w),
            ("box_height", h),
            ("top_skin_thickness", tt),
            ("bottom_skin_thickness", tb),
            ("front_spar_thickness", tf),
            ("rear_spar_thickness", tr),
        ):
            check_range(
                name,
                val,
                lower=0.0,
                lower_open=True,
                units="m",
                error=om.AnalysisError,
                where=self.msginfo,
            )
        tw = 0.5 * (tf + tr)
        bad = np.flatnonzero(~((h - tt - tb).real > 0.0) | ~((w - 2.0 * tw).real > 0.0))
        if bad.size:
            raise om.AnalysisError(
                f"{self.msginfo}: the walls do not fit in the box at elements {bad.tolist()}: "
                f"need top + bottom skin thickness < box_height (got {(tt + tb).real[bad]} vs "
                f"{h.real[bad]} m) and 2 x web thickness < box_width (got "
                f"{(2.0 * tw).real[bad]} vs {w.real[bad]} m)."
            )

    def _unpack(self, inputs):
        return (
            inputs["box_width"],
            inputs["box_height"],
            inputs["top_skin_thickness"],
            inputs["bottom_skin_thickness"],
            inputs["front_spar_thickness"],
            inputs["rear_spar_thickness"],
        )

    def compute(self, inputs, outputs):
        w, h, tt, tb, tf, tr = self._unpack(inputs)
        self._check(w, h, tt, tb, tf, tr)
        vals = _box_properties(w, h, tt, tb, tf, tr, self.options["torsion_formula"])
        for name in (
            "area",
            "bending_inertia_vertical",
            "bending_inertia_inplane",
            "torsion_constant",
            "web_thickness",
        ):
            outputs[name] = vals[name]

    def compute_partials(self, inputs, partials):
        w, h, tt, tb, tf, tr = self._unpack(inputs)
        derivs = _box_property_partials(w, h, tt, tb, tf, tr, self.options["torsion_formula"])
        for (of, wrt), val in derivs.items():
            partials[of, wrt] = val


_WRT = (
    "box_width",
    "box_height",
    "top_skin_thickness",
    "bottom_skin_thickness",
    "front_spar_thickness",
    "rear_spar_thickness",
)


def _box_properties(w, h, tt, tb, tf, tr, torsion_formula="polar"):
    """Section properties of the box (complex-safe), as a dict of arrays."""
    tw = 0.5 * (tf + tr)
    hw = h - tt - tb
    zc = (tt - tb) * (w - 2.0 * tw) / w
    d_top = 0.5 * h - 0.5 * tt - zc
    d_bot = -0.5 * h + 0.5 * tb - zc
    area = w * h - (w - 2.0 * tw) * hw
    iy = (
        w * tt**3 / 12.0
        + w * tt * d_top**2
        + w * tb**3 / 12.0
        + w * tb * d_bot**2
        + 2.0 * (tw * hw**3 / 12.0 + tw * hw * zc**2)
    )
    iz = (tt + tb) * w**3 / 12.0 + 2.0 * (hw * tw**3 / 12.0 + hw * tw * (0.5 * w - 0.5 * tw) ** 2)
    if torsion_formula == "polar":
        j = iy + iz
    else:
        wm = w - tw
        hm = h - 0.5 * (tt + tb)
        j = 4.0 * (wm * hm) ** 2 / (wm / tt + wm / tb + hm / tf + hm / tr)
    return {
        "area": area,
        "bending_inertia_vertical": iy,
        "bending_inertia_inplane": iz,
        "torsion_constant": j,
        "web_thickness": tw,
    }


def _box_property_partials(w, h, tt, tb, tf, tr, torsion_formula="polar"):
    """Analytic partials {(of, wrt): (num_elements,)} of _box_properties (diagonal)."""
    tw = 0.5 * (tf + tr)
    hw = h - tt - tb
    zc = (tt - tb) * (w - 2.0 * tw) / w
    d_top = 0.5 * h - 0.5 * tt - zc
    d_bot = -0.5 * h + 0.5 * tb - zc
    zero = np.zeros_like(w)
    half = 0.5 * np.ones_like(w)

    # Primary variables x = (w, h, tt, tb, tw); tw = (tf + tr)/2 is chained at the end.
    d_tw = {"w": zero, "h": zero, "tt": zero, "tb": zero, "tw": np.ones_like(w)}
    d_hw = {
        "w": zero,
        "h": np.ones_like(w),
        "tt": -np.ones_like(w),
        "tb": -np.ones_like(w),
        "tw": zero,
    }
    d_zc = {
        "w": (tt - tb) * 2.0 * tw / w**2,
        "h": zero,
        "tt": 1.0 - 2.0 * tw / w,
        "tb": -(1.0 - 2.0 * tw / w),
        "tw": -2.0 * (tt - tb) / w,
    }
    d_area = {
        "w": h - hw,
        "h": w - (w - 2.0 * tw),
        "tt": w - 2.0 * tw,
        "tb": w - 2.0 * tw,
        "tw": 2.0 * hw,
    }

    # I_y = f(w, tt, tb, tw, hw, zc, d_top(h, tt, zc), d_bot(h, tb, zc))
    iy_w = tt**3 / 12.0 + tt * d_top**2 + tb**3 / 12.0 + tb * d_bot**2
    iy_tt = w * tt**2 / 4.0 + w * d_top**2
    iy_tb = w * tb**2 / 4.0 + w * d_bot**2
    iy_tw = 2.0 * (hw**3 / 12.0 + hw * zc**2)
    iy_hw = 2.0 * (tw * hw**2 / 4.0 + tw * zc**2)
    iy_dtop = 2.0 * w * tt * d_top
    iy_dbot = 2.0 * w * tb * d_bot
    iy_zc = 4.0 * tw * hw * zc - iy_dtop - iy_dbot  # d_top and d_bot both hold -z_c
    d_dtop_direct = {"w": zero, "h": half, "tt": -half, "tb": zero, "tw": zero}
    d_dbot_direct = {"w": zero, "h": -half, "tt": zero, "tb": half, "tw": zero}
    explicit_iy = {"w": iy_w, "h": zero, "tt": iy_tt, "tb": iy_tb, "tw": iy_tw}
    d_iy = {
        x: (
            explicit_iy[x]
            + iy_hw * d_hw[x]
            + iy_dtop * d_dtop_direct[x]
            + iy_dbot * d_dbot_direct[x]
            + iy_zc * d_zc[x]
        )
        for x in d_tw
    }

    # I_z = (tt + tb) w³/12 + 2 [hw tw³/12 + hw tw (w - tw)²/4]
    iz_hw = 2.0 * (tw**3 / 12.0 + tw * (w - tw) ** 2 / 4.0)
    explicit_iz = {
        "w": (tt + tb) * w**2 / 4.0 + hw * tw * (w - tw),
        "h": zero,
        "tt": w**3 / 12.0,
        "tb": w**3 / 12.0,
        "tw": 2.0 * (hw * tw**2 / 4.0 + hw * (w - tw) ** 2 / 4.0 - hw * tw * (w - tw) / 2.0),
    }
    d_iz = {x: explicit_iz[x] + iz_hw * d_hw[x] for x in d_tw}

    names = {
        "w": "box_width",
        "h": "box_height",
        "tt": "top_skin_thickness",
        "tb": "bottom_skin_thickness",
    }
    out = {}
    for of, d in (
        ("area", d_area),
        ("bending_inertia_vertical", d_iy),
        ("bending_inertia_inplane", d_iz),
    ):
        for x, name in names.items():
            out[of, name] = d[x]
        out[of, "front_spar_thickness"] = 0.5 * d["tw"]
        out[of, "rear_spar_thickness"] = 0.5 * d["tw"]

    if torsion_formula == "polar":
        for wrt in _WRT:
            out["torsion_constant", wrt] = (
                out["bending_inertia_vertical", wrt] + out["bending_inertia_inplane", wrt]
            )
    else:
        wm = w - tw
        hm = h - 0.5 * (tt + tb)
        am = wm * hm
        s = wm / tt + wm / tb + hm / tf + hm / tr
        # J = 4 A_m² / s: dJ = 8 A_m dA_m / s - 4 A_m² ds / s²
        d_am = {
            "box_width": hm,
            "box_height": wm,
            "top_skin_thickness": -0.5 * wm,
            "bottom_skin_thickness": -0.5 * wm,
            "front_spar_thickness": -0.5 * hm,
            "rear_spar_thickness": -0.5 * hm,
        }
        inv_skins = 1.0 / tt + 1.0 / tb
        inv_webs = 1.0 / tf + 1.0 / tr
        d_s = {
            "box_width": inv_skins,
            "box_height": inv_webs,
            "top_skin_thickness": -wm / tt**2 - 0.5 * inv_webs,
            "bottom_skin_thickness": -wm / tb**2 - 0.5 * inv_webs,
            "front_spar_thickness": -0.5 * inv_skins - hm / tf**2,
            "rear_spar_thickness": -0.5 * inv_skins - hm / tr**2,
        }
        for wrt in _WRT:
            out["torsion_constant", wrt] = 8.0 * am * d_am[wrt] / s - 4.0 * am**2 * d_s[wrt] / s**2
    return out
