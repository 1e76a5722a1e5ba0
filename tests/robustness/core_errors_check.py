"""Rejected input always raises the core's own exception, with a message that can be shown:
never a UnicodeDecodeError (a message quoting bytes that are not UTF-8, or cut inside a
character), never a crash of the interpreter (JSON nested 100,000 deep). Plain python3 with
the installed addon on the path (no FreeCAD needed):

    AERONC_MOD_DIR=build/stage/AeroNC python3 tests/robustness/core_errors_check.py
"""
import json
import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

MOD = os.environ.get("AERONC_MOD_DIR", "")
if MOD:
    sys.path.insert(0, MOD)

from aeronc import _core  # noqa: E402
from aeronc.post import apt, machines  # noqa: E402


def sections(gcode):
    return [{"kind": "tool", "label": "TC", "tool": {"number": 1, "name": "EM10", "diameter": 10.0},
             "rpm": 8000.0, "spindle_dir": 1},
            {"kind": "operation", "label": "Op", "gcode": gcode, "coolant": "none"}]


class CoreErrors(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.machine, _ = machines.load("AC-5AX")

    def test_a_character_that_is_no_command_is_quoted_whole(self):
        with self.assertRaises(_core.PostError) as cm:
            _core.post_nc(sections("G0 X0 Y0 Z5 \u00e9\n"), self.machine, "AC-5AX")
        self.assertIn("cannot read '\u00e9'", str(cm.exception))

    def test_bytes_that_are_not_utf8_are_escaped(self):
        with self.assertRaises(_core.PostError) as cm:
            _core.post_apt(b"LOADTL/1\n\xff\xfe/1\n", self.machine, "AC-5AX")
        self.assertIn("APT line 2", str(cm.exception))
        self.assertIn("\\xff\\xfe", str(cm.exception))

    def test_the_apt_command_line_reports_a_file_that_is_not_utf8(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "bad.apt")
            with open(path, "wb") as f:
                f.write(b"LOADTL/1\nPPRINT/caf\xe9\nFEDRAT/1e64\nGOTO/0,0,50\nFINI\n")
            r = subprocess.run([sys.executable, "-m", "aeronc.post.apt", path, "-"], capture_output=True, text=True,
                               env=dict(os.environ, PYTHONPATH=MOD), timeout=120)
            self.assertEqual(r.returncode, 1, r.stderr)
            self.assertIn("APT line 4: feed 1e+64 mm/min exceeds the machine's maximum feed", r.stderr)
            self.assertNotIn("Traceback", r.stderr)

    def test_a_machine_file_with_a_sinumerik_string_is_refused(self):
        machine = json.loads(self.machine)
        machine["sinumerik"] = "TC2"
        with self.assertRaises(_core.PostError) as cm:
            _core.check_machine(json.dumps(machine), "m.json")
        self.assertIn("\"sinumerik\" must be an object", str(cm.exception))

    def test_a_part_that_makes_occt_fault_raises_recognition_error(self):
        # A damaged copy of a NIST part on which OpenCASCADE's STEP reader once faulted
        # (step_mutation_check.py, seed 15, the first copy). In a child: a fault would kill it.
        nist = os.environ.get("AERONC_NIST_DIR", "")
        part = os.path.join(nist, "nist_ftc_06_asme1_rd.stp")
        if not os.path.exists(part):
            self.skipTest("NIST parts not found (AERONC_NIST_DIR)")
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import step_mutation_check
        import random
        with open(part, "rb") as f:
            kind, damaged = step_mutation_check.mutate(f.read(), random.Random("15:nist_ftc_06_asme1_rd.stp"))
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "damaged.stp")
            with open(path, "wb") as f:
                f.write(damaged)
            code = textwrap.dedent("""
                import sys
                sys.path.insert(0, %r)
                from aeronc import _core
                try:
                    _core.recognise_file(%r)
                    print("recognised")
                except _core.RecognitionError as e:
                    print("RecognitionError", e)
                """) % (MOD, path)
            r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
        self.assertEqual(r.returncode, 0, "%s copy: %s" % (kind, r.stderr[-500:]))
        last = r.stdout.strip().splitlines()[-1] if r.stdout.strip() else ""  # OCCT prints its own notes first
        self.assertTrue(last.startswith(("RecognitionError", "recognised")), r.stdout)

    def test_deeply_nested_json_is_an_error_not_a_crash(self):
        # In a child: a stack overflow would take the interpreter with it.
        code = textwrap.dedent("""
            import sys
            sys.path.insert(0, %r)
            from aeronc import _core
            deep = "[" * 100000 + "]" * 100000
            for call in (lambda: _core.optimise_cutting('{"notes": %%s}' %% deep),
                         lambda: _core.post_apt("FINI\\n", '{"name": %%s}' %% deep, "m.json"),
                         lambda: _core.post_apt("FINI\\n", %r, "m.json", '{"a": %%s}' %% deep)):
                try:
                    call()
                    print("no error")
                except RuntimeError as e:
                    print(type(e).__name__, str(e)[:200])
            """) % (MOD, self.machine)
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = r.stdout.splitlines()
        self.assertEqual(len(lines), 3, r.stdout)
        for line in lines:
            self.assertIn("nested deeper than 64 levels", line)


if __name__ == "__main__":
    unittest.main()
