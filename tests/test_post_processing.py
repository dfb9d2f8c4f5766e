"""lpc_mdo.post: tables, statistics, figures and the report, from real recorded optimizations.

Problems (small, solved once per module):

* paraboloid f = (x - 3)^2 + x y + (y + 4)^2 - 3 subject to c = x - y >= L and
  v = [x, y, x + y] (m) <= 1000 cm. For L = 15 the optimum is x = 43/6, y = -47/6,
  f = -27.0833 (OpenMDAO's documentation); in general x = (3L - 2)/6, y = x - L, so c is active
  and every entry of v (|v| < 8 m) is inactive.
* Sellar MDA (implicit disciplines, Newton + DirectSolver on the cycle) with the vector
  constraint [3.16 - y1, y2 - 24] <= 0: at the optimum z = (1.9776, 0), x = 0 the first entry is
  active and the second is not (y2 = 3.755), and x and z[1] sit at their lower bounds.
"""

import csv
import re
import shutil
from pathlib import Path

import numpy as np
import openmdao.api as om
import pytest
from openmdao.test_suite.components.paraboloid import Paraboloid
from openmdao.test_suite.components.sellar import SellarImplicitDis1, SellarImplicitDis2

from lpc_mdo.drivers import IpoptDriver
from lpc_mdo.post import figures, report, statistics, tables

# Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = [
    pytest.mark.integration,
    pytest.mark.filterwarnings("ignore:The following groups have a nonlinear solver"),
]

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


class VectorComp(om.ExplicitComponent):
    """v = [x, y, x + y] in metres."""

    def setup(self):
        self.add_input("x", 0.0)
        self.add_input("y", 0.0)
        self.add_output("v", np.zeros(3), units="m")
        self.declare_partials("v", "x", rows=[0, 2], cols=[0, 0], val=1.0)
        self.declare_partials("v", "y", rows=[1, 2], cols=[0, 0], val=1.0)

    def compute(self, inputs, outputs):
        x, y = inputs["x"][0], inputs["y"][0]
        outputs["v"] = [x, y, x + y]


class SellarConstraints(om.ExplicitComponent):
    """con = [3.16 - y1, y2 - 24]."""

    def setup(self):
        self.add_input("y1", 0.0)
        self.add_input("y2", 0.0)
        self.add_output("con", np.zeros(2))
        self.declare_partials("con", "y1", rows=[0], cols=[0], val=-1.0)
        self.declare_partials("con", "y2", rows=[1], cols=[0], val=1.0)

    def compute(self, inputs, outputs):
        outputs["con"] = [3.16 - inputs["y1"][0], inputs["y2"][0] - 24.0]


def _record_and_run(prob, path, driver):
    prob.driver = driver
    rec = om.SqliteRecorder(str(path))
    prob.driver.add_recorder(rec)
    prob.add_recorder(rec)
    prob.recording_options["includes"] = ["*"]
    prob.setup()
    result = prob.run_driver()
    prob.record("final")
    prob.cleanup()
    statistics.write_run_stats(result, path.parent, peak_memory_mb=123.5)
    return result


