"""One-call report: every table and figure the case files support, linked from an index.md.

:func:`write_report` reads case files only. The generic parts work for any OpenMDAO problem
whose driver was recorded: optimization statistics (paper Table 9) over all runs, and per run
the constraint table (Table 7), the design-variable table and the convergence history. The
LPC-specific parts (design table like Table 8, planform Fig. 15, mass breakdown Figs. 19-20,
power and figure of merit per condition Fig. 16, thickness and stress distributions Figs. 13,
21, sweeps Figs. 17-18) compare all runs and take their variable names from a
:class:`ReportSpec`; a part whose variables are absent is skipped with a note in the index.

Layout of ``out_dir``::

    index.md                 links to everything below, notes on skipped parts
    tables/*.md, *.csv       statistics, constraints_<run>, trim_residuals_<run>,
                             design_variables_<run>, designs
    figures/*.png            convergence_<run>, planform, mass_breakdown, power,
                             figure_of_merit, <distribution stem>, <sweep stem>
"""

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from os import PathLike
from pathlib import Path

import numpy as np

from lpc_mdo.api.weights import mass_properties as item_mass_properties
from lpc_mdo.components.weights.gross_weight import BREAKDOWN_LABELS
from lpc_mdo.post import figures, tables
from lpc_mdo.post.design_review import design_review_table
from lpc_mdo.post.statistics import statistics_table
from lpc_mdo.post.tables import DEFAULT_TOL, MissingVariableError, Quantity
from lpc_mdo.post.trim_residuals import trim_residual_table
from lpc_mdo.sensitivities import read_sensitivities, sensitivities_path, sensitivity_table
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.condition_contract import condition_kind

__all__ = [
    "lpc_design_quantities",
    "LPC_THICKNESS_DISTRIBUTIONS",
    "lpc_distributions",
    "LPC_SWEEPS",
    "DistributionSpec",
    "ReportSpec",
    "SweepSpec",
    "find_case_files",
    "replaced_files_note",
    "write_report",
]

_CASE_SUFFIXES = (".sql", ".db", ".sqlite", ".sqlite3")
_GENERIC_STEMS = ("cases", "case", "driver", "recording")


@dataclass(frozen=True)
class DistributionSpec:
    """
    A distribution figure (:func:`~lpc_mdo.post.figures.plot_distribution`).

    Attributes
    ----------
    stem : str
        File name (without ``.png``) and index heading.
    names : tuple of str
        Arrays plotted together.
    x : str or None
        Abscissa variable; None uses the index.
    units, x_units : str or None
        Units of the arrays and of the abscissa.
    limit : float or None
        Horizontal limit line, in ``units``.
    title : str or None
        Figure title.
    ylabel, xlabel : str or None
        Axis labels in words with units; None: from the label table
        (:data:`lpc_mdo.post.figures.LABELS`).
    limit_label : str
        Legend words of the limit line.
    column_label : str
        Legend words of column j + 1 of a 2-D array.
    """

    stem: str
    names: tuple
    x: str | None = None
    units: str | None = None
    x_units: str | None = None
    limit: float | None = None
    title: str | None = None
    ylabel: str | None = None
    xlabel: str | None = None
    limit_label: str = "Limit"
    column_label: str = "column {}"


@dataclass(frozen=True)
class SweepSpec:
    """
    A sweep figure (:func:`~lpc_mdo.post.figures.plot_sweep`) over the runs of the report.

    The parameter values are read from each run (:func:`~lpc_mdo.post.figures.sweep_points`);
    ``'lower:NAME'`` reads a constraint's declared lower bound.

    Attributes
    ----------
    stem : str
        File name (without ``.png``) and index heading.
    x : str
        Swept parameter.
    group : str or None
        Second parameter: one line per value.
    x_units, group_units : str or None
        Units to read the parameters in.
    xlabel, group_label : str or None
        Axis label and legend prefix.
    """

    stem: str
    x: str
    group: str | None = None
    x_units: str | None = None
    group_units: str | None = None
    xlabel: str | None = None
    group_label: str | None = None


