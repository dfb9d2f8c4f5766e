"""
Size a vehicle to its mission without an optimizer: battery, gross mass and motors.

:func:`size_vehicle` holds the vehicle's planform, rotors and wing box and closes what a sizing
code closes on its mission (as NDARC or FLOPS do):

- the battery mass m_b, so that the mission and its reserve end at the state-of-charge floor
  ``constraints.min_final_soc``: with the battery model SoC = SoC_0 - E/(e m_b) (docs
  theory/energy), the mass that would end there at the current energy is
  m* = E(m_b)/(e (SoC_0 - SoC_min)); the closure is m_b = m*(m_b), solved by secant steps on
  g(m_b) = m_b - m*(m_b) (the energy grows with the battery's own mass, so plain substitution
  converges slowly, by a factor of about 0.4 per step);
- the design gross mass W_dg of the regressions that scale with it (landing gear, wing secondary
  structure, systems; docs theory/weights) equal to the gross mass W0 it gives, by secant steps
  on model runs at each new battery mass (the slope dW0/dW_dg is about 0.14); a calibrated
  vehicle, ``masses.other_rule = "calibrated"``, keeps its W_dg (its W_other closes it);
- each motor design to its margins at the step's loads (:mod:`lpc_mdo.motor_sizing`: the
  length to the torque margin and the control reserve, the winding to the bus), in every
  condition whose motors turn (hover, one rotor out, transition, climb, cruise, descent);

each step trimming those conditions at the step's masses and motors (:func:`lpc_mdo.trim.trim`;
where a family of trims holds a condition, the one of least electrical power within its limits,
so that the energy and the motors' loads are defined by the design, not by the trim's start).
Closed: SoC within 5e-4 above SoC_min (aimed at 2.5e-4 above: never below the floor), W0 within 0.01
kg of W_dg (which also sizes the landing gear's tyres and so their drag), and the motors sized at
the step's loads within 0.2 mm and 1 A of those the step flew; then one more trim flies the sized
motors, so that their margins sit at the limits plus the trim allowance
(:data:`lpc_mdo.motor_sizing.TRIM_ALLOWANCE`; the battery and W_dg still closed there). The
rotors, the wing and its gauges stay as the vehicle file gives them
(the optimizer sizes those).
"""

from __future__ import annotations

import dataclasses
import math
import os
import re
import time
from importlib import resources
from pathlib import Path

import numpy as np
import openmdao.api as om

from lpc_mdo.core.constants import GRAVITY
from lpc_mdo.groups.vehicle import close_design_gross_mass
from lpc_mdo.motor_sizing import (
    CURRENT,
    LENGTH,
    MotorSizing,
    MotorSizingError,
    control_ratio,
    motor_margins,
    size_motors,
)
from lpc_mdo.problems import build_analysis_problem
from lpc_mdo.trim import trim
from lpc_mdo.vehicle import AIRFOILS, load_vehicle
from lpc_mdo.vehicle.file_edit import replace_initial, replace_table_value

__all__ = [
    "SizingError",
    "SizingResult",
    "rounded_up",
    "size_vehicle",
    "sized_vehicle_text",
    "with_sized_values",
]

