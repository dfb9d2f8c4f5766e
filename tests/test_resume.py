"""A run killed with kill -9 can be resumed from its last recorded iteration (--start-case)."""

import os
import signal
import sqlite3
import subprocess
import sys
import time

import numpy as np
import openmdao.api as om
import pytest

from lpc_mdo import warm_start
from lpc_mdo.cli import main
from lpc_mdo.run_lock import LOCK_NAME
from lpc_mdo.vehicle import reference_vehicle

pytestmark = pytest.mark.integration


def _driver_cases(path):
    try:
        with sqlite3.connect(f"file:{path}?mode=ro", uri=True) as con:
            return con.execute("SELECT COUNT(*) FROM driver_iterations").fetchone()[0]
    except sqlite3.Error:
        return 0


@pytest.fixture(scope="module")
def killed_run(tmp_path_factory):
    """Return the folder and case file of a rotor presizing killed after 3 iterations."""
    out = tmp_path_factory.mktemp("killed")
    case_file = out / "rotor_presizing.sql"
    argv = ["optimize", "--problem", "rotor_presizing", "--optimizer", "SLSQP", "--quiet"]
    run = subprocess.Popen(
        [sys.executable, "-m", "lpc_mdo.cli", *argv, "--output-dir", str(out)],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    deadline = time.monotonic() + 300
    while _driver_cases(case_file) < 3 and run.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    os.kill(run.pid, signal.SIGKILL)
    run.wait()
    assert run.returncode == -signal.SIGKILL, "the run ended before it could be killed"
    return out, case_file


def test_the_killed_run_left_no_final_case_and_a_stale_lock(killed_run):
    out, case_file = killed_run
    reader = om.CaseReader(str(case_file))
    assert "final" not in reader.list_cases("problem", recurse=False, out_stream=None)
    assert len(reader.list_cases("driver", recurse=False, out_stream=None)) >= 3
    assert (out / LOCK_NAME).exists()  # its process is gone: the next run takes it over


def test_a_start_from_it_resumes_at_its_last_iteration(killed_run, tmp_path):
    _, case_file = killed_run
    vehicle = reference_vehicle()
    case, label = warm_start.start_point(case_file, vehicle)
    names = om.CaseReader(str(case_file)).list_cases("driver", recurse=False, out_stream=None)
    assert label.startswith(f"driver iteration {len(names)} of {len(names)}")
    lines = []
    resumed = tmp_path / "resumed.sql"
    warm_start.solve_stage(
        "rotor_presizing",
        str(resumed),
        vehicle=vehicle,
        start_case=str(case_file),
        optimizer="SLSQP",
        driver_settings={"max_iter": 1},
        trim_first=False,
        log=lines.append,
    )
    assert lines[0] == f"rotor_presizing: starts from {case_file}, {label}"
    first = om.CaseReader(str(resumed)).get_case(0)  # the resumed run's first evaluation
    for name in vehicle.design_variables:
        np.testing.assert_allclose(first.get_val(name), case.get_val(name), rtol=1e-12)


def test_the_command_line_accepts_it_as_a_start(killed_run, monkeypatch, tmp_path):
    _, case_file = killed_run
    from lpc_mdo import cli

    monkeypatch.setattr(cli, "_optimize", lambda args: 0)  # the check only, no second run
    argv = ["optimize", "--problem", "full", "--start-case", str(case_file)]
    assert main([*argv, "--output-dir", str(tmp_path / "next")]) == 0