def paraboloid_run(path, driver, c_lower=15.0):
    """Paraboloid optimization recorded to ``path``, with LPC-like extra outputs."""
    prob = om.Problem(reports=False)
    m = prob.model
    geom = m.add_subsystem("geom", om.IndepVarComp(), promotes=["*"])
    geom.add_output(
        "wing_mesh",
        np.array(
            [
                [[0.0, -4.0, 0.0], [0.5, 0.0, 0.0], [0.0, 4.0, 0.0]],
                [[-1.0, -4.0, 0.0], [-1.5, 0.0, 0.0], [-1.0, 4.0, 0.0]],
            ]
        ),
        units="m",
    )
    geom.add_output(
        "tail_mesh",
        np.array([[[-5.0, -1.0, 0.0], [-5.0, 1.0, 0.0]], [[-5.5, -1.0, 0.0], [-5.5, 1.0, 0.0]]]),
        units="m",
    )
    geom.add_output("hubs", np.array([[0.5, -2.0, 0.0], [0.5, 2.0, 0.0]]), units="m")
    geom.add_output("radii", np.array([0.6, 0.6]), units="m")
    # Planform extras: fuselage length, pusher hub and radius (the last one), fin root LE.
    geom.add_output("fus_length", 6.0, units="m")
    geom.add_output("pusher_hub", np.array([-6.2, 0.0, 0.0]), units="m")
    geom.add_output("all_radii", np.array([0.6, 0.8]), units="m")
    geom.add_output("fin_le", np.array([-5.0, 0.0, -0.3]), units="m")
    geom.add_output("skin", np.array([4.0, 3.0, 2.0, 1.0]), units="mm")
    geom.add_output("stations", np.linspace(0.0, 4.0, 5), units="m")
    geom.add_output("stress", np.arange(8.0).reshape(4, 2), units="MPa")
    m.add_subsystem("parab", Paraboloid(), promotes=["*"])
    m.add_subsystem("con", om.ExecComp("c = x - y"), promotes=["*"])
    m.add_subsystem("vec", VectorComp(), promotes=["*"])
    m.add_subsystem(
        "hover",
        om.ExecComp(
            ["electrical_power = 1000.0*(x**2 + 1.0)", "lift_figure_of_merit = 0.1*x*r"],
            electrical_power={"units": "W"},
            lift_figure_of_merit={"shape": (2,)},
            r={"shape": (2,), "val": [1.0, 0.5]},
        ),
        promotes_inputs=["x"],
    )
    m.add_subsystem(
        "cruise",
        om.ExecComp("electrical_power = 500.0*(y**2 + 1.0)", electrical_power={"units": "W"}),
        promotes_inputs=["y"],
    )
    m.set_input_defaults("x", 3.0)
    m.set_input_defaults("y", -4.0)
    m.add_design_var("x", lower=-50.0, upper=50.0)
    m.add_design_var("y", lower=-50.0, upper=50.0)
    m.add_objective("f_xy")
    m.add_constraint("c", lower=c_lower)
    m.add_constraint("v", upper=1000.0, units="cm")
    return _record_and_run(prob, path, driver)


def sellar_run(path):
    """Sellar MDA with IPOPT and recorded derivatives; returns (result, live model counts)."""
    prob = om.Problem(reports=False)
    m = prob.model
    cycle = m.add_subsystem("cycle", om.Group(), promotes=["*"])
    cycle.add_subsystem("d1", SellarImplicitDis1(), promotes=["*"])
    cycle.add_subsystem("d2", SellarImplicitDis2(), promotes=["*"])
    cycle.nonlinear_solver = om.NewtonSolver(solve_subsystems=False, iprint=-1, maxiter=30)
    cycle.linear_solver = om.DirectSolver()
    m.add_subsystem(
        "obj_cmp", om.ExecComp("obj = x**2 + z[1] + y1 + exp(-y2)", z=np.zeros(2)), promotes=["*"]
    )
    m.add_subsystem("cons", SellarConstraints(), promotes=["*"])
    m.set_input_defaults("x", 1.0)
    m.set_input_defaults("z", np.array([5.0, 2.0]))
    m.add_design_var("x", lower=0.0, upper=10.0)
    m.add_design_var("z", lower=np.array([-10.0, 0.0]), upper=np.array([10.0, 10.0]))
    m.add_objective("obj")
    m.add_constraint("con", upper=0.0)
    driver = IpoptDriver(print_level=0)
    driver.recording_options["record_derivatives"] = True
    result = _record_and_run(prob, path, driver)

    from openmdao.core.component import Component

    outputs = m.list_outputs(out_stream=None, shape=True)
    live = dict(
        components=sum(
            1 for s in m.system_iter(recurse=True, typ=Component) if s.pathname != "_auto_ivc"
        ),
        groups=len(list(m.system_iter(recurse=True, typ=om.Group))),
        implicit_components=len(list(m.system_iter(recurse=True, typ=om.ImplicitComponent))),
        inputs=len(m.list_inputs(out_stream=None)),
        outputs=len(outputs),
        output_size=sum(int(np.prod(meta["shape"])) for _, meta in outputs),
    )
    return result, live


@pytest.fixture(scope="module")
def runs(tmp_path_factory, ipopt):
    """Case files of all runs, each in its own folder of one study folder."""
    root = tmp_path_factory.mktemp("study")
    with pytest.MonkeyPatch.context() as mp:
        mp.chdir(root)
        mp.setenv("OPENMDAO_WORKDIR", str(root))
        out = {}
        for name, driver, c_lower in (
            ("ipopt", IpoptDriver(print_level=0), 15.0),
            ("slsqp", om.ScipyOptimizeDriver(optimizer="SLSQP", disp=False), 16.0),
        ):
            path = root / "runs" / name / "cases.sql"
            path.parent.mkdir(parents=True)
            out[name] = (path, paraboloid_run(path, driver, c_lower), c_lower)
        path = root / "runs" / "sellar" / "cases.sql"
        path.parent.mkdir(parents=True)
        out["sellar"] = (path, *sellar_run(path))
    out["root"] = root / "runs"
    return out


