"""
Chordwise pressure of the wing sections at alpha* and the section loads from integrating it.

Paper Sec. III.C, eq. 16b: q = f(alpha*, Re, M) with q the pressure distribution; the section
force and pitching moment about the wing-box beam axis feed the structural model
(docs theory/aerodynamics 'Airfoil coupling' steps 3–4; docs theory/structures 'Material, mesh and
load transfer').

The Cp tables (upper and lower surface over alpha, Re, M) ship with the wing airfoils' polar files
``lpc_mdo/data/airfoil_ls413.npz`` and ``airfoil_ls417.npz``; they come from XFOIL 6.99 (viscous,
240 panel nodes) resampled to cosine-spaced stations (``run_scripts/make_airfoil_tables.py``).

Integration (pressure only, per unit span, coefficients on the chord c; airfoil frame of the
coordinate file: x aft from the leading edge, y up, both over c; trapezoid rule on the stations):

- normal force  cn = int (Cp_l - Cp_u) dx
- axial force   ca = int Cp_u dy_u - int Cp_l dy_l            (positive aft)
- moment about the leading edge, nose up positive,
  cm_0 = int Cp_u (x dx + y_u dy_u) - int Cp_l (x dx + y_l dy_l)
- moment about the axis (x_a, y_a): cm_a = cm_0 + x_a cn - y_a ca, with y_a the mid-height of the
  section at x_a (the beam node is at mid-height of the outer mould line);
- lift (pressure part)  cl_p = cn cos(alpha) - ca sin(alpha).
"""

import numpy as np
import openmdao.api as om

from .airfoil import get_polar
from .pressure_table import PressureTable


def get_pressure_table(airfoil):
    """Return the pressure table of an airfoil name, a TablePolar with one, or a PressureTable."""
    if isinstance(airfoil, PressureTable):
        return airfoil
    polar = get_polar(airfoil)
    table = getattr(polar, "pressure", None)
    if table is None:
        raise ValueError(
            f"airfoil = {airfoil!r} has no pressure (Cp) table; allowed: 'ls413', "
            f"'ls417', a TablePolar with a pressure table, or a PressureTable"
        )
    return table


