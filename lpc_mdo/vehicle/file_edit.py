"""Edit values in a vehicle file's text in place, keeping its comments and layout.

The run scripts that size part of the reference design (the wing-box gauges and the design gross
mass of the closed initial design, the motor windings) write their results back into the
vehicle file with ``--write``. A TOML writer would drop the file's comments, which hold every
value's source, so these functions replace single lines and check that each replaced exactly
one.
"""

import re

__all__ = ["replace_initial", "replace_table_value", "replace_value", "write_values"]


def replace_initial(text, name, values, comment, fmt="{:.6g}"):
    """
    Return ``text`` with the ``initial = [...]`` line of ``[design_variables.<name>]`` replaced.

    The new line lists ``values`` formatted by ``fmt`` and ends with ``# <comment>``. The table's
    lines before ``initial`` (units, a comment) are kept.

    Raises
    ------
    ValueError
        When the text has no such table with an ``initial`` line, or more than one.
    """
    listed = ", ".join(fmt.format(v) for v in values)
    line = f"initial = [{listed}]   # {comment}"
    pattern = rf"(^\[design_variables\.{re.escape(name)}\]\n(?:[^\[\n][^\n]*\n)*?)initial = [^\n]*"
    text, count = re.subn(pattern, lambda m: m.group(1) + line, text, flags=re.MULTILINE)
    if count != 1:
        raise ValueError(f"no unique [design_variables.{name}] table with an 'initial' line")
    return text


def replace_value(text, key, value):
    """
    Return ``text`` with the line ``<key> = <number>`` (its number) replaced by ``value``.

    Raises
    ------
    ValueError
        When the text has no such line, or more than one.
    """
    pattern = rf"^({re.escape(key)} = )[0-9.eE+-]+"
    text, count = re.subn(pattern, lambda m: m.group(1) + value, text, flags=re.MULTILINE)
    if count != 1:
        raise ValueError(f"no unique '{key} = <number>' line")
    return text


def replace_table_value(text, table, key, value):
    """
    Return ``text`` with the ``<key> = <number>`` line of table ``[<table>]`` set to ``value``.

    The line keeps its comment. Raises ValueError when the table has no such line, or when the
    text has the table more than once.
    """
    pattern = (
        rf"(^\[{re.escape(table)}\]\n(?:(?:[^\[\n][^\n]*)?\n)*?){re.escape(key)} = [0-9.eE+-]+"
    )
    text, count = re.subn(pattern, lambda m: f"{m.group(1)}{key} = {value}", text, flags=re.M)
    if count != 1:
        raise ValueError(f"no unique '{key} = <number>' line in table [{table}]")
    return text


def write_values(path, edit):
    """Apply ``edit`` (text -> text) to the file at ``path``; a ValueError names the file."""
    with open(path) as f:
        text = f.read()
    try:
        text = edit(text)
    except ValueError as err:
        raise ValueError(f"{path}: {err}") from None
    with open(path, "w") as f:
        f.write(text)