def paraboloid_optimum(c_lower):
    x = (3.0 * c_lower - 2.0) / 6.0
    y = x - c_lower
    return x, y, (x - 3.0) ** 2 + x * y + (y + 4.0) ** 2 - 3.0


# ------------------------------------------------------------------------------------------------
# tables


@pytest.mark.parametrize("name", ["ipopt", "slsqp"])
def test_constraint_table_equals_recorded_values(runs, name):
    path, result, c_lower = runs[name]
    assert result.success
    cr = om.CaseReader(str(path))
    last = cr.get_case(cr.list_cases("driver", recurse=False, out_stream=None)[-1])
    recorded = last.get_constraints()
    x, y, _ = paraboloid_optimum(c_lower)
    np.testing.assert_allclose(last.get_val("x"), x, rtol=1e-5)

    rows = {r["constraint"]: r for r in tables.constraint_table(path).as_dicts()}
    assert list(rows) == ["c", "v"]
    for con in rows:
        assert rows[con]["min"] == float(np.min(recorded[con]))
        assert rows[con]["max"] == float(np.max(recorded[con]))
    # v is recorded in its declared units (cm), not the output's metres.
    np.testing.assert_allclose(rows["v"]["min"], 100.0 * y, rtol=1e-5)
    assert rows["c"]["lower"] == c_lower and rows["c"]["upper"] is None
    assert rows["v"]["upper"] == 1000.0 and rows["v"]["units"] == "cm"
    assert rows["c"]["status"] == "active" and rows["c"]["active"] == "1/1"
    assert rows["v"]["status"] == "inactive" and rows["v"]["active"] == "0/3"
    assert rows["c"]["% viol."] < 1e-4 and rows["v"]["% viol."] == 0.0


def test_constraint_table_partially_active_vector(runs):
    path = runs["sellar"][0]
    (row,) = tables.constraint_table(path).as_dicts()
    assert row["constraint"] == "con" and row["upper"] == 0.0
    assert row["status"] == "partially active (1 of 2)" and row["active"] == "1/2"


def test_entry_status_equality_violation_and_two_sided():
    viol, active, violated = tables.entry_status([1.0, 1.00001, 1.1], equals=1.0, scale=1.0)
    np.testing.assert_allclose(viol, [0.0, 1e-5, 0.1], atol=1e-12)
    assert active.tolist() == [True, True, False] and violated.tolist() == [False, False, True]
    viol, active, violated = tables.entry_status(
        [0.0, 0.5, 1.0, 1.2], lower=0.0, upper=1.0, scale=np.array([1.0, 1.0, 1.0, 1.0])
    )
    assert active.tolist() == [True, False, True, False]
    assert violated.tolist() == [False, False, False, True]
    np.testing.assert_allclose(viol, [0.0, 0.0, 0.0, 0.2])


def test_limit_scale_of_a_scaled_constraint_is_at_least_its_ref():
    # A prescribed acceleration of 0.017 m/s^2 on a row scaled by g: the band is tol * g, the
    # magnitude the optimizer's tolerance is measured in, not tol * 0.017.
    equals = np.array([0.017, 0.25])
    scaled = tables.limit_scale({"size": 2, "ref": 9.81, "ref0": None}, equals=equals)
    np.testing.assert_allclose(scaled, [9.81, 9.81])
    np.testing.assert_allclose(
        tables.limit_scale({"size": 2, "ref": 0.1}, equals=equals), [0.1, 0.25]
    )
    # Unscaled: the limit itself, else 1.
    np.testing.assert_allclose(
        tables.limit_scale({"size": 2}, equals=np.array([0.017, 0.0])), [0.017, 1.0]
    )


