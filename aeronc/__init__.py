"""AeroNC: knowledge-based NC programming, an addon of FreeCAD's Path workbench.

Imported as aeronc: installed as <Mod>/AeroNC/aeronc, and FreeCAD puts <Mod>/AeroNC on
sys.path, so `aeronc` is the only name AeroNC adds there. The folders are the layers
(docs/architecture.md):
  _core           C++ core (pybind11): recognition, knowledge base, chain, toolpaths, posts, ...
  errors          AeroNCError, the base of every AeroNC exception; from_core
  pathcompat      the only module that imports FreeCAD's Path (CAM) workbench
  pipeline        part -> tree -> tool plan -> cutting data -> chain -> Jobs -> verification
  drilling        hole geometry, datum-hole pattern, camera program, compensation
  impeller        impeller recognition and Program impeller
  objects         App-side document objects, proxies only (work under freecadcmd)
  operations      AeroNC's Path operations
  makers          create, remake and remove the document objects (one undo step each)
  post            the 5-axis posts and APT files
  reports         HTML reports and pictures
  runs            whole runs, headless: the main job, the impeller run, the drilling run
  viewproviders   GUI side of the objects (GUI only)
  commands        GUI commands and the hook into the Path workbench (commands/)
  panels          task panels (panels/)
  tests           FreeCAD-side tests, test-part makers and their helpers (tests/; not in a
                  user install)
This file must stay cheap to import: FreeCAD imports it at GUI start-up.
"""
import os

from aeronc import moved

__version__ = "0.1.0"

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
ICON_DIR = os.path.join(PACKAGE_DIR, "resources", "icons")


def icon(name):
    """Path of an icon file shipped in resources/icons (name without .svg)."""
    return os.path.join(ICON_DIR, name + ".svg")


moved.install()  # documents saved before a module moved still open
