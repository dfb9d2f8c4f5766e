"""A designer's own wing and tail sections in the vehicle file (lpc_mdo.vehicle.sections)."""

import copy
import dataclasses
import re
from pathlib import Path

import numpy as np
import pytest

from lpc_mdo.components.aero.airfoil_coordinates import naca_four_digit
from lpc_mdo.components.structures.wing_box_geometry import (
    WING_BOX_SECTIONS,
    WingBoxSection,
    wing_box_section,
)
from lpc_mdo.vehicle import VehicleSpecError, load_vehicle, read_vehicle_file, vehicle_from_dict

DATA = Path(__file__).parent / "data" / "airfoils"
POLAR = str(DATA / "naca4412_re5e6.pol")
COORDINATES = str(DATA / "naca4412.dat")
REFERENCE = read_vehicle_file()


def _data(**surfaces):
    """Return the reference data with the given surface tables updated."""
    data = copy.deepcopy(REFERENCE)
    for name, values in surfaces.items():
        data[name].update(values)
    return data


def _coordinates(tmp_path, code):
    path = tmp_path / f"naca{code}.dat"
    rows = "\n".join(f"{x:.6f} {y:.6f}" for x, y in naca_four_digit(code))
    path.write_text(f"NACA {code}\n{rows}\n", "utf-8")
    return str(path)


def _fails(data, message):
    with pytest.raises(VehicleSpecError, match=re.escape(message)):
        vehicle_from_dict(data)


def test_polar_file_wing_with_its_coordinates_loads():
    vehicle = vehicle_from_dict(_data(wing={"airfoil": POLAR, "coordinates": COORDINATES}))
    wing = vehicle.wing
    assert wing.airfoil == POLAR and wing.coordinates == COORDINATES
    assert wing.thickness_to_chord == pytest.approx(0.12, abs=5e-4)  # NACA 4412
    assert wing.max_thickness_location == pytest.approx(0.30, abs=0.01)
    section = wing_box_section(vehicle)  # the wing box from the coordinates
    assert section == WingBoxSection.from_file(COORDINATES, 0.25, 0.75, 0.5)
    # the flat-bottomed 4412 has a lower skin far flatter than the LS(1)-0413's
    assert section.bottom_radius > 3.0 * WING_BOX_SECTIONS["ls413"].bottom_radius


def test_polar_file_wing_needs_coordinates_and_a_moment_column(tmp_path):
    _fails(_data(wing={"airfoil": POLAR}), "missing key 'wing.coordinates'")
    plain = tmp_path / "no_cm.dat"  # alpha, cl, cd only
    rows = [line.split()[:3] for line in Path(POLAR).read_text().splitlines()[11:]]
    plain.write_text("\n".join(" ".join(r) for r in rows) + "\n", "utf-8")
    _fails(
        _data(wing={"airfoil": str(plain), "coordinates": COORDINATES}),
        "the polar has no moment coefficient",
    )


def test_coordinates_of_another_section_than_the_polar_are_refused(tmp_path):
    # NACA 0012 coordinates (alpha_L0 0) with the NACA 4412 polar (-4.3 deg).
    data = _data(wing={"airfoil": POLAR, "coordinates": _coordinates(tmp_path, "0012")})
    _fails(data, "describe different sections")


def test_tails_must_be_symmetric_sections(tmp_path):
    _fails(
        _data(horizontal_tail={"airfoil": POLAR, "coordinates": COORDINATES}),
        "'horizontal_tail.airfoil' = " + repr(POLAR) + " has a zero-lift angle of -4.3",
    )
    _fails(_data(vertical_tail={"airfoil": "ls413"}), "allowed: a symmetric section")
    symmetric = _data(horizontal_tail={"coordinates": _coordinates(tmp_path, "0015")})
    assert vehicle_from_dict(symmetric).horizontal_tail.thickness_to_chord == pytest.approx(
        0.15, abs=5e-4
    )


