"""Write a vehicle description (the parsed TOML: dicts, lists, numbers, strings) back as TOML.

For the example vehicles the run scripts derive from the reference (their comments are lost: a
header states where the values come from). Tables of tables become ``[a.b]`` headers, lists of
tables ``[[a.b]]`` headers, in the order of the dicts.
"""

__all__ = ["toml_text"]


def toml_text(data):
    """Return the TOML text of ``data`` (a vehicle dict)."""
    lines = []
    _table(lines, "", data)
    return "\n".join(lines) + "\n"


def _value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    return repr(v)


def _table(lines, path, table):
    for key, value in table.items():
        if not isinstance(value, dict) and not _is_tables(value):
            lines.append(f"{key} = {_value(value)}")
    for key, value in table.items():
        if isinstance(value, dict):
            lines.append("")
            lines.append(f"[{path}{key}]")
            _table(lines, f"{path}{key}.", value)
        elif _is_tables(value):
            for item in value:
                lines.append("")
                lines.append(f"[[{path}{key}]]")
                _table(lines, f"{path}{key}.", item)


def _is_tables(value):
    return isinstance(value, list) and value and all(isinstance(x, dict) for x in value)
