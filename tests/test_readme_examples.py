"""The Python examples of the README and the docs' examples page marked ``<!-- test ... -->`` run.

Each marked block runs in a fresh interpreter (so that an example that registers a condition kind
cannot leak into other tests), in a temporary folder holding ``my_lpc.toml``, a copy of the
reference vehicle file, which the examples load as "your own vehicle file". A block whose comments
say what it prints (``# -> <line>``) must print exactly those lines: the numbers the README
shows are the numbers the code gives.
"""

import re
import subprocess
import sys
from importlib import resources
from pathlib import Path

import pytest

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration

ROOT = Path(__file__).resolve().parents[1]
#: The user-facing pages whose marked examples run: the README and the docs' examples page.
PAGES = (ROOT / "README.md", ROOT / "docs" / "examples.md")
MARKER = "<!-- test"


def _marked_blocks():
    pattern = re.compile(r"^" + re.escape(MARKER) + r"[^\n]*\n```python\n(.*?)^```", re.S | re.M)
    return [code for page in PAGES for code in pattern.findall(page.read_text(encoding="utf-8"))]


BLOCKS = _marked_blocks()


def test_the_readme_marks_examples_to_run():
    assert len(BLOCKS) >= 3


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_readme_example_runs(code, tmp_path):
    reference = resources.files("lpc_mdo").joinpath("data", "lpc_reference.toml")
    (tmp_path / "my_lpc.toml").write_text(reference.read_text(encoding="utf-8"), encoding="utf-8")
    result = subprocess.run(
        [sys.executable, "-c", code],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert result.returncode == 0, result.stderr[-3000:]
    expected = [line[len("# -> ") :] for line in code.splitlines() if line.startswith("# -> ")]
    if expected:
        assert result.stdout.splitlines() == expected
