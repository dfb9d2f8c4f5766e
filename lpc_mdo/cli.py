"""Command-line interface: ``lpc-mdo analyze | optimize | sweep | report``.

A user error (an argument, a vehicle file, a case file or an output path that cannot work) ends
the command with one line on stderr, ``lpc-mdo: error: <message>``, and exit code 2, before any
model is built: the message names the argument, its value and what is allowed (the form of
:mod:`lpc_mdo.core.checks`). ``--debug`` adds the traceback. An unexpected exception, a bug, still
prints its traceback, followed by one line asking for a report, and exits with code 1.

``lpc-mdo analyze`` trims every design condition by its trim variables (``--no-trim``: the raw
initial design, said so in its header). A condition whose largest scaled trim residual stays at
or above :data:`lpc_mdo.analysis.TRIM_TOLERANCE` (0.1 % of the weight) is named in the summary
and on stderr, and the command exits with code 1 after writing its case file and tables.
"""

import argparse
import contextlib
import errno
import os
import sqlite3
import sys
import tempfile
import tomllib
import traceback
from pathlib import Path

import numpy as np
import openmdao.api as om

from lpc_mdo import drivers, study_plan, warm_start
from lpc_mdo.analysis import (
    TRIM_TOLERANCE,
    airframe_lift_drag,
    analyze_vehicle,
    format_drag_breakdown,
    format_mass_table,
    format_static_margin_budget,
    format_trim_variables,
    lift_to_drag,
    status_tolerances,
)
from lpc_mdo.api.weights import format_mass_breakdown, mass_breakdown
from lpc_mdo.core.checks import check_choice, check_integer, check_number, cut_text
from lpc_mdo.post.mission_table import format_mission
from lpc_mdo.post.report import _CASE_SUFFIXES, ReportSpec, find_case_files, write_report
from lpc_mdo.post.stall import format_stall_speed_check
from lpc_mdo.post.statistics import run_stats_path
from lpc_mdo.post.tables import (
    DEFAULT_TOL,
    constraint_rows,
    constraint_summary,
    constraint_table,
    entry_status,
    format_constraint_status,
    status_word,
)
from lpc_mdo.problems import CONSTRAINT_KINDS
from lpc_mdo.progress import interrupt_message
from lpc_mdo.run_lock import LOCK_NAME, FolderInUse, LockFailed, folder_lock
from lpc_mdo.sensitivities import sensitivities_from_case, sensitivities_path
from lpc_mdo.sizing import SizingError, size_vehicle, sized_vehicle_text
from lpc_mdo.sweep_parameters import (
    LIMIT_CONSTRAINT_KINDS,
    PAPER_SWEEPS,
    SWEEP_PARAMETERS,
    reference_value,
    sweep_vehicle,
)
from lpc_mdo.sweeps import point_case_file, run_sweep
from lpc_mdo.vehicle import VehicleSpecError, load_vehicle
from lpc_mdo.vehicle.condition_contract import condition_kind
from lpc_mdo.vehicle.sections import SURFACE_NAMES

#: Exit code of a user error (as argparse's own), of a bug, and of Ctrl-C.
EXIT_USER_ERROR, EXIT_BUG, EXIT_INTERRUPTED = 2, 1, 130
#: A write into the output folder failed (full disk, read-only file system).
EXIT_WRITE_ERROR = 1
#: A model raised om.AnalysisError outside an optimization (its range left at this design).
EXIT_ANALYSIS_ERROR = 1
#: How far (as a fraction of its range) a start case's design variable may lie outside the
#: bounds: the optimizers' own feasibility tolerances, not a different problem.
START_BOUND_SLACK = 0.01

#: Characters of a value (a path, a word) an error message shows: a longer one is cut, with its
#: length, so that the message stays one short line.
SHOWN_CHARACTERS = 200
#: Most values ``lpc-mdo sweep --values`` takes: each is an optimization of the full problem
#: (minutes to hours), and more than this is a mistake rather than a study.
MAX_SWEEP_VALUES = 1000

SQLITE_MAGIC = b"SQLite format 3\x00"
#: Tables every OpenMDAO SqliteRecorder file has.
RECORDER_TABLES = ("metadata", "driver_iterations", "problem_cases", "global_iterations")
CASE_FILE_TEXT = (
    "an OpenMDAO case file (SQLite) written by lpc-mdo optimize or analyze, "
    "e.g. optimize_out/full.sql"
)


class CLIError(Exception):
    """A user error of the command line (the message names the argument, value and allowed)."""


def _shown(text):
    """``repr`` of a path or word for a message, cut to :data:`SHOWN_CHARACTERS` if longer."""
    return cut_text(os.fspath(text), SHOWN_CHARACTERS)


def _values_text(values):
    """Return the numbers of ``--values`` for a message (a long list: its first and its count)."""
    if len(values) <= 5:
        return " ".join(f"{v:g}" for v in values)
    return " ".join(f"{v:g}" for v in values[:3]) + f" ... ({len(values)} values)"


class _Parser(argparse.ArgumentParser):
    """An ArgumentParser whose errors are :class:`CLIError` (one line, no usage block)."""

    def parse_known_args(self, args=None, namespace=None):
        """Parse as argparse does, keeping the arguments for :meth:`error` (also a command's)."""
        self._arguments = list(sys.argv[1:] if args is None else args)
        return super().parse_known_args(args, namespace)

    def parse_args(self, args=None, namespace=None):
        """Parse as argparse does; name at most three unrecognized arguments, each cut."""
        parsed, extras = self.parse_known_args(args, namespace)
        if extras:
            shown = ", ".join(_shown(text) for text in extras[:3])
            more = f" and {len(extras) - 3} more" if len(extras) > 3 else ""
            self.error(f"unrecognized arguments: {shown}{more}")
        return parsed

    def error(self, message):
        """Raise the parse error as a CLIError; :func:`main` prints it as one line.

        argparse puts an offending value into its message in full ('invalid choice: <value>'):
        a long one is cut here.
        """
        for text in sorted(set(getattr(self, "_arguments", ())), key=len, reverse=True):
            if len(text) > SHOWN_CHARACTERS and text in message:
                message = message.replace(repr(text), _shown(text)).replace(text, _shown(text))
        raise CLIError(f"{message} (see '{self.prog} --help')")


# ------------------------------------------------------------------------------------------------
# argparse type= validators: each names its argument and raises CLIError.


def _integer(flag, lower, upper=None):
    """Return an argparse type: an integer in [``lower``, ``upper``]."""

    def parse(text):
        try:
            value = int(text)
        except ValueError:
            value = text
        return check_integer(flag, value, lower=lower, upper=upper, error=CLIError)

    parse.__name__ = "integer"
    return parse


def _finite_float(flag, **bounds):
    """Return an argparse type: a finite number (within ``bounds``, as check_number takes)."""

    def parse(text):
        try:
            value = float(text)
        except ValueError:
            value = text
        return check_number(flag, value, error=CLIError, **bounds)

    parse.__name__ = "number"
    return parse


def _existing(flag, what, folder_ok=False):
    """Return an argparse type: a path that exists (a file, or also a folder if ``folder_ok``)."""

    def parse(text):
        if not text:
            raise CLIError(f"'{flag}' = '' is empty: must be {what}")
        path = Path(text)
        try:
            exists, is_dir = path.exists(), path.is_dir()
        except OSError as err:
            raise CLIError(
                f"'{flag}' = {_shown(text)} cannot be read ({err.strerror}): must be {what}"
            ) from err
        if not exists and os.path.islink(text):
            raise CLIError(
                f"'{flag}' = {_shown(text)} is a symbolic link that leads nowhere (a broken link "
                f"or a loop): must be {what}"
            )
        if not exists:
            raise CLIError(f"'{flag}' = {_shown(text)} does not exist: must be {what}")
        if text.endswith(("/", os.sep)) and not is_dir:
            raise CLIError(
                f"'{flag}' = {_shown(text)} ends with '/', but it names a file, not a folder: "
                f"must be {what} (without the trailing '/')"
            )
        if is_dir and not folder_ok:
            raise CLIError(f"'{flag}' = {_shown(text)} is a folder: must be {what}")
        if not is_dir and not path.is_file():  # a pipe or device would block the read
            raise CLIError(f"'{flag}' = {_shown(text)} is not a regular file (a pipe or device): "
                           f"must be {what}")  # fmt: skip
        if not is_dir and not os.access(path, os.R_OK):
            raise CLIError(f"'{flag}' = {_shown(text)} is not readable: must be {what}")
        return text

    parse.__name__ = "path"
    return parse


