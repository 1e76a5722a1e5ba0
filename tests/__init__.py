"""AeroNC's FreeCAD-side tests (installed as aeronc.tests). app/: headless, run by
run_app_tests.py under freecadcmd; gui/: a script run inside the FreeCAD GUI."""
