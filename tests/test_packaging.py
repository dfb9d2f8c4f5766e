"""The distribution's layout and OpenMDAO plugin registration."""

import tomllib
from pathlib import Path

import openmdao.api as om
import pytest
from openmdao.core.driver import Driver

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())


def test_every_subpackage_is_installed():
    """components/ and groups/ map onto lpc_mdo.*; a forgotten subpackage would not install."""
    listed = set(PYPROJECT["tool"]["setuptools"]["packages"])
    for top, namespace in (
        ("components", "lpc_mdo.components"),
        ("groups", "lpc_mdo.groups"),
        ("lpc_mdo", "lpc_mdo"),
    ):
        for init in (ROOT / top).rglob("__init__.py"):
            rel = init.parent.relative_to(ROOT / top).parts
            name = ".".join((namespace, *rel))
            assert name in listed, f"{name} is missing from [tool.setuptools] packages"


@pytest.mark.parametrize(
    ("group", "base"),
    [
        ("openmdao_component", om.ExplicitComponent),
        ("openmdao_group", om.Group),
        ("openmdao_driver", Driver),
    ],
)
def test_entry_points_load(group, base):
    """What `openmdao list_installed` shows must import and be the right kind of class."""
    entries = PYPROJECT["project"]["entry-points"][group]
    assert entries
    for target in entries.values():
        module, _, attr = target.partition(":")
        cls = getattr(__import__(module, fromlist=[attr]), attr)
        assert issubclass(cls, (base, om.ImplicitComponent)), target


def test_plugin_keywords():
    keywords = PYPROJECT["project"]["keywords"]
    for word in ("openmdao", "openmdao_component", "openmdao_group", "openmdao_driver"):
        assert word in keywords