def optimizer_problem(name):
    """
    Say why an optimizer cannot run here, or return None if it can.

    Parameters
    ----------
    name : str
        ``'IPOPT'``, ``'SNOPT'`` or ``'SLSQP'``.

    Returns
    -------
    str or None
        What is missing and what to install.
    """
    if name == "SLSQP" or name in drivers.pyoptsparse_optimizers():
        return None
    if name == "SNOPT":
        return (
            "SNOPT is reached only through pyoptsparse built with SNOPT, which is not importable "
            "here (SNOPT is licensed: build pyoptsparse with your SNOPT source, e.g. OpenMDAO's "
            "build_pyoptsparse), or use IPOPT (pip install 'lpc-mdo[ipopt]') or SLSQP"
        )
    try:  # optional dependency, imported only to see whether it is there
        import cyipopt  # noqa: F401
    except ImportError:
        return (
            "IPOPT needs cyipopt (pip install 'lpc-mdo[ipopt]', or conda-forge cyipopt) or "
            "pyoptsparse with IPOPT, neither of which is importable here; or use SLSQP"
        )
    return None


def _optimizer(flag):
    """Return an argparse type: an optimizer name (any case) that can run here."""

    def parse(text):
        name = check_choice(flag, text.upper(), drivers.KNOWN_OPTIMIZERS, error=CLIError)
        missing = optimizer_problem(name)
        if missing:
            raise CLIError(f"'{flag}' = {_shown(text)} is not available: {missing}")
        return name

    parse.__name__ = "optimizer"
    return parse


# ------------------------------------------------------------------------------------------------
# Checks of paths and files, run before any model is built.


def _folder_problem(folder):
    """Say why files cannot be written into a folder (created if missing), or return None.

    The text follows the folder's name: ``is a file, not a folder``, ``cannot be created: ...``,
    ``is not writable: ...``.
    """
    target = Path(folder).absolute()
    existing = target
    try:
        if target.exists() and not target.is_dir():
            return "is a file, not a folder"
        while not existing.exists():
            existing = existing.parent
        if not existing.is_dir():
            kind = "a regular file" if existing.is_file() else "a pipe, socket or device"
            return f"cannot be created: {_shown(existing)} is {kind}, not a folder"
        # The one reliable test (os.access says yes to root on a read-only folder).
        with tempfile.TemporaryFile(dir=existing, prefix=".lpc-mdo-write-test-"):
            pass
    except OSError as err:
        if existing == target:
            return f"is not writable: {err.strerror}"
        return f"cannot be created: {_shown(existing)} is not writable: {err.strerror}"
    return None


def check_output_folder(flag, path):
    """
    Check that a folder exists or can be created, and that files can be written into it.

    Parameters
    ----------
    flag : str
        The argument, for the message.
    path : str or os.PathLike
        The folder (not created here).

    Raises
    ------
    CLIError
        If the path is a file, lies under a regular file, or the folder (or the existing folder
        it would be created in) is not writable.
    """
    text = os.fspath(path)
    if not text.strip():
        problem = "is empty"
    elif os.path.islink(text) and not os.path.exists(text):
        problem = f"is a link to '{os.readlink(text)}', which does not exist"
    else:
        problem = _folder_problem(path)
    if problem:
        raise CLIError(
            f"'{flag}' = {_shown(path)} {problem}: must be a folder that exists or can be "
            "created, and is writable"
        )


def check_output_file(flag, path):
    """
    Check that a file can be written: not a folder, its folder exists or can be created.

    Parameters
    ----------
    flag : str
        The argument, for the message.
    path : str or os.PathLike
        The file.

    Raises
    ------
    CLIError
        If the path is a folder or another file that is not a regular one (a device, pipe or
        socket), or its folder cannot be created or written into.
    """
    text = os.fspath(path)
    target = Path(text).absolute()
    allowed = (
        "a file name (e.g. n2.html) in a folder that exists or can be created, and is writable"
    )
    try:
        is_dir = target.is_dir()
    except OSError as err:  # e.g. a name longer than the file system allows
        raise CLIError(
            f"'{flag}' = {_shown(text)} cannot be used ({err.strerror}): must be {allowed}"
        ) from err
    if is_dir:
        raise CLIError(f"'{flag}' = {_shown(text)} is a folder: must be {allowed}")
    if target.exists() and not target.is_file():  # writing it would block or fail at the end
        raise CLIError(
            f"'{flag}' = {_shown(text)} is not a regular file (a device, pipe or socket): "
            f"must be {allowed}"
        )
    problem = _folder_problem(target.parent)
    if problem:
        raise CLIError(
            f"'{flag}' = {_shown(text)}: its folder {_shown(target.parent)} {problem}: "
            f"must be {allowed}"
        )


def _sqlite_header_problem(path, size):
    """Say what is wrong with an SQLite file's header or size, or return None."""
    with open(path, "rb") as fh:
        header = fh.read(100)
    if len(header) < 100 or not header.startswith(SQLITE_MAGIC):
        return None
    page_size = int.from_bytes(header[16:18], "big")
    page_size = 65536 if page_size == 1 else page_size
    pages = int.from_bytes(header[28:32], "big")
    # The header's page count is valid when the "version-valid-for" number equals the change
    # counter (SQLite file format, section 1.3.7); the file then holds pages * page_size bytes.
    if page_size < 512 or size % page_size:
        return f"is truncated or damaged ({size} bytes, not whole pages of {page_size} bytes)"
    if header[24:28] == header[92:96] and size < pages * page_size:
        return f"is truncated ({size} bytes of the {pages * page_size} its header declares)"
    return None


def _not_sqlite_problem(path, head):
    """Say what a file that is not SQLite seems to be."""
    if not head:
        return "is empty (0 bytes)"
    try:
        text = Path(path).read_text(encoding="utf-8-sig")
        parsed = tomllib.loads(text)
    except (UnicodeDecodeError, tomllib.TOMLDecodeError):
        return f"is not an SQLite file (it starts with {head[:16]!r})"
    if parsed:
        return "is a TOML file (a vehicle file belongs to --vehicle), not an SQLite case file"
    return "is a text file, not an SQLite case file"


