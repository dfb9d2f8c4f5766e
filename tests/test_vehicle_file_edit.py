"""Editing values in a vehicle file's text (the run scripts' ``--write``)."""

import tomllib
from importlib import resources

import pytest

from lpc_mdo.vehicle.file_edit import replace_initial, replace_value, write_values


def _reference_text():
    return resources.files("lpc_mdo").joinpath("data", "lpc_reference.toml").read_text()


def test_replaced_values_parse_back_and_the_comments_stay():
    text = _reference_text()
    edited = replace_initial(text, "top_skin_thickness", [1e-3] * 8, "by a test")
    edited = replace_initial(edited, "motor_rated_current", [101.04, 2, 3, 4, 5], "x", "{:.1f}")
    edited = replace_value(edited, "design_gross_mass", "3000.00")
    data = tomllib.loads(edited)
    assert data["design_variables"]["top_skin_thickness"]["initial"] == [1e-3] * 8
    assert data["design_variables"]["motor_rated_current"]["initial"] == [101.0, 2, 3, 4, 5]
    assert data["masses"]["design_gross_mass"] == 3000.0
    # Only those lines changed: every other line, comments included, is the file's.
    changed = [a for a, b in zip(text.splitlines(), edited.splitlines(), strict=True) if a != b]
    assert len(changed) == 3
    assert "initial = [0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001]   # by a test" in (
        edited
    )


def test_a_missing_table_or_line_is_an_error_naming_the_file(tmp_path):
    with pytest.raises(ValueError, match=r"no unique \[design_variables.nothing\]"):
        replace_initial(_reference_text(), "nothing", [1.0], "x")
    with pytest.raises(ValueError, match="no unique 'no_such_key = <number>' line"):
        replace_value(_reference_text(), "no_such_key", "1")
    path = tmp_path / "vehicle.toml"
    path.write_text("a = 1\n")
    with pytest.raises(ValueError, match=r"vehicle.toml: no unique 'b = <number>' line"):
        write_values(path, lambda text: replace_value(text, "b", "2"))
    assert path.read_text() == "a = 1\n"  # untouched on error
    write_values(path, lambda text: replace_value(text, "a", "2"))
    assert path.read_text() == "a = 2\n"
