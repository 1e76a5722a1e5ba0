"""The main job on every STEP part of the shared data, one FreeCAD process per part, and a table.

    python3 scripts/corpus.py [--data ../shared/data] [--out out/corpus] [--cell 1.0] [--mfcad]
                              [--parts NAME,...] [--timeout S] [--machine M] [--large M|none]
                              [--no-pictures] [--check]

(`scripts/run.sh corpus` runs it with the installed addon.) For each part (nist/*.stp,
real/*.stp, and with --mfcad the MFCAD sample) it runs scripts/demo.py into OUT/<part>/ and reads
the run.json the main job writes there, also when the run failed. It writes OUT/summary.json
and OUT/summary.md: per part the elements, those machined, those not machined by reason, the
unclaimed faces, the operations the gate left out, gouges and colliding rapids in the delivered
programs (count, worst), the material left against the part, the time of each stage, and whether
a program was delivered (or the stage that failed, or why there is none). A part whose post
the machine (--machine; by default the main job chooses the smallest that holds it,
docs/machine-choice.md) refuses because a move leaves its travel is recorded so, and run again on
the large machine (--large, none by default) as a row of its own.

--check: exit 1 when any delivered program gouges or rapids through material (or a part's run
left no run.json: it crashed or timed out); the ctest `corpus` runs it so.
FreeCAD must find AeroNC (HOME with the addon in .local/share/FreeCAD/Mod, as run.sh sets up).
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STAGE_SHORT = {"read part": "read", "recognise": "recog", "machine": "mach", "select tools": "tools",
               "machining chain": "chain", "post": "post", "verify": "verify", "pictures": "pics", "save": "save"}


def parts_of(data, mfcad=False, only=None):
    found = []
    for pattern in ("nist/*.stp", "nist/*.step", "real/*.stp", "real/*.step") + (("mfcad/*.step",) if mfcad else ()):
        found += sorted(glob.glob(os.path.join(data, pattern)))
    if only:
        names = set(only)
        found = [p for p in found if os.path.splitext(os.path.basename(p))[0] in names]
    return found


def run_part(part, out, cell, timeout, machine, folder_name=None, pictures=True):
    """Run the main job on one part in its own FreeCAD; returns (run.json's dict or None, seconds,
    the last line it printed on stderr)."""
    name = os.path.splitext(os.path.basename(part))[0]
    folder = os.path.join(out, folder_name or name)
    os.makedirs(folder, exist_ok=True)
    summary = os.path.join(folder, "run.json")
    if os.path.exists(summary):
        os.unlink(summary)  # a crash must not pass for the last run's result
    env = dict(os.environ, AERONC_PART=os.path.abspath(part), AERONC_OUT=folder, AERONC_CELL=str(cell),
               AERONC_MACHINE=machine, AERONC_PICTURES="1" if pictures else "0")
    t0 = time.perf_counter()
    try:
        p = subprocess.run(["freecadcmd", os.path.join(ROOT, "scripts", "demo.py")], env=env, capture_output=True,
                           text=True, errors="replace", timeout=timeout)
        err = [l for l in p.stderr.splitlines() if l.strip()]
        last = err[-1] if err else ("exit {}".format(p.returncode) if p.returncode else "")
    except subprocess.TimeoutExpired:
        last = "timed out after {:.0f} s".format(timeout)
    seconds = time.perf_counter() - t0
    with open(os.path.join(folder, "console.log"), "w") as f:
        f.write(last + "\n")
    if not os.path.exists(summary):
        return None, seconds, last
    with open(summary) as f:
        return json.load(f), seconds, last


def reason_key(text):
    """A reason without its element's name and figures, to count alike reasons together."""
    text = re.sub(r"'element \d+'", "'element'", text or "")
    text = re.sub(r"\d+(\.\d+)?", "#", text)
    return text.split(";")[0].strip()