def open_case_file(flag, path, need_final=False, vehicle=None, given=None):
    """
    Check that a file is an OpenMDAO case file that holds what a command needs; open it.

    The checks, in order: an SQLite file (its first 16 bytes), not truncated (its size against
    the page count of its header), the tables of an OpenMDAO recorder, readable by
    ``om.CaseReader``, at least one case; with ``need_final`` the problem case ``'final'``
    (what :func:`lpc_mdo.warm_start.solve_stage` starts from); with ``vehicle`` that case holds
    the vehicle's design variables in their shapes.

    Parameters
    ----------
    flag : str
        The argument, for the message.
    path : str or os.PathLike
        The file.
    need_final : bool
        Require the problem case ``'final'``.
    vehicle : Vehicle or None
        Require design variables of this vehicle in the ``'final'`` case.
    given : str or None
        The folder the user gave, if ``path`` was found in it (for the message).

    Returns
    -------
    openmdao CaseReader
        The reader of the file.

    Raises
    ------
    CLIError
        Naming the argument, the file and what is wrong.
    """
    text = os.fspath(path)
    what = CASE_FILE_TEXT

    def fail(problem):
        named = f"{_shown(given)}: its case file {_shown(text)}" if given else _shown(text)
        return CLIError(f"'{flag}' = {named} {problem}: must be {what}")

    size = os.path.getsize(text)
    with open(text, "rb") as fh:
        head = fh.read(16)
    if head != SQLITE_MAGIC:
        raise fail(_not_sqlite_problem(text, head))
    problem = _sqlite_header_problem(text, size)
    if problem:
        raise fail(problem)
    try:
        uri = Path(text).absolute().as_uri() + "?mode=ro"
        with sqlite3.connect(uri, uri=True) as con:
            tables = {row[0] for row in con.execute("SELECT name FROM sqlite_master")}
        con.close()
    except sqlite3.Error as err:
        if "locked" in str(err):
            raise fail(
                "is locked by another process (a run still writing it?): wait until it ends"
            ) from err
        raise fail(f"is a damaged SQLite file ({err})") from err
    missing = [t for t in RECORDER_TABLES if t not in tables]
    if missing:
        listed = ", ".join(sorted(tables)) or "none"
        raise fail(f"is an SQLite database but not an OpenMDAO case file (its tables: {listed})")
    try:
        reader = om.CaseReader(text)
        problem_cases = reader.list_cases("problem", recurse=False, out_stream=None)
        driver_cases = reader.list_cases("driver", recurse=False, out_stream=None)
        final = reader.get_case("final") if "final" in problem_cases else None
    except Exception as err:  # noqa: BLE001 - any failure to read the user's file is this error
        raise fail(f"cannot be read by om.CaseReader ({type(err).__name__}: {err})") from err
    if not problem_cases and not driver_cases:
        raise fail("holds no cases (the run that wrote it recorded none)")
    if need_final and final is None:
        others = f" (problem cases: {', '.join(problem_cases)})" if problem_cases else ""
        if vehicle is None:
            raise fail(
                f"holds {len(driver_cases)} driver case(s) but not the problem case "
                f"'final'{others}, which a report reads (lpc-mdo records it when a run ends)"
            )
        try:  # an interrupted run: its last recorded iteration (warm_start.start_point)
            warm_start.start_point(text, vehicle)
        except ValueError as err:
            raise fail(
                f"holds {len(driver_cases)} driver case(s) but not the problem case "
                f"'final'{others}, and no iteration to resume from ({err})"
            ) from err
    if vehicle is not None and final is not None:
        found = 0
        for name, dv, value in _recorded_design_variables(final, vehicle):
            found += 1
            if np.size(value) != dv.size:
                raise fail(
                    f"holds design variable '{name}' with {np.size(value)} value(s) where the "
                    f"vehicle has {dv.size} (a run of another vehicle file?)"
                )
            if not np.all(np.isfinite(value)):
                raise fail(
                    f"holds design variable '{name}' with values that are not numbers (NaN or "
                    "inf): a run that failed, which no optimizer can start from"
                )
            units = None if dv.units == "unitless" else dv.units
            _within_bounds(fail, name, dv, final.get_val(name, units=units))
        if not found:
            raise fail(
                f"holds none of the vehicle's {len(vehicle.design_variables)} design variables "
                "(not an lpc-mdo run)"
            )
    return reader


def _recorded_design_variables(case, vehicle):
    """Yield (name, design variable, value) of each vehicle design variable ``case`` records."""
    for name, dv in vehicle.design_variables.items():
        try:
            value = case.get_val(name)
        except KeyError:
            continue
        yield name, dv, value


def _within_bounds(fail, name, dv, value):
    """Refuse start values outside a design variable's bounds by more than 1 % of its range."""
    value = np.ravel(value)
    lower, upper = np.ravel(dv.lower_array), np.ravel(dv.upper_array)
    slack = START_BOUND_SLACK * np.maximum(upper - lower, np.finfo(float).tiny)
    outside = (value < lower - slack) | (value > upper + slack)
    if np.any(outside):
        k = int(np.argmax(outside))
        raise fail(
            f"holds design variable '{name}' with entry {k} = {value[k]:.6g} {dv.units}, outside "
            f"the vehicle file's bounds [{lower[k]:.6g}, {upper[k]:.6g}] (a run of other bounds "
            "or another vehicle file?); allowed: a start inside the bounds"
        )


def load_vehicle_argument(flag, path):
    """
    Load and validate the vehicle file of an argument (None: the reference vehicle).

    Parameters
    ----------
    flag : str
        The argument, for the message.
    path : str or None
        The vehicle file.

    Returns
    -------
    Vehicle
        The validated vehicle.

    Raises
    ------
    VehicleSpecError
        For an invalid vehicle file (:func:`lpc_mdo.vehicle.load_vehicle`).
    CLIError
        For a file that is not text (e.g. a case file given as a vehicle file).
    """
    allowed = "a vehicle TOML file (UTF-8 text), e.g. a copy of lpc_mdo/data/lpc_reference.toml"
    if path is not None:
        with open(path, "rb") as fh:
            head = fh.read(16)
        if head == SQLITE_MAGIC:
            raise CLIError(
                f"'{flag}' = {_shown(path)} is an SQLite file (a case file belongs to "
                "--start-case): "
                f"must be {allowed}"
            )
    try:
        return load_vehicle(path)
    except VehicleSpecError as err:
        label = "the reference vehicle" if path is None else _shown(path)
        raise VehicleSpecError(f"'{flag}' = {label}: {err}") from err
    except UnicodeDecodeError as err:
        raise CLIError(
            f"'{flag}' = {_shown(path)} is not UTF-8 text (byte {err.start}): must be {allowed}"
        ) from err


def _preflight(args):
    """Check every path and file of the command before any model is built."""
    command = args.command
    if command == "sweep":
        _check_sweep_count(args)
    args.vehicle_spec = load_vehicle_argument("--vehicle", args.vehicle)
    check_output_folder("--output-dir", args.output_dir)
    inputs, written = _input_files(args), _files_written(args)
    if command == "analyze" and args.n2 is not None:
        _check_n2_file(args.n2, args.output_dir, inputs, written)
    for path in written:
        _not_an_input("--output-dir", path, inputs)
        _not_taken("--output-dir", args.output_dir, path)
    if command in ("optimize", "sweep"):
        if args.optimizer is None:  # a given --optimizer was checked by its type
            names = study_plan.SEQUENCE if args.problem == "sequence" else [args.problem]
            needed = {study_plan.default_optimizer(name) for name in names}
            for name in sorted(needed):
                missing = optimizer_problem(name)
                if missing:
                    raise CLIError(
                        f"'--optimizer' = None (the default: {name} for --problem "
                        f"{args.problem}) is not available: {missing}"
                    )
        if command == "sweep":
            _check_sweep_problem(args)
            _check_sweep_values(args)
            if args.mpi:
                _check_mpi_ranks()
        if args.start_case is not None:
            open_case_file(
                "--start-case", args.start_case, need_final=True, vehicle=args.vehicle_spec
            )
    if command == "report":
        given = f"--vehicle = {_shown(args.vehicle)}" if args.vehicle else "the reference vehicle"
        _check_report_cases(args.cases, args.vehicle_spec, given)


def _check_mpi_ranks():
    """``--mpi`` needs mpi4py and more than one MPI rank (a run under ``mpirun -n N``)."""
    try:  # optional dependency, imported only here
        from mpi4py import MPI
    except (ImportError, RuntimeError) as err:  # RuntimeError: mpi4py without an MPI library
        raise CLIError(
            "'--mpi' needs mpi4py, which is not importable here: must be run with "
            "mpi4py installed (pip install 'lpc-mdo[mpi]'), or use --processes N"
        ) from err
    if MPI.COMM_WORLD.size < 2:
        raise CLIError(
            "'--mpi' was given outside mpirun (1 MPI rank): must be started as "
            "'mpirun -n N lpc-mdo sweep ... --mpi' with N >= 2, or use --processes N"
        )


def _input_files(args):
    """Return the files a command reads: the vehicle file, its airfoil files, the start case."""
    files = {}
    if getattr(args, "vehicle", None):
        files["--vehicle"] = args.vehicle
    vehicle = args.vehicle_spec
    parts = [(f"lift_rotors[{i}]", rotor) for i, rotor in enumerate(vehicle.lift_rotors)]
    parts += [(name, getattr(vehicle, name)) for name in ("pusher", *SURFACE_NAMES)]
    for where, part in parts:
        if os.path.isfile(part.airfoil):  # a polar file (a name is a shipped table)
            files[f"{where}.airfoil of --vehicle"] = part.airfoil
        if getattr(part, "coordinates", None) is not None:
            files[f"{where}.coordinates of --vehicle"] = part.coordinates
    if getattr(args, "start_case", None):
        files["--start-case"] = args.start_case
    return files