def lpc_design_quantities(vehicle):
    """
    Return the Table 8 columns of a vehicle: its vehicle-level design variables and W_0.

    ``rotor_radius`` holds one radius per lift-rotor pair, then the pusher's: one column per
    pair of the vehicle's layout.
    """
    num_pairs = len(vehicle.lift_rotor_pairs)
    return (
        ("l_fuselage", "fuselage_length", "m"),
        ("S_ref,wing", "wing_area", "m**2"),
        ("AR_wing", "wing_aspect_ratio"),
        ("S_ref,tail", "htail_area", "m**2"),
        ("AR_tail", "htail_aspect_ratio"),
        ("R_pusher", "rotor_radius", "m", num_pairs),
        *((f"R_lift,{i + 1}", "rotor_radius", "m", i) for i in range(num_pairs)),
        ("W_0", "gross_mass", "kg"),
    )


#: The paper's Table 8 (its two lift-rotor radii; W0 from the 3723.99 kg calibrated reference),
#: printed beside ours in the report (``ReportSpec.paper_designs``).
PAPER_TABLE_8 = (
    [
        "design",
        "l_fuselage (m)",
        "S_ref,wing (m**2)",
        "AR_wing",
        "S_ref,tail (m**2)",
        "AR_tail",
        "R_pusher (m)",
        "R_lift,1 (m)",
        "R_lift,2 (m)",
        "W_0 (kg)",
    ],
    [
        ["Initial", 9.14, 19.60, 12.12, 3.70, 4.30, 1.37, 1.52, 1.52, 3723.99],
        ["Baseline w/o SM", 8.81, 19.35, 12.24, 3.70, 4.30, 1.37, 1.54, 1.54, 3846.90],
        ["Optimized w/o SM", 8.72, 15.04, 15.76, 2.59, 3.01, 1.78, 1.65, 1.42, 3601.95],
        ["Baseline w/ SM", 10.64, 17.65, 13.30, 3.64, 4.27, 1.38, 1.51, 1.55, 4077.36],
        ["Optimized w/ SM", 10.66, 15.04, 15.76, 2.59, 3.01, 1.78, 1.47, 1.60, 3814.75],
    ],
)

#: Wing-box design variables of VehicleGroup (per bay, root to tip).
LPC_THICKNESS_DISTRIBUTIONS = (
    DistributionSpec(
        "skin_thickness",
        ("top_skin_thickness", "bottom_skin_thickness"),
        units="mm",
        title="Wing-box skin thickness, root to tip",
        ylabel="Skin thickness (mm)",
        xlabel="Wing-box bay, root (0) to tip (-)",
    ),
    DistributionSpec(
        "spar_thickness",
        ("front_spar_thickness", "rear_spar_thickness"),
        units="mm",
        title="Wing-box spar thickness, root to tip",
        ylabel="Spar thickness (mm)",
        xlabel="Wing-box bay, root (0) to tip (-)",
    ),
)


def lpc_distributions(vehicle):
    """
    Return the wing-box thicknesses and the beam stress per structural condition of the vehicle.

    The stress is BeamGroup ``von_mises_stress``, (num_elements, 5) recovery points; limit: the
    material's allowable.
    """
    allowable = vehicle.material.allowable_stress / 1e6
    return LPC_THICKNESS_DISTRIBUTIONS + tuple(
        DistributionSpec(
            f"stress_{c.name}",
            (f"{c.name}.von_mises_stress",),
            units="MPa",
            limit=allowable,
            title=f"Wing-box von Mises stress, condition {c.name}",
            xlabel="Beam element, root (0) to tip (-)",
            limit_label="Allowable stress",
            column_label="recovery point {}",
        )
        for c in vehicle.conditions
        if c.kind == "structural"
    )


def _powered_conditions(vehicle):
    return tuple(c.name for c in vehicle.conditions if condition_kind(c.kind).power_output)


def _all_lift_rotor_conditions(vehicle):
    """Conditions that run every lift rotor (hover and transition in the reference)."""
    n = len(vehicle.lift_rotors)
    return tuple(
        c.name
        for c in vehicle.conditions
        if len(condition_kind(c.kind).motor_sets(vehicle, c).get("lift", ())) == n
    )


LPC_SWEEPS = (
    SweepSpec(
        "sweep_energy_density",
        "battery.specific_energy",
        x_units="W*h/kg",
        xlabel="Battery energy density (Wh/kg)",
    ),
    SweepSpec(
        "sweep_final_soc", "lower:state_of_charge", xlabel="Required final state of charge (-)"
    ),
)


