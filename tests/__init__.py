"""AeroNC's FreeCAD-side tests, imported as aeronc.tests (tests/ in the source tree, installed
as <Mod>/AeroNC/aeronc/tests in the stage the tests run against; not in a user's install).

  app/           headless tests, run by run_app_tests.py under freecadcmd (aeronc.tests.app),
                 with their helpers (support, post_support, post_sample_job)
  gui/           scripts run inside the FreeCAD GUI under Xvfb (aeronc.tests.gui)
  post/          rs274_check.py, plain python3 against the installed addon
  cli/           the command line's tests (shell)
  pathcompat.py  the tests' side of aeronc.pathcompat: the only test-side module that imports
                 FreeCAD's Path workbench modules (aeronc.tests.pathcompat)
  script.py      the entry of freecadcmd scripts (scripts/, tools/)
"""