#: Closure tolerances: state of charge (-) and W0 - W_dg (kg).
SOC_TOLERANCE = 5e-4
MASS_TOLERANCE = 0.01
#: Motors closed when a step's sizing moves no length by more than this (m; 0.2 mm, 0.2 % of a
#: lift motor: 0.5 % of its peak torque) and no winding by more than this (A).
LENGTH_TOLERANCE = 2e-4
CURRENT_TOLERANCE = 1.0
#: A step that moves the motors by less than this (m) and no winding keeps the motors it flew;
#: otherwise a closed step is followed by one more trim with the sized motors.
EXACT_LENGTH = 1e-5
#: dW0/dm_b with W_dg closed: 1/(1 - 0.14), dW0/dW_dg about 0.14 (module docstring): the slope
#: of the battery closure until a secant replaces it.
GROSS_PER_BATTERY = 1.0 / (1.0 - 0.14)
#: d ln(L)/d ln(W0) of a motor sized for hover torque: the peak torque grows as L^3 at a fixed L/D
#: (the mass (pi/2) A B D^2 L over a torque density, docs theory/motor 'Sizing'), the hover torque
#: as W0^(3/2) at a fixed rotor speed (momentum theory, P = T^(3/2)/sqrt(2 rho A)). It predicts
#: the next step's motors, which speeds the closure; the closed motors do not depend on it.
LENGTH_PER_GROSS_EXPONENT = 0.5
#: The largest motor length change (m) of a step whose battery residual a secant may use.
SECANT_MOTOR_MOVE = 1e-3
#: Condition kinds whose motors turn: the conditions the motors are sized in.
MOTOR_KINDS = ("hover", "oei", "transition", "steady")
#: A battery heavier than this fraction of the gross mass does not close: the energy it adds to
#: carry itself grows faster than its capacity (no battery-electric design in the literature
#: exceeds about 40 %; NASA's lift+cruise: 22 %, Johnson and Silva 2022, Table 3).
MAX_BATTERY_FRACTION = 0.6
#: Units of the summary: J per kWh; Pa per lb/ft^2 (4.4482216 N over 0.09290304 m^2); W per
#: mechanical horsepower (550 ft lbf/s).
_J_PER_KWH = 3.6e6
_PA_PER_PSF = 4.4482216152605 / 0.09290304
_W_PER_HP = 745.69987158227


class SizingError(om.AnalysisError):
    """The vehicle does not close on its mission; the message says what was measured."""


@dataclasses.dataclass
class SizingResult:
    """The closed vehicle (masses in kg, energy in J, powers in W, disk loading in N/m^2)."""

    vehicle: str
    gross_mass: float
    battery_mass: float
    battery_energy: float
    energy_used: float
    final_soc: float
    soc_floor: float
    design_gross_mass: float
    disk_loading: float
    installed_power: dict
    motors: MotorSizing
    peak_torque: np.ndarray
    breakdown: dict
    history: list
    seconds: float

    def summary(self) -> str:
        """Return the result as text (``lpc-mdo size`` prints it)."""
        steps = len(self.history)
        lines = [
            f"sized '{self.vehicle}' to its mission in {steps} step{'s' * (steps > 1)} "
            f"({self.seconds:.1f} s): state of charge {self.final_soc:.4f} (floor "
            f"{self.soc_floor:g}), W0 {self.gross_mass:.2f} kg, W_dg "
            f"{self.design_gross_mass:.2f} kg",
            f"  gross mass      {self.gross_mass:10.2f} kg",
            f"  battery         {self.battery_mass:10.2f} kg, "
            f"{self.battery_energy / _J_PER_KWH:.1f} kWh ({self.energy_used / _J_PER_KWH:.1f} "
            "kWh used over the mission and reserve)",
            f"  empty mass      {self.gross_mass - self.breakdown.get('payload', 0.0):10.2f} kg "
            "(gross minus payload, battery included)",
            f"  disk loading    {self.disk_loading:10.1f} N/m^2 "
            f"({self.disk_loading / _PA_PER_PSF:.2f} lb/ft^2)",
        ]
        for name, (power, where) in self.installed_power.items():
            lines.append(
                f"  {name:<15} {power / 1e3:10.1f} kW per motor ({power / _W_PER_HP:.0f} hp), "
                f"the most over the conditions: {where}"
            )
        m = self.motors
        lines.append(
            "  motor designs   length  winding  peak torque  torque margin  voltage margin  "
            "length set by"
        )
        for k, label in enumerate(m.labels):
            lines.append(
                f"    {label:<44} {m.length[k] * 1e3:6.1f} mm {m.rated_current[k]:5.0f} A "
                f"{self.peak_torque[k]:8.1f} N m {m.torque_margin[k]:8.3f} "
                f"{m.voltage_margin[k]:14.3f}   {m.sets_length[k]}"
            )
        lines.append(f"  control reserve / required acceleration: {m.control_ratio:.2f}")
        lines.append("  steps (battery kg, W0 kg, state of charge):")
        lines += [f"    {m:10.2f} {w:10.2f} {s:8.4f}" for m, w, s in self.history]
        return "\n".join(lines)