@dataclass
class ReportSpec:
    """
    What :func:`write_report` writes and the variable names of its LPC-specific parts.

    The defaults are the lift-plus-cruise names as far as they are settled (VehicleGroup design
    variables, WeightsGroup, RotorLayoutComp, VLM ``{surface}_mesh``, ``electrical_power`` of the
    power sum, condition groups of docs theory/dynamics 'Design conditions'); override any field
    when the assembled model promotes differently. :meth:`generic` switches every LPC part off.
    Names may be anything :func:`~lpc_mdo.post.tables.read_value` accepts.

    Attributes
    ----------
    tol : float
        Activity/feasibility tolerance of the constraint tables.
    refs : Mapping
        Constraint name -> reference magnitude for % violation (e.g. trim -> 1e4 N).
    design_quantities : tuple
        Table 8 columns: :class:`~lpc_mdo.post.tables.Quantity` or ``(label, name[, units[,
        index]])``; default fuselage length, wing/tail area and aspect ratio, rotor radii,
        gross mass.
    paper_designs : tuple or None
        (columns, rows) printed under the design table for comparison; default the paper's
        Table 8 (:data:`PAPER_TABLE_8`).
    meshes : tuple of str
        Surface meshes (nx, ny, 3) of the planform figure; default ``('wing_mesh',
        'horizontal_tail_mesh')``.
    rotors : tuple of (str, str)
        (hub positions, radii) drawn as disks; default lift rotors
        ``('lift_hub_position', 'lift_rotor_radius')``; dropped with a note when absent.
    fuselage : str or None
        Fuselage length drawn in the planform (the maximum width is the vehicle's);
        default ``'fuselage_length'``.
    pusher : tuple or None
        ``(hub position, radii, index)`` of the pusher disk; default
        ``('pusher_hub_position', 'rotor_radius', -1)`` (the last radius is the pusher's).
    vertical_tail : str or None
        Root leading edge of the fin (its shape is the vehicle's); default
        ``'vtail_root_leading_edge'``.
    booms : str or None
        Lift-rotor hub positions; each boom is drawn from a hub to its wing junction, which
        keeps the vehicle's offset (hub minus ``booms.attach_points``) as in RotorLayoutComp;
        default ``'lift_hub_position'``.
    mass_breakdown : str or None
        Vector for the mass bar chart; default ``'mass_breakdown'`` (GrossWeightComp).
    mass_labels : tuple of str or None
        Its entry labels; default ``BREAKDOWN_LABELS``.
    mass_units : str or None
        Default ``'kg'``.
    vehicle : Vehicle or None
        The vehicle of the runs (None: the reference vehicle); the defaults of ``conditions``,
        ``fom_conditions`` and ``distributions`` and the trim rows come from its conditions.
    conditions : tuple of str or None
        Condition names for the power figure; None: the vehicle's conditions with motors.
    power : str or None
        Template (``{condition}``) or per-condition vector; default
        ``'{condition}.electrical_power'``, summed per condition.
    power_units : str or None
        Default ``'kW'``.
    figure_of_merit : str or None
        Template or vector; default ``'{condition}.lift_figure_of_merit'``, averaged over all its
        entries (rotors) per condition.
    fom_conditions : tuple of str or None
        None: the vehicle's conditions that run every lift rotor (the reference: hover and the
        five transition points).
    distributions : tuple of DistributionSpec or None
        None: ``top/bottom_skin_thickness`` and ``front/rear_spar_thickness`` (mm) and each
        structural condition's ``von_mises_stress`` (MPa, limit: the allowable stress).
    sweeps : tuple of SweepSpec
        Default battery energy density (``battery.specific_energy`` in Wh/kg) and final SoC
        (``lower:state_of_charge``).
    trim_residuals : bool
        Per run, every Table 6 trim row as a force or moment in % of the weight
        (:func:`~lpc_mdo.post.trim_residuals.trim_residual_table`), declared or not.
    design_review : bool
        Per run over every condition, each buildability limit at its worst point
        (:func:`~lpc_mdo.post.design_review.design_review_table`), constrained or not.
    """

    tol: float = DEFAULT_TOL
    refs: Mapping = field(default_factory=dict)
    design_quantities: tuple | None = None
    paper_designs: tuple | None = PAPER_TABLE_8
    meshes: tuple = ("wing_mesh", "horizontal_tail_mesh")
    rotors: tuple = (("lift_hub_position", "lift_rotor_radius"),)
    fuselage: str | None = "fuselage_length"
    pusher: tuple | None = ("pusher_hub_position", "rotor_radius", -1)
    vertical_tail: str | None = "vtail_root_leading_edge"
    booms: str | None = "lift_hub_position"
    mass_breakdown: str | None = "mass_breakdown"
    mass_labels: tuple | None = BREAKDOWN_LABELS
    mass_units: str | None = "kg"
    vehicle: object = None
    conditions: tuple | None = None
    power: str | None = "{condition}.electrical_power"
    power_units: str | None = "kW"
    figure_of_merit: str | None = "{condition}.lift_figure_of_merit"
    fom_conditions: tuple | None = None
    distributions: tuple | None = None
    sweeps: tuple = LPC_SWEEPS
    trim_residuals: bool = True
    mass_properties: bool = True
    design_review: bool = True

    def __post_init__(self):
        if self.vehicle is None:
            self.vehicle = reference_vehicle()
        if self.design_quantities is None:
            self.design_quantities = lpc_design_quantities(self.vehicle)
        if len(self.vehicle.lift_rotor_pairs) != 4:  # the paper's designs have 4 pairs
            self.paper_designs = None
        if self.conditions is None:
            self.conditions = _powered_conditions(self.vehicle)
        if self.fom_conditions is None:
            self.fom_conditions = _all_lift_rotor_conditions(self.vehicle)
        if self.distributions is None:
            self.distributions = lpc_distributions(self.vehicle)

    @classmethod
    def generic(cls, **overrides):
        """Return a spec with every LPC-specific part off (only the generic tables and figures)."""
        off = dict(
            design_quantities=(),
            paper_designs=None,
            meshes=(),
            rotors=(),
            fuselage=None,
            pusher=None,
            vertical_tail=None,
            booms=None,
            mass_breakdown=None,
            power=None,
            figure_of_merit=None,
            distributions=(),
            sweeps=(),
            trim_residuals=False,
            mass_properties=False,
            design_review=False,
        )
        return cls(**{**off, **overrides})


