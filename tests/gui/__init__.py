"""GUI tests of AeroNC, imported as aeronc.tests.gui: scripts FreeCAD runs under Xvfb (tests/CMakeLists.txt)."""
