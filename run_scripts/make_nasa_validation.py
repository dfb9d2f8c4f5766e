"""Write the NASA validation vehicle: the lift-plus-cruise vehicle on NASA's own sizing mission.

Usage::

    python run_scripts/make_nasa_validation.py [--output-dir lpc_mdo/data]

NASA sized its all-electric lift+cruise concept (NDARC) for the UAM sizing mission and published
the result: Silva, Johnson, Antcliff and Patterson, "VTOL Urban Air Mobility Concept Vehicles
for Technology Development", AIAA 2018-3847, Table 3 (design gross weight 8210 lb, the paper's
initial design; best-range speed 112 kt), and the mission in Johnson and Silva, "NASA concept
vehicles and the engineering of advanced air mobility aircraft", The Aeronautical Journal 126
(2022), Fig. 4, with the segments of NASA's table 'Sizing mission segments and their associated
properties' (docs results 'Validation' lists every number and how it was seen). This file is our
reference vehicle (the NASA LPC OpenVSP geometry, itemised masses, motors and wing box as in
``lpc_reference.toml``) with NASA's mission, payload and battery assumptions:

- payload 1200 lb = 544.31 kg (6 passengers);
- take-off at 6000 ft ISA (1828.8 m); a vertical climb to 50 ft at 100 ft/min (0.508 m/s, 30 s);
  the transition, 10 s; a climb at 900 ft/min (4.572 m/s) to the cruise altitude, 4000 ft above
  the ground (10000 ft = 3048 m); the cruise at the best-range speed, 112 kt (57.62 m/s), for
  37.5 nm (69.45 km) less the climb's ground distance (the descent earns no credit); a descent
  (NASA gives none: ours at the reference's 3 deg); the transition, 10 s; a 30 s hover; a
  vertical descent of 50 ft at 100 ft/min;
- two such legs without recharging, then a 20-minute cruise reserve (preset ``nasa_uam``);
- the battery at 400 Wh/kg "installed, usable" (JS22 sec. 4.1): the whole capacity may be used,
  so the state-of-charge floor is 0 (ours, 0.2 in the reference, would count a second reserve);
- the one-rotor-out hover cases at the take-off altitude (NASA sizes the lift motors for hover
  out of ground effect at 6000 ft at 100 % of their rating);
- the sizing's start: battery 600 kg and design gross mass 3500 kg. The reference's start as
  closed on its own mission on 2026-12-07 (932 kg, 3910.97 kg) did not trim the climb to
  10000 ft at this payload, so ``lpc-mdo size`` stopped at its first step; from any start that
  trims, the sizing closes on the same vehicle (docs results 'Validation').

Assumptions where NASA publishes nothing for the electric vehicle (its wing, tail and fuselage
sizes, its weights by item): the reference's values. Not modelled: the 15 s taxis at 10 % power
(0.2 % of the mission energy at the reference's hover power), a 10 kt headwind NASA's text (not
its figure) mentions.

Refuses to write over a file it did not create (a file without this script's header).
"""

import sys
import tomllib
from pathlib import Path

from lpc_mdo.vehicle.mission_profile import DERIVED_KEYS
from lpc_mdo.vehicle.toml_writer import example_script_main

ROOT = Path(__file__).resolve().parents[1]
REFERENCE = ROOT / "lpc_mdo" / "data" / "lpc_reference.toml"
HEADER = "# Written by run_scripts/make_nasa_validation.py"
NAME = "nasa_lpc_mission.toml"

FT, KT, NM, LB = 0.3048, 0.514444, 1852.0, 0.45359237
TAKEOFF = 6000.0 * FT
HOVER_TOP = TAKEOFF + 50.0 * FT
CRUISE_ALTITUDE = 10000.0 * FT
CLIMB_RATE = 900.0 * FT / 60.0
VERTICAL_RATE = 100.0 * FT / 60.0
BEST_RANGE_SPEED = 112.0 * KT
LEG = 37.5 * NM
CLIMB_SPEED = 60.8756  # the reference's climb speed, m/s
DESCENT_RATE = -60.8756 * 0.052335956  # the reference's 3 deg descent, m/s
START_BATTERY, START_GROSS_MASS = 600.0, 3500.0  # kg, the sizing's start (docstring)


def example():
    """Return the validation vehicle's data."""
    data = tomllib.loads(REFERENCE.read_text(encoding="utf-8"))
    data["name"] = "NASA lift-plus-cruise on NASA's UAM sizing mission (validation)"
    data["masses"]["payload"] = round(1200.0 * LB, 2)
    data["constraints"]["min_final_soc"] = 0.0
    data["battery"]["mass"] = START_BATTERY
    data["masses"]["design_gross_mass"] = START_GROSS_MASS
    climb_time = (CRUISE_ALTITUDE - HOVER_TOP) / CLIMB_RATE
    climb_ground = climb_time * (CLIMB_SPEED**2 - CLIMB_RATE**2) ** 0.5
    for c in data["conditions"]:
        if c["kind"] == "oei":
            c["altitude"] = TAKEOFF
        if c["name"] == "cruise":
            c["speed"] = round(BEST_RANGE_SPEED, 4)
        flown = c["kind"] in ("hover", "transition", "steady")
        for key in DERIVED_KEYS.values() if flown else ("duration", "energy_weight"):
            c.pop(key)
    data["mission"].update(
        start_altitude=TAKEOFF,
        legs=2,
        segments=[
            {"condition": "hover", "to_altitude": HOVER_TOP, "vertical_speed": VERTICAL_RATE},
            {"condition": "transition", "duration": 10.0},
            {"condition": "climb", "to_altitude": CRUISE_ALTITUDE, "vertical_speed": CLIMB_RATE},
            {"condition": "cruise", "distance_km": round((LEG - climb_ground) / 1e3, 4)},
            {"condition": "descent", "to_altitude": HOVER_TOP, "vertical_speed": DESCENT_RATE},
            {"condition": "transition", "duration": 10.0},
            {"condition": "hover", "duration": 30.0},
            {"condition": "hover", "to_altitude": TAKEOFF, "vertical_speed": -VERTICAL_RATE},
        ],
        reserve={"rule": "nasa_uam"},
    )
    return data


def main(argv=None):
    """Write the file; refuse one this script did not write."""
    comments = [
        "# The NASA lift-plus-cruise vehicle on NASA's UAM sizing mission (Johnson and Silva",
        "# 2022): see the script's docstring for each value and lpc_reference.toml for the rest.",
    ]
    return example_script_main(
        argv, "make_nasa_validation", __doc__, ROOT / "lpc_mdo" / "data", NAME,
        HEADER + " from lpc_mdo/data/lpc_reference.toml.", comments, example,
    )  # fmt: skip


if __name__ == "__main__":
    sys.exit(main())