# ------------------------------------------------------------------------------------------------
# Case files


def _is_sqlite(path):
    try:
        with open(path, "rb") as fh:
            return fh.read(16) == b"SQLite format 3\x00"
    except OSError:
        return False


def _label(path, root):
    rel = path.relative_to(root) if root is not None else Path(path.name)
    parts = [p.removesuffix("_out") for p in rel.parent.parts]
    if path.stem in _GENERIC_STEMS and not parts:
        # analysis_out/cases.sql: the run is named by its folder.
        folder = (root if root is not None else path.resolve().parent).name
        parts.append(folder.removesuffix("_out") or path.stem)
    elif path.stem not in _GENERIC_STEMS or not parts:
        parts.append(path.stem)
    return "/".join(parts)


def find_case_files(case_files_or_dir):
    """
    Resolve the report's input into labelled case files.

    Parameters
    ----------
    case_files_or_dir : str, os.PathLike, Mapping or Sequence
        A folder (searched recursively for SQLite files ending ``.sql``, ``.db``, ``.sqlite``
        or ``.sqlite3``), one case file, a mapping label -> case file, or a sequence of case
        files or ``(label, case file)`` pairs.

    Returns
    -------
    list of (str, Path)
        Unique labels (from the folder structure: ``run_a/cases.sql`` -> ``run_a``) and paths.
    """
    src = case_files_or_dir
    if isinstance(src, (str, PathLike)) and Path(src).is_dir():
        root = Path(src)
        found = [
            (None, p)
            for p in sorted(root.rglob("*"))
            if p.suffix in _CASE_SUFFIXES and p.is_file() and _is_sqlite(p)
        ]
    else:
        root = None
        if isinstance(src, (str, PathLike)):
            src = [src]
        elif isinstance(src, Mapping):
            src = list(src.items())
        found = [
            (item[0], Path(item[1])) if isinstance(item, tuple) else (None, Path(item))
            for item in src
        ]
    out, seen = [], set()
    for label, path in found:
        if not path.is_file():
            raise FileNotFoundError(f"Case file {str(path)!r} does not exist.")
        label = label or _label(path, root)
        base, k = label, 2
        while label in seen:
            label, k = f"{base}_{k}", k + 1
        seen.add(label)
        out.append((label, path))
    return out


# ------------------------------------------------------------------------------------------------
# Report


def _slug(label):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", label).strip("_") or "run"


