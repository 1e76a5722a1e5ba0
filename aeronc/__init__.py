"""AeroNC: knowledge-based NC programming, an addon of FreeCAD's Path workbench.

Layout (installed under <Mod>/AeroNC/aeronc):
  _core          C++ recognition core (pybind11)
  recognition    App-side wrapper around _core
  pathcompat     the only module that imports FreeCAD's Path modules
  objects        App-side document objects (work under freecadcmd)
  viewproviders  GUI side of the objects (imported only when FreeCAD.GuiUp)
  commands       GUI commands and the hook into the Path workbench
  panels         task panels
This file must stay cheap to import: FreeCAD imports it at GUI start-up.
"""
import os

__version__ = "0.1.0"

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
ICON_DIR = os.path.join(PACKAGE_DIR, "resources", "icons")


def icon(name):
    """Path of an icon file shipped in resources/icons (name without .svg)."""
    return os.path.join(ICON_DIR, name + ".svg")