def _mission_conditions(vehicle):
    names = [c.name for c in vehicle.mission_segments]
    reserve = vehicle.mission.reserve_condition
    if reserve is not None and reserve not in names:
        names.append(reserve)
    return names


def size_vehicle(vehicle=None, processes=1, max_steps=12, log=None):
    """
    Close a vehicle's battery, gross mass and motors on its mission (module docstring).

    Parameters
    ----------
    vehicle : Vehicle, str, os.PathLike or None
        A vehicle, a vehicle file, or None for the reference.
    processes : int
        Processes that trim conditions at the same time.
    max_steps : int
        Closure steps before giving up.
    log : callable or None
        Called with one line per step.

    Returns
    -------
    SizingResult

    Raises
    ------
    SizingError
        When a trim fails or the closure does not converge (diverges: the mission needs a battery
        heavier than :data:`MAX_BATTERY_FRACTION` of the gross mass), naming what was measured.
    """
    # lpc_mdo.api exports this function, so its weights module is imported here, not at the top
    from lpc_mdo.api.weights import mass_breakdown

    start = time.perf_counter()
    if vehicle is None or isinstance(vehicle, (str,)) or hasattr(vehicle, "__fspath__"):
        vehicle = load_vehicle(vehicle)
    history = []
    prob, conditions, state, motors = _close(vehicle, processes, max_steps, log, history)
    battery, design, gross, soc, energy = state
    return SizingResult(
        vehicle=vehicle.name,
        gross_mass=gross,
        battery_mass=battery,
        battery_energy=float(prob.get_val("energy_capacity", units="J")[0]),
        energy_used=energy,
        final_soc=soc,
        soc_floor=vehicle.constraints.min_final_soc,
        design_gross_mass=design,
        disk_loading=_disk_loading(prob, vehicle, gross),
        installed_power=_installed_power(prob, conditions),
        motors=motors,
        peak_torque=np.ravel(prob.get_val("motor_peak_torque", units="N*m")).copy(),
        breakdown=dict(mass_breakdown(prob)),
        history=history,
        seconds=time.perf_counter() - start,
    )