def row_of(part, run, seconds, last, machine):
    name = os.path.splitext(os.path.basename(part))[0]
    if run is None:
        return {"part": name, "machine": machine, "file": os.path.relpath(part, ROOT), "crashed": last,
                "seconds": seconds}
    reasons = {}
    for _, why in (run.get("notMachined") or {}).items():
        k = reason_key(why)
        reasons[k] = reasons.get(k, 0) + 1
    delivered = bool(run.get("programs"))
    machine = (run.get("machine") or {}).get("name") or machine  # the one the main job chose
    return {"part": name, "machine": machine, "file": os.path.relpath(part, ROOT), "seconds": seconds,
            "elements": run.get("elements", 0), "notMachined": len(run.get("notMachined") or {}),
            "notMachinedByReason": reasons, "unclaimedFaces": run.get("unclaimedFaces", 0),
            "leftOut": len(run.get("leftOut") or []),
            "leftOutByKind": _count(e.get("kind") for e in run.get("leftOut") or []),
            "gouges": (run.get("gouges") or {}) if delivered else None,
            "collisions": (run.get("collisions") or {}) if delivered else None,
            "materialLeft": run.get("materialLeft"), "stages": run.get("stages") or [],
            "programs": run.get("programs") or [], "delivered": delivered,
            "status": (run.get("verdict") or {}).get("status"), "verdict": (run.get("verdict") or {}).get("text"),
            "failed": run.get("failed")}


def beyond_travel(row):
    """The run stopped because the machine named is too small: at its post (a move beyond the
    travel) or before (the machine choice's check of the blank and the toolpaths)."""
    failed = row.get("failed") or {}
    error = failed.get("error", "")
    return (failed.get("stage") == "post" and "beyond the travel" in error) or "does not hold the part" in error


def _count(items):
    out = {}
    for k in items:
        out[k] = out.get(k, 0) + 1
    return out


def unsafe(row):
    """Why a row fails the corpus check: a delivered program that gouges or rapids through
    material, or a run that left no summary."""
    if "crashed" in row:
        return "no run.json: {}".format(row["crashed"])
    if row["delivered"] and (int(row["gouges"].get("count", 0)) or int(row["collisions"].get("count", 0))):
        return "delivered programs: {} gouging moves (worst {} mm), {} colliding rapids (worst {} mm)".format(
            row["gouges"].get("count"), row["gouges"].get("worst"), row["collisions"].get("count"),
            row["collisions"].get("worst"))
    return None


def markdown(rows, cell, command):
    out = ["# Corpus run: the main job on every STEP part of the shared data", "",
           "`{}` (verification cell {} mm). Generated by scripts/corpus.py.".format(command, cell), "",
           "Delivered: the programs the gate let through (operations that gouge, rapid through material or "
           "have no toolpath are left out and named in them). Gouges and colliding rapids are those of the "
           "delivered programs. Material left: against every face of the part inside the blank. Not machined: "
           "the elements the chain could not plan, and those one of whose operations the gate left out.", "",
           "| part | machine | elements | not machined | unclaimed faces | ops left out | gouges (worst mm) | "
           "colliding rapids (worst mm) | material left mm² (max mm) | program | verdict | time s |",
           "|---|---|---:|---:|---:|---:|---:|---:|---:|---|---|---:|"]
    for r in rows:
        if "crashed" in r:
            out.append("| {} | {} | | | | | | | | **none: {}** | | {:.0f} |".format(
                r["part"], r["machine"], r["crashed"], r["seconds"]))
            continue
        m = r["materialLeft"] or {}
        program = ("yes ({} files)".format(len(r["programs"])) if r["delivered"] else
                   "**none: beyond the travel**" if beyond_travel(r) else
                   "**none: failed at {}**".format(r["failed"]["stage"]) if r.get("failed") else "**none**")
        out.append("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.0f} |".format(
            r["part"], r["machine"], r["elements"], r["notMachined"], r["unclaimedFaces"],
            r["leftOut"] if not r["leftOut"] else "{} ({})".format(
                r["leftOut"], ", ".join("{} {}".format(n, k) for k, n in sorted(r["leftOutByKind"].items()))),
            _pair(r["gouges"]), _pair(r["collisions"]),
            "{:,.0f} ({:.2f})".format(m.get("area", 0), m.get("maxLeft", 0)) if m.get("entries") else "0",
            program, r["status"] or "", r["seconds"]))
    out += ["", "## Not machined, by reason", ""]
    for r in rows:
        if r.get("notMachinedByReason") and not beyond_travel(r):
            out.append("- **{}**: ".format(r["part"]) + "; ".join(
                "{} × {}".format(n, k) for k, n in sorted(r["notMachinedByReason"].items(), key=lambda kv: -kv[1])))
    out += ["", "## Verdicts and failures", ""]
    for r in rows:
        who = "{} ({})".format(r["part"], r["machine"])
        if "crashed" in r:
            out.append("- **{}**: {}".format(who, r["crashed"]))
        elif r.get("failed"):
            out.append("- **{}**: {}".format(who, r["failed"]["error"]))
        else:
            out.append("- **{}**: {}".format(who, r["verdict"]))
    out += ["", "## Stage times (s)", "",
            "| part | " + " | ".join(STAGE_SHORT.values()) + " |", "|---|" + "---:|" * len(STAGE_SHORT)]
    for r in rows:
        times = dict((n, t) for n, t in r.get("stages") or [])
        out.append("| {} ({}) | ".format(r["part"], r["machine"]) + " | ".join(
            "{:.1f}".format(times[n]) if n in times else "" for n in STAGE_SHORT) + " |")
    return "\n".join(out) + "\n"


