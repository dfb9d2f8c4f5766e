"""Studies built on the full model: the structural sizing subproblem (paper Tables 4-5)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.mpi import serial_comm
from lpc_mdo.drivers import make_driver
from lpc_mdo.groups.lpc import LPCGroup, openmdao_units
from lpc_mdo.problems import attach_recorder, conditions_of_kinds, trim_constraints
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.condition_kinds import StructuralKind
from lpc_mdo.vehicle.condition_layout import condition_layout

THICKNESSES = (
    "front_spar_thickness",
    "rear_spar_thickness",
    "top_skin_thickness",
    "bottom_skin_thickness",
)


def structural_sizing_problem(
    vehicle=None,
    aggregated=False,
    ks_rho=50.0,
    optimizer="IPOPT",
    max_displacement=None,
    recorder_path=None,
    coupling="one_way",
    **model_options,
):
    """
    Build the paper's wing structural optimization (Table 4) as an OpenMDAO problem.

    Minimise the wing-box mass over the 32 skin and spar thicknesses (8 bays each) and the
    pitch angles of the vehicle's structural conditions (the reference: +3g and -1g), subject
    to their trim rows (z-force equilibrium) and,
    per case, skin buckling on all bays but the tip bay (top skin at +3g, bottom skin at -1g),
    von Mises stress at the 5 recovery points of every element <= the allowable, and the
    vertical displacement of every node <= the limit; with ``aggregated`` each of the three
    failure sets is one KS constraint per case (paper eq. 7). One-way coupled: the VLM loads the
    beam; two-way: the beam also deforms the VLM wing mesh (block Gauss-Seidel per case).

    Parameters
    ----------
    vehicle : Vehicle or None
    aggregated : bool
        KS-aggregate buckling, stress and displacement (8 constraints instead of 114).
    ks_rho : float
        KS parameter of the aggregates.
    optimizer : str
        Passed to :func:`lpc_mdo.drivers.make_driver`.
    max_displacement : float or None
        Displacement limit, m (None: the vehicle file's ``constraints.max_displacement``).
    recorder_path : str or None
        Case file for the driver and the final problem case.
    coupling : str
        'one_way' or 'two_way'.
    **model_options
        Further LPCGroup options (e.g. ``rotor_polar``).

    Returns
    -------
    om.Problem
        Set up, not run.
    """
    vehicle = vehicle or reference_vehicle()
    prob = om.Problem(reports=False, comm=serial_comm())
    structural = conditions_of_kinds(vehicle, ["structural"])
    prob.model = model = LPCGroup(
        vehicle=vehicle,
        conditions=structural,
        structural_ks_rho=ks_rho if aggregated else None,
        structural_coupling=coupling,
        **model_options,
    )
    prob.driver = make_driver(optimizer)
    prob.driver.recording_options["includes"] = ["wing_mass"]
    if recorder_path is not None:
        attach_recorder(prob, recorder_path)
    limits = vehicle.constraints
    max_w = limits.max_displacement if max_displacement is None else max_displacement
    material = vehicle.material

    for name in THICKNESSES:
        dv = vehicle.design_variables[name]
        model.add_design_var(
            name, lower=material.min_gauge, upper=np.asarray(dv.upper_array), ref=1e-3, units="m"
        )
    model.add_objective("wing_mass", ref=100.0, units="kg")
    bays = list(range(vehicle.wing_box.num_bays - 1))
    layout = condition_layout(vehicle)
    for name in structural:
        condition = vehicle.condition(name)
        for entry in layout.entries[name].values():
            dv = vehicle.design_variables[entry.design_variable]
            model.add_design_var(
                entry.design_variable,
                lower=dv.lower_array,
                upper=dv.upper_array,
                ref=dv.ref,
                units=openmdao_units(dv.units),
            )
        for output, indices, targets, ref in trim_constraints(vehicle, condition):
            model.add_constraint(
                f"{name}.{output}", indices=indices, flat_indices=True, equals=targets, ref=ref
            )
        skin = StructuralKind.compressed_skin(condition)
        if aggregated:
            model.add_constraint(
                f"{name}.{skin}_skin_buckling_ratio_ks", upper=limits.max_buckling_ratio
            )
            model.add_constraint(f"{name}.stress_ratio_ks", upper=1.0)
            model.add_constraint(f"{name}.displacement_ks", upper=max_w, ref=0.1, units="m")
        else:
            model.add_constraint(
                f"{name}.{skin}_skin_buckling_ratio",
                indices=bays,
                flat_indices=True,
                upper=limits.max_buckling_ratio,
            )
            model.add_constraint(f"{name}.stress_ratio", upper=1.0)
            # Every node but the clamped root (whose displacement is identically zero).
            model.add_constraint(
                f"{name}.displacements",
                indices=om.slicer[1:, 2],
                lower=-max_w,
                upper=max_w,
                ref=0.1,
                units="m",
            )
    prob.setup(mode="rev")
    return prob
