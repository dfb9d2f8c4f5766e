"""Parameter sweeps: chains, vehicle changes, local-parallel and MPI runs (lpc_mdo.sweeps).

The paper's sweeps solve the full problem at every point (minutes each); these tests run the
same machinery on subproblem 4 (seconds each), which is what CI can afford.
"""

import csv
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from lpc_mdo.sweep_parameters import SWEEP_PARAMETERS, reference_value, sweep_vehicle
from lpc_mdo.sweeps import run_sweep, sweep_chains
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.warm_start import solve_stage

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration


def test_chains_start_at_the_reference_and_walk_outwards():
    values = SWEEP_PARAMETERS["energy_density"][2]
    assert sweep_chains(values, 400.0, 1) == [[400.0, 350.0, 300.0, 250.0], [450.0]]
    # More workers: the longest chain is split (its second half starts from the start case).
    assert sweep_chains(values, 400.0, 3) == [[450.0], [400.0, 350.0], [300.0, 250.0]]
    assert sweep_chains([0.1, 0.3], 0.2, 4) == [[0.1], [0.3]]


def test_sweep_vehicle_changes_one_parameter():
    vehicle = reference_vehicle()
    changed = sweep_vehicle(vehicle, "energy_density", 250.0)
    assert changed.battery.energy_density == pytest.approx(250.0 * 3600.0)
    assert changed.constraints == vehicle.constraints
    assert sweep_vehicle(vehicle, "final_soc", 0.3).constraints.min_final_soc == 0.3
    # Each value within the vehicle file's range of its field, named by the file's key.
    with pytest.raises(ValueError, match=r"'constraints.min_final_soc' = 1.5 is out of range"):
        sweep_vehicle(vehicle, "final_soc", 1.5)
    with pytest.raises(ValueError, match=r"'battery.energy_density_wh_per_kg' = 1000000000.0 is"):
        sweep_vehicle(vehicle, "energy_density", 1e9)
    with pytest.raises(ValueError, match="allowed: \\['energy_density', 'final_soc', 'max_noise'"):
        sweep_vehicle(vehicle, "wing_area", 1.0)
    # The parameters of the post-optimal sensitivities, swept to check them by re-optimizing.
    assert sweep_vehicle(vehicle, "max_noise", 71.0).constraints.max_noise == 71.0
    assert sweep_vehicle(vehicle, "min_static_margin", 0.1).constraints.min_static_margin == 0.1
    assert sweep_vehicle(vehicle, "payload", 560.0).masses.payload == 560.0
    with pytest.raises(ValueError, match=r"'masses.payload' = -1.0 is out of range"):
        sweep_vehicle(vehicle, "payload", -1.0)
    with pytest.raises(ValueError, match=r"must be < 'masses.design_gross_mass'"):
        sweep_vehicle(vehicle, "payload", 5000.0)
    longer = sweep_vehicle(vehicle, "cruise_range", 80.0)
    cruise = next(c for c in longer.conditions if c.name == "cruise")
    assert cruise.duration * cruise.speed == pytest.approx(80_000.0)
    assert [c.name for c in longer.conditions] == [c.name for c in vehicle.conditions]
    assert reference_value(longer, "cruise_range") == pytest.approx(80.0)
    assert reference_value(vehicle, "cruise_range") == pytest.approx(57.1897 * 1210.04 / 1000)


def test_swept_parameters_reach_the_model():
    # The energy density of the vehicle file is the battery's specific energy (it was once left
    # at the component default, 400 Wh/kg, so an energy-density sweep changed nothing), and the
    # final-SoC limit is the SoC constraint's lower bound.
    import openmdao.api as om

    from lpc_mdo.groups.lpc import LPCGroup
    from lpc_mdo.problems import declare_problem

    base = reference_vehicle()
    vehicle = sweep_vehicle(sweep_vehicle(base, "energy_density", 300.0), "final_soc", 0.3)
    prob = om.Problem(LPCGroup(vehicle=vehicle, conditions=["cruise"]), reports=False)
    declare_problem(prob.model, vehicle)
    prob.setup()
    prob.run_model()
    mass = prob.get_val("battery_mass", units="kg")[0]
    assert prob.get_val("energy_capacity", units="W*h")[0] == pytest.approx(300.0 * mass, rel=1e-12)
    soc = prob.model.get_constraints()["state_of_charge"]
    assert soc["lower"] == pytest.approx(0.3)


@pytest.fixture(scope="module")
def start_case(tmp_path_factory):
    pytest.importorskip("cyipopt")
    path = tmp_path_factory.mktemp("start") / "subproblem_4.sql"
    stage = solve_stage(
        "subproblem_4", str(path), driver_settings={"print_level": 0}, log=lambda message: None
    )
    assert stage.success
    return str(path)


def read_summary(out):
    with open(out / "sweep_summary.csv", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def test_local_parallel_sweep(start_case, tmp_path):
    out = tmp_path / "sweep"
    points = run_sweep(
        str(out),
        start_case,
        parameters=("energy_density",),
        values={"energy_density": [350.0, 400.0, 450.0]},
        static_margins=(True,),
        processes=2,
        problem="subproblem_4",
        driver_settings={"print_level": 0},
    )
    assert sorted(p.value for p in points) == [350.0, 400.0, 450.0]
    assert all(p.success for p in points), [p.exit_status for p in points]
    rows = read_summary(out)
    assert [float(r["value"]) for r in rows] == [350.0, 400.0, 450.0]
    assert all(Path(r["case_file"]).exists() for r in rows)
    # 350 follows 400 in its chain (neighbour warm start); 450 starts its own chain.
    by_value = {float(r["value"]): r for r in rows}
    assert by_value[350.0]["start_case"] == by_value[400.0]["case_file"]
    assert by_value[450.0]["start_case"] == start_case
    assert (out / "sweep_energy_density.png").exists()


def test_failed_point_is_retried_and_reported(start_case, tmp_path):
    # One iteration cannot converge subproblem 4: the point is retried (two iterations) from
    # the start case, still fails, and stays in the summary as failed.
    out = tmp_path / "sweep"
    points = run_sweep(
        str(out),
        start_case,
        parameters=("final_soc",),
        values={"final_soc": [0.2]},
        static_margins=(False,),
        processes=1,
        problem="subproblem_4",
        driver_settings={"max_iter": 1, "print_level": 0},
    )
    assert len(points) == 1 and not points[0].success and points[0].retried
    assert read_summary(out)[0]["success"] == "False"


def test_mpi_sweep_on_two_ranks(start_case, tmp_path):
    pytest.importorskip("mpi4py")
    mpirun = shutil.which(
        "mpirun",
        path=os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")]),
    )
    if mpirun is None:
        pytest.skip("no mpirun (pip install 'lpc-mdo[mpi]')")
    env = dict(
        os.environ,
        OMPI_ALLOW_RUN_AS_ROOT="1",
        OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
        OPENBLAS_NUM_THREADS="1",
        OPENMDAO_REPORTS="0",
    )
    out = tmp_path / "mpi"
    cmd = [
        mpirun,
        "--oversubscribe",
        "-n",
        "2",
        sys.executable,
        "-m",
        "lpc_mdo.cli",
        "sweep",
        "--mpi",
        "--problem",
        "subproblem_4",
        "--parameter",
        "energy_density",
        "--values",
        "350",
        "450",
        "--static-margin",
        "on",
        "--start-case",
        start_case,
        "--output-dir",
        str(out),
    ]
    run = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=600)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    rows = read_summary(out)
    assert sorted(float(r["value"]) for r in rows) == [350.0, 450.0]
    assert all(r["success"] == "True" for r in rows)
