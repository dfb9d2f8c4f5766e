"""Sphinx configuration of the lpc-mdo documentation (theory manual and API pages).

Build (warnings are errors, as in CI)::

    python -m sphinx -W --keep-going -b html docs docs/_build/html

The build needs no network: no intersphinx, and the theme (furo) and MathJax come from the
installed packages (MathJax is loaded by the reader's browser, not at build time).
"""

import os
import sys

import lpc_mdo

# Local extensions: the study-table directive renders lpc_mdo.study_plan (docs/_ext).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "_ext"))

project = "lpc-mdo"
author = "lpc-mdo developers"
copyright = "2026, lpc-mdo developers"
release = lpc_mdo.__version__
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "study_table",
    "myst_parser",
]
# Markdown pages (examples, optimizing, results) next to the reStructuredText ones.
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}

templates_path = ["_templates"]
exclude_patterns = ["_build"]
root_doc = "index"

# API pages: autosummary walks the lpc_mdo package recursively (lpc_mdo.components and
# lpc_mdo.groups are its subpackages), so a module that is added, moved or split appears
# without editing a list; see docs/api.rst.
autosummary_generate = True
autosummary_imported_members = False
# A package that re-exports names in __all__ (lpc_mdo.vehicle, lpc_mdo.api, lpc_mdo.drivers)
# documents only what it defines: each object is described once, on its own module's page.
autodoc_default_options = {"members": True, "show-inheritance": True, "ignore-module-all": True}
autodoc_member_order = "bysource"
autodoc_typehints = "description"
autoclass_content = "class"

# numpydoc docstrings
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
# The components' class docstrings list their OpenMDAO variables and options in numpydoc
# parameter form under these headings (ARCHITECTURE conventions); render them as parameter
# lists.
napoleon_custom_sections = [
    ("Inputs", "params_style"),
    ("Outputs", "params_style"),
    ("Options", "params_style"),
    ("Subsystems", "params_style"),
]

html_theme = "furo"
html_title = f"lpc-mdo {release}"