def test_named_airfoil_with_coordinates_frees_the_spar_layout():
    # The reference's own section as coordinates: the same wing box; and spars elsewhere.
    data = _data(wing={"coordinates": str(DATA / "ls413_gaw2.dat")})
    vehicle = vehicle_from_dict(data)
    section = wing_box_section(vehicle)
    packaged = WING_BOX_SECTIONS["ls413"]
    for name in ("thickness", "camber", "top_radius", "bottom_radius"):
        assert getattr(section, name) == pytest.approx(getattr(packaged, name), rel=1e-12)
    data["wing_box"].update(front_spar=0.2, rear_spar=0.65, beam_axis=0.4)
    assert wing_box_section(vehicle_from_dict(data)).front_spar == 0.2
    # without coordinates the layout has no packaged numbers
    data["wing"].pop("coordinates")
    _fails(data, "or any layout with the section's coordinate file as 'wing.coordinates'")


def test_coordinates_that_are_not_the_named_section_are_refused(tmp_path):
    _fails(
        _data(wing={"coordinates": _coordinates(tmp_path, "0020")}),
        "t/c 0.2 is not that of 'wing.airfoil' = 'ls413' (0.13)",
    )
    _fails(
        _data(wing={"airfoil": POLAR, "coordinates": _coordinates(tmp_path, "4430")}),
        "the section is 0.3 thick (t/c); allowed: 0.04 to 0.25",
    )


def test_missing_coordinate_file_and_a_relative_path(tmp_path, monkeypatch):
    _fails(
        _data(wing={"coordinates": str(tmp_path / "none.dat")}),
        "'wing.coordinates' = " + repr(str(tmp_path / "none.dat")) + ": coordinate file",
    )
    folder = tmp_path / "vehicle"
    (folder / "sections").mkdir(parents=True)
    for name in ("naca4412.dat", "naca4412_re5e6.pol"):
        (folder / "sections" / name).write_bytes((DATA / name).read_bytes())
    text = (Path(__file__).parents[1] / "lpc_mdo" / "data" / "lpc_reference.toml").read_text()
    text = re.sub(
        r'(?m)^airfoil = "ls413".*$',
        'airfoil = "sections/naca4412_re5e6.pol"\ncoordinates = "sections/naca4412.dat"',
        text,
    )
    (folder / "own.toml").write_text(text, "utf-8")
    monkeypatch.chdir(tmp_path)
    wing = load_vehicle(folder / "own.toml").wing
    assert wing.coordinates == str((folder / "sections" / "naca4412.dat").resolve())


def test_rotor_thickness_key_must_match_a_named_airfoil():
    data = copy.deepcopy(REFERENCE)
    data["pusher"]["thickness_to_chord"] = 0.2
    _fails(data, "'pusher.thickness_to_chord' = 0.2 is not that of 'pusher.airfoil' = 'naca0012'")
    data["pusher"]["thickness_to_chord"] = 0.12  # its own: allowed
    assert vehicle_from_dict(data).pusher.thickness_to_chord == 0.12


def test_mirror_rotors_share_their_thickness(tmp_path):
    alpha = np.linspace(-10.0, 12.0, 23)
    path = tmp_path / "blade.dat"
    np.savetxt(path, np.column_stack([alpha, 0.1 * alpha, 0.01 + 1e-4 * alpha**2]))
    data = copy.deepcopy(REFERENCE)
    for rotor in data["lift_rotors"]:
        rotor.update(airfoil=str(path), thickness_to_chord=0.1)
    data["lift_rotors"][0]["thickness_to_chord"] = 0.11
    with pytest.raises(VehicleSpecError, match="thickness_to_chord"):
        vehicle_from_dict(data)


def test_reference_sections_are_unchanged():
    vehicle = vehicle_from_dict(copy.deepcopy(REFERENCE))
    assert vehicle.wing.coordinates is None and vehicle.wing.thickness_to_chord == 0.13
    assert {r.thickness_to_chord for r in (*vehicle.lift_rotors, vehicle.pusher)} == {0.12}
    assert dataclasses.replace(vehicle.wing).max_thickness_location == 0.4
