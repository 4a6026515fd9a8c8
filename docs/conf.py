"""Sphinx configuration of poinsot's documentation site (`make docs` → docs/_build/html).

Sphinx + pydata-sphinx-theme + myst-nb + sphinx-gallery, docstrings in numpydoc sections read
by napoleon, as scipy, matplotlib and scikit-learn do: the topic pages stay markdown (MyST), the API reference is generated from the
numpydoc docstrings, the gallery executes examples/ at build time, and MathJax is served from
the site itself (docs/node_modules/mathjax, `npm ci` in docs/), so the built site works offline.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import poinsot

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE / "_ext"))

project = "poinsot"
author = "the poinsot developers"
copyright = "2025-2026, the poinsot developers"
release = poinsot.__version__
version = release

extensions = [
    "myst_nb",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx_gallery.gen_gallery",
    "sphinx_click",
    "sphinx_copybutton",
    "sphinx_design",
    "poinsot_docs",
    "pictures",
    "cited_equations",
    "world_pages",
]

source_suffix = {".rst": "restructuredtext", ".md": "myst-nb", ".ipynb": "myst-nb"}
root_doc = "index"
exclude_patterns = [
    "_build",
    "node_modules",
    "_ext",
    "README.md",
    "gallery/*.ipynb",
    "gallery/*.py",
    "gallery/*.md5",
    "gallery/*.codeobj.json",
    "gallery/*.zip",
]
suppress_warnings = ["myst.header"]

# MyST: $…$ and $$…$$ math, ::: fences, definition lists, heading anchors for links like
# page.md#section.
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist", "attrs_inline"]
myst_heading_anchors = 4
myst_dmath_double_inline = True

# Notebooks are executed at build time (they are lessons; a stale output would lie).
nb_execution_mode = "force"
nb_execution_timeout = 300
nb_execution_raise_on_error = True

# MathJax from the site itself: copied from docs/node_modules/mathjax into _static/mathjax by
# poinsot_docs (the `builder-inited` hook), never from a CDN.
mathjax_path = "mathjax/tex-chtml.js"

autosummary_generate = True
autodoc_typehints = "none"
autodoc_default_options = {"members": True, "inherited-members": False}
# The docstrings use numpydoc sections (Parameters / Returns with units and shapes) and, in
# older modules, Google-style ones (Attributes:, Raises:); napoleon reads both.
napoleon_google_docstring = True
napoleon_numpy_docstring = True
napoleon_use_rtype = False
napoleon_attr_annotations = True
napoleon_use_ivar = True

sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": "gallery",
    "filename_pattern": r".*\.py$",
    "ignore_pattern": r"__init__\.py",
    # The examples write their files into the folder given as argument (poinsot_docs).
    "reset_argv": "poinsot_docs.gallery_argv",
    "image_scrapers": ("matplotlib",),
    "matplotlib_animations": True,
    "download_all_examples": False,
    "remove_config_comments": True,
    # The unit's order (docs/_ext/pictures.py), not the alphabet.
    "within_subsection_order": "pictures.UnitOrder",
    # No execution-times pages: sphinx-gallery builds them with scripts and styles from public
    # CDNs, which would be the only network requests of the site.
    "write_computation_times": False,
    "show_memory": False,
    "line_numbers": False,
    "plot_gallery": os.environ.get("POINSOT_DOCS_GALLERY", "1") != "0",
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
}

html_theme = "pydata_sphinx_theme"
html_title = f"poinsot {release}"
html_static_path = ["_static"]
html_favicon = "_static/favicon.svg"
html_css_files = ["poinsot.css"]
html_theme_options = {
    "navbar_align": "left",
    "show_toc_level": 2,
    "navigation_with_keys": True,
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
    "secondary_sidebar_items": ["page-toc"],
    "use_edit_page_button": False,
    # Nothing fetched from outside the site (no version switcher, no analytics, no icons CDN).
    "icon_links": [],
    "header_links_before_dropdown": 6,
}
html_context = {"default_mode": "auto"}
html_sidebars: dict[str, list[str]] = {"index": [], "getting_started": []}
html_copy_source = False
html_show_sourcelink = False

nitpicky = False
templates_path = ["_templates"]