def test_tables_written_as_markdown_and_csv(runs, tmp_path):
    path = runs["ipopt"][0]
    table = tables.constraint_table(path)
    md, csv_path = table.write(tmp_path, "constraints")
    assert md.read_text().startswith("# Constraints")
    with open(csv_path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [r["constraint"] for r in rows] == ["c", "v"]
    # CSV keeps full precision.
    assert float(rows[1]["min"]) == table.as_dicts()[1]["min"]


def test_design_variable_table_initial_final_and_bounds(runs):
    path = runs["sellar"][0]
    cr = om.CaseReader(str(path))
    ids = cr.list_cases("driver", recurse=False, out_stream=None)
    first, last = cr.get_case(ids[0]), cr.get_case(ids[-1])
    rows = {r["design variable"]: r for r in tables.design_variable_table(path).as_dicts()}
    assert list(rows) == ["x", "z[0]", "z[1]"]
    assert rows["x"]["initial"] == first.get_val("x")[0] == 1.0
    assert rows["z[0]"]["final"] == last.get_val("z")[0]
    assert (rows["x"]["at bound"], rows["z[0]"]["at bound"], rows["z[1]"]["at bound"]) == (
        "lower",
        "",
        "lower",
    )
    (agg,) = [
        r
        for r in tables.design_variable_table(path, expand=False).as_dicts()
        if r["design variable"] == "z"
    ]
    assert agg["size"] == 2 and agg["at bound"] == "1 lower"


def test_design_table_reads_each_design(runs):
    designs = [("IPOPT", runs["ipopt"][0]), ("SLSQP", runs["slsqp"][0])]
    table = tables.design_table(
        designs,
        [
            ("x", "x"),
            ("tip", "wing_mesh", "cm", 7),
            ("S", "not_recorded"),
            ("P", "hover.electrical_power"),
        ],
    )
    # Columns without units given show the recorded units.
    assert table.columns == ["design", "x", "tip (cm)", "P (W)"]
    assert tables.recorded_units(designs[0][1], "v") == "m"
    assert tables.recorded_units(designs[0][1], "x") is None
    assert any("not_recorded" in note for note in table.notes)
    for (label, path), row in zip(designs, table.rows, strict=True):
        final = om.CaseReader(str(path)).get_case("final")
        assert row[0] == label and row[1] == final.get_val("x")[0]
        assert row[2] == pytest.approx(400.0)  # flat index 7: y of the right leading-edge tip


# ------------------------------------------------------------------------------------------------
# statistics


def test_run_stats_round_trip(runs, tmp_path):
    path, result, _ = runs["ipopt"]
    stats = statistics.read_run_stats(path)
    for key in (
        "runtime",
        "iter_count",
        "model_evals",
        "model_time",
        "deriv_evals",
        "deriv_time",
        "success",
        "exit_status",
    ):
        assert stats[key] == getattr(result, key), key
    assert stats["peak_memory_mb"] == 123.5
    written = statistics.write_run_stats(
        {"runtime": 2.5, "success": False}, tmp_path / "other.json"
    )
    assert statistics.read_run_stats(written) == {
        **dict.fromkeys(statistics.RUN_STATS_KEYS),
        "runtime": 2.5,
        "success": False,
    }
    assert statistics.read_run_stats(tmp_path / "cases.sql") is None


def test_statistics_count_the_model_and_the_run(runs):
    path, result, live = runs["sellar"]
    stats = statistics.run_statistics(path)
    for key, value in live.items():
        assert stats[key] == value, key
    assert stats["implicit_components"] == 2 and stats["implicit_outputs"] == 2
    cr = om.CaseReader(str(path))
    cases = cr.get_cases("driver", recurse=False)
    assert stats["driver_cases"] == len(cases)
    assert stats["derivative_cases"] == sum(c.derivatives is not None for c in cases) > 0
    assert stats["wall_time"] == result.runtime
    assert stats["iter_count"] == result.iter_count
    assert stats["mean_deriv_time"] == pytest.approx(result.deriv_time / result.deriv_evals)
    assert (stats["design_var_size"], stats["constraint_size"]) == (3, 2)

    table = statistics.statistics_table([("sellar", path), ("ipopt", runs["ipopt"][0])])
    rows = {r["metric"]: r for r in table.as_dicts()}
    assert rows["Components"]["sellar"] == live["components"]
    assert rows["Implicit components"]["ipopt"] == 0
    assert rows["Wall time source"]["sellar"] == "run_stats.json"


# ------------------------------------------------------------------------------------------------
# figures


def _is_png(path):
    path = Path(path)
    return path.is_file() and path.read_bytes()[:8] == PNG_MAGIC


def test_convergence_history_matches_driver_cases(runs, tmp_path):
    path = runs["sellar"][0]
    hist = figures.convergence_history(path)
    cases = om.CaseReader(str(path)).get_cases("driver", recurse=False)
    np.testing.assert_array_equal(hist["objective"], [c.get_objectives()["obj"][0] for c in cases])
    assert hist["max_violation"][-1] < 1e-6 and hist["derivatives"].sum() > 0
    assert _is_png(figures.plot_convergence(path, tmp_path / "conv.png"))


def test_figures_are_written(runs, tmp_path):
    designs = [("IPOPT", runs["ipopt"][0]), ("SLSQP", runs["slsqp"][0])]
    written = [
        figures.plot_bars(
            designs, "v", tmp_path / "bars.png", labels=["x", "y", "x+y"], units="cm"
        ),
        figures.plot_per_condition(
            designs,
            "{condition}.electrical_power",
            ["hover", "cruise", "climb"],
            tmp_path / "power.png",
            units="kW",
        ),
        figures.plot_per_condition(
            designs,
            "{condition}.lift_figure_of_merit",
            ["hover"],
            tmp_path / "fom.png",
            reduce="mean",
        ),
        figures.plot_per_condition(designs, "v", ["a", "b", "c"], tmp_path / "vector.png"),
        figures.plot_distribution(
            designs, "stress", tmp_path / "stress.png", x="stations", limit=5.0
        ),
        figures.plot_distribution(runs["ipopt"][0], ["skin", "skin"], tmp_path / "skin.png"),
        figures.plot_planform(
            designs,
            ["wing_mesh", "tail_mesh"],
            tmp_path / "plan.png",
            rotors=[("hubs", "radii")],
            mirror=True,
        ),
    ]
    assert all(_is_png(p) for p in written)
    with pytest.raises(tables.MissingVariableError, match="not_there"):
        figures.plot_bars(designs, "not_there", tmp_path / "missing.png")
    with pytest.raises(tables.MissingVariableError, match="climb"):
        figures.plot_per_condition(designs, "{condition}.power", ["climb"], tmp_path / "p.png")


def test_sweep_points_and_plot(runs, tmp_path):
    sources = [runs["ipopt"][0], runs["slsqp"][0], runs["sellar"][0]]
    points = figures.sweep_points(sources, "lower:c")
    assert [x for _, x, _ in points] == [15.0, 16.0]  # Sellar has no constraint c
    for cr, c_lower, _ in points:
        assert figures.objective_value(cr)[1] == pytest.approx(
            paraboloid_optimum(c_lower)[2], rel=1e-6
        )
    path = figures.plot_sweep(
        points, tmp_path / "sweep.png", xlabel="L", highlight=[("start", runs["ipopt"][0], 15.0)]
    )
    assert _is_png(path)


# ------------------------------------------------------------------------------------------------
# report


def _links(index):
    return re.findall(r"\]\(([^)]+)\)", index.read_text())


def test_write_report_on_a_folder(runs, tmp_path):
    spec = report.ReportSpec(
        design_quantities=(("x", "x"), ("f", "f_xy")),
        meshes=("wing_mesh", "tail_mesh"),
        rotors=(("hubs", "radii"), ("no_hubs", "radii")),
        fuselage="fus_length",
        pusher=("pusher_hub", "all_radii", -1),
        vertical_tail="fin_le",
        booms="hubs",
        mass_breakdown="v",
        mass_labels=("x", "y", "x+y"),
        mass_units="cm",
        conditions=("hover", "cruise"),
        power="{condition}.electrical_power",
        figure_of_merit="{condition}.lift_figure_of_merit",
        fom_conditions=("hover",),
        distributions=(report.DistributionSpec("stress", ("stress",), x="stations"),),
        sweeps=(report.SweepSpec("sweep_c", "lower:c"),),
        trim_residuals=False,
        mass_properties=False,
    )  # the test models have no LPC trim or mass-item outputs
    index = report.write_report(runs["root"], tmp_path / "report", spec)
    links = _links(index)
    assert links and all((index.parent / link).is_file() for link in links)
    names = {Path(link).name for link in links}
    for run in ("ipopt", "slsqp", "sellar"):
        assert {
            f"constraints_{run}.md",
            f"constraints_{run}.csv",
            f"design_variables_{run}.csv",
            f"convergence_{run}.png",
        } <= names
    assert {
        "statistics.md",
        "designs.md",
        "planform.png",
        "mass_breakdown.png",
        "power.png",
        "figure_of_merit.png",
        "stress.png",
        "sweep_c.png",
    } <= names
    text = index.read_text()
    # Sellar records none of the paraboloid's extras: the comparisons leave it out with a note,
    # as they leave out the rotor pair that no run records.
    # Sellar's x and z[1] end on their lower bounds (test_design_variable_table_...).
    assert "On a bound at the final case (2 of 3): x (lower), z[1] (lower)." in text
    assert "Runs left out (variables not recorded): sellar." in text
    assert "Rotor disks ('no_hubs', 'radii') left out" in text
    # 2 hubs in the test model, 8 booms in the (reference) vehicle: no boom is drawn.
    assert "Booms left out: 'hubs' holds [2] hubs, the vehicle has 8 booms." in text
    assert "## Skipped parts" not in text


def test_write_report_lpc_defaults_skip_absent_parts(runs, tmp_path):
    index = report.write_report({"opt": runs["ipopt"][0]}, tmp_path / "report")
    text = index.read_text()
    assert all((index.parent / link).is_file() for link in _links(index))
    assert "## Skipped parts" in text
    for part in (
        "design table",
        "planform",
        "mass breakdown",
        "skin_thickness",
        "stress_plus_3g",
        "sweep_energy_density",
        "sweep_final_soc",
        "trim residuals of opt",
        "mass properties of opt",
    ):
        assert f"- {part}:" in text, part
    # The test model records hover.electrical_power etc. under the LPC default names.
    assert {"power.png", "figure_of_merit.png"} <= {Path(link).name for link in _links(index)}
    # The paper's Table 8 is printed beside ours (its W0 of the calibrated 3723.99 kg reference).
    assert (
        "| Optimized w/ SM | 10.66 | 15.04 | 15.76 | 2.59 | 3.01 | 1.78 | 1.47 | 1.6 | 3814.8 |"
        in text
    )
    generic = report.write_report(
        runs["ipopt"][0], tmp_path / "generic", report.ReportSpec.generic()
    )
    assert "Skipped" not in generic.read_text()
    assert "Paper Table 8" not in generic.read_text()


# ------------------------------------------------------------------------------------------------
# figures a person reads: titles, labels in words with units, the planform to scale

# "Words (units)": starts with a capital letter, no variable-name underscores, units in brackets.
WORDS_WITH_UNITS = re.compile(r"^[A-Z][^_]*\([^()_]+\)$")


@pytest.fixture
def drawn(monkeypatch):
    """Collect the Figure objects the figure functions save, in order."""
    figs = []
    save = figures._save

    def keep(fig, path):
        figs.append(fig)
        return save(fig, path)

    monkeypatch.setattr(figures, "_save", keep)
    return figs


def _texts(ax):
    legend = ax.get_legend()
    return [t.get_text() for t in legend.get_texts()] if legend else []


def test_label_table_gives_words_and_units():
    assert figures.axis_label("mass_breakdown") == "Mass (kg)"
    assert figures.axis_label("hover.electrical_power") == "Electrical power (kW)"
    assert figures.axis_label("{condition}.electrical_power") == "Electrical power (kW)"
    assert figures.axis_label("cruise.lift_figure_of_merit") == "Lift-rotor figure of merit (-)"
    assert figures.axis_label("battery.specific_energy") == "Battery energy density (Wh/kg)"
    # A name not in the table: its words, the given units.
    assert figures.describe("plus_3g.tip_deflection") == ("Tip deflection", None)
    assert figures.axis_label("tip_deflection", "mm") == "Tip deflection (mm)"
    for name, (words, units) in figures.LABELS.items():
        assert "_" not in words and words[0].isupper() and units, name


def test_every_figure_has_a_title_and_axes_in_words_with_units(runs, tmp_path, drawn):
    designs = [("IPOPT", runs["ipopt"][0]), ("SLSQP", runs["slsqp"][0])]
    paths = [
        figures.plot_convergence(runs["sellar"][0], tmp_path / "conv.png"),
        figures.plot_bars(designs, "v", tmp_path / "bars.png", labels=["x", "y", "x+y"]),
        figures.plot_per_condition(
            designs, "{condition}.electrical_power", ["hover", "cruise"], tmp_path / "power.png"
        ),
        figures.plot_per_condition(
            designs,
            "{condition}.lift_figure_of_merit",
            ["hover"],
            tmp_path / "fom.png",
            reduce="mean",
        ),
        figures.plot_distribution(
            runs["ipopt"][0], "stress", tmp_path / "stress.png", x="stations", limit=5.0
        ),
        figures.plot_planform(designs, ["wing_mesh"], tmp_path / "plan.png"),
        figures.plot_sweep(
            figures.sweep_points(designs, "lower:c"), tmp_path / "sweep.png", xlabel="L (-)"
        ),
    ]
    assert len(drawn) == len(paths) and all(_is_png(p) for p in paths)
    for fig, path in zip(drawn, paths, strict=True):
        axes = fig.get_axes()
        assert axes[0].get_title(), path.name
        for ax in axes:
            if ax.get_ylabel():
                assert WORDS_WITH_UNITS.match(ax.get_ylabel()), (path.name, ax.get_ylabel())
            assert all("_" not in text for text in _texts(ax)), (path.name, _texts(ax))
        xlabel = axes[-1].get_xlabel()
        assert WORDS_WITH_UNITS.match(xlabel) or xlabel in ("Item", "Design condition"), xlabel
    conv, bars, power, fom, stress, plan, sweep = drawn
    assert conv.axes[0].get_ylabel() == "Objective: obj (-)"
    assert bars.axes[0].get_ylabel() == "V (m)" and bars.axes[0].get_title() == "V"
    # The table's kW: the bars are 1000 (x^2 + 1) W and 500 (y^2 + 1) W in kW.
    ax = power.axes[0]
    assert ax.get_ylabel() == "Electrical power (kW)"
    assert ax.get_title() == "Electrical power per design condition"
    x, y, _ = paraboloid_optimum(15.0)
    heights = [bar.get_height() for bar in ax.containers[0]]
    np.testing.assert_allclose(heights, [x**2 + 1.0, 0.5 * (y**2 + 1.0)], rtol=1e-5)
    assert _texts(ax) == ["IPOPT", "SLSQP"]
    assert fom.axes[0].get_ylabel() == "Lift-rotor figure of merit (-)"
    ax = stress.axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("Stations (m)", "Stress (MPa)")
    assert _texts(ax) == ["Column 1", "Column 2", "Limit 5 MPa"]
    assert plan.axes[0].get_aspect() == 1.0
    assert plan.axes[0].get_ylabel() == "Body x, forward (m)"
    assert sweep.axes[0].get_ylabel() == "F xy (-)"


def test_planform_draws_every_part_to_scale(runs, tmp_path, drawn):
    class Fin:  # root chord 1, tip chord 0.5, height 1, 45 deg sweep, t/c 0.1
        root_chord, tip_chord, span, sweep, thickness_to_chord = 1.0, 0.5, 1.0, np.pi / 4, 0.1

    offsets = [[1.0, 0.5, 0.0], [1.0, -0.5, 0.0]]  # hub minus wing junction
    designs = [("IPOPT", runs["ipopt"][0]), ("SLSQP", runs["slsqp"][0])]
    figures.plot_planform(
        designs,
        ["wing_mesh", "tail_mesh"],
        tmp_path / "plan.png",
        rotors=[("hubs", "radii")],
        fuselage=("fus_length", 1.5),
        pushers=[("pusher_hub", "all_radii", -1)],
        vertical_tail=("fin_le", Fin),
        booms=("hubs", offsets),
    )
    (ax,) = drawn[0].get_axes()
    artists = ax.get_children()

    def parts(gid):
        return [a for a in artists if a.get_gid() == gid]

    # Per design: 2 lift-rotor disks, 1 fuselage, 1 fin, 2 booms, 1 pusher, 2 surfaces.
    counts = {g: len(parts(g)) for g in ("lift_rotor_disk", "fuselage", "vertical_tail")}
    counts.update({g: len(parts(g)) for g in ("boom", "pusher_disk", "surface")})
    assert counts == dict(
        lift_rotor_disk=4, fuselage=2, vertical_tail=2, boom=4, pusher_disk=2, surface=4
    )
    disk = parts("lift_rotor_disk")[0]
    assert disk.get_radius() == pytest.approx(0.6) and disk.center == pytest.approx((-2.0, 0.5))
    body = parts("fuselage")[0].get_xy()  # (y, x) points
    assert body[:, 1].max() == pytest.approx(0.0) and body[:, 1].min() == pytest.approx(-6.0)
    assert np.abs(body[:, 0]).max() == pytest.approx(0.75)
    pusher = parts("pusher_disk")[0].get_xydata()  # across y = +-0.8 m at x = -6.2 m
    np.testing.assert_allclose(pusher, [[-0.8, -6.2], [0.8, -6.2]])
    boom = parts("boom")[0].get_xydata()  # from the hub (0.5, -2) to the junction (-0.5, -2.5)
    np.testing.assert_allclose(boom, [[-2.0, 0.5], [-2.5, -0.5]])
    fin = parts("vertical_tail")[0].get_xy()
    # Tip TE: -5 - 1 tan 45 - 0.5 = -6.5 behind the root TE -6; width t/c c_root = 0.1 m.
    assert fin[:, 1].min() == pytest.approx(-6.5) and np.ptp(fin[:, 0]) == pytest.approx(0.1)
    assert ax.get_aspect() == 1.0
    legend = _texts(ax)
    assert {"Lift-rotor disk (radius)", "Fuselage (length, maximum width)", "IPOPT"} <= set(legend)
    assert all("_" not in text for text in legend)


def test_fuselage_outline_has_the_true_length_and_width():
    outline = figures.fuselage_outline(9.144, 1.557)
    x, y = outline[:, 0], outline[:, 1]
    assert (x.max(), x.min()) == (0.0, pytest.approx(-9.144))
    assert y.max() == pytest.approx(1.557 / 2) and y.min() == pytest.approx(-1.557 / 2)
    assert y[np.argmin(x)] == pytest.approx(0.15 * 1.557 / 2)  # the tail cone's end


def test_report_says_when_it_replaces_files(runs, tmp_path):
    out = tmp_path / "report"
    notes = []
    index = report.write_report(runs["ipopt"][0], out, report.ReportSpec.generic(), notes.append)
    assert notes == []  # a new folder: nothing replaced
    (out / "mine.txt").write_text("not the report's")
    written = {index.resolve(), *((index.parent / link).resolve() for link in _links(index))}
    report.write_report(runs["ipopt"][0], out, report.ReportSpec.generic(), notes.append)
    (line,) = notes
    assert line.startswith(f"report: replaced {len(written)} existing file(s) in {out}/ (")
    assert line.endswith("; 1 other file(s) in it left as they were")
    assert (out / "mine.txt").read_text() == "not the report's"
    assert all(p.is_relative_to(out.resolve()) for p in written)  # it writes only there


def test_report_run_label_of_a_run_folder(runs):
    # analysis_out/cases.sql is named by its folder, not "cases".
    ((label, _),) = report.find_case_files(runs["ipopt"][0])
    assert label == "ipopt"


def test_bars_mark_what_a_run_did_not_compute(runs, tmp_path, drawn):
    # Sellar records no hover.electrical_power: its slot is an 'x', not an empty (zero) bar.
    designs = [("IPOPT", runs["ipopt"][0]), ("Sellar", runs["sellar"][0])]
    figures.plot_per_condition(
        designs, "{condition}.electrical_power", ["hover"], tmp_path / "power.png"
    )
    (ax,) = drawn[0].get_axes()
    assert "not computed in that run" in _texts(ax)
    marks = [line for line in ax.get_lines() if line.get_marker() == "x" and len(line.get_xdata())]
    assert len(marks) == 1 and marks[0].get_ydata().tolist() == [0.0]


def test_constraint_status_words_and_own_tolerance():
    import numpy as np

    # satisfied / active / violated from entry_status's bands (tol * r).
    _, active, violated = tables.entry_status([0.5], upper=1.0, scale=1.0)
    assert tables.status_word(active, violated) == "satisfied"
    _, active, violated = tables.entry_status([0.99995, 0.5], upper=1.0, scale=1.0)
    assert tables.status_word(active, violated) == "active (1 of 2)"
    _, active, violated = tables.entry_status([1.01], upper=1.0, scale=1.0)
    assert tables.status_word(active, violated) == "violated"
    # A trim-like row 5e-4 off its target reads violated at tol 1e-4, active at 1e-3.
    _, active, violated = tables.entry_status(np.array([5e-4]), equals=0.0, scale=1.0)
    assert tables.status_word(active, violated) == "violated"
    _, active, violated = tables.entry_status([5e-4], equals=0.0, scale=1.0, tol=1e-3)
    assert tables.status_word(active, violated) == "active"


def test_report_prints_the_sensitivities_written_beside_a_case_file(runs, tmp_path):
    from lpc_mdo.sensitivities import Sensitivity, SensitivityResult, sensitivities_path

    case_file = tmp_path / "full.sql"
    shutil.copy(runs["slsqp"][0], case_file)
    rows = [Sensitivity("payload", "payload", "kg", 540.0, 1.5627, 0.3179)]
    polished = SensitivityResult(gross_mass=2654.5, rows=rows, kkt_residual=0.01, active=[])
    polished.to_json(sensitivities_path(case_file))
    index = report.write_report(case_file, tmp_path / "report", report.ReportSpec.generic())
    text = index.read_text()
    assert "**Post-optimal sensitivities**" in text
    assert "| payload | 540 | kg | 1.5627 | 0.3179 |" in text
    assert "relative KKT residual 1.0e-02" in text
    # A loosely converged optimum (0.06 > LOOSE_KKT_RESIDUAL): no numbers, the polish command.
    loose = SensitivityResult(gross_mass=2654.5, rows=rows, kkt_residual=0.06, active=[])
    loose.to_json(sensitivities_path(case_file))
    index = report.write_report(case_file, tmp_path / "report2", report.ReportSpec.generic())
    text = index.read_text()
    assert "1.5627" not in text and "Not shown: the optimum is loosely converged" in text
    assert f"--start-case {case_file} --tol 1e-6" in text