def _no_option_before_the_command(parser, argv):
    """Refuse an option of a command given before it (argparse: 'invalid choice: <its value>')."""
    own = {flag for action in parser._actions for flag in action.option_strings}
    given = next((token for token in argv if token in parser.commands), None)
    for token in argv:
        if token in parser.commands or token == "--":
            return
        flag = token.split("=", 1)[0]
        if not flag.startswith("-") or flag in own:
            continue
        having = {}  # command -> its option that ``flag`` is (argparse takes a prefix too)
        for name, command in parser.commands.items():
            options = [o for action in command._actions for o in action.option_strings]
            found = [o for o in options if o == flag or (len(flag) > 2 and o.startswith(flag))]
            if len(found) == 1 or flag in found:
                having[name] = flag if flag in found else found[0]
        if having:
            name = given if given in having else next(iter(having))
            other = f"; {given} has no {having[name]}" if given and given not in having else ""
            raise CLIError(
                f"'{flag}' must come after the command: lpc-mdo {name} {having[name]} ... "
                f"(commands: {', '.join(parser.commands)}){other}"
            )


def _no_option_twice(argv):
    """Refuse an option given twice (argparse would keep the last one without a word)."""
    seen = set()
    for token in argv:
        if token == "--":
            break
        flag = token.split("=", 1)[0]
        if flag.startswith("--") and flag != "--debug":
            if flag in seen:
                raise CLIError(f"'{flag}' is given twice: must be given once")
            seen.add(flag)


def _check_n2_file(text, output_dir, inputs, written):
    """``--n2``: a new HTML file, not ``output_dir``, none of the ``inputs`` or ``written``."""
    allowed = "must be a file name, e.g. n2.html"
    if not text.strip() or text.endswith(("/", os.sep)):
        why = "is empty" if not text.strip() else "names a folder"
        raise CLIError(f"'--n2' = {_shown(text)} {why}: {allowed}")
    check_output_file("--n2", text)
    _not_an_input("--n2", text, inputs)
    # Where the paths lead (links and '..' followed): the folder the command creates, a file
    # it writes, or a folder of one of them, are no place for the diagram.
    target, out = os.path.realpath(text), os.path.realpath(output_dir)
    if target == out or out.startswith(target + os.sep):
        which = "is the folder" if target == out else "is a folder of"
        raise CLIError(
            f"'--n2' = {_shown(text)} {which} --output-dir = {_shown(output_dir)}, which the "
            f"command creates: must be a file name, e.g. {_shown(Path(output_dir, 'n2.html'))}"
        )
    for path in written:
        place = os.path.realpath(path)
        if target == place or target.startswith(place + os.sep):
            which = "is" if target == place else "lies under"
            raise CLIError(
                f"'--n2' = {_shown(text)} {which} {path.name}, a file the command writes into "
                f"--output-dir: {allowed}"
            )


def _files_written(args):
    """Return the files a command writes into its output folder (checked against inputs).

    The folder's lock file; the case files, each with its run statistics (optimize, sweep), and
    the tables: the sweep summary, the constraint tables of analyze, the index of a report.
    """
    out = Path(args.output_dir)
    return [out / LOCK_NAME, *_outputs(args, out)]


def _outputs(args, out):
    """Return the files of :func:`_files_written` but the lock file."""
    if args.command == "analyze":
        return [out / name for name in ("cases.sql", "constraints.md", "constraints.csv")]
    if args.command == "report":
        return [out / "index.md"]
    if args.command == "size":
        return [out / name for name in SIZING_FILES]
    if args.command == "optimize":
        names = study_plan.SEQUENCE if args.problem == "sequence" else [args.problem]
        cases = [out / f"{name}.sql" for name in names]
        return [*cases, *map(run_stats_path, cases)]
    if args.command == "sweep":
        parameters = list(PAPER_SWEEPS) if args.parameter == "all" else [args.parameter]
        margins = {"on": (True,), "off": (False,), "both": (True, False)}[args.static_margin]
        files = {}
        for parameter in parameters:
            for value in args.values or SWEEP_PARAMETERS[parameter][2] or ():
                for margin in margins:
                    path = Path(point_case_file(str(out), parameter, value, margin))
                    if path in files:  # two values that print alike (6 digits)
                        raise CLIError(
                            f"'--values' = {files[path]!r} and {value!r} give the same case file "
                            f"name {path.name} (they agree to 6 significant digits): must be "
                            "distinct values"
                        )
                    files[path] = value
        return [*files, *map(run_stats_path, files), out / "sweep_summary.csv"]
    return []


def _not_taken(flag, folder, path):
    """Refuse a file the command writes whose name a folder (or a device, pipe) already has."""
    try:
        taken = path.exists() and not path.is_file()
    except OSError:  # e.g. a name too long: check_output_folder has said so
        return
    if taken:
        what = "a folder" if path.is_dir() else "a device, pipe or socket"
        raise CLIError(
            f"'{flag}' = {_shown(folder)} holds {what} {_shown(path)} where the command writes "
            f"the file {path.name}: must be a folder in which {path.name} is a regular file or "
            "does not exist (remove or rename it, or choose another folder)"
        )


def _not_an_input(flag, path, inputs):
    """Refuse an output path that is one of the command's input files."""
    for source, given in inputs.items():
        try:
            same = os.path.exists(path) and os.path.samefile(path, given)
        except OSError:
            same = False
        if same:
            raise CLIError(
                f"'{flag}' = {_shown(path)} is the file of {source}, which the command "
                "reads: must be a new file name (lpc-mdo never writes over its inputs)"
            )


def _check_sweep_count(args):
    """Refuse more ``--values`` than :data:`MAX_SWEEP_VALUES` (before any check per value)."""
    if args.values and len(args.values) > MAX_SWEEP_VALUES:
        raise CLIError(
            f"'--values' = {_values_text(args.values)} are too many: must be at most "
            f"{MAX_SWEEP_VALUES} values (each is an optimization of its own)"
        )


def _check_sweep_problem(args):
    """Refuse a swept constraint limit that the points' problem does not constrain."""
    parameters = list(PAPER_SWEEPS) if args.parameter == "all" else [args.parameter]
    for parameter in parameters:
        kind = LIMIT_CONSTRAINT_KINDS.get(parameter)
        if kind is None:
            continue
        what = SWEEP_PARAMETERS[parameter][0]
        if kind == "static_margin" and args.static_margin == "off":
            raise CLIError(
                f"'--static-margin' = off leaves out the constraint that --parameter {parameter} "
                f"moves (the {what}), so every point would be the same problem: must be on "
                "with --parameter min_static_margin"
            )
        posed = study_plan.stage(args.problem).constraint_kinds or CONSTRAINT_KINDS
        if kind not in posed:
            problems = [
                s.name
                for s in study_plan.STAGES
                if kind in (s.constraint_kinds or CONSTRAINT_KINDS)
            ]
            raise CLIError(
                f"'--problem' = {args.problem} has no {kind} constraint, which --parameter "
                f"{args.parameter} moves (the {what}), so every point would be the same "
                f"problem: must be one of {', '.join(problems)} with --parameter {args.parameter}"
            )


def _check_sweep_values(args):
    if not args.values:
        if args.parameter != "all" and not SWEEP_PARAMETERS[args.parameter][2]:
            raise CLIError(
                f"'--parameter' = {args.parameter} has no default values (the paper did not "
                f"sweep it): must be used with --values, e.g. --values "
                f"{_sweep_example(args.vehicle_spec, args.parameter)}"
            )
        return
    if args.parameter == "all":
        raise CLIError(
            f"'--values' = {_values_text(args.values)} needs one '--parameter': must be used with "
            f"--parameter {' or --parameter '.join(SWEEP_PARAMETERS)}"
        )
    for value in args.values:
        try:
            sweep_vehicle(args.vehicle_spec, args.parameter, value)
        except ValueError as err:
            reason = str(err).removeprefix("sweep: ")
            raise CLIError(
                f"'--values' = {value:g} is out of range for --parameter {args.parameter} "
                f"({reason})"
            ) from err