def _close(vehicle, processes, max_steps, log, history):
    """Close the battery, W_dg and the motors; return (prob, conditions, state, motors).

    ``state`` is (battery, W_dg, W0, SoC, energy) of the last trim. Each step trims every
    condition whose motors turn at the step's battery, W_dg and motors, sizes the motors at
    those loads (:func:`lpc_mdo.motor_sizing.size_motors`) and takes a secant step on the
    battery; closed when the state of charge and W_dg are closed and the sizing moved no motor
    by more than its tolerance (the motors the step flew are kept).
    """
    mission = _mission_conditions(vehicle)
    conditions = [c.name for c in vehicle.conditions if c.kind in MOTOR_KINDS or c.name in mission]
    prob = build_analysis_problem(
        vehicle, name="sizing", conditions=conditions, static_margin=False
    )
    prob.final_setup()
    # Every trim starts from the vehicle file's trim values, as the analysis of the sized file
    # does, so that the trims do not depend on the path of the closure.
    start_values = {
        name: prob.get_val(name).copy()
        for name in prob.model.get_design_vars(use_prom_ivc=True)
        if name not in ("battery_mass", LENGTH, CURRENT)
    }
    motors = {name: prob.get_val(name).copy() for name in (LENGTH, CURRENT)}
    dv = vehicle.design_variables[LENGTH]
    length_bounds = (np.asarray(dv.lower_array, float), np.asarray(dv.upper_array, float))
    floor = vehicle.constraints.min_final_soc
    target = floor + 0.5 * SOC_TOLERANCE  # the middle of the closed band [floor, floor + tol]
    soc0 = vehicle.battery.initial_soc
    density = vehicle.battery.energy_density
    calibrated = vehicle.masses.other_rule == "calibrated"
    battery = float(prob.get_val("battery_mass", units="kg")[0])
    design = vehicle.masses.design_gross_mass
    _reserve_fits(prob, vehicle)
    previous, polish, sized = None, False, None
    for step in range(1, max_steps + 1):
        prob.set_val("battery_mass", battery, units="kg")
        for name, value in {**start_values, **motors}.items():
            prob.set_val(name, value)
        if not calibrated:
            design = _close_design_gross_mass(prob, design)
        prob.set_val("design_gross_mass", design, units="kg")
        _trim(prob, conditions, processes, f"step {step}")
        soc = float(prob.get_val("state_of_charge")[0])
        gross = float(prob.get_val("gross_mass", units="kg")[0])
        energy = float(prob.get_val("energy_used", units="J")[0])
        state = (battery, design, gross, soc, energy)
        closed_mass = calibrated or abs(gross - design) <= MASS_TOLERANCE
        closed = 0.0 <= soc - floor <= SOC_TOLERANCE and closed_mass
        if polish and closed:  # flown with the motors sized at the previous step's loads
            history.append((battery, gross, soc))
            if log is not None:
                log(
                    f"size: step {step}: battery {battery:.2f} kg, W0 {gross:.2f} kg, SoC "
                    f"{soc:.4f}; the motors sized at step {step - 1}'s loads"
                )
            return prob, conditions, state, _flown_motors(prob, vehicle, motors, sized)
        try:
            sized = size_motors(prob, vehicle, guess=motors)
        except MotorSizingError as err:
            raise SizingError(f"sizing the motors at step {step}: {err}") from None
        moved = (
            float(np.max(np.abs(sized.length - motors[LENGTH]))),
            float(np.max(np.abs(sized.rated_current - motors[CURRENT]))),
        )
        history.append((battery, gross, soc))
        if log is not None:
            log(
                f"size: step {step}: battery {battery:.2f} kg, W0 {gross:.2f} kg, SoC {soc:.4f}; "
                f"motors moved by {moved[0] * 1e3:.2f} mm and {moved[1]:.0f} A"
            )
        if closed and moved[0] <= LENGTH_TOLERANCE and moved[1] <= CURRENT_TOLERANCE:
            if moved[0] <= EXACT_LENGTH and moved[1] == 0.0:
                return prob, conditions, state, _flown_motors(prob, vehicle, motors, sized)
            # One more trim with the sized motors, whose margins are then at their limits plus
            # the trim allowance (the loads move with the motors' small change of mass only).
            polish = True
            motors = {LENGTH: rounded_up(sized.length), CURRENT: sized.rated_current}
            continue
        polish = False
        if battery > MAX_BATTERY_FRACTION * gross or not math.isfinite(gross):
            raise SizingError(
                f"the mission does not close: at step {step} the battery would be {battery:.0f} "
                f"kg of a {gross:.0f} kg vehicle (more than {MAX_BATTERY_FRACTION:.0%}), the "
                f"mission and reserve taking {energy / _J_PER_KWH:.1f} kWh; shorten the mission or "
                "the reserve, or raise battery.energy_density"
            )
        # The battery the mission would need with the sized motors: their mass change scales
        # the energy with the gross mass (E ~ W0; the secant corrects the exponent).
        sized_gross = float(prob.get_val("gross_mass", units="kg")[0])
        needed = energy * sized_gross / gross / (density * (soc0 - target))
        residual = battery - needed
        if previous is not None and residual != previous[1]:
            slope = (residual - previous[1]) / (battery - previous[0])
        else:  # dg/dm_b = 1 - (m*/W0) dW0/dm_b with E ~ W0
            slope = 1.0 - needed / sized_gross * GROSS_PER_BATTERY
        step_to = battery - residual / slope
        # A secant over a step whose motors moved far would mix their effect into the slope.
        previous = (battery, residual) if moved[0] <= SECANT_MOTOR_MOVE else None
        # The next step's motors anticipate its gross mass (the path only, not the fixed point,
        # where the prediction is W0 itself): W0 moves by the motors' and the battery's mass
        # changes with W_dg closed, and the lengths by W0^(1/2).
        predicted = gross + GROSS_PER_BATTERY * (sized_gross - gross + max(step_to, 1.0) - battery)
        # Flown as the vehicle file keeps them (battery to 0.01 kg, lengths to the micrometre),
        # so that the sized file analyzes to the closure found here.
        battery = round(max(step_to, 1.0), 2)
        length = sized.length * (predicted / gross) ** LENGTH_PER_GROSS_EXPONENT
        motors = {LENGTH: rounded_up(np.clip(length, *length_bounds)), CURRENT: sized.rated_current}
    raise SizingError(
        f"the closure did not converge in {max_steps} steps: last battery {history[-1][0]:.2f} "
        f"kg, W0 {history[-1][1]:.2f} kg, state of charge {history[-1][2]:.4f} against the "
        f"floor {floor:g}; the last step moved the motors by {moved[0] * 1e3:.2f} mm and "
        f"{moved[1]:.0f} A"
    )