def _pair(section):
    if section is None:
        return "&ndash;"
    n = int(section.get("count", 0))
    return "0" if n == 0 else "**{} ({:.2f})**".format(n, float(section.get("worst", 0)))


def main(argv):
    a = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    a.add_argument("--data", default=os.path.join(ROOT, "..", "shared", "data"))
    a.add_argument("--out", default=os.path.join(ROOT, "out", "corpus"))
    a.add_argument("--cell", type=float, default=1.0, help="the verification's cell size, mm")
    a.add_argument("--mfcad", action="store_true", help="also the MFCAD sample")
    a.add_argument("--parts", default="", help="only these parts (file names without extension, comma-separated)")
    a.add_argument("--timeout", type=float, default=1800, help="seconds per part")
    a.add_argument("--machine", default="auto",
                   help="the machine the main job posts for ('auto': the smallest whose travel holds the part)")
    a.add_argument("--large", default="none",
                   help="the machine for a part beyond the first one's travel ('none': no second run)")
    a.add_argument("--no-pictures", action="store_true", help="skip the main job's pictures (the ctest: time)")
    a.add_argument("--check", action="store_true", help="exit 1 on a gouge or colliding rapid in a delivered program")
    a.add_argument("--crib", default="",
                   help="the user's own tool crib in place of the shipped one: a knowledge-base file or a FreeCAD "
                        ".fctl library (docs/tool-crib.md)")
    args = a.parse_args(argv)
    if args.crib:
        os.environ["AERONC_CRIB"] = os.path.abspath(args.crib)  # run_part passes the environment on
    parts = parts_of(args.data, args.mfcad, [p for p in args.parts.split(",") if p])
    if not parts:
        print("corpus: no STEP part under {}".format(args.data), file=sys.stderr)
        return 2
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for k, part in enumerate(parts, 1):
        machine = args.machine
        while True:
            name = os.path.splitext(os.path.basename(part))[0]
            run, seconds, last = run_part(part, args.out, args.cell, args.timeout, machine,
                                          name if machine == args.machine else "{}.{}".format(name, machine),
                                          not args.no_pictures)
            row = row_of(part, run, seconds, last, machine)
            rows.append(row)
            print("[{}/{}] {:<28s} {:<9s} {:>6.0f} s  {}".format(
                k, len(parts), row["part"], machine, seconds, row.get("verdict") or row.get("crashed")), flush=True)
            if not beyond_travel(row) or args.large in ("none", machine):
                break
            machine = args.large
    command = "scripts/run.sh corpus" + ("" if args.cell == 1.0 else " (AERONC_CELL={})".format(args.cell))
    with open(os.path.join(args.out, "summary.json"), "w") as f:
        json.dump({"cell": args.cell, "parts": rows}, f, indent=1)
    with open(os.path.join(args.out, "summary.md"), "w") as f:
        f.write(markdown(rows, args.cell, command))
    bad = [(r["part"], unsafe(r)) for r in rows if unsafe(r)]
    for name, why in bad:
        print("corpus: {}: {}".format(name, why), file=sys.stderr)
    print("corpus: {} parts in {} runs, {} with programs delivered, {} unsafe; {}".format(
        len(parts), len(rows), sum(1 for r in rows if r.get("delivered")), len(bad),
        os.path.join(args.out, "summary.md")))
    return 1 if args.check and bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
