"""Write the 4- and 12-lift-rotor example vehicles from the NASA reference vehicle file.

Usage::

    python run_scripts/make_layout_examples.py [--output-dir lpc_mdo/data]

The examples are the NASA lift-plus-cruise vehicle (its fuselage, wing, tails, pusher, masses,
battery, motors, mission and limits) with its lift-rotor disk area spread over another number of
rotors, so that the disk loading, the hover power and the mission stay those of the reference
and only the layout differs (docs user guide 'Bring your own vehicle'):

- radius R_n = 1.524 m x sqrt(8 / n): the reference's total disk area on n rotors;
- two rows, front and rear, at the reference's stations (front x = -0.79 m, ahead of and 0.2 m
  below the wing; rear x = -5.10 m, 0.5 m above it); with 4 rotors the front row moves to
  x = -0.60 m so that the larger front and rear disks keep 0.19 m apart;
- n/4 rotors per side in each row, from y = W/2 + R + 0.1 m (0.1 m from the fuselage side)
  outwards, 0.16 m between neighbouring disks (the reference's inner-outer gap);
- booms under the wing at the reference's chord station (x = -2.85 m, 0.12 m below the wing's
  chord plane), as long as the farthest hub is from its attach point plus 0.2 m;
- blade chords and their upper bound scaled with the radius; the rotor-speed bounds scaled with
  1/R (the reference's
  tip speeds); each motor's stack length with the cube root of the hover torque (for equal
  disk loading and tip speed the torque grows as R^3, and a stack of fixed length-to-diameter
  ratio carries a torque of its length cubed) and its rated current with the hover power (R^2);
- the one-rotor-out cases generated from the layout: 6 for 12 rotors; a 4-rotor vehicle has none
  (3 working rotors cannot balance the weight and three moments), so its file leaves them out.

Refuses to write over a file it did not create (a file without this script's header).
"""

import argparse
import copy
import math
import sys
import tomllib
from pathlib import Path

from lpc_mdo.vehicle.condition_kinds import MIN_HOVER_ROTORS
from lpc_mdo.vehicle.toml_writer import toml_text

ROOT = Path(__file__).resolve().parents[1]
REFERENCE = ROOT / "lpc_mdo" / "data" / "lpc_reference.toml"
HEADER = "# Written by run_scripts/make_layout_examples.py"
REFERENCE_RADIUS = 1.524
FRONT_X, REAR_X = -0.79431, -5.10113
BOOM_X = -2.85
FUSELAGE_GAP, DISK_GAP = 0.1, 0.16


def _wing_z(wing, y):
    """Body-frame z of the wing's chord plane at span station y (dihedral > 0 raises the tip)."""
    return wing["root_leading_edge"][2] - abs(y) * math.tan(math.radians(wing["dihedral_deg"]))


def layout(data, n):
    """Return the lift rotors and the boom attach points of an n-rotor layout (module doc)."""
    radius = REFERENCE_RADIUS * math.sqrt(8.0 / n)
    per_side = n // 4
    front_x = FRONT_X if n > 4 else -0.60
    half_width = data["fuselage"]["max_width"] / 2.0
    ys = [
        half_width + radius + FUSELAGE_GAP + k * (2.0 * radius + DISK_GAP) for k in range(per_side)
    ]
    template = data["lift_rotors"][0]
    scale = radius / REFERENCE_RADIUS
    left, right, attach_left, attach_right = [], [], [], []
    pair = 0
    for k, y in enumerate(ys):
        for row, (x, dz) in enumerate(((front_x, 0.2), (REAR_X, -0.5))):
            spin = 1 if (k + row) % 2 == 0 else -1
            z = _wing_z(data["wing"], y) + dz
            where = ("front", "rear")[row]
            rotor = copy.deepcopy(template)
            rotor.update(
                name=f"{where}_left_{k + 1}",
                hub_position=[x, -y, round(z, 5)],
                radius=round(radius, 5),
                chord_cp=[round(c * scale, 5) for c in template["chord_cp"]],
                spin_direction=spin,
                pair=pair,
            )
            mirror = copy.deepcopy(rotor)
            mirror.update(
                name=f"{where}_right_{k + 1}",
                hub_position=[x, y, round(z, 5)],
                spin_direction=-spin,
            )
            left.append(rotor)
            right.append(mirror)
            point_z = round(_wing_z(data["wing"], y) + 0.12, 5)
            attach_left.append([BOOM_X, -y, point_z])
            attach_right.append([BOOM_X, y, point_z])
            pair += 1
    rotors = left + right
    attach = attach_left + attach_right
    reach = max(math.dist(r["hub_position"], a) for r, a in zip(rotors, attach, strict=True))
    for r in rotors:
        r["hub_position"] = [round(v, 5) for v in r["hub_position"]]
    return rotors, [[round(v, 5) for v in a] for a in attach], round(reach + 0.2, 4), radius


