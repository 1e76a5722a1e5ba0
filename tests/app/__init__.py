"""Headless FreeCAD tests of AeroNC, imported as aeronc.tests.app (run by tests/run_app_tests.py)."""
