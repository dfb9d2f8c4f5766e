"""Load a script of run_scripts/ as a module, for the tests that call its functions."""

import importlib.util
from pathlib import Path

RUN_SCRIPTS = Path(__file__).resolve().parents[1] / "run_scripts"


def load_run_script(name):
    """Return the module of ``run_scripts/<name>.py``, executed once."""
    spec = importlib.util.spec_from_file_location(name, RUN_SCRIPTS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