class _Index:
    """Markdown lines of index.md with links relative to the report folder."""

    def __init__(self, out_dir):
        self.out_dir = out_dir
        self.lines = []
        self.skipped = []
        self.written = []

    def add(self, *lines):
        self.lines.extend(lines)

    def link(self, path):
        return path.relative_to(self.out_dir).as_posix()

    def table(self, table, stem, inline=True):
        md, csv = table.write(self.out_dir / "tables", stem)
        self.written += [md, csv]
        if inline:
            self.add(table.to_markdown(heading=False))
        self.add(f"Files: [{md.name}]({self.link(md)}) · [{csv.name}]({self.link(csv)})", "")

    def figure(self, path, caption):
        self.written.append(path)
        self.add(f"![{caption}]({self.link(path)})", "")

    def skip(self, part, reason):
        note = f"*Skipped: {reason}*"
        self.add(note, "")
        self.skipped.append(f"{part}: {reason}")


def _try(index, part, func):
    """Run one report part; a missing variable or an unusable value becomes a skip note."""
    try:
        func()
    except (MissingVariableError, ValueError) as err:
        index.skip(part, str(err))


def _run_section(index, label, cr, spec):
    slug = _slug(label)
    index.add(f"### {label}", "")

    def constraints():
        table = tables.constraint_table(cr, tol=spec.tol, refs=spec.refs)
        status = [row[-1] for row in table.rows]
        counts = {
            s: sum(1 for t in status if t.startswith(s))
            for s in ("active", "partially active", "inactive", "violated")
        }
        summary = ", ".join(f"{n} {s}" for s, n in counts.items() if n)
        index.add(f"**Constraints** (Table 7), final case: {summary}.", "")
        index.table(table, f"constraints_{slug}")

    if tables.constraint_metadata(cr):
        _try(index, f"constraints of {label}", constraints)
    else:
        index.add("The problem has no constraints.", "")

    def design_variables():
        table = tables.design_variable_table(cr, tol=spec.tol)
        on_bound = [f"{row[0]} ({row[-1]})" for row in table.rows if row[-1]]
        index.add("**Design variables**:", "")
        index.table(table, f"design_variables_{slug}", inline=False)
        index.add(
            f"On a bound at the final case ({len(on_bound)} of {len(table.rows)}): "
            + (", ".join(on_bound) if on_bound else "none")
            + ".",
            "",
        )

    def trim():
        table = trim_residual_table(cr, vehicle=spec.vehicle)
        index.add("**Trim residuals** (Table 6 rows, forces and moments in % of the weight):", "")
        index.table(table, f"trim_residuals_{slug}")

    if spec.trim_residuals:
        _try(index, f"trim residuals of {label}", trim)

    def review():
        table = design_review_table(cr, vehicle=spec.vehicle)
        index.add(
            "**Design review** (each buildability limit at its worst point, constrained or "
            "not; docs results 'study'):",
            "",
        )
        index.table(table, f"design_review_{slug}")

    every_condition = [f"{c.name}.linear_acceleration" for c in spec.vehicle.conditions]
    if spec.design_review and _recorded(cr, every_condition):  # runs over every condition
        _try(index, f"design review of {label}", review)

    def mass_properties():
        table = mass_properties_table(cr, spec.vehicle)
        index.add("**Mass properties** (mass, cg and inertia per item), final case:", "")
        index.table(table, f"mass_properties_{slug}")

    if spec.mass_properties:
        _try(index, f"mass properties of {label}", mass_properties)

    if tables.design_var_metadata(cr):
        _try(index, f"design variables of {label}", design_variables)

    found = read_sensitivities(sensitivities_path(cr._filename))
    if found is not None:
        index.add(
            "**Post-optimal sensitivities** d(W0*)/d(parameter) (KKT multipliers and adjoint; "
            "docs theory/optimization 'Post-optimal sensitivities'):",
            "",
        )
        index.table(sensitivity_table(found, cr._filename), f"sensitivities_{slug}")

    def convergence():
        path = figures.plot_convergence(
            cr,
            index.out_dir / "figures" / f"convergence_{slug}.png",
            refs=spec.refs,
            title=f"Convergence of {label}",
        )
        index.figure(path, f"Convergence of {label}")

    index.add("**Convergence**:", "")
    _try(index, f"convergence of {label}", convergence)

    def footprint():
        path = figures.plot_footprint(
            spec.vehicle,
            tables.read_value(cr, "footprint_sel"),
            tables.read_value(cr, "footprint_lamax"),
            index.out_dir / "figures" / f"footprint_{slug}.png",
            title=f"Departure noise footprint of {label}: SEL and L_Amax on the ground",
        )
        index.figure(path, f"Departure noise footprint of {label}")

    if spec.vehicle.noise_footprint is not None and _recorded(cr, ["footprint_sel"]):
        index.add("**Departure noise footprint** (docs theory/acoustics 'Noise footprint'):", "")
        _try(index, f"noise footprint of {label}", footprint)