def _check_report_cases(cases, vehicle, vehicle_flag):

    given = None
    if Path(cases).is_dir():
        given = cases
        files = [path for _, path in find_case_files(cases)]
        if not files:
            raise CLIError(
                f"'cases' = {_shown(cases)} is a folder without case files (no SQLite file named "
                f"*{', *'.join(_CASE_SUFFIXES)} in it or its subfolders): must be {CASE_FILE_TEXT}"
                ", or a folder holding such files"
            )
    else:
        files = [cases]
    for path in files:
        reader = open_case_file("cases", path, given=given)
        _same_layout("cases", path, reader, vehicle, vehicle_flag)


def _same_layout(flag, path, reader, vehicle, vehicle_flag):
    """Refuse a run whose design variables have other sizes than the vehicle's (another vehicle)."""
    names = reader.list_cases("problem", recurse=False, out_stream=None)
    drivers = reader.list_cases("driver", recurse=False, out_stream=None)
    if "final" in names:
        case = reader.get_case("final")
    elif drivers:
        case = reader.get_case(drivers[-1])
    else:
        return
    for name, dv, value in _recorded_design_variables(case, vehicle):
        size = np.size(value)
        if size != dv.size:
            raise CLIError(
                f"'{flag}' = {_shown(os.fspath(path))} is a run of another vehicle: its design "
                f"variable '{name}' has {size} value(s), {vehicle_flag} has {dv.size}; allowed: "
                "runs of the vehicle given with --vehicle (report the runs of each vehicle "
                "separately)"
            )


# ------------------------------------------------------------------------------------------------
# The commands.


def _analyze_header(analysis, args):
    prob, vehicle = analysis.prob, analysis.vehicle
    dvs = prob.model.get_design_vars()
    cons = prob.model.get_constraints()
    state = (
        "initial design, trimmed: each condition by its rotor speeds, pitch and elevator"
        if analysis.trimmed
        else "initial design, NOT trimmed (--no-trim): the vehicle file's initial rotor "
        "speeds, pitch and elevator; the accelerations are not at their targets"
    )
    return "\n".join(
        [
            f"lpc-mdo analysis of '{vehicle.name}' ({state})",
            f"  {len(prob.model.condition_names)} design conditions, "
            f"{sum(m['size'] for m in dvs.values())} design variables, {len(cons)} "
            f"constraints of {sum(m['size'] for m in cons.values())} rows "
            f"({sum(m['size'] for m in cons.values() if not m['linear'])} nonlinear, "
            f"{sum(m['size'] for m in cons.values() if m['linear'])} linear bounds)",
            f"  wing: S = {prob.get_val('wing_area')[0]:.2f} m^2, "
            f"AR = {prob.get_val('wing_aspect_ratio')[0]:.2f}, "
            f"span = {prob.get_val('wing_span')[0]:.2f} m; fuselage "
            f"{prob.get_val('fuselage_length')[0]:.3f} m; rotor radii "
            f"{np.array2string(prob.get_val('rotor_radius'), precision=3)} m",
        ]
    )


def _analyze_mission(analysis, args):
    return format_mission(analysis.vehicle, analysis.prob)


def _analyze_masses(analysis, args):
    return "\n\n".join(
        [format_mass_breakdown(mass_breakdown(analysis.prob)), format_mass_table(analysis)]
    )


def _analyze_conditions(analysis, args):
    prob, vehicle = analysis.prob, analysis.vehicle
    trim = analysis.trim.conditions if analysis.trim else {}
    lines = [
        f"  {'condition':<14}{'power [kW]':>12}{'u_dot':>9}{'w_dot':>9}{'q_dot':>9}"
        f"{'V margin':>21}{'trim residual':>15}   (accelerations in m/s^2, rad/s^2; structural "
        "conditions show their load factor n instead of a power; V margin: the lowest motor "
        "voltage margin 1 - |U|/V_lim and its status against constraints.min_voltage_margin, "
        "violated: the motor needs more than the voltage limit; trim residual: the largest "
        "scaled trim row, 1e-3 = 0.1 % of the weight)"
    ]
    floor = vehicle.constraints.min_voltage_margin
    for condition in prob.model.conditions:
        name = condition.name
        lin = prob.get_val(f"{name}.linear_acceleration")[0]
        ang = prob.get_val(f"{name}.angular_acceleration")[0]
        kind = condition_kind(condition.kind)
        if kind.power_output:
            power = f"{prob.get_val(f'{name}.{kind.power_output}', units='kW')[0]:>12.1f}"
        else:
            factor = getattr(condition, "load_factor", None)
            power = f"{f'n = {factor:+g}' if factor is not None else '-':>12}"
        motors = kind.motor_sets(vehicle, condition)
        margins = [prob.get_val(f"{name}.{prefix}_motor_voltage_margin").min() for prefix in motors]
        if margins:
            _, active, violated = entry_status([min(margins)], lower=[floor])
            margin = f"{min(margins):>10.3f} {status_word(active, violated):>10}"
        else:
            margin = f"{'-':>21}"
        residual = f"{trim[name].max_residual:>15.2e}" if name in trim else f"{'-':>15}"
        if name in analysis.failed:
            residual += "  NOT TRIMMED"
        lines.append(
            f"  {name:<14}{power}{lin[0]:>9.3f}{lin[2]:>9.3f}{ang[1]:>9.3f}{margin}{residual}"
        )
    return "\n".join(lines)


def _analyze_trim_variables(analysis, args):
    title = "trim variables" if analysis.trimmed else "trim variables (initial values, not trimmed)"
    return f"  {title}:\n" + format_trim_variables(analysis.prob)


def _constraint_rows(analysis, args):
    """Return the constraint rows of the analysed case (read once per command)."""
    if getattr(args, "constraint_rows", None) is None:
        tols = status_tolerances(analysis.prob)
        args.constraint_rows = constraint_rows(str(args.case_file), case="final", tols=tols)
    return args.constraint_rows


def _analyze_constraints(analysis, args):
    rows = _constraint_rows(analysis, args)
    return (
        f"  constraints (status band: {DEFAULT_TOL:g} of the limit or scaling reference; trim "
        f"rows {TRIM_TOLERANCE:g}, 0.1 % of the weight):\n" + format_constraint_status(rows)
    )


def _analyze_summary(analysis, args):
    prob, vehicle = analysis.prob, analysis.vehicle
    summary = [f"final state of charge {prob.get_val('state_of_charge')[0]:.3f}"]
    for condition in prob.model.conditions:
        for con in condition_kind(condition.kind).constraints(vehicle, condition, None):
            if con.kind == "noise":
                value = prob.get_val(f"{condition.name}.{con.output}")[0]
                summary.append(f"{condition.name} noise {value:.1f} dBA")
    cruise = vehicle.mission.cruise_condition
    if cruise in prob.model.condition_names:
        summary.append(f"{cruise} static margin {prob.get_val(f'{cruise}.static_margin')[0]:.3f}")
    lines = ["  " + ", ".join(summary)]
    if not analysis.trimmed:
        lines.append("  trim: not trimmed (--no-trim)")
    elif analysis.failed:
        failed = ", ".join(f"{n} (residual {r:.3g})" for n, r in analysis.failed.items())
        lines.append(f"  trim FAILED for {failed}: the values above are not a trimmed state")
    else:
        lines.append(f"  trim: all {len(analysis.trim.conditions)} conditions trimmed")
    lines.append(constraint_summary(_constraint_rows(analysis, args)))
    return "\n".join(lines)


def _analyze_static_margin_budget(analysis, args):
    prob, cruise = analysis.prob, analysis.vehicle.mission.cruise_condition
    if cruise not in prob.model.condition_names or args.no_static_margin:
        return f"  static-margin budget: {cruise} has no stability solve"
    title = f"static-margin budget of {cruise} (dSM per part)"
    return f"  {title}:\n" + format_static_margin_budget(prob, cruise)


def _analyze_drag(analysis, args):
    return format_drag_breakdown(analysis.prob)


