"""BEM loads at the converged inflow angle, and rotor performance (coefficients, efficiencies).

docs theory/rotors 'Loads and coefficients'. :class:`BEMLoadsComp` integrates the blade-element
loads of :class:`~lpc_mdo.components.rotor.bem_inflow.BEMSections`;
:class:`RotorPerformanceComp` turns any rotor model's thrust and torque (BEM or Pitt–Peters)
into power, coefficients, efficiency, figure of merit and tip Mach number.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.geometry.blade import per_rotor
from lpc_mdo.components.rotor.bem_inflow import (
    SECTION_INPUTS,
    BEMSections,
    add_section_inputs,
    check_section_inputs,
    declare_bem_options,
    linearized_sections,
    station_columns,
)
from lpc_mdo.core.checks import check_range
from lpc_mdo.core.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND

_RPM_TO_RAD_S = RPM_TO_RAD_S


class BEMLoadsComp(om.ExplicitComponent):
    """
    Sectional and total BEM loads of several rotors at several operating points.

    docs theory/rotors 'Loads and coefficients' and paper eq. 12, at the inflow angle phi solved by
    BEMInflowComp. Per blade and unit span (blade-element form; at the solution it equals the
    momentum form dT = 4 pi r rho u_x (u_x - V_x) F dr,
    dQ = 2 pi r^2 rho u_x u_theta F dr):

    - W = 4 F V_t abs(sin phi) / (4 F abs(sin phi) cos(phi) + sigma C_theta)   (resultant velocity)
    - thrust_per_span = rho W^2 c C_x / 2,   drag_per_span = rho W^2 c C_theta / 2
    - thrust T = B sum_i thrust_per_span_i dr_i,  torque Q = B sum_i r_i drag_per_span_i dr_i
      (dr_i = station_width: the midpoint rule, or the public code's end-corrected sum, docs
      theory/rotors 'Public-code compatibility')

    Partials are analytic (the hand-derived chain rule of BEMSections.tangent), sparse.

    Inputs
    ------
    inflow_angle : float, (num_rotors, num_nodes, num_radial), rad
        Converged inflow angle (BEMInflowComp).
    station_width : float, (num_rotors, num_radial), m
        Radial quadrature widths dr_i.
    axial_velocity, rpm : float, (num_rotors, num_nodes), m/s, rpm
    station_radius, chord, twist : float, (num_rotors, num_radial), m, m, rad
    radius, hub_radius : float, (num_rotors,), m
    density, speed_of_sound, dynamic_viscosity : float, (num_nodes,), kg/m**3, m/s, Pa*s
        As in BEMInflowComp.

    Outputs
    -------
    thrust_per_span : float, (num_rotors, num_nodes, num_radial), N/m
        Sectional thrust of one blade per unit span.
    drag_per_span : float, (num_rotors, num_nodes, num_radial), N/m
        Sectional in-plane drag (opposing the rotation) of one blade per unit span, dQ/dr/(B r).
    angle_of_attack : float, (num_rotors, num_nodes, num_radial), rad
        Sectional angle of attack twist - inflow_angle.
    thrust : float, (num_rotors, num_nodes), N
        Rotor thrust along the thrust axis.
    torque : float, (num_rotors, num_nodes), N*m
        Aerodynamic torque the rotor needs (the shaft torque).

    Options
    -------
    As BEMInflowComp (num_rotors, num_nodes, num_radial, num_blades, polar, tip_loss, hub_loss,
    tip_loss_form).
    """

    def initialize(self):
        declare_bem_options(self.options)

    def setup(self):
        opts = self.options
        nr, nn, nrad = opts["num_rotors"], opts["num_nodes"], opts["num_radial"]
        self._shape = (nr, nn, nrad)
        self._blades = per_rotor(
            opts["num_blades"], nr, "num_blades", kind=int, lower=1, owner=self.msginfo
        )
        add_section_inputs(self, nr, nn, nrad)
        self.add_input(
            "inflow_angle",
            val=np.full(self._shape, 0.1),
            units="rad",
            desc="Inflow angle of each blade station",
        )
        self.add_input(
            "station_width",
            val=np.full((nr, nrad), 0.8 / nrad),
            units="m",
            desc="Radial quadrature width of each blade element",
        )

        shape = self._shape
        self.add_output(
            "thrust_per_span",
            val=np.zeros(shape),
            units="N/m",
            desc="Sectional thrust of one blade per unit span",
        )
        self.add_output(
            "drag_per_span",
            val=np.zeros(shape),
            units="N/m",
            desc="Sectional in-plane drag of one blade per unit span",
        )
        self.add_output(
            "angle_of_attack", val=np.zeros(shape), units="rad", desc="Sectional angle of attack"
        )
        self.add_output("thrust", val=np.zeros((nr, nn)), units="N", desc="Rotor thrust")
        self.add_output("torque", val=np.zeros((nr, nn)), units="N*m", desc="Rotor (shaft) torque")

        size = nr * nn * nrad
        ar = np.arange(size)
        total_rows = ar // nrad
        n_tot = nr * nn
        ar_tot = np.arange(n_tot)
        self._wrt = [
            name
            for name in SECTION_INPUTS
            if not (
                (name == "radius" and not opts["tip_loss"])
                or (name == "hub_radius" and not opts["hub_loss"])
            )
        ]
        sectional = ("thrust_per_span", "drag_per_span")
        self.declare_partials(sectional, "inflow_angle", diagonal=True)
        self.declare_partials(("thrust", "torque"), "inflow_angle", rows=total_rows, cols=ar)
        for name in self._wrt:
            kind = SECTION_INPUTS[name][0]
            self.declare_partials(
                sectional, name, rows=ar, cols=station_columns(kind, nr, nn, nrad)
            )
            if kind == "rotor_node" or (kind == "rotor" and nn == 1):
                # one entry per (rotor, node) and input entry: diagonal (a plain multiply in
                # OpenMDAO's products)
                self.declare_partials(("thrust", "torque"), name, diagonal=True)
                continue
            if kind == "rotor_station":
                rows, cols = total_rows, station_columns(kind, nr, nn, nrad)
            elif kind == "rotor":
                rows, cols = ar_tot, ar_tot // nn
            else:
                rows, cols = ar_tot, ar_tot % nn
            self.declare_partials(("thrust", "torque"), name, rows=rows, cols=cols)
        self.declare_partials(
            ("thrust", "torque"),
            "station_width",
            rows=total_rows,
            cols=station_columns("rotor_station", nr, nn, nrad),
        )
        self.declare_partials("angle_of_attack", "inflow_angle", diagonal=True, val=-1.0)
        self.declare_partials(
            "angle_of_attack",
            "twist",
            rows=ar,
            cols=station_columns("rotor_station", nr, nn, nrad),
            val=1.0,
        )

    def _sections(self, inputs):
        check_section_inputs(self, inputs, self.options["hub_loss"])
        opts = self.options
        return BEMSections(
            inputs,
            self._blades,
            opts["polar"],
            opts["tip_loss"],
            opts["hub_loss"],
            opts["tip_loss_form"],
            self._shape,
        )

    def _flat_station(self, array):
        return np.broadcast_to(array[:, None, :], self._shape).ravel()

    def compute(self, inputs, outputs):
        sections = self._sections(inputs)
        phi = inputs["inflow_angle"].ravel()
        st = sections.evaluate(phi)
        w, thrust_ps, drag_ps = sections.loads(st)
        if not (
            np.all(np.isfinite(w))
            and np.all(np.isfinite(thrust_ps))
            and np.all(np.isfinite(drag_ps))
        ):
            bad = np.flatnonzero(~np.isfinite(w) | ~np.isfinite(thrust_ps) | ~np.isfinite(drag_ps))
            raise om.AnalysisError(
                f"{self.msginfo}: non-finite BEM loads at flat stations {bad[:10].tolist()} "
                f"(inflow_angle {phi[bad[:10]].real.tolist()} rad); 4 F sin(phi) cos(phi) + "
                "sigma C_theta vanishes there."
            )
        shape = self._shape
        outputs["thrust_per_span"] = thrust_ps.reshape(shape)
        outputs["drag_per_span"] = drag_ps.reshape(shape)
        outputs["angle_of_attack"] = inputs["twist"][:, None, :] - inputs["inflow_angle"]
        bw = self._blades[:, None, None] * inputs["station_width"][:, None, :]
        outputs["thrust"] = np.sum(bw * outputs["thrust_per_span"], axis=-1)
        outputs["torque"] = np.sum(
            bw * inputs["station_radius"][:, None, :] * outputs["drag_per_span"], axis=-1
        )

    def compute_partials(self, inputs, partials):
        # The inflow component's linearization at the same point, if it is the last one.
        sections, st, local = linearized_sections(
            self, inputs, inputs["inflow_angle"], ["inflow_angle"] + self._wrt
        )
        _, thrust_ps, drag_ps = sections.loads(st)
        shape = self._shape
        nr, nn, nrad = shape
        bw = (
            self._blades[:, None, None] * inputs["station_width"][:, None, :] * np.ones(shape)
        ).ravel()
        r = self._flat_station(inputs["station_radius"])
        bwr = bw * r
        for name, (_, d_thrust, d_drag) in local.items():
            partials["thrust_per_span", name] = d_thrust
            partials["drag_per_span", name] = d_drag
            d_total_thrust = bw * d_thrust
            d_total_torque = bwr * d_drag
            if name == "station_radius":
                d_total_torque = d_total_torque + bw * drag_ps
            kind = "station" if name == "inflow_angle" else SECTION_INPUTS[name][0]
            if kind not in ("station", "rotor_station"):
                d_total_thrust = d_total_thrust.reshape(shape).sum(axis=-1).ravel()
                d_total_torque = d_total_torque.reshape(shape).sum(axis=-1).ravel()
            partials["thrust", name] = d_total_thrust
            partials["torque", name] = d_total_torque
        blades = (self._blades[:, None, None] * np.ones(shape)).ravel()
        partials["thrust", "station_width"] = blades * thrust_ps
        partials["torque", "station_width"] = blades * r * drag_ps


class RotorPerformanceComp(om.ExplicitComponent):
    """
    Power, thrust and power coefficients, advance ratio, efficiency, figure of merit, tip Mach.

    docs theory/rotors 'Loads and coefficients' (also the Pitt–Peters outputs, docs theory/rotors
    'Pitt-Peters inflow'), with n = rpm/60 (rev/s), D = 2R, Omega = 2 pi n:

    - P = Omega Q
    - C_T = T/(rho n^2 D^4),  C_P = P/(rho n^3 D^5)   (propeller coefficients; the rotorcraft
      C_T = T/(rho pi R^2 (Omega R)^2) = C_T 4/pi^3)
    - J = V_x/(n D),  eta = T V_x / P = J C_T / C_P
    - FoM = T^(3/2)/(sqrt(2 rho pi R^2) P), i.e. C_T,H^(3/2)/(sqrt(2) C_Q,H) (hover; computed as
      T sqrt|T| so that a negative thrust gives a negative value, not NaN)
    - M_tip = Omega R / a   (paper's hover constraint <= 0.6)
    - M_helical = sqrt(V_x^2 + (Omega R + abs(V_ip))^2) / a, the largest resultant Mach number at
      the blade tip over a revolution: the helical tip Mach number of a propeller
      (Raymer, Aircraft Design, sec. 10.4) and, with ``edgewise``, at the advancing blade
      (V_ip the in-plane velocity of the disk, Johnson, Rotorcraft Aeromechanics, ch. 1:
      M_at = M_tip (1 + mu) in level flight). It bounds the Mach number of every blade section
      the BEM (axial: abs(V_ip) not in its sections, so not here) or the Pitt-Peters model
      (edgewise) evaluates, so its limit keeps the polar inside its table (docs theory/rotors
      'Tip Mach number limits').

    Analytic partials, elementwise over (rotor, node).

    Inputs
    ------
    thrust : float, (num_rotors, num_nodes), N
    torque : float, (num_rotors, num_nodes), N*m
    rpm : float, (num_rotors, num_nodes), rpm
    axial_velocity : float, (num_rotors, num_nodes), m/s
        Freestream velocity along the thrust axis V_x.
    radius : float, (num_rotors,), m
    density, speed_of_sound : float, (num_nodes,), kg/m**3, m/s

    Outputs
    -------
    power : float, (num_rotors, num_nodes), W
        Shaft power.
    thrust_coefficient, power_coefficient : float, (num_rotors, num_nodes), -
        Propeller C_T and C_P.
    advance_ratio : float, (num_rotors, num_nodes), -
        J.
    efficiency : float, (num_rotors, num_nodes), -
        Propulsive efficiency eta (0 in hover).
    figure_of_merit : float, (num_rotors, num_nodes), -
        Hover figure of merit.
    tip_mach : float, (num_rotors, num_nodes), -
        Rotational tip Mach number.
    helical_tip_mach : float, (num_rotors, num_nodes), -
        Largest resultant tip Mach number (helical; at the advancing blade with ``edgewise``).

    With ``edgewise`` the input ``inplane_velocity`` (num_rotors, num_nodes, 2), m/s, the
    freestream velocity in the disk plane, enters the helical tip Mach number.

    Options
    -------
    num_rotors, num_nodes : int
        Array sizes (>= 1).
    edgewise : bool
        The rotor model resolves the in-plane velocity (Pitt-Peters): the helical tip Mach
        number is the advancing blade's (default False: axial BEM).
    """

    _OUTPUTS = (
        ("power", "W", "Shaft power Omega Q"),
        ("thrust_coefficient", None, "Thrust coefficient T/(rho n^2 D^4)"),
        ("power_coefficient", None, "Power coefficient P/(rho n^3 D^5)"),
        ("advance_ratio", None, "Advance ratio V_x/(n D)"),
        ("efficiency", None, "Propulsive efficiency T V_x / P"),
        ("figure_of_merit", None, "Hover figure of merit T^1.5/(sqrt(2 rho A) P)"),
        ("tip_mach", None, "Rotational tip Mach number Omega R / a"),
        (
            "helical_tip_mach",
            None,
            "Largest resultant tip Mach number sqrt(V_x^2 + (Omega R + abs(V_ip))^2)/a",
        ),
    )

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="Number of operating points per rotor"
        )
        self.options.declare(
            "edgewise",
            default=False,
            types=bool,
            desc="In-plane velocity enters the helical tip Mach number (advancing blade)",
        )

    def setup(self):
        nr, nn = self.options["num_rotors"], self.options["num_nodes"]
        shape = (nr, nn)
        self.add_input("thrust", val=np.zeros(shape), units="N", desc="Rotor thrust")
        self.add_input("torque", val=np.ones(shape), units="N*m", desc="Rotor shaft torque")
        self.add_input("rpm", val=np.full(shape, 1000.0), units="rpm", desc="Rotor speed")
        self.add_input(
            "axial_velocity",
            val=np.zeros(shape),
            units="m/s",
            desc="Freestream velocity along the thrust axis",
        )
        self.add_input("radius", val=np.ones(nr), units="m", desc="Rotor tip radius")
        self.add_input(
            "density", val=np.full(nn, SEA_LEVEL_DENSITY), units="kg/m**3", desc="Air density"
        )
        self.add_input(
            "speed_of_sound",
            val=np.full(nn, SEA_LEVEL_SPEED_OF_SOUND),
            units="m/s",
            desc="Speed of sound",
        )
        edgewise = self.options["edgewise"]
        if edgewise:
            self.add_input(
                "inplane_velocity",
                val=np.zeros(shape + (2,)),
                units="m/s",
                desc="Freestream velocity in the disk plane",
            )
        for name, units, desc in self._OUTPUTS:
            self.add_output(name, val=np.zeros(shape), units=units, desc=desc)

        ar = np.arange(nr * nn)
        deps = {
            "power": ("torque", "rpm"),
            "thrust_coefficient": ("thrust", "rpm", "radius", "density"),
            "power_coefficient": ("torque", "rpm", "radius", "density"),
            "advance_ratio": ("axial_velocity", "rpm", "radius"),
            "efficiency": ("thrust", "torque", "rpm", "axial_velocity"),
            "figure_of_merit": ("thrust", "torque", "rpm", "radius", "density"),
            "tip_mach": ("rpm", "radius", "speed_of_sound"),
            "helical_tip_mach": ("rpm", "radius", "speed_of_sound", "axial_velocity"),
        }
        for of, wrts in deps.items():
            for wrt in wrts:
                cols = (
                    ar // nn
                    if wrt == "radius"
                    else (ar % nn if wrt in ("density", "speed_of_sound") else ar)
                )
                self.declare_partials(of, wrt, rows=ar, cols=cols)
        if edgewise:
            self.declare_partials(
                "helical_tip_mach",
                "inplane_velocity",
                rows=np.repeat(ar, 2),
                cols=np.arange(2 * nr * nn),
            )

    def _helical(self, v, inputs):
        """Helical tip Mach number and its pieces: (M, w = Omega R + abs(V_ip), U, abs(V_ip))."""
        if self.options["edgewise"]:
            vip = inputs["inplane_velocity"]
            speed_ip = np.sqrt(np.sum(vip * vip, axis=-1))
        else:
            speed_ip = np.zeros_like(v["omega"])
        w = v["omega"] * v["R"] + speed_ip
        u = np.sqrt(v["vx"] * v["vx"] + w * w)
        return u / v["a"], w, u, speed_ip

    def _values(self, inputs):
        rpm = inputs["rpm"]
        for name, units in (
            ("rpm", "rpm"),
            ("radius", "m"),
            ("density", "kg/m**3"),
            ("speed_of_sound", "m/s"),
        ):
            check_range(
                name,
                inputs[name],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        v = {
            "T": inputs["thrust"],
            "Q": inputs["torque"],
            "rpm": rpm,
            "vx": inputs["axial_velocity"],
            "R": inputs["radius"][:, None],
            "rho": inputs["density"][None, :],
            "a": inputs["speed_of_sound"][None, :],
        }
        v["n"] = rpm / 60.0
        v["omega"] = _RPM_TO_RAD_S * rpm
        v["D"] = 2.0 * v["R"]
        v["P"] = v["omega"] * v["Q"]
        if np.any(v["P"].real == 0.0):
            raise om.AnalysisError(
                f"{self.msginfo}: input 'torque' = {v['Q'].real.tolist()} "
                "N*m; zero torque (zero power) leaves the efficiency and "
                "figure of merit undefined."
            )
        v["sqrt_abs_T"] = np.sqrt(v["T"] * np.sign(v["T"].real))
        v["k_fom"] = 1.0 / (np.sqrt(2.0 * np.pi * v["rho"]) * v["R"])
        return v

    def compute(self, inputs, outputs):
        v = self._values(inputs)
        n, d_, rho = v["n"], v["D"], v["rho"]
        outputs["power"] = v["P"]
        outputs["thrust_coefficient"] = v["T"] / (rho * n**2 * d_**4)
        outputs["power_coefficient"] = v["P"] / (rho * n**3 * d_**5)
        outputs["advance_ratio"] = v["vx"] / (n * d_)
        outputs["efficiency"] = v["T"] * v["vx"] / v["P"]
        outputs["figure_of_merit"] = v["k_fom"] * v["T"] * v["sqrt_abs_T"] / v["P"]
        outputs["tip_mach"] = v["omega"] * v["R"] / v["a"]
        outputs["helical_tip_mach"] = self._helical(v, inputs)[0]

    def compute_partials(self, inputs, partials):
        v = self._values(inputs)
        nr, nn = self.options["num_rotors"], self.options["num_nodes"]
        shape = (nr, nn)
        t, q, rpm, vx = v["T"], v["Q"], v["rpm"], v["vx"]
        big_r, rho, a, n, d_, omega, p = (v[k] for k in ("R", "rho", "a", "n", "D", "omega", "P"))
        dp_drpm = _RPM_TO_RAD_S * q

        def put(of, wrt, value):
            partials[of, wrt] = np.broadcast_to(value, shape).ravel()

        put("power", "torque", omega)
        put("power", "rpm", dp_drpm)

        ct = t / (rho * n**2 * d_**4)
        put("thrust_coefficient", "thrust", 1.0 / (rho * n**2 * d_**4))
        put("thrust_coefficient", "rpm", -2.0 * ct / rpm)
        put("thrust_coefficient", "radius", -4.0 * ct / big_r)
        put("thrust_coefficient", "density", -ct / rho)

        cp = p / (rho * n**3 * d_**5)
        put("power_coefficient", "torque", omega / (rho * n**3 * d_**5))
        put("power_coefficient", "rpm", -2.0 * cp / rpm)
        put("power_coefficient", "radius", -5.0 * cp / big_r)
        put("power_coefficient", "density", -cp / rho)

        j = vx / (n * d_)
        put("advance_ratio", "axial_velocity", 1.0 / (n * d_))
        put("advance_ratio", "rpm", -j / rpm)
        put("advance_ratio", "radius", -j / big_r)

        put("efficiency", "thrust", vx / p)
        put("efficiency", "axial_velocity", t / p)
        put("efficiency", "torque", -t * vx * omega / p**2)
        put("efficiency", "rpm", -t * vx * dp_drpm / p**2)

        k = v["k_fom"]
        t15 = t * v["sqrt_abs_T"]
        fom = k * t15 / p
        put("figure_of_merit", "thrust", 1.5 * k * v["sqrt_abs_T"] / p)
        put("figure_of_merit", "torque", -k * t15 * omega / p**2)
        put("figure_of_merit", "rpm", -k * t15 * dp_drpm / p**2)
        put("figure_of_merit", "radius", -fom / big_r)
        put("figure_of_merit", "density", -0.5 * fom / rho)

        put("tip_mach", "rpm", _RPM_TO_RAD_S * big_r / a)
        put("tip_mach", "radius", omega / a)
        put("tip_mach", "speed_of_sound", -omega * big_r / a**2)

        mach, w, u, speed_ip = self._helical(v, inputs)
        dm_dw = w / (u * a)
        put("helical_tip_mach", "rpm", dm_dw * _RPM_TO_RAD_S * big_r)
        put("helical_tip_mach", "radius", dm_dw * omega)
        put("helical_tip_mach", "axial_velocity", vx / (u * a))
        put("helical_tip_mach", "speed_of_sound", -mach / a)
        if self.options["edgewise"]:
            # dabs(V_ip)/dV_ip = V_ip/abs(V_ip); at abs(V_ip) = 0 (hover) the subgradient 0.
            safe = np.where(np.real(speed_ip) > 0.0, speed_ip, 1.0)
            unit = np.where(
                (np.real(speed_ip) > 0.0)[..., None],
                inputs["inplane_velocity"] / safe[..., None],
                0.0,
            )
            partials["helical_tip_mach", "inplane_velocity"] = (dm_dw[..., None] * unit).ravel()