class _RecordedValues:
    """``get_val`` over a case file's final values (:func:`tables.read_value`)."""

    def __init__(self, cr):
        self.cr = cr

    def get_val(self, name, units=None):
        return tables.read_value(self.cr, name, units)


def mass_properties_table(cr, vehicle=None):
    """
    Return the mass, cg and inertia per mass item of a run's final case as a :class:`Table`.

    The rows of :func:`lpc_mdo.api.weights.mass_properties` (the ``item_mass_properties``
    output of the WeightsGroup, recorded by ``prob.record('final')``); inertia about the
    vehicle cg, the rows add up to the vehicle's.
    """
    rows = item_mass_properties(_RecordedValues(cr), vehicle)
    total = rows[-1]["mass"]
    table = tables.Table(
        columns=["item", "mass (kg)", "share (%)", "x (m)", "y (m)", "z (m)",
                 "Ixx (kg m^2)", "Iyy (kg m^2)", "Izz (kg m^2)", "Ixz (kg m^2)"],
        title="Mass properties",
        notes=["Body frame (x forward, z down); inertia of each item about the vehicle cg "
               "(parallel-axis theorem), the rows add up to the vehicle's."],
    )  # fmt: skip
    for row in rows:
        i = row["inertia"]
        table.rows.append(
            [row["name"].replace("_", " "), row["mass"], 100.0 * row["mass"] / total,
             *(float(v) for v in row["cg"]), i[0, 0], i[1, 1], i[2, 2], i[0, 2]]
        )  # fmt: skip
    return table


def _recorded(cr, names, any_of=False):
    found = []
    for name in names:
        try:
            tables.read_value(cr, name)
            found.append(True)
        except MissingVariableError:
            found.append(False)
    return any(found) if any_of else all(found)


def _runs_with(index, runs, names, any_of=False):
    """
    Return the runs that record ``names`` and note the others.

    A run must record all of them, or any with ``any_of``.
    """
    names = list(names)
    kept = [(label, cr) for label, cr in runs if _recorded(cr, names, any_of)]
    if not kept:
        listed = (" or " if any_of else ", ").join(map(repr, names))
        raise MissingVariableError(f"no run records {listed}.")
    left_out = [label for label, _ in runs if all(label != k for k, _ in kept)]
    if left_out:
        index.add(f"*Runs left out (variables not recorded): {', '.join(left_out)}.*", "")
    return kept