def _analyze_lift_to_drag(analysis, args):
    prob, cruise = analysis.prob, analysis.vehicle.mission.cruise_condition
    if cruise not in prob.model.condition_names:
        return f"  lift-to-drag: {cruise} is not in the model"
    cl, cd = airframe_lift_drag(prob, cruise)
    here = f"{cl / cd:.2f} at C_L {cl:.3f}, C_D {cd:.4f}"
    sweep = lift_to_drag(prob, cruise)
    state = "trimmed" if analysis.trimmed else "initial design"
    return (
        f"  {cruise} airframe lift-to-drag (wing, tail, profile and parasite drag; no rotors): "
        f"{state} {here}; maximum {sweep['max_L/D']:.2f} at C_L {sweep['CL_at_max']:.3f} "
        f"(pitch sweep {sweep['pitch_deg'][0]:g}..{sweep['pitch_deg'][-1]:g} deg at the {cruise} "
        "speed, elevator and rotor speeds as above)"
    )


def _analyze_stall_speed(analysis, args):
    return format_stall_speed_check(analysis.prob, analysis.vehicle)


#: The sections ``lpc-mdo analyze`` prints, in order: each takes (Analysis, args) and returns
#: text. A new table is one more function here.
ANALYZE_SECTIONS = (
    _analyze_header,
    _analyze_mission,
    _analyze_masses,
    _analyze_conditions,
    _analyze_trim_variables,
    _analyze_drag,
    _analyze_lift_to_drag,
    _analyze_stall_speed,
    _analyze_constraints,
    _analyze_summary,
    _analyze_static_margin_budget,
)


#: The files ``lpc-mdo size`` writes into its output folder.
SIZING_FILES = ("sizing.txt", "sized_vehicle.toml")


def _size(args):
    out = Path(args.output_dir)
    out.mkdir(parents=True, exist_ok=True)
    replaced = [out / name for name in SIZING_FILES if (out / name).exists()]
    if replaced:
        print(f"lpc-mdo: replacing {', '.join(str(p) for p in replaced)}")
    result = size_vehicle(args.vehicle_spec, processes=args.processes, log=print)
    text = result.summary()
    print(text)
    (out / SIZING_FILES[0]).write_text(text + "\n", encoding="utf-8")
    source = args.vehicle if args.vehicle else None
    sized = out / SIZING_FILES[1]
    sized.write_text(sized_vehicle_text(source, result), encoding="utf-8")
    print(f"sized vehicle file: {sized} (lpc-mdo optimize --vehicle {sized})")
    return 0


def _analyze(args):
    out = Path(args.output_dir)
    out.mkdir(parents=True, exist_ok=True)
    case_file = args.case_file = out / "cases.sql"
    replaced = [
        p for p in (case_file, out / "constraints.md", out / "constraints.csv") if p.exists()
    ]
    if args.n2 and Path(args.n2).exists():
        replaced.append(Path(args.n2))
    if replaced:
        print(f"lpc-mdo: replacing {', '.join(str(p) for p in replaced)}")
    analysis = analyze_vehicle(
        args.vehicle_spec,
        trim=not args.no_trim,
        recorder_path=case_file,
        static_margin=not args.no_static_margin,
        processes=args.processes,
    )
    prob = analysis.prob
    tols = status_tolerances(prob)
    for section in ANALYZE_SECTIONS:
        print(section(analysis, args))
        print()
    prob.cleanup()

    table = constraint_table(str(case_file), case="final", tols=tols)
    table.write(str(out), "constraints")
    print(f"constraint table (paper Table 7 layout): {out / 'constraints.md'}")
    print(f"case file: {case_file}")
    if args.n2:
        Path(args.n2).absolute().parent.mkdir(parents=True, exist_ok=True)
        om.n2(str(case_file), outfile=str(args.n2), show_browser=False)
        print(f"N2 diagram: {args.n2}")
    if analysis.failed:
        names = ", ".join(analysis.failed)
        print(f"lpc-mdo: trim failed for {names} (exit status 1)", file=sys.stderr)
        return 1
    return 0


def _optimize(args):
    out = Path(args.output_dir)
    out.mkdir(parents=True, exist_ok=True)
    settings = {}
    if args.max_iter is not None:
        settings["max_iter"] = args.max_iter
    if args.tol is not None:  # the tolerance asked for is the one to meet
        settings.update(drivers.tolerance_settings(args.tol))
    if args.quiet:
        settings["print_level"] = 0
    common = dict(
        vehicle=args.vehicle_spec,
        static_margin=not args.no_static_margin,
        driver_settings=settings,
        trim_first=not args.no_trim,
        progress=not args.quiet,
        log=print,  # one line per stage, also with --quiet
        trim_processes=args.processes,
    )
    # Each stage prints a progress line per iteration (and IPOPT its own table unless
    # --quiet); Ctrl-C stops cleanly: the case file keeps every recorded iteration and a
    # 'final' case of the interrupted point.
    try:
        if args.problem == "sequence":
            results = warm_start.run_sequence(
                str(out),
                optimizer=args.optimizer,
                full_optimizer=args.optimizer,
                start_case=args.start_case,
                keep_going=args.keep_going,
                **common,
            )
            failed = [r for r in results if not r.success]
            if failed:
                stopped = (
                    ""
                    if args.keep_going
                    else "; the sequence stopped there (--keep-going runs the later stages)"
                )
                print(
                    f"lpc-mdo: {failed[0].name}: {failed[0].exit_status}{stopped} "
                    f"(case file {failed[0].case_file})",
                    file=sys.stderr,
                )
                return 1
            return 0
        case_file = out / f"{args.problem}.sql"
        if args.problem == "baseline":  # continuation in alpha (paper eq. 8)
            stage = warm_start.solve_baseline(
                str(case_file), start_case=args.start_case, optimizer=args.optimizer, **common
            )
        else:
            stage = warm_start.solve_stage(
                args.problem,
                str(case_file),
                start_case=args.start_case,
                optimizer=args.optimizer,
                rescale=study_plan.stage(args.problem).rescales and args.start_case is not None,
                **common,
            )
    except KeyboardInterrupt:
        # What each case file of the output folder holds (driver cases, a 'final' case or not).
        print(f"lpc-mdo: {interrupt_message(out)}", file=sys.stderr)
        return 130
    print(f"case file: {case_file}")
    return 0 if stage.success else 1


def _sweep_example(vehicle, parameter):
    """Two values either side of the vehicle's own, for an error message."""
    ref = reference_value(vehicle, parameter)
    step = 0.05 * abs(ref) if ref else 0.01
    return f"{ref - step:g} {ref + step:g}"


def _sweep(args):
    parameters = list(PAPER_SWEEPS) if args.parameter == "all" else [args.parameter]
    values = {parameters[0]: args.values} if args.values else None  # checked by _preflight
    margins = {"on": (True,), "off": (False,), "both": (True, False)}[args.static_margin]
    points = run_sweep(
        args.output_dir,
        args.start_case,
        parameters=parameters,
        values=values,
        static_margins=margins,
        vehicle=args.vehicle,
        processes=args.processes,
        mpi=args.mpi,
        driver_settings={"max_iter": args.max_iter, "print_level": 0},
        optimizer=args.optimizer,
        problem=args.problem,
    )
    if points is None:  # an MPI rank other than 0
        return 0
    for p in points:
        print(
            f"{p.parameter}={p.value:g} static margin {'on' if p.static_margin else 'off'}: "
            f"{'converged' if p.success else 'FAILED'}{' (retried)' if p.retried else ''}, "
            f"gross mass {p.gross_mass:.2f} kg, {p.iterations} iterations, {p.seconds:.1f} s"
        )
    print(f"summary: {Path(args.output_dir) / 'sweep_summary.csv'}")
    return 0 if all(p.success for p in points) else 1


def _report(args):
    if args.sensitivities:
        for label, path in find_case_files(args.cases):
            sidecar = sensitivities_path(path)
            if sidecar.is_file():
                continue
            reader = om.CaseReader(str(path))
            if "final" not in reader.list_cases("problem", out_stream=None):
                continue
            objectives = list(reader.get_case("final").get_objectives())
            if [n.split(".")[-1] for n in objectives] != ["gross_mass"]:
                continue
            print(f"report: post-optimal sensitivities of {label} ...", flush=True)
            try:
                found = sensitivities_from_case(path, args.vehicle_spec)
            except ValueError as err:  # another vehicle's run (a sweep point): say so, go on
                print(f"report: {label}: {str(err).removeprefix('sensitivities: ')}")
                continue
            found.to_json(sidecar)
    spec = ReportSpec(vehicle=args.vehicle_spec)
    index = write_report(args.cases, args.output_dir, spec)
    print(f"report: {index}")
    return 0


