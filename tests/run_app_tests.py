"""Runs AeroNC's headless tests against the INSTALLED addon:

    freecadcmd tests/run_app_tests.py

The addon is found on FreeCAD's Mod path (user Mods: $HOME/.local/share/FreeCAD/Mod) or in
env AERONC_MOD_DIR (the folder holding aeronc/, i.e. <Mod>/AeroNC). Prints one line per test,
then "N passed, N failed", and ends with exit code 0 when all passed, 1 otherwise. Env
AERONC_APP_TEST_PATTERN picks other files than test_*.py (the impeller's slower tests,
impeller_*_tests.py and shared_impeller_tests.py, each run as a CTest of its own).
freecadcmd runs this file as a module (not __main__), so the code runs at import.
"""
import os
import sys
import traceback
import unittest


def _locate():
    mod = os.environ.get("AERONC_MOD_DIR")
    if mod:
        if not os.path.isdir(os.path.join(mod, "aeronc")):
            raise RuntimeError("AERONC_MOD_DIR={} holds no aeronc/ package".format(mod))
        sys.path.insert(0, mod)
    import aeronc
    here = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
    if os.path.realpath(aeronc.PACKAGE_DIR) == os.path.join(here, "aeronc"):
        raise RuntimeError("imported aeronc from the source tree ({}); install the addon first"
                           .format(aeronc.PACKAGE_DIR))
    return aeronc


def _main():
    aeronc = _locate()
    print("aeronc from {}".format(aeronc.PACKAGE_DIR))
    tests_dir = os.path.join(aeronc.PACKAGE_DIR, "tests", "app")
    top = os.path.dirname(aeronc.PACKAGE_DIR)
    pattern = os.environ.get("AERONC_APP_TEST_PATTERN") or "test_*.py"
    suite = unittest.defaultTestLoader.discover(tests_dir, pattern=pattern, top_level_dir=top)
    result = unittest.TextTestRunner(stream=sys.stdout, verbosity=2).run(suite)
    failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
    return result.testsRun - failed, failed


try:
    passed, failed = _main()
except Exception:
    traceback.print_exc()
    passed, failed = 0, 1
print("{} passed, {} failed".format(passed, failed))
sys.stdout.flush()
os._exit(0 if failed == 0 and passed > 0 else 1)