def _flown_motors(prob, vehicle, motors, sized):
    """Return ``sized`` with the motors the last trim flew and their margins there."""
    for name, value in motors.items():
        prob.set_val(name, value)
    prob.run_model()
    torque, voltage, _ = motor_margins(prob, vehicle)
    return dataclasses.replace(
        sized,
        length=motors[LENGTH].copy(),
        rated_current=motors[CURRENT].copy(),
        torque_margin=torque,
        voltage_margin=voltage,
        control_ratio=control_ratio(prob, vehicle),
    )


def _reserve_fits(prob, vehicle):
    """Refuse, before any trim, a reserve that no battery the vehicle can carry would hold.

    At the vehicle file's initial design (one model run, its rotor speeds and pitch as given:
    near the trimmed power for a file whose initial values come from a trimmed design): the
    reserve energy P_r t_res against the usable energy of a battery of
    :data:`MAX_BATTERY_FRACTION` of the gross mass.
    """
    mission = vehicle.mission
    if mission.reserve_condition is None:
        return
    prob.run_model()
    power = float(prob.get_val(f"{mission.reserve_condition}.electrical_power", units="W")[0])
    gross = float(prob.get_val("gross_mass", units="kg")[0])
    battery = vehicle.battery
    usable = battery.initial_soc - vehicle.constraints.min_final_soc
    largest = MAX_BATTERY_FRACTION * gross * battery.energy_density * usable
    if power * mission.reserve_time > largest:
        raise SizingError(
            f"'mission.reserve': {mission.reserve_time / 60:.4g} min at "
            f"{mission.reserve_condition!r} ({power / 1e3:.0f} kW) take "
            f"{power * mission.reserve_time / _J_PER_KWH:.0f} kWh, more than a battery of "
            f"{MAX_BATTERY_FRACTION:.0%} of the {gross:.0f} kg vehicle holds between its charge "
            f"and the floor ({largest / _J_PER_KWH:.0f} kWh); allowed: a shorter reserve, or a "
            "higher battery.energy_density"
        )


def _close_design_gross_mass(prob, design):
    """Return W_dg = W0(W_dg) at the problem's state (SizingError when it does not settle)."""
    try:
        return close_design_gross_mass(prob, design, 0.1 * MASS_TOLERANCE, max_runs=30)
    except om.AnalysisError as err:
        raise SizingError(str(err)) from None