def _add_debug(parser, default):
    parser.add_argument(
        "--debug",
        action="store_true",
        default=default,
        help="show the traceback of an error (for a bug report)",
    )


def _problem_help():
    """Help of ``optimize --problem``: every stage of the stage table and the sequence."""
    stages = "; ".join(f"{s.name}: {s.summary}" for s in study_plan.STAGES)
    return (
        f"the stage to solve (lpc_mdo.study_plan): {stages}; or sequence (default): "
        f"{', '.join(study_plan.SEQUENCE)} in turn, each from the previous one's final case"
    )


def _optimizer_help():
    """Help of ``--optimizer``: the default optimizer of each stage, from the stage table."""
    stages = {}
    for s in study_plan.STAGES:
        stages.setdefault(s.optimizer, []).append(s.name)
    words = {study_plan.SQP: "SQP (SNOPT if pyoptsparse has it, else SLSQP)"}
    parts = [f"{words.get(name, name)} for {', '.join(names)}" for name, names in stages.items()]
    return "default: the stage's, " + "; ".join(parts)


def _max_iter_help():
    """Help of ``optimize --max-iter``: the stages' iteration limits, from the stage table."""
    limits = {
        options.max_iter
        for s in study_plan.STAGES
        for table in (s.options, s.sequence_options or {})
        for options in table.values()
        if options.max_iter is not None
    }
    return f"iteration limit (default: the stage's, {', '.join(map(str, sorted(limits)))})"


def _tol_help():
    """Help of ``optimize --tol``: the full problem's SLSQP tolerance, from the stage table."""
    tol = f"{study_plan.stage('full').optimizer_options('SLSQP').tol:.0e}".replace("e-0", "e-")
    return (
        f"optimizer tolerance (default: the stage's; SLSQP {tol} on the full problem); given, "
        "the run does not stop earlier at an acceptable point. E.g. 1e-6 with --max-iter 150 "
        "from a full.sql polishes an optimum before reading its post-optimal sensitivities"
    )


def build_parser():
    """
    Return the argument parser of the ``lpc-mdo`` command.

    Returns
    -------
    argparse.ArgumentParser
        Its errors raise :class:`CLIError`.
    """
    # No abbreviated options (--out for --output-dir): an abbreviation and the full name given
    # together would pass the given-twice check, and a future option could change its meaning.
    parser = _Parser(
        prog="lpc-mdo",
        description="Analyze, size, optimize, sweep and report the NASA lift-plus-cruise eVTOL.",
        allow_abbrev=False,
    )
    _add_debug(parser, False)
    sub = parser.add_subparsers(dest="command", required=True)
    vehicle_type = _existing("--vehicle", "a vehicle TOML file")
    # 10^6 iterations are days of optimizing; 1024 processes more than any one machine has.
    positive = {
        "--max-iter": _integer("--max-iter", 1, upper=1_000_000),
        "--processes": _integer("--processes", 1, upper=1024),
    }

    parser.commands = {}  # name -> its parser (for _no_option_before_the_command)

    def add_command(name, help):
        command = parser.commands[name] = sub.add_parser(name, help=help, allow_abbrev=False)
        _add_debug(command, argparse.SUPPRESS)  # also accepted after the command
        return command

    def add_vehicle(command):
        command.add_argument(
            "--vehicle",
            type=vehicle_type,
            default=None,
            help="vehicle TOML file (default: the reference vehicle)",
        )

    def add_trim_processes(command):
        command.add_argument(
            "--processes",
            type=positive["--processes"],
            default=os.cpu_count() or 1,
            help="processes that trim conditions at the same time (default: the CPU count)",
        )

    analyze = add_command("analyze", "analyze a vehicle's design conditions")
    add_vehicle(analyze)
    analyze.add_argument(
        "--output-dir",
        default="analysis_out",
        help="folder for the case file and tables (default: analysis_out)",
    )
    analyze.add_argument(
        "--n2", default=None, metavar="HTML", help="also write the N2 diagram to this file"
    )
    analyze.add_argument(
        "--no-static-margin", action="store_true", help="leave the static-margin constraint out"
    )
    analyze.add_argument(
        "--no-trim",
        action="store_true",
        help="show the raw initial design, untrimmed (default: trim every condition)",
    )
    add_trim_processes(analyze)
    analyze.set_defaults(func=_analyze)

    size = add_command(
        "size", "close a vehicle's battery, gross mass and motors on its mission (no optimizer)"
    )
    add_vehicle(size)
    size.add_argument(
        "--output-dir",
        default="sizing_out",
        help=f"folder for {' and '.join(SIZING_FILES)}: the summary and the vehicle file with "
        "the closed battery mass, design gross mass and motors, to optimize from (default: "
        "sizing_out)",
    )
    add_trim_processes(size)
    size.set_defaults(func=_size)

    start_case_type = _existing("--start-case", CASE_FILE_TEXT)
    optimize = add_command(
        "optimize", "solve a subproblem, the full problem, or the warm-start sequence"
    )
    optimize.add_argument(
        "--problem",
        default="sequence",
        choices=(*study_plan.STAGE_NAMES, "sequence"),
        help=_problem_help(),
    )
    optimize.add_argument(
        "--optimizer",
        type=_optimizer("--optimizer"),
        default=None,
        choices=drivers.KNOWN_OPTIMIZERS,
        help=_optimizer_help(),
    )
    optimize.add_argument(
        "--max-iter", type=positive["--max-iter"], default=None, help=_max_iter_help()
    )
    optimize.add_argument(
        "--tol",
        # 1e-12 is below what the model's inner solves resolve; 0.1 stops at the start.
        type=_finite_float("--tol", lower=1e-12, upper=0.1),
        default=None,
        help=_tol_help(),
    )
    optimize.add_argument("--vehicle", type=vehicle_type, default=None, help="vehicle TOML file")
    optimize.add_argument(
        "--no-static-margin", action="store_true", help="leave the static-margin constraint out"
    )
    optimize.add_argument(
        "--start-case",
        type=start_case_type,
        default=None,
        help="case file whose final case gives the starting design",
    )
    optimize.add_argument(
        "--output-dir", default="optimize_out", help="folder for case files and run statistics"
    )
    optimize.add_argument(
        "--no-trim", action="store_true", help="do not trim the conditions before optimizing"
    )
    optimize.add_argument(
        "--quiet",
        action="store_true",
        help="one line per stage and the reason of a failure, no iteration tables",
    )
    optimize.add_argument(
        "--keep-going",
        action="store_true",
        help="run the later stages of the sequence after a stage that did not converge "
        "(default: stop there, exit status 1)",
    )
    optimize.add_argument(
        "--processes",
        type=positive["--processes"],
        default=os.cpu_count() or 1,
        help="processes that trim the conditions before each stage (default: the CPU count)",
    )
    optimize.set_defaults(func=_optimize)

    sweep = add_command("sweep", "parameter sweeps of the full problem (paper Sec. V.C)")
    sweep.add_argument(
        "--start-case",
        type=start_case_type,
        required=True,
        help="case file whose final case starts every chain, e.g. the sequence's full.sql",
    )
    sweep.add_argument(
        "--parameter",
        default="all",
        choices=(*SWEEP_PARAMETERS, "all"),
        help="all: the paper's two sweeps (energy density, final SoC); the others check the "
        "post-optimal sensitivities and need --values",
    )
    sweep.add_argument(
        "--values",
        type=_finite_float("--values"),
        nargs="+",
        default=None,
        help="values of the one --parameter (default: the paper's five); units: Wh/kg, -, "
        "dBA, kg, -, km",
    )
    sweep.add_argument("--static-margin", default="both", choices=("on", "off", "both"))
    sweep.add_argument(
        "--processes", type=positive["--processes"], default=2, help="local worker processes"
    )
    sweep.add_argument(
        "--mpi",
        action="store_true",
        help="distribute over MPI ranks (run under mpirun; needs mpi4py)",
    )
    sweep.add_argument(
        "--problem",
        default="full",
        choices=study_plan.STAGE_NAMES,
        help="problem each point solves (default: full)",
    )
    sweep.add_argument(
        "--max-iter", type=positive["--max-iter"], default=200, help="iteration limit per point"
    )
    sweep.add_argument(
        "--optimizer",
        type=_optimizer("--optimizer"),
        default=None,
        choices=drivers.KNOWN_OPTIMIZERS,
        help="default: as optimize (SNOPT if pyoptsparse has it, else SLSQP)",
    )
    sweep.add_argument("--vehicle", type=vehicle_type, default=None, help="vehicle TOML file")
    sweep.add_argument("--output-dir", default="sweep_out", help="folder for case files")
    sweep.set_defaults(func=_sweep)

    report = add_command("report", "tables and figures from case files")
    report.add_argument(
        "cases",
        type=_existing("cases", "a case file or a folder of case files", folder_ok=True),
        help="a case file or a folder of case files",
    )
    report.add_argument("--output-dir", default="report", help="report folder")
    report.add_argument(
        "--vehicle",
        type=vehicle_type,
        default=None,
        help="vehicle file the runs were made with (its conditions and trim "
        "rows; default: the reference vehicle)",
    )
    report.add_argument(
        "--sensitivities",
        action="store_true",
        help="evaluate the post-optimal sensitivities of gross-mass optima that have none "
        "beside their case file (a live model, about 10 s each; the optimize and sweep "
        "commands write them)",
    )
    report.set_defaults(func=_report)
    return parser


