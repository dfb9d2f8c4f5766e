"""Blade-station angle of attack over the section's stall angle: how close each is to stall."""

import numpy as np
import openmdao.api as om

from .bem_inflow import _RPM_TO_RAD_S, add_section_inputs, station_flow

#: The BEM section inputs that fix a station's Reynolds and Mach numbers.
_FLOW_INPUTS = (
    "rpm",
    "axial_velocity",
    "station_radius",
    "chord",
    "density",
    "speed_of_sound",
    "dynamic_viscosity",
)


class BladeStallRatioComp(om.ExplicitComponent):
    """
    Each blade station's angle of attack over its section's positive and negative stall angles.

    For station j of rotor i at node k, with the blade-element angle of attack alpha_ikj (output
    of :class:`~lpc_mdo.components.rotor.bem_loads.BEMLoadsComp`) and the polar's stall angles
    at the station's chord Reynolds and Mach numbers
    (:meth:`~lpc_mdo.components.aero.airfoil.TablePolar.stall_angles`):

        r^+ = alpha / alpha_s+(Re, M),    r^- = alpha / alpha_s-(Re, M)   (alpha_s- < 0),

    Re = rho U c / mu, M = U / a with the undisturbed resultant U = sqrt(V_x^2 + (Omega r)^2), as
    the BEM's polar lookup takes them (docs theory/rotors 'Stations and disk frame'). r^+ reaches
    1 where a station reaches its positive stall, r^- its negative one. The ratio is of angles,
    not lift coefficients: past the stall the polar's c_l falls again (Viterna), so a c_l ratio
    could not tell a stalled station from an attached one; for the symmetric rotor section
    (zero-lift angle 0) r^+ equals c_l / c_l,max in the linear range. The stall angles are the
    table's stall points, moved down to the measured compressibility stall where the section
    has one (:mod:`~lpc_mdo.components.aero.compressible_stall`; docs theory/rotors 'Blade stall
    limit').

    Inputs
    ------
    angle_of_attack : float, (nr, nn, nrad)
        Blade-element angle of attack, rad.
    rpm, axial_velocity : float, (nr, nn)
        Rotor speed and the freestream through the disk along the thrust axis.
    station_radius, chord : float, (nr, nrad)
        Station radius and chord.
    density, speed_of_sound, dynamic_viscosity : float, (nn,)
        Air at each node.

    Outputs
    -------
    blade_stall_ratio : float, (1, 2 nr nn nrad)
        r^+ of every station (rotor, node, station order), then r^- of every station.

    Options
    -------
    num_rotors, num_nodes, num_radial : int
        nr, nn, nrad.
    polar : Polar
        The blade section; it must give ``stall_angles(reynolds, mach)`` (a
        :class:`~lpc_mdo.components.aero.airfoil.TablePolar`).
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="rotors")
        self.options.declare("num_nodes", default=1, types=int, lower=1, desc="operating points")
        self.options.declare("num_radial", default=25, types=int, lower=1, desc="radial stations")
        self.options.declare("polar", desc="blade-section polar with stall_angles(Re, M)")

    def setup(self):
        opts = self.options
        nr, nn, nrad = opts["num_rotors"], opts["num_nodes"], opts["num_radial"]
        if not callable(getattr(opts["polar"], "stall_angles", None)):
            raise ValueError(
                f"{self.msginfo}: option 'polar' = {opts['polar']!r} has no stall_angles(Re, M); "
                "allowed: a TablePolar (an airfoil name or table, see get_polar)"
            )
        self._shape = shape = (nr, nn, nrad)
        size = nr * nn * nrad
        self.add_input("angle_of_attack", val=np.zeros(shape), units="rad",
                       desc="Blade-element angle of attack")  # fmt: skip
        add_section_inputs(self, nr, nn, nrad, names=_FLOW_INPUTS)
        self.add_output(
            "blade_stall_ratio",
            val=np.zeros((1, 2 * size)),
            desc="alpha / alpha_stall+ of every station, then alpha / alpha_stall-",
        )

        station = np.arange(size).reshape(shape)
        rows = np.concatenate([station.ravel(), size + station.ravel()])
        cols = {
            "angle_of_attack": station,
            "rpm": np.broadcast_to((np.arange(nr)[:, None] * nn + np.arange(nn))[..., None], shape),
            "axial_velocity": None,
            "station_radius": np.broadcast_to(
                (np.arange(nr)[:, None] * nrad + np.arange(nrad))[:, None, :], shape
            ),
            "chord": None,
            "density": np.broadcast_to(np.arange(nn)[None, :, None], shape),
            "speed_of_sound": None,
            "dynamic_viscosity": None,
        }
        cols["axial_velocity"] = cols["rpm"]
        cols["chord"] = cols["station_radius"]
        cols["speed_of_sound"] = cols["dynamic_viscosity"] = cols["density"]
        for name, col in cols.items():
            col = np.ravel(col)
            self.declare_partials("blade_stall_ratio", name, rows=rows,
                                  cols=np.concatenate([col, col]))  # fmt: skip

    def _flow(self, inputs):
        """V_t, V_x, U, Re and M at every station, (nr, nn, nrad) (bem_inflow.station_flow)."""
        vx = inputs["axial_velocity"][..., None]
        rho, a, mu = (inputs[n][None, :, None] for n in ("density", "speed_of_sound",
                                                        "dynamic_viscosity"))  # fmt: skip
        vt, u, re, mach = station_flow(
            inputs["rpm"][..., None], inputs["station_radius"][:, None, :], vx,
            inputs["chord"][:, None, :], rho, a, mu,
        )  # fmt: skip
        if np.any(np.real(u) <= 0.0):
            raise om.AnalysisError(
                f"{self.msginfo}: a blade station has no relative flow (rpm "
                f"{np.real(inputs['rpm']).tolist()}, axial velocity "
                f"{np.real(inputs['axial_velocity']).tolist()} m/s); its Reynolds and Mach "
                "numbers, and so its stall angle, are undefined."
            )
        return vt, vx, u, re, mach

    def compute(self, inputs, outputs):
        _, _, _, re, mach = self._flow(inputs)
        neg, pos, *_ = self.options["polar"].stall_angles(re, mach)
        alpha = inputs["angle_of_attack"]
        outputs["blade_stall_ratio"] = np.concatenate([(alpha / pos).ravel(),
                                                       (alpha / neg).ravel()])[None, :]  # fmt: skip

    def compute_partials(self, inputs, partials):
        vt, vx, u, re, mach = self._flow(inputs)
        neg, pos, dneg_dre, dpos_dre, dneg_dm, dpos_dm = self.options["polar"].stall_angles(
            re, mach
        )
        alpha = inputs["angle_of_attack"]
        chord = inputs["chord"][:, None, :]
        rho, a, mu = (inputs[n][None, :, None] for n in ("density", "speed_of_sound",
                                                        "dynamic_viscosity"))  # fmt: skip
        # dU of rpm, axial velocity and station radius; Re and M through U and the air.
        omega = _RPM_TO_RAD_S * inputs["rpm"][..., None]
        du = {
            "rpm": vt * _RPM_TO_RAD_S * inputs["station_radius"][:, None, :] / u,
            "axial_velocity": vx / u,
            "station_radius": vt * omega / u,
        }
        d_re = {n: re / u * v for n, v in du.items()}
        d_m = {n: v / a for n, v in du.items()}
        d_re.update(chord=rho * u / mu, density=u * chord / mu, dynamic_viscosity=-re / mu)
        d_m.update(speed_of_sound=-mach / a)
        for stall, dre, dm, half in ((pos, dpos_dre, dpos_dm, 0), (neg, dneg_dre, dneg_dm, 1)):
            factor = -alpha / stall**2  # d(alpha / alpha_s) / d alpha_s
            for name in ("rpm", "axial_velocity", "station_radius", "chord", "density",
                         "speed_of_sound", "dynamic_viscosity"):  # fmt: skip
                value = factor * (dre * d_re.get(name, 0.0) + dm * d_m.get(name, 0.0))
                self._set(partials, name, half, np.broadcast_to(value, self._shape))
            self._set(partials, "angle_of_attack", half, 1.0 / stall)

    def _set(self, partials, name, half, value):
        size = int(np.prod(self._shape))
        block = partials["blade_stall_ratio", name]
        if half == 0:
            block[:size] = np.ravel(value)
        else:
            block[size:] = np.ravel(value)
