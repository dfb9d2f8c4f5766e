"""Write a vehicle description (the parsed TOML: dicts, lists, numbers, strings) back as TOML.

For the example vehicles the run scripts derive from the reference (their comments are lost: a
header states where the values come from). Tables of tables become ``[a.b]`` headers, lists of
tables ``[[a.b]]`` headers, in the order of the dicts.
"""

import argparse
from pathlib import Path

__all__ = ["example_script_main", "toml_text", "write_generated_file"]


def toml_text(data):
    """Return the TOML text of ``data`` (a vehicle dict)."""
    lines = []
    _table(lines, "", data)
    return "\n".join(lines) + "\n"


def write_generated_file(path, header, comments, data):
    """
    Write ``data`` as TOML to ``path`` under ``header`` and the ``comments`` lines.

    Raises FileExistsError for a file that is there and does not start with ``header`` (a file
    the writing script did not create is never written over).
    """
    path = Path(path)
    if path.exists() and not path.read_text(encoding="utf-8").startswith(header):
        raise FileExistsError(f"{path} exists and was not written by this script")
    path.write_text("\n".join([header, *comments, ""]) + "\n" + toml_text(data), encoding="utf-8")


def example_script_main(argv, tool, doc, default_dir, name, header, comments, build):
    """
    Run a script that writes an example vehicle file (``build()``) into ``--output-dir``.

    ``--output-dir`` defaults to ``default_dir``; the file is ``name`` there, written by
    :func:`write_generated_file`. Returns the exit code: 0 written, 1 a file there that the
    script did not write (said on stdout).
    """
    parser = argparse.ArgumentParser(prog=tool, description=doc.splitlines()[0])
    parser.add_argument("--output-dir", type=Path, default=Path(default_dir))
    args = parser.parse_args(argv)
    path = args.output_dir / name
    try:
        write_generated_file(path, header, comments, build())
    except FileExistsError as err:
        print(f"{tool}: error: {err}")
        return 1
    print(f"wrote {path}")
    return 0


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
