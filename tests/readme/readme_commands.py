"""Every command the README documents exists and runs (quick settings), so none can silently go.

    python3 tests/readme/readme_commands.py SOURCE_DIR [--only CMD ...]

1. Each `scripts/run.sh <command>` in README.md has its case in scripts/run.sh.
2. The commands that run a job are run here, against the installed addon in the test home
   (HOME from the environment), the way scripts/run.sh runs them, with quick settings: each
   must exit 0 and write its outputs. `test` (this suite), `bench` (the benchmarks),
   `install` and `corpus` (their own tests) are not run from here.
Exit 1 listing each failure.
"""
import os
import re
import subprocess
import sys
import tempfile

# command -> (script, quick environment, outputs that must exist)
RUNS = {
    "demo": ("scripts/demo.py", {"AERONC_CELL": "1.0"},
             ["report.html", "sample_panel_setup1.mpf", "sample_panel_setup1.ngc", "verification.json"]),
    "drill": ("scripts/drill.py", {}, ["compensation_report.html", "drilling.mpf", "camera.apt",
                                       "measured_datum_holes.csv", "wing_skin.FCStd"]),
    "post": ("scripts/post_sample.py", {}, ["sample_panel.mpf", "sample_panel.ngc", "sample_panel.apt"]),
    "impeller": ("scripts/impeller.py",
                 {"AERONC_STATIONS": "4", "AERONC_CHANNELS": "1",
                  "AERONC_IMPELLER_SPEC": '{"bladeCount": 3, "filletRadius": 2.0, "bladeHeight": 11.0}'},
                 ["report.html", "IMPELLER.mpf", "impeller.FCStd"]),
}
NOT_RUN_HERE = {"test", "bench", "install", "corpus"}  # corpus: its own ctest (tests/CMakeLists.txt)


def documented(root):
    with open(os.path.join(root, "README.md"), encoding="utf-8") as f:
        return sorted(set(re.findall(r"scripts/run\.sh (\w+)", f.read())))


def cases(root):
    with open(os.path.join(root, "scripts", "run.sh"), encoding="utf-8") as f:
        return set(re.findall(r"^\s+(\w+)\)\s*$", f.read(), re.M))


def main(argv):
    root = argv[1]
    only = argv[argv.index("--only") + 1:] if "--only" in argv else None
    failures = []
    have = cases(root)
    commands = documented(root)
    for c in commands:
        if c not in have:
            failures.append("README documents `scripts/run.sh {}`, which scripts/run.sh does not know".format(c))
        elif c not in RUNS and c not in NOT_RUN_HERE:
            failures.append("`scripts/run.sh {}` is documented but no test runs it (add it to RUNS)".format(c))
    for c in commands:
        if c not in RUNS or (only and c not in only):
            continue
        script, env, outputs = RUNS[c]
        with tempfile.TemporaryDirectory(prefix="aeronc_readme_{}_".format(c)) as out:
            run = subprocess.run(["freecadcmd", os.path.join(root, script)], capture_output=True, text=True,
                                 env=dict(os.environ, AERONC_OUT=out, **env), timeout=1500)
            missing = [o for o in outputs if not os.path.isfile(os.path.join(out, o))]
            if run.returncode != 0 or missing:
                failures.append("`scripts/run.sh {}`: exit {}, missing {}; last output: {}".format(
                    c, run.returncode, missing or "nothing", (run.stdout + run.stderr)[-1500:]))
            else:
                print("scripts/run.sh {}: ran, wrote {}".format(c, ", ".join(outputs)))
    for f in failures:
        print("FAIL: " + f)
    print("README commands: {} documented ({}), {}".format(len(commands), ", ".join(commands),
                                                          "all run" if not failures else "{} failure(s)".format(
                                                              len(failures))))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
