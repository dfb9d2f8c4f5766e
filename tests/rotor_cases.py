"""Shared rotor test cases: a two-rotor BEM problem and the APC Sport 14x13 propeller data."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.polar import LinearQuadraticPolar
from lpc_mdo.components.rotor.bem_inflow import BEMInflowComp
from lpc_mdo.components.rotor.bem_loads import BEMLoadsComp, RotorPerformanceComp

# Two rotors of different geometry, blade count and rpm; node 0 near hover, node 1 in climb.
RADIUS = np.array([1.524, 1.2])
HUB = np.array([0.2, 0.15])
BLADES = [2, 3]
NRAD = 6


def stations(num_radial=NRAD):
    eta = (np.arange(num_radial) + 0.5) / num_radial
    rh = HUB * RADIUS
    r = rh[:, None] + (RADIUS - rh)[:, None] * eta
    width = np.repeat(((RADIUS - rh) / num_radial)[:, None], num_radial, axis=1)
    return r, width


def bem_problem(polar=None, num_radial=NRAD, performance=True, mode="auto", **options):
    opts = dict(num_rotors=2, num_nodes=2, num_radial=num_radial, num_blades=BLADES, **options)
    if polar is not None:
        opts["polar"] = polar
    prob = om.Problem()
    prob.model.add_subsystem("inflow", BEMInflowComp(**opts), promotes=["*"])
    prob.model.add_subsystem("loads", BEMLoadsComp(**opts), promotes=["*"])
    if performance:
        prob.model.add_subsystem(
            "performance", RotorPerformanceComp(num_rotors=2, num_nodes=2), promotes=["*"]
        )
    prob.setup(mode=mode, force_alloc_complex=True)
    r, width = stations(num_radial)
    eta = np.linspace(0.0, 1.0, num_radial)
    prob.set_val("radius", RADIUS)
    prob.set_val("hub_radius", HUB * RADIUS)
    prob.set_val("station_radius", r)
    prob.set_val("station_width", width)
    prob.set_val("chord", np.stack([0.3 - 0.2 * eta, 0.2 - 0.12 * eta]))
    prob.set_val("twist", np.radians(np.stack([30.0 - 20.0 * eta, 45.0 - 25.0 * eta])))
    prob.set_val("rpm", [[1200.0, 1300.0], [1500.0, 1800.0]])
    prob.set_val("axial_velocity", [[0.0, 10.0], [2.0, 40.0]])
    prob.set_val("density", [1.2, 1.1])
    prob.set_val("speed_of_sound", [340.0, 336.0])
    prob.set_val("dynamic_viscosity", [1.8e-5, 1.7e-5])
    prob.run_model()
    return prob


# APC Sport 14x13, UIUC Propeller Data Site, as redistributed in LSDOlab/lsdo_rotor
# (shared/data/validation/APC_sport_14_13_*.txt, values unchanged).
# Geometry: r/R, c/R, beta (deg).
APC_GEOMETRY = np.array(
    [
        [0.15, 0.143, 37.64],
        [0.20, 0.140, 44.46],
        [0.25, 0.140, 47.79],
        [0.30, 0.140, 46.71],
        [0.35, 0.141, 43.63],
        [0.40, 0.143, 39.82],
        [0.45, 0.147, 36.06],
        [0.50, 0.150, 32.77],
        [0.55, 0.153, 29.99],
        [0.60, 0.155, 27.62],
        [0.65, 0.155, 25.54],
        [0.70, 0.152, 23.80],
        [0.75, 0.144, 22.25],
        [0.80, 0.131, 20.78],
        [0.85, 0.113, 19.56],
        [0.90, 0.088, 18.04],
        [0.95, 0.055, 16.00],
        [1.00, 0.021, 13.93],
    ]
)


# Performance: J, C_T, C_P, eta (two sweeps, rows 1-15 and 16-34).
APC_PERFORMANCE = np.array(
    [
        [0.179, 0.1205, 0.0749, 0.288],
        [0.206, 0.1185, 0.0735, 0.332],
        [0.234, 0.1180, 0.0737, 0.375],
        [0.266, 0.1170, 0.0739, 0.421],
        [0.293, 0.1147, 0.0734, 0.458],
        [0.324, 0.1152, 0.0748, 0.500],
        [0.355, 0.1137, 0.0753, 0.536],
        [0.385, 0.1121, 0.0760, 0.568],
        [0.414, 0.1100, 0.0764, 0.596],
        [0.440, 0.1080, 0.0768, 0.618],
        [0.473, 0.1045, 0.0768, 0.644],
        [0.499, 0.1017, 0.0767, 0.662],
        [0.533, 0.0979, 0.0764, 0.682],
        [0.557, 0.0950, 0.0762, 0.695],
        [0.587, 0.0903, 0.0752, 0.705],
        [0.499, 0.1016, 0.0766, 0.662],
        [0.528, 0.0984, 0.0765, 0.679],
        [0.563, 0.0938, 0.0758, 0.697],
        [0.587, 0.0904, 0.0752, 0.705],
        [0.621, 0.0849, 0.0736, 0.716],
        [0.649, 0.0804, 0.0720, 0.725],
        [0.674, 0.0759, 0.0702, 0.728],
        [0.701, 0.0713, 0.0681, 0.734],
        [0.740, 0.0641, 0.0644, 0.736],
        [0.769, 0.0587, 0.0613, 0.736],
        [0.793, 0.0536, 0.0582, 0.731],
        [0.824, 0.0474, 0.0547, 0.714],
        [0.858, 0.0404, 0.0500, 0.693],
        [0.885, 0.0347, 0.0460, 0.668],
        [0.912, 0.0292, 0.0421, 0.632],
        [0.945, 0.0223, 0.0368, 0.572],
        [0.971, 0.0171, 0.0321, 0.517],
        [1.005, 0.0093, 0.0253, 0.370],
        [1.031, 0.0040, 0.0203, 0.201],
    ]
)


#: Thin-airfoil-like polar for the APC blade: the thin-airfoil slope 2 pi, cl0 = 0.30
#: (alpha_L0 = -2.7 deg, thin-airfoil theory for about 3 % camber), a low-Reynolds profile drag
#: cd0 = 0.028 (QPROP's default for propellers near Re = 1e5) and otherwise
#: docs theory/aerodynamics 'Linear-quadratic polar' polar (stall at -10 and 15 deg, stall drag
#: 0.012 and 0.052 above cd0).
APC_POLAR = LinearQuadraticPolar(cl0=0.30, cl_alpha=2.0 * np.pi, cd0=0.028, cd_stall=(0.040, 0.080))
