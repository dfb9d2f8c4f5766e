"""Stress recovery in the box beam: von Mises stress at five points per section, skin stresses."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.structures.box_section import TORSION_FORMULAS
from lpc_mdo.core.checks import check_range

# Stress points (sign of local y, sign of local z): corners top-front, top-rear, bottom-rear,
# bottom-front, then the web at local y = +w/2 (and, with web_points='both', at -w/2). For a right
# wing (local y aft, local z down) "front" is y = -w/2 and "top" is z = -h/2.
_CORNERS = ((-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0))
_WEBS = {"one": (1.0,), "both": (1.0, -1.0)}

# Regularisation of the von Mises square root (Pa**2): keeps its derivative finite at zero stress
# and changes the stress by at most 1e-4 Pa.
_VM_EPS = 1e-8

_VARS = ("N", "Vz", "Mx", "My", "Mz", "w", "h", "tt", "tb", "tw", "A", "Iy", "Iz", "J")
# (input name, column within the element's entries) for each derivative variable
_INPUT_OF = {
    "N": ("section_forces", 0),
    "Vz": ("section_forces", 2),
    "Mx": ("section_moments", 0),
    "My": ("section_moments", 1),
    "Mz": ("section_moments", 2),
    "w": ("box_width", None),
    "h": ("box_height", None),
    "tt": ("top_skin_thickness", None),
    "tb": ("bottom_skin_thickness", None),
    "tw": ("web_thickness", None),
    "A": ("area", None),
    "Iy": ("bending_inertia_vertical", None),
    "Iz": ("bending_inertia_inplane", None),
    "J": ("torsion_constant", None),
}


class BoxStressComp(om.ExplicitComponent):
    """
    Von Mises stress at the stress points of each box section, and the skin normal stresses.

    Reference docs theory/structures 'Stress', with the section resultants of BeamForcesComp
    (internal forces on the positive face, element frame: axial N, shear V_z, torque M_x, bending
    M_y, M_z; local y
    across the box width, local z vertical, down for a wing in the body frame):

    - normal stress at (y, z): σ = N/A + M_y z/I_y - M_z y/I_z (tension positive);
    - torsional shear: 'polar' (reference model, with J = I_y + I_z): τ_t = M_x r/J with
      r = sqrt(y² + z²); 'bredt': τ_t = M_x/(2 A_m t) in the wall of thickness t, with the
      mid-line area A_m = (w - t_web)(h - (t_top + t_bot)/2) (see BoxSectionComp);
    - transverse shear in the webs (main-branch form of docs theory/structures 'Stress'): τ_s = V_z
      Q/(2 t_web I_y), Q = w t_cap h/2 + t_web h²/4, t_cap = (t_top + t_bot)/2;
    - σ_vm = sqrt(σ² + 3 τ² + ε), ε = 1e-8 Pa².

    Points (y, z): 0 (-w/2, -h/2) top/front corner, 1 (+w/2, -h/2) top/rear, 2 (+w/2, +h/2)
    bottom/rear, 3 (-w/2, +h/2) bottom/front, 4 (+w/2, 0) web, where the torsional and the
    transverse shear flows add (τ = τ_s + τ_t); with ``web_points='both'`` a sixth point
    5 (-w/2, 0) on the other web, where they subtract (τ = τ_s - τ_t). "Front"/"rear" and
    "top"/"bottom" are the physical positions for a right wing in the body frame; the five
    points are the reference's points 2, 3, 0, 1, 4 (its element loads have the opposite sign).

    Skin stresses for panel buckling: the normal stress at the skin's outer fibre averaged over
    the width (the M_z term cancels): σ_top = N/A - M_y (h/2)/I_y, σ_bot = N/A + M_y (h/2)/I_y;
    negative in compression.

    Analytic partials, block-diagonal over elements.

    Inputs
    ------
    section_forces : float, (num_elements, 3), N
        Mean internal (axial N, shear V_y, shear V_z), element frame; V_y is not used.
    section_moments : float, (num_elements, 3), N*m
        Mean internal (torque M_x, bending M_y, bending M_z), element frame.
    box_width, box_height : float, (num_elements,), m
    top_skin_thickness, bottom_skin_thickness, web_thickness : float, (num_elements,), m
    area : float, (num_elements,), m**2
    bending_inertia_vertical, bending_inertia_inplane : float, (num_elements,), m**4
    torsion_constant : float, (num_elements,), m**4
        Only with torsion_formula='polar'.
    allowable_stress : float, scalar, Pa
        Allowable von Mises stress (350 MPa for the aluminium of the reference).

    Outputs
    -------
    von_mises_stress : float, (num_elements, 5) or (num_elements, 6), Pa
    stress_ratio : float, same shape as von_mises_stress
        von_mises_stress / allowable_stress; the constraint is <= 1 (order one, so it suits
        KSComp's default rho when aggregated).
    top_skin_stress : float, (num_elements,), Pa
    bottom_skin_stress : float, (num_elements,), Pa

    Options
    -------
    num_elements : int
    torsion_formula : str
        'polar' (default) or 'bredt'; use the same as in BoxSectionComp.
    web_points : str
        'one' (default, the paper's five points) or 'both' (adds the other web, point 5).
    """

    def initialize(self):
        self.options.declare("num_elements", types=int, lower=1, desc="Number of beam elements")
        self.options.declare(
            "torsion_formula",
            default="polar",
            values=TORSION_FORMULAS,
            desc="Torsional shear: 'polar' (M_x r/J) or 'bredt' (M_x/(2 A_m t))",
        )
        self.options.declare(
            "web_points",
            default="one",
            values=tuple(_WEBS),
            desc="'one': five points (paper); 'both': a sixth point on the other web",
        )

    def setup(self):
        ne = self.options["num_elements"]
        polar = self.options["torsion_formula"] == "polar"
        npts = 4 + len(_WEBS[self.options["web_points"]])
        self._npts = npts

        self.add_input(
            "section_forces",
            val=np.zeros((ne, 3)),
            units="N",
            desc="mean internal forces (axial, shear y, shear z), element frame",
        )
        self.add_input(
            "section_moments",
            val=np.zeros((ne, 3)),
            units="N*m",
            desc="mean internal moments (torque, bending y, bending z), element frame",
        )
        self.add_input("box_width", val=np.full(ne, 0.5), units="m", desc="outer box width")
        self.add_input("box_height", val=np.full(ne, 0.15), units="m", desc="outer box height")
        self.add_input(
            "top_skin_thickness", val=np.full(ne, 1.5e-3), units="m", desc="top skin thickness"
        )
        self.add_input(
            "bottom_skin_thickness",
            val=np.full(ne, 1.5e-3),
            units="m",
            desc="bottom skin thickness",
        )
        self.add_input(
            "web_thickness", val=np.full(ne, 1.5e-3), units="m", desc="mean spar web thickness"
        )
        self.add_input("area", val=np.ones(ne), units="m**2", desc="cross-section area")
        self.add_input(
            "bending_inertia_vertical",
            val=np.ones(ne),
            units="m**4",
            desc="second moment of area I_y (vertical bending)",
        )
        self.add_input(
            "bending_inertia_inplane",
            val=np.ones(ne),
            units="m**4",
            desc="second moment of area I_z (in-plane bending)",
        )
        if polar:
            self.add_input(
                "torsion_constant", val=np.ones(ne), units="m**4", desc="torsion constant J"
            )
        self.add_input(
            "allowable_stress", val=350.0e6, units="Pa", desc="allowable von Mises stress"
        )
        self.add_output(
            "von_mises_stress",
            val=np.zeros((ne, npts)),
            units="Pa",
            desc="von Mises stress at the stress points of each section",
        )
        self.add_output(
            "stress_ratio",
            val=np.zeros((ne, npts)),
            units=None,
            desc="von Mises stress over the allowable stress",
        )
        self.add_output(
            "top_skin_stress",
            val=np.zeros(ne),
            units="Pa",
            desc="normal stress in the top skin (outer fibre), tension positive",
        )
        self.add_output(
            "bottom_skin_stress",
            val=np.zeros(ne),
            units="Pa",
            desc="normal stress in the bottom skin (outer fibre), tension positive",
        )

        # Which variables each output depends on (structurally).
        self._vm_vars = [v for v in _VARS if polar or v != "J"]
        e = np.arange(ne)
        rows_vm = np.arange(ne * npts).reshape(ne, npts)
        for name, cols_of in self._input_columns(ne, self._vm_vars).items():
            ncol = cols_of.shape[1]
            self.declare_partials(
                ["von_mises_stress", "stress_ratio"],
                name,
                rows=np.repeat(rows_vm, ncol, axis=1).ravel(),
                cols=np.tile(cols_of, (1, npts)).ravel(),
            )
        self.declare_partials("stress_ratio", "allowable_stress")
        skin_vars = ("N", "My", "h", "A", "Iy")
        for name, cols_of in self._input_columns(ne, skin_vars).items():
            ncol = cols_of.shape[1]
            self.declare_partials(
                ["top_skin_stress", "bottom_skin_stress"],
                name,
                rows=np.repeat(e, ncol),
                cols=cols_of.ravel(),
            )

    @staticmethod
    def _input_columns(ne, variables):
        """{input name: (ne, k) flat column indices} for the variables used, in _VARS order."""
        cols = {}
        e = np.arange(ne)
        for var in variables:
            name, comp = _INPUT_OF[var]
            col = e if comp is None else 3 * e + comp
            cols.setdefault(name, []).append(col)
        return {name: np.stack(c, axis=1) for name, c in cols.items()}

    def _variables(self, inputs):
        forces, moments = inputs["section_forces"], inputs["section_moments"]
        x = {
            "N": forces[:, 0],
            "Vz": forces[:, 2],
            "Mx": moments[:, 0],
            "My": moments[:, 1],
            "Mz": moments[:, 2],
        }
        for var in ("w", "h", "tt", "tb", "tw", "A", "Iy", "Iz", "J"):
            name = _INPUT_OF[var][0]
            if name in inputs:
                x[var] = inputs[name]
        return x

    def _check(self, x):
        for var in ("w", "h", "tt", "tb", "tw", "A", "Iy", "Iz", "J"):
            if var in x:
                check_range(
                    _INPUT_OF[var][0],
                    x[var],
                    lower=0.0,
                    lower_open=True,
                    error=om.AnalysisError,
                    where=self.msginfo,
                )

    def _terms(self, x, derivs):
        """σ, τ (ne, npts) and, if derivs, their partials {var: (ne, npts)}."""
        polar = self.options["torsion_formula"] == "polar"
        webs = _WEBS[self.options["web_points"]]
        points = list(_CORNERS) + [(sy, 0.0) for sy in webs]
        sy = np.array([p[0] for p in points])
        sz = np.array([p[1] for p in points])
        is_web = np.arange(len(points)) >= 4
        col = np.newaxis
        w, h, tt, tb, tw = (
            x["w"][:, col],
            x["h"][:, col],
            x["tt"][:, col],
            x["tb"][:, col],
            x["tw"][:, col],
        )
        area, iy, iz = x["A"][:, col], x["Iy"][:, col], x["Iz"][:, col]
        n, vz, mx, my, mz = (x[k][:, col] for k in ("N", "Vz", "Mx", "My", "Mz"))
        zero = np.zeros((w.shape[0], len(points)))

        sigma = n / area + my * sz * h / (2.0 * iy) - mz * sy * w / (2.0 * iz)

        # Torsional shear at each point (sign: + on the web at +y, - on the web at -y).
        sign_t = np.where(is_web, sy, 1.0)
        if polar:
            j = x["J"][:, col]
            r = np.where(is_web, 0.5 * w, 0.5 * np.sqrt(w * w + h * h))
            tau_t = sign_t * mx * r / j
        else:
            wm = w - tw
            hm = h - 0.5 * (tt + tb)
            am = wm * hm
            t_wall = np.where(is_web, tw, np.where(sz < 0.0, tt, tb))
            tau_t = sign_t * mx / (2.0 * am * t_wall)
        t_cap = 0.5 * (tt + tb)
        q = w * t_cap * h / 2.0 + tw * h * h / 4.0
        tau_s = np.where(is_web, vz * q / (2.0 * tw * iy), 0.0)
        tau = tau_t + tau_s
        if not derivs:
            return sigma, tau, None, None

        ds = {k: zero.copy() for k in self._vm_vars}
        dt = {k: zero.copy() for k in self._vm_vars}
        ds["N"] = ds["N"] + 1.0 / area
        ds["A"] = ds["A"] - n / area**2
        ds["My"] = ds["My"] + sz * h / (2.0 * iy)
        ds["h"] = ds["h"] + my * sz / (2.0 * iy)
        ds["Iy"] = ds["Iy"] - my * sz * h / (2.0 * iy**2)
        ds["Mz"] = ds["Mz"] - sy * w / (2.0 * iz)
        ds["w"] = ds["w"] - mz * sy / (2.0 * iz)
        ds["Iz"] = ds["Iz"] + mz * sy * w / (2.0 * iz**2)

        if polar:
            dt["Mx"] = dt["Mx"] + sign_t * r / j
            dt["J"] = dt["J"] - tau_t / j
            dr_dw = np.where(is_web, 0.5, w / (4.0 * np.where(is_web, 1.0, r)))
            dr_dh = np.where(is_web, 0.0, h / (4.0 * np.where(is_web, 1.0, r)))
            dt["w"] = dt["w"] + sign_t * mx / j * dr_dw
            dt["h"] = dt["h"] + sign_t * mx / j * dr_dh
        else:
            dt["Mx"] = dt["Mx"] + sign_t / (2.0 * am * t_wall)
            d_am = -tau_t / am
            dt["w"] = dt["w"] + d_am * hm
            dt["h"] = dt["h"] + d_am * wm
            dt["tt"] = (
                dt["tt"] - d_am * 0.5 * wm - np.where(~is_web & (sz < 0.0), tau_t / t_wall, 0.0)
            )
            dt["tb"] = (
                dt["tb"] - d_am * 0.5 * wm - np.where(~is_web & (sz > 0.0), tau_t / t_wall, 0.0)
            )
            dt["tw"] = dt["tw"] - d_am * hm - np.where(is_web, tau_t / t_wall, 0.0)

        # Transverse shear in the webs.
        web = is_web.astype(float)
        c_q = web * vz / (2.0 * tw * iy)
        dt["Vz"] = dt["Vz"] + web * q / (2.0 * tw * iy)
        dt["Iy"] = dt["Iy"] - tau_s / iy
        dt["tw"] = dt["tw"] - tau_s / tw + c_q * h * h / 4.0
        dt["w"] = dt["w"] + c_q * t_cap * h / 2.0
        dt["h"] = dt["h"] + c_q * (w * t_cap / 2.0 + tw * h / 2.0)
        dt["tt"] = dt["tt"] + c_q * w * h / 4.0
        dt["tb"] = dt["tb"] + c_q * w * h / 4.0
        return sigma, tau, ds, dt

    def compute(self, inputs, outputs):
        x = self._variables(inputs)
        self._check(x)
        sigma, tau, _, _ = self._terms(x, derivs=False)
        allowable = inputs["allowable_stress"]
        check_range(
            "allowable_stress",
            allowable[0],
            lower=0.0,
            lower_open=True,
            units="Pa",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        vm = np.sqrt(sigma**2 + 3.0 * tau**2 + _VM_EPS)
        outputs["von_mises_stress"] = vm
        outputs["stress_ratio"] = vm / allowable
        bending = x["My"] * x["h"] / (2.0 * x["Iy"])
        outputs["top_skin_stress"] = x["N"] / x["A"] - bending
        outputs["bottom_skin_stress"] = x["N"] / x["A"] + bending

    def compute_partials(self, inputs, partials):
        ne = self.options["num_elements"]
        x = self._variables(inputs)
        sigma, tau, ds, dt = self._terms(x, derivs=True)
        vm = np.sqrt(sigma**2 + 3.0 * tau**2 + _VM_EPS)
        dvm = {k: (sigma * ds[k] + 3.0 * tau * dt[k]) / vm for k in self._vm_vars}
        allowable = inputs["allowable_stress"]
        for name, variables in self._grouped(self._vm_vars).items():
            # rows (e, point), cols (variables of that input): (ne, npts, k)
            val = np.stack([dvm[v] for v in variables], axis=-1).ravel()
            partials["von_mises_stress", name] = val
            partials["stress_ratio", name] = val / allowable
        partials["stress_ratio", "allowable_stress"] = -(vm / allowable**2).reshape(-1, 1)

        n, my, h, area, iy = x["N"], x["My"], x["h"], x["A"], x["Iy"]
        skin = {
            "N": (1.0 / area, 1.0 / area),
            "My": (-h / (2.0 * iy), h / (2.0 * iy)),
            "h": (-my / (2.0 * iy), my / (2.0 * iy)),
            "A": (-n / area**2, -n / area**2),
            "Iy": (my * h / (2.0 * iy**2), -my * h / (2.0 * iy**2)),
        }
        for name, variables in self._grouped(("N", "My", "h", "A", "Iy")).items():
            for i, out in enumerate(("top_skin_stress", "bottom_skin_stress")):
                partials[out, name] = np.stack(
                    [np.broadcast_to(skin[v][i], (ne,)) for v in variables], axis=-1
                ).ravel()

    @staticmethod
    def _grouped(variables):
        grouped = {}
        for var in variables:
            grouped.setdefault(_INPUT_OF[var][0], []).append(var)
        return grouped