def example(n):
    """Return the vehicle data of the n-rotor example."""
    data = tomllib.loads(REFERENCE.read_text(encoding="utf-8"))
    rotors, attach, boom_length, radius = layout(data, n)
    pairs = n // 2
    scale = radius / REFERENCE_RADIUS
    data["name"] = f"NASA LPC disk area on {n} lift rotors"
    data["lift_rotors"] = rotors
    data["booms"]["attach_points"] = attach
    data["booms"]["length"] = boom_length
    data["pusher"]["pair"] = pairs  # the group after the lift pairs
    if n - 1 < MIN_HOVER_ROTORS:  # no one-rotor-out hover: 3 thrusts cannot trim 4 demands
        data["conditions"] = [c for c in data["conditions"] if c["kind"] != "oei"]
        del data["design_variables"]["oei_lift_rpm"]
    dv = data["design_variables"]
    pusher = {key: dv["rotor_radius"][key][-1] for key in ("lower", "upper")}
    dv["rotor_radius"]["lower"] = [round(1.2 * scale, 4)] * pairs + [pusher["lower"]]
    dv["rotor_radius"]["upper"] = [round(1.8 * scale, 4)] * pairs + [pusher["upper"]]
    chord_upper = dv["blade_chord_cp"]["upper"]  # one number in the reference: every group
    dv["blade_chord_cp"]["upper"] = [[round(chord_upper * scale, 4)] * 4] * pairs + [
        [chord_upper] * 4
    ]
    torque = scale**3  # hover torque per rotor over the reference's
    dv["motor_length"]["initial"] = [round(0.1 * torque ** (1 / 3), 4)] * pairs + [0.15]
    dv["motor_length"]["upper"] = [round(0.25 * torque ** (1 / 3), 4)] * pairs + [0.3]
    lift_current = sum(dv["motor_rated_current"]["initial"][:4]) / 4.0
    dv["motor_rated_current"]["initial"] = [round(lift_current * scale**2, 1)] * pairs + [
        dv["motor_rated_current"]["initial"][-1]
    ]
    for name in ("hover_lift_rpm", "transition_lift_rpm", "oei_lift_rpm"):
        if name not in dv:
            continue
        for key in ("initial", "lower", "upper"):
            dv[name][key] = round(dv[name][key] / scale, 1)
    return data


def to_toml(data, n):
    """Return the TOML text of an example's data, with a header that says where it came from."""
    lines = [
        HEADER + f" from lpc_mdo/data/lpc_reference.toml: {n} lift rotors.",
        "# The NASA lift-plus-cruise vehicle with its lift-rotor disk area on another number of",
        "# rotors; every other value is the reference's (see the script's docstring for each rule",
        "# and lpc_reference.toml for the sources of the rest).",
        "",
    ]
    return "\n".join(lines) + "\n" + toml_text(data)


def main(argv=None):
    """Write both examples; refuse a file this script did not write."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", type=Path, default=ROOT / "lpc_mdo" / "data")
    args = parser.parse_args(argv)
    for n in (4, 12):
        path = args.output_dir / f"lpc_{n}_lift_rotors.toml"
        if path.exists() and not path.read_text(encoding="utf-8").startswith(HEADER):
            print(f"make_layout_examples: error: {path} exists and was not written by this script")
            return 1
        path.write_text(to_toml(example(n), n), encoding="utf-8")
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