class SectionPressureComp(om.ExplicitComponent):
    """
    Chordwise Cp at alpha* and the section loads from integrating it (paper eq. 16b).

    Vectorized over ``num_sections`` spanwise wing sections. Formulas in the module docstring;
    outside the Cp table's alpha, Re and M ranges the Cp is held at the table edge.

    Inputs
    ------
    alpha_star : float, (num_sections,), rad
        Section angle of attack from the alpha* inversion (AlphaStarComp).
    reynolds : float, (num_sections,)
        Chord Reynolds number.
    mach : float, (num_sections,)
        Mach number (the condition's; reference quirk Q4 hard-codes 0.18 — not here).
    dynamic_pressure : float, (num_sections,), Pa
        Dynamic pressure of the local flow, 1/2 rho V^2.
    chord : float, (num_sections,), m
        Section chord.
    axis_location : float, (num_sections,)
        Chordwise position of the moment axis (beam axis), x/c; default 0.5. The axis height is
        the section's mid-height there.

    Outputs
    -------
    cp_upper, cp_lower : float, (num_sections, num_stations)
        Pressure coefficients on the upper and lower surface at the stations
        ``x_stations`` (x/c, cosine spaced, attribute of the component after setup).
    normal_force_coefficient : float, (num_sections,)
        cn, normal to the chord line (x axis of the airfoil file), positive up.
    axial_force_coefficient : float, (num_sections,)
        ca, along the chord, positive aft.
    pressure_lift_coefficient : float, (num_sections,)
        cl_p = cn cos(alpha*) - ca sin(alpha*) (compare with the VLM cl: the consistency check).
    moment_coefficient : float, (num_sections,)
        Pitching moment about the axis over (q c^2), nose up positive.
    normal_force : float, (num_sections,), N/m
        q c cn, per unit span.
    axial_force : float, (num_sections,), N/m
        q c ca, per unit span.
    pitching_moment : float, (num_sections,), N*m/m
        q c^2 cm_a about the axis, per unit span, nose up positive.

    Options
    -------
    num_sections : int
        Number of spanwise sections (>= 1).
    airfoil : str, TablePolar or PressureTable
        Wing airfoil with a Cp table: 'ls413' (default, GA(W)-2) or 'ls417' (GA(W)-1).
    """

    def initialize(self):
        self.options.declare(
            "num_sections", default=1, types=int, lower=1, desc="Number of spanwise sections"
        )
        self.options.declare(
            "airfoil",
            default="ls413",
            desc="Wing airfoil with a Cp table: 'ls413', 'ls417', a TablePolar "
            "with a pressure table or a PressureTable",
        )

    def setup(self):
        n = self.options["num_sections"]
        self._table = get_pressure_table(self.options["airfoil"])
        self.x_stations = self._table.x
        n_x = self.x_stations.size
        self.add_input(
            "alpha_star", val=np.zeros(n), units="rad", desc="Section angle of attack alpha*"
        )
        self.add_input("reynolds", val=1e6 * np.ones(n), desc="Chord Reynolds number")
        self.add_input("mach", val=np.zeros(n), desc="Mach number")
        self.add_input(
            "dynamic_pressure", val=np.ones(n), units="Pa", desc="Local dynamic pressure"
        )
        self.add_input("chord", val=np.ones(n), units="m", desc="Section chord")
        self.add_input(
            "axis_location",
            val=0.5 * np.ones(n),
            desc="Chordwise position x/c of the moment (beam) axis",
        )
        self.add_output("cp_upper", val=np.zeros((n, n_x)), desc="Upper-surface Cp")
        self.add_output("cp_lower", val=np.zeros((n, n_x)), desc="Lower-surface Cp")
        for name, desc in (
            ("normal_force_coefficient", "cn, normal to the chord, up"),
            ("axial_force_coefficient", "ca, along the chord, aft"),
            ("pressure_lift_coefficient", "cn cos(a) - ca sin(a)"),
            ("moment_coefficient", "Pitching moment about the axis / (q c^2)"),
        ):
            self.add_output(name, val=np.zeros(n), desc=desc)
        self.add_output(
            "normal_force", val=np.zeros(n), units="N/m", desc="Section normal force per unit span"
        )
        self.add_output(
            "axial_force", val=np.zeros(n), units="N/m", desc="Section axial force per unit span"
        )
        self.add_output(
            "pitching_moment",
            val=np.zeros(n),
            units="N*m/m",
            desc="Section pitching moment about the axis per unit span, nose up",
        )

        diag = np.arange(n)
        rows_cp = np.arange(n * n_x)
        cols_cp = np.repeat(diag, n_x)
        flow = ["alpha_star", "reynolds", "mach"]
        for cp in ("cp_upper", "cp_lower"):
            self.declare_partials(cp, flow, rows=rows_cp, cols=cols_cp)
        self.declare_partials(
            ["normal_force_coefficient", "axial_force_coefficient", "pressure_lift_coefficient"],
            flow,
            rows=diag,
            cols=diag,
        )
        self.declare_partials("moment_coefficient", flow + ["axis_location"], diagonal=True)
        self.declare_partials(
            ["normal_force", "axial_force"],
            flow + ["dynamic_pressure", "chord"],
            rows=diag,
            cols=diag,
        )
        self.declare_partials(
            "pitching_moment",
            flow + ["dynamic_pressure", "chord", "axis_location"],
            rows=diag,
            cols=diag,
        )

    def _evaluate(self, inputs):
        a = inputs["alpha_star"]
        cps = self._table.cp(a, inputs["reynolds"], inputs["mach"])
        loads = [self._table.integrate(c) for c in cps]  # each (3, N): cn, ca, cm_0
        y_a, dy_a = self._table.mid_height(inputs["axis_location"])
        return cps, loads, y_a, dy_a

    def compute(self, inputs, outputs):
        a = inputs["alpha_star"]
        q, c, x_a = inputs["dynamic_pressure"], inputs["chord"], inputs["axis_location"]
        (cp, *_), ((cn, ca, cm0), *_), y_a, _ = self._evaluate(inputs)
        outputs["cp_upper"] = cp[:, 0]
        outputs["cp_lower"] = cp[:, 1]
        cm = cm0 + x_a * cn - y_a * ca
        outputs["normal_force_coefficient"] = cn
        outputs["axial_force_coefficient"] = ca
        outputs["pressure_lift_coefficient"] = cn * np.cos(a) - ca * np.sin(a)
        outputs["moment_coefficient"] = cm
        outputs["normal_force"] = q * c * cn
        outputs["axial_force"] = q * c * ca
        outputs["pitching_moment"] = q * c**2 * cm

    def compute_partials(self, inputs, partials):
        a = inputs["alpha_star"]
        q, c, x_a = inputs["dynamic_pressure"], inputs["chord"], inputs["axis_location"]
        cps, loads, y_a, dy_a = self._evaluate(inputs)
        cn, ca, cm0 = loads[0]
        cos, sin = np.cos(a), np.sin(a)
        for name, dcp, (dcn, dca, dcm0), extra in zip(
            ("alpha_star", "reynolds", "mach"),
            cps[1:],
            loads[1:],
            (-cn * sin - ca * cos, 0.0, 0.0),
            strict=True,
        ):
            partials["cp_upper", name] = dcp[:, 0].ravel()
            partials["cp_lower", name] = dcp[:, 1].ravel()
            dcm = dcm0 + x_a * dcn - y_a * dca
            partials["normal_force_coefficient", name] = dcn
            partials["axial_force_coefficient", name] = dca
            partials["pressure_lift_coefficient", name] = dcn * cos - dca * sin + extra
            partials["moment_coefficient", name] = dcm
            partials["normal_force", name] = q * c * dcn
            partials["axial_force", name] = q * c * dca
            partials["pitching_moment", name] = q * c**2 * dcm
        cm = cm0 + x_a * cn - y_a * ca
        dcm_dxa = cn - dy_a * ca
        partials["moment_coefficient", "axis_location"] = dcm_dxa
        partials["pitching_moment", "axis_location"] = q * c**2 * dcm_dxa
        partials["normal_force", "dynamic_pressure"] = c * cn
        partials["normal_force", "chord"] = q * cn
        partials["axial_force", "dynamic_pressure"] = c * ca
        partials["axial_force", "chord"] = q * ca
        partials["pitching_moment", "dynamic_pressure"] = c**2 * cm
        partials["pitching_moment", "chord"] = 2 * q * c * cm
