"""AeroNC: knowledge-based NC programming, an addon of FreeCAD's Path workbench.

Imported as aeronc: installed as <Mod>/AeroNC/aeronc, and FreeCAD puts <Mod>/AeroNC on
sys.path, so `aeronc` is the only name AeroNC adds there. Every source folder is a
subpackage (the top-level commands/ and panels/ and tests/ of the source tree included):
  _core                C++ core (pybind11): recognition, knowledge base, optimiser, posts
  errors               AeroNCError, the base of every AeroNC exception; from_core
  recognition          App-side wrapper of the recognition core
  knowledge_base       the user's knowledge base (SQLite, through the core)
  tool_planning        Select tools: the plan written into the document and the Job
  cutting_optimisation spindle speeds and feeds of a Job's ToolControllers
  makers               create, remake and remove the Machining Features tree
  pathcompat           the only shipped module that imports FreeCAD's Path modules
  picture, optimisation_plot, feature_colours   pictures of results
  objects              App-side document objects, proxies only (work under freecadcmd)
  post                 the 5-axis posts and APT files (aeronc.post)
  viewproviders        GUI side of the objects (GUI only)
  commands             GUI commands and the hook into the Path workbench (commands/)
  panels               task panels (panels/)
  tests                FreeCAD-side tests and their helpers (tests/; not in a user install)
This file must stay cheap to import: FreeCAD imports it at GUI start-up.
"""
import os

__version__ = "0.1.0"

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
ICON_DIR = os.path.join(PACKAGE_DIR, "resources", "icons")


def icon(name):
    """Path of an icon file shipped in resources/icons (name without .svg)."""
    return os.path.join(ICON_DIR, name + ".svg")