def _trim(prob, conditions, processes, what):
    result = trim(prob, conditions=conditions, workers=processes, least_power=True)
    if not result.success:
        raise SizingError(f"sizing, {what}: {result.message}")


def _disk_loading(prob, vehicle, gross):
    """W0 g over the lift rotors' disk area (N/m^2)."""
    radii = np.asarray(prob.get_val("rotor_radius", units="m")).ravel()
    area = sum(math.pi * radii[r.pair] ** 2 for r in vehicle.lift_rotors)
    return gross * GRAVITY / area


def _installed_power(prob, conditions):
    """Each motor group's largest shaft power per motor over the conditions: {name: (W, where)}."""
    found = {}
    for name in conditions:
        for group, label in (("lift_motors", "lift motors"), ("pusher_motors", "pusher motor")):
            path = f"{name}.{group}.output_power"
            try:
                power = float(np.max(prob.get_val(path, units="W")))
            except KeyError:
                continue
            if power > found.get(label, (-np.inf, ""))[0]:
                found[label] = (power, name)
    return found


#: Keys of a vehicle file whose string may be a file path (relative to the file's folder).
_FILE_KEYS = ("airfoil", "coordinates")
_AIRFOIL_NAMES = tuple(AIRFOILS)


def rounded_up(length):
    """Motor lengths (m) rounded up to the micrometre a vehicle file keeps: margins not lost."""
    return np.ceil(np.asarray(length) * 1e6 - 1e-6) / 1e6


def with_sized_values(text, result, note):
    """
    Return a vehicle file's text with a sizing's closed values, each line's comment ``note``.

    ``battery.mass``, ``masses.design_gross_mass`` (to the 0.01 kg the sizing flew) and the
    initial values of ``motor_length`` (to the micrometre, rounded up) and
    ``motor_rated_current``.
    """
    text = replace_table_value(text, "battery", "mass", f"{result.battery_mass:.2f}")
    text = replace_table_value(
        text, "masses", "design_gross_mass", f"{result.design_gross_mass:.2f}"
    )
    motors = result.motors
    text = replace_initial(text, LENGTH, rounded_up(motors.length), note, fmt="{:.6f}")
    return replace_initial(text, CURRENT, motors.rated_current, note, fmt="{:.1f}")


def sized_vehicle_text(path, result):
    """
    Return the vehicle file at ``path`` (None: the reference) with the sizing's masses.

    ``battery.mass`` (the battery's initial design value), ``masses.design_gross_mass`` and the
    initial values of ``motor_length`` and ``motor_rated_current`` take the closed values; the
    file's comments stay; relative polar and coordinate paths become
    absolute, so the sized file works from any folder. A header line says what changed.
    """
    if path is None:
        text = resources.files("lpc_mdo").joinpath("data", "lpc_reference.toml").read_text()
        folder, label = None, "the reference vehicle"
    else:
        text = Path(path).read_text(encoding="utf-8-sig")
        folder, label = Path(path).resolve().parent, str(path)
    text = with_sized_values(text, result, "sized by lpc-mdo size")
    if folder is not None:

        def absolute(match):
            value = match.group(2)
            if value.lower() in _AIRFOIL_NAMES or os.path.isabs(os.path.expanduser(value)):
                return match.group(0)
            here = folder / value
            where = here if here.exists() else Path.cwd() / value
            return f'{match.group(1)}"{where.resolve()}"'

        keys = "|".join(_FILE_KEYS)
        text = re.sub(rf'^((?:{keys}) = )"([^"]*)"', absolute, text, flags=re.M)
    header = (
        f"# Sized by lpc-mdo size from {label}: battery.mass {result.battery_mass:.2f} kg, "
        f"masses.design_gross_mass {result.design_gross_mass:.2f} kg and the motors close the "
        "mission\n"
        f"# (state of charge {result.final_soc:.4f} at the floor {result.soc_floor:g}, W0 "
        f"{result.gross_mass:.2f} kg).\n"
    )
    return header + text