def _user_error(err):
    """Whether an exception is a user error: CLIError, VehicleSpecError, lpc_mdo's ValueError."""
    if isinstance(err, (CLIError, VehicleSpecError)):
        return True
    if not isinstance(err, ValueError) or err.__traceback__ is None:
        return False
    # A ValueError raised by lpc_mdo's own checks (which name the field), not by a library:
    # by the module of the frame that raised it (the components and groups are lpc_mdo
    # subpackages wherever their files are installed).
    tb = err.__traceback__
    while tb.tb_next is not None:
        tb = tb.tb_next
    module = tb.tb_frame.f_globals.get("__name__", "")
    return module == "lpc_mdo" or module.startswith("lpc_mdo.")


def _one_line(err):
    return " ".join(part.strip() for part in str(err).splitlines() if part.strip())


def _short(line):
    """Cut an error line that a value made long (the checks cut what they echo; this is the net).

    Its beginning (the argument and value) and its end (what is allowed) are kept.
    """
    if len(line) <= 5 * SHOWN_CHARACTERS:
        return line
    head, tail = line[: 3 * SHOWN_CHARACTERS], line[-SHOWN_CHARACTERS:]
    return f"{head} ... ({len(line)} characters) ... {tail}"


def _working_folder_exists():
    """Refuse to start in a working folder that was removed (relative paths cannot resolve)."""
    try:
        os.getcwd()
    except FileNotFoundError as err:
        raise CLIError(
            "the working folder no longer exists (it was removed after this shell entered it): "
            "must start lpc-mdo in an existing folder, e.g. after 'cd ~'"
        ) from err


def _quiet_stdout():
    """Point stdout at /dev/null, so that Python's flush at exit does not fail again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # no file descriptor behind stdout (e.g. under pytest)
        pass


def main(argv=None):
    """
    Run the ``lpc-mdo`` command.

    Parameters
    ----------
    argv : list of str or None
        The arguments (None: ``sys.argv[1:]``).

    Returns
    -------
    int
        Exit code: 0 success, 1 an optimization that did not converge, an analysis with a
        condition that did not trim (named on stderr), a failed write into the output folder
        (one line) or a bug (with its traceback), 2 a user error (one line ``lpc-mdo: error:
        ...``), 130 interrupted.
    """
    os.environ.setdefault("OPENMDAO_REPORTS", "0")
    argv = sys.argv[1:] if argv is None else list(argv)
    debug = "--debug" in argv
    args = None
    try:
        _working_folder_exists()
        _no_option_twice(argv)
        parser = build_parser()
        _no_option_before_the_command(parser, argv)
        args = parser.parse_args(argv)
        debug = args.debug
        _preflight(args)
        with _output_folder_lock(args):
            return args.func(args)
    except KeyboardInterrupt:
        print("lpc-mdo: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:  # the reader of the output went away (lpc-mdo ... | head)
        _quiet_stdout()
        return EXIT_WRITE_ERROR
    except (CLIError, ValueError) as err:  # VehicleSpecError is a ValueError
        if not _user_error(err):
            return _bug(err)
        if debug:
            traceback.print_exc()
        print(f"lpc-mdo: error: {_short(_one_line(err))}", file=sys.stderr)
        return EXIT_USER_ERROR
    except (OSError, sqlite3.Error) as err:
        problem = _write_failure(err)
        if problem is None:
            return _bug(err)
        if debug:
            traceback.print_exc()
        print(f"lpc-mdo: error: {_kept_after_write_failure(args, problem)}", file=sys.stderr)
        return EXIT_WRITE_ERROR
    except Exception as err:  # not hidden: the traceback, then what to do with it
        if isinstance(err, SizingError):
            if debug:
                traceback.print_exc()
            print(f"lpc-mdo: error: sizing: {_short(_one_line(err))}", file=sys.stderr)
            return EXIT_ANALYSIS_ERROR
        if type(err).__name__ == "AnalysisError" and type(err).__module__.startswith("openmdao"):
            # A model left its stated range for this vehicle's design (om.AnalysisError names the
            # component and the values): a result, not a bug.
            if debug:
                traceback.print_exc()
            print(
                f"lpc-mdo: error: the analysis left a model's range: {_short(_one_line(err))}",
                file=sys.stderr,
            )
            return EXIT_ANALYSIS_ERROR
        return _bug(err)


def _write_failure(err):
    """Say what went wrong when ``err`` is a failed write (full disk, read-only), else None."""
    text = str(err)
    if isinstance(err, OSError) and err.errno in (errno.ENOSPC, errno.EDQUOT, errno.EROFS):
        return err.strerror or os.strerror(err.errno)
    if isinstance(err, sqlite3.Error) and any(
        fragment in text for fragment in ("disk is full", "readonly database", "disk I/O error")
    ):
        return text
    return None


def _kept_after_write_failure(args, problem):
    """One line: the folder whose write failed, why, and the case files it keeps."""
    folder = getattr(args, "output_dir", None) or "."
    kept = sorted(p.name for p in Path(folder).glob("*.sql")) if Path(folder).is_dir() else []
    listed = ", ".join(kept) if kept else "none"
    return (
        f"writing into '--output-dir' = {_shown(folder)} failed ({problem}); the case files there "
        f"are kept as they were last written ({listed}): free space (or choose another folder) "
        "and start again, e.g. from the last one with --start-case"
    )


@contextlib.contextmanager
def _output_folder_lock(args):
    """Hold the ``--output-dir`` lock while the command runs (one run per folder)."""
    if getattr(args, "mpi", False):
        from mpi4py import MPI  # checked by _preflight

        if MPI.COMM_WORLD.rank != 0:  # the ranks of one sweep share its folder
            yield
            return
    try:
        with folder_lock(args.output_dir):
            yield
    except LockFailed as err:
        raise CLIError(
            f"'--output-dir' = {_shown(args.output_dir)}: its lock file cannot be created "
            f"({_shown(err.path)}: {err.reason}): must be a folder lpc-mdo can write into"
        ) from err
    except FolderInUse as err:
        raise CLIError(
            f"'--output-dir' = {_shown(args.output_dir)} is in use by another lpc-mdo run "
            f"(process {err.pid}, lock file {LOCK_NAME} in it): must be a folder "
            "no running lpc-mdo writes into (wait for it, or choose another folder)"
        ) from err


def _bug(err):
    traceback.print_exc()
    print(
        f"lpc-mdo: internal error: {type(err).__name__}: {_one_line(err)} - this is a bug of "
        "lpc-mdo (or an input its checks miss): please report it with the command and the "
        "traceback above",
        file=sys.stderr,
    )
    return EXIT_BUG


if __name__ == "__main__":
    sys.exit(main())