def _comparison_parts(index, runs, spec):
    fig_dir = index.out_dir / "figures"

    if spec.design_quantities:

        def design_table():
            table = tables.design_table(runs, spec.design_quantities)
            if len(table.columns) == 1:
                raise MissingVariableError(
                    "none of the design quantities is recorded ("
                    + ", ".join(Quantity.coerce(q).name for q in spec.design_quantities)
                    + ")."
                )
            index.table(table, "designs")

        index.add("### Design comparison (Table 8)", "")
        _try(index, "design table", design_table)
        if spec.paper_designs:
            columns, rows = spec.paper_designs
            index.add("The paper's Table 8, for comparison:", "")
            index.table(
                tables.Table(list(columns), [list(r) for r in rows], title="Paper Table 8"),
                "designs_paper",
            )

    if spec.meshes:

        def planform():
            kept = _runs_with(index, runs, spec.meshes)

            def recorded(names, what):
                if all(_recorded(cr, names) for _, cr in kept):
                    return True
                index.add(f"*{what} {tuple(names)} left out: not recorded in every run.*", "")
                return False

            rotors = [pair for pair in spec.rotors if recorded(pair, "Rotor disks")]
            vehicle = spec.vehicle
            extras = {}
            if spec.fuselage and recorded([spec.fuselage], "Fuselage"):
                extras["fuselage"] = (spec.fuselage, vehicle.fuselage.max_width)
            if spec.pusher and recorded(spec.pusher[:2], "Pusher disk"):
                extras["pushers"] = [spec.pusher]
            if spec.vertical_tail and recorded([spec.vertical_tail], "Vertical tail"):
                extras["vertical_tail"] = (spec.vertical_tail, vehicle.vertical_tail)
            if spec.booms and recorded([spec.booms], "Booms"):
                hubs = np.array([r.hub_position for r in vehicle.lift_rotors])
                counts = {tables.read_value(cr, spec.booms).size // 3 for _, cr in kept}
                if counts == {len(hubs)}:
                    extras["booms"] = (spec.booms, hubs - np.array(vehicle.booms.attach_points))
                else:
                    index.add(
                        f"*Booms left out: {spec.booms!r} holds {sorted(counts)} hubs, the "
                        f"vehicle has {len(hubs)} booms.*",
                        "",
                    )
            path = figures.plot_planform(
                kept,
                spec.meshes,
                fig_dir / "planform.png",
                rotors=rotors,
                title="Planform, top view to scale (Fig. 15)",
                **extras,
            )
            index.figure(path, "Planform, top view to scale")
            if "booms" in extras:
                index.add(
                    "Booms: from each recorded lift-rotor hub to its wing junction, placed at "
                    "the vehicle file's hub-to-junction offset (RotorLayoutComp keeps it). "
                    "Fuselage: recorded length, the vehicle's maximum width, schematic shape.",
                    "",
                )

        index.add("### Planform (Fig. 15)", "")
        _try(index, "planform", planform)

    if spec.mass_breakdown:

        def mass():
            kept = _runs_with(index, runs, [spec.mass_breakdown])
            labels = spec.mass_labels
            if labels is not None:
                labels = [str(label).replace("_", " ") for label in labels]
            path = figures.plot_bars(
                kept,
                spec.mass_breakdown,
                fig_dir / "mass_breakdown.png",
                labels=labels,
                units=spec.mass_units,
                title="Mass breakdown (Figs. 19-20)",
                xlabel="Mass item",
            )
            index.figure(path, "Mass breakdown")

        index.add("### Mass breakdown (Figs. 19-20)", "")
        _try(index, "mass breakdown", mass)

    for key, stem, heading, conditions, reduce, units, title in (
        (
            "power",
            "power",
            "Power per condition (Fig. 16b)",
            spec.conditions,
            "sum",
            spec.power_units,
            "Electrical power per design condition, all motors (Fig. 16b)",
        ),
        (
            "figure_of_merit",
            "figure_of_merit",
            "Figure of merit per condition (Fig. 16a)",
            spec.fom_conditions,
            "mean",
            None,
            "Lift-rotor figure of merit per design condition, mean of the rotors (Fig. 16a)",
        ),
    ):
        variable = getattr(spec, key)
        if not variable:
            continue
        if variable != getattr(ReportSpec, key):
            title = None  # another variable: the figure's own title from the label table

        def per_condition(
            variable=variable,
            stem=stem,
            conditions=conditions,
            reduce=reduce,
            units=units,
            title=title,
        ):
            names = (
                [variable.format(condition=c) for c in conditions]
                if "{condition}" in variable
                else [variable]
            )
            kept = _runs_with(index, runs, names, any_of=True)
            path = figures.plot_per_condition(
                kept,
                variable,
                conditions,
                fig_dir / f"{stem}.png",
                units=units,
                reduce=reduce,
                title=title,
            )
            index.figure(path, stem.replace("_", " "))
            if stem == "figure_of_merit" and variable == ReportSpec.figure_of_merit:
                index.add(
                    "The figure of merit is the hover definition T^1.5 / (sqrt(2 rho A) P) "
                    "(BEM loads); with the freestream through the disk (transition) it can "
                    "exceed 1 and is no longer an efficiency.",
                    "",
                )

        index.add(f"### {heading}", "")
        _try(index, stem.replace("_", " "), per_condition)

    for dist in spec.distributions:

        def distribution(dist=dist):
            names = list(dist.names) + ([dist.x] if dist.x else [])
            kept = _runs_with(index, runs, names)
            path = figures.plot_distribution(
                kept,
                dist.names,
                fig_dir / f"{dist.stem}.png",
                x=dist.x,
                units=dist.units,
                x_units=dist.x_units,
                limit=dist.limit,
                title=dist.title,
                ylabel=dist.ylabel,
                xlabel=dist.xlabel,
                limit_label=dist.limit_label,
                column_label=dist.column_label,
            )
            index.figure(path, dist.stem.replace("_", " "))

        index.add(f"### Distribution: {dist.title or dist.stem}", "")
        _try(index, dist.stem, distribution)

    for sweep in spec.sweeps:

        def sweep_figure(sweep=sweep):
            points = figures.sweep_points(
                runs, sweep.x, sweep.group, sweep.x_units, sweep.group_units
            )
            if len({x for _, x, _ in points}) < 2:
                raise MissingVariableError(
                    f"fewer than two runs with different values of "
                    f"{sweep.x!r} ({len(points)} record it)."
                )
            path = figures.plot_sweep(
                points,
                fig_dir / f"{sweep.stem}.png",
                xlabel=sweep.xlabel or figures.axis_label(sweep.x, sweep.x_units),
                group_label=sweep.group_label,
            )
            index.figure(path, sweep.stem.replace("_", " "))

        index.add(f"### Sweep: {sweep.xlabel or sweep.x} (Figs. 17-18)", "")
        _try(index, sweep.stem, sweep_figure)


def write_report(case_files_or_dir, out_dir, spec=None, notify=print):
    """
    Write every table and figure the case files support into ``out_dir``, with an index.md.

    Reads each case file (driver cases, the final problem case, ``problem_metadata``) and the
    ``run_stats.json`` next to it; never a live model.

    Parameters
    ----------
    case_files_or_dir : str, os.PathLike, Mapping or Sequence
        A folder searched recursively for case files (one run per case file; a run's
        ``run_stats.json`` sits in its folder), one case file, a mapping label -> case file,
        or a sequence of case files or ``(label, case file)`` pairs.
    out_dir : str or os.PathLike
        Report folder (created); the report writes only inside it. Existing files of the same
        names are replaced, and ``notify`` is told so in one line.
    spec : ReportSpec or None
        Variable names of the LPC-specific parts; None = ``ReportSpec()`` (LPC defaults), and
        ``ReportSpec.generic()`` leaves those parts out.
    notify : callable or None
        Called with one line of text when files that existed before are replaced (default:
        ``print``); None says nothing.

    Returns
    -------
    Path
        The index.md written.

    Raises
    ------
    FileNotFoundError
        When no case file is found.
    """
    spec = ReportSpec() if spec is None else spec
    files = find_case_files(case_files_or_dir)
    if not files:
        raise FileNotFoundError(f"No case files found in {str(case_files_or_dir)!r}.")
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    existing = {p.resolve() for p in out_dir.rglob("*") if p.is_file()}
    runs = [(label, tables.open_reader(path)) for label, path in files]
    index = _Index(out_dir)

    index.add(
        "# Optimization report", "", f"Generated by lpc_mdo.post from {len(runs)} case file(s):", ""
    )
    index.add(*(f"- **{label}**: `{path}`" for label, path in files), "")

    index.add("## Statistics (Table 9)", "")
    index.table(statistics_table(runs), "statistics")

    index.add("## Runs", "")
    for label, cr in runs:
        _run_section(index, label, cr, spec)

    index.add("## Design comparison", "")
    start = len(index.lines)
    _comparison_parts(index, runs, spec)
    if len(index.lines) == start:
        index.add("No design-comparison parts requested (ReportSpec.generic()).", "")

    if index.skipped:
        index.add("## Skipped parts", "", *(f"- {note}" for note in index.skipped), "")
    path = out_dir / "index.md"
    path.write_text("\n".join(index.lines), encoding="utf-8")
    index.written.append(path)
    if notify is not None:
        line = replaced_files_note(out_dir, existing, index.written)
        if line:
            notify(line)
    return path


def replaced_files_note(out_dir, existing, written):
    """
    Return the one line that says which existing files a report replaced, or ''.

    Parameters
    ----------
    out_dir : Path
        The report folder.
    existing : set of Path
        Resolved paths of the files in it before the report was written.
    written : Sequence of Path
        Files the report wrote.

    Returns
    -------
    str
        E.g. ``'report: replaced 3 existing files in report/ (index.md, tables/statistics.md,
        tables/statistics.csv)'``; files it did not write are named as left as they were.
    """
    written = list(dict.fromkeys(Path(p).resolve() for p in written))
    replaced = [p for p in written if p in existing]
    if not replaced:
        return ""
    root = out_dir.resolve()
    names = [p.relative_to(root).as_posix() for p in replaced]
    shown = ", ".join(names[:3]) + (f" and {len(names) - 3} more" if len(names) > 3 else "")
    others = len(existing - set(written))
    kept = f"; {others} other file(s) in it left as they were" if others else ""
    return f"report: replaced {len(replaced)} existing file(s) in {out_dir}/ ({shown}){kept}"
