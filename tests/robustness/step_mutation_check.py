"""A fixed, seeded set of damaged copies of the NIST STEP parts through `aeronc recognise`:
every one must end cleanly, with exit 0 or with exit 1 and one "aeronc: error: ..." line,
never a signal, never a hang. Plain python3:

    python3 tests/robustness/step_mutation_check.py AERONC_CLI NIST_DIR [--per-part N] [--seed S]
                                                    [--time-limit SECONDS] [--keep DIR]

The damage is what a corrupt download, a bad editor or a careless export does: the file cut
short, bytes overwritten, lines repeated or dropped, numbers replaced by absurd ones,
references pointed at other entities. The CLI runs with --time-limit (OCCT's shape healing
can loop for good on a damaged file); a copy it gives up on is a clean exit 1 as well, counted
apart. Exit 0: all clean; 1: a signal, a hang past the limit or an unclear failure (the
offending files are kept with --keep).
"""
import argparse
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ABSURD_NUMBERS = [b"1.E308", b"-1.E308", b"1.E-320", b"0.", b"-0.", b"NAN", b"INF", b"99999999999999999999.",
                  b"1.E+99999", b".", b"-", b"1.#INF", b"4294967297", b"-2147483649"]
NUMBER = re.compile(rb"(?<![#A-Za-z_\d])-?\d+\.\d*(?:E[+-]?\d+)?")
REFERENCE = re.compile(rb"#\d+")


def data_section(text):
    """Byte range of the DATA section, where damage matters (a damaged header is refused early)."""
    start = text.find(b"DATA;")
    end = text.rfind(b"ENDSEC;")
    if start < 0 or end <= start:
        return 0, len(text)
    return start + 5, end


def mutate(text, rng):
    """One damaged copy of `text`: (kind, bytes)."""
    lo, hi = data_section(text)
    kind = rng.choice(["truncate", "overwrite", "duplicate", "drop", "number", "reference", "splice"])
    if kind == "truncate":
        return kind, text[:rng.randrange(lo, hi)]
    if kind == "overwrite":
        b = bytearray(text)
        for _ in range(rng.randint(1, 40)):
            b[rng.randrange(lo, hi)] = rng.choice(b"0123456789.,;()#=-+'EX$*/ \n" + bytes([rng.randrange(256)]))
        return kind, bytes(b)
    lines = text[lo:hi].split(b"\n")
    if kind in ("duplicate", "drop", "splice"):
        for _ in range(rng.randint(1, 20)):
            i = rng.randrange(len(lines))
            if kind == "duplicate":
                lines.insert(rng.randrange(len(lines)), lines[i])
            elif kind == "drop":
                del lines[i]
            else:  # half of one line joined to half of another
                j = rng.randrange(len(lines))
                lines[i] = lines[i][:len(lines[i]) // 2] + lines[j][len(lines[j]) // 2:]
        return kind, text[:lo] + b"\n".join(lines) + text[hi:]
    body = text[lo:hi]
    pattern = NUMBER if kind == "number" else REFERENCE
    spans = [m.span() for m in pattern.finditer(body)]
    if not spans:
        return kind, text
    chosen = sorted(rng.sample(spans, min(len(spans), rng.randint(1, 30))))
    out, last = [], 0
    for a, b in chosen:
        out.append(body[last:a])
        out.append(rng.choice(ABSURD_NUMBERS) if kind == "number" else b"#%d" % rng.randrange(1, 10 ** rng.randint(1, 7)))
        last = b
    out.append(body[last:])
    return kind, text[:lo] + b"".join(out) + text[hi:]


def run_case(cli, path, out_json, limit):
    """(verdict, detail): 'exit0', 'exit1', 'limit', or a failure kind with its detail."""
    timeout = limit + 60
    try:
        r = subprocess.run([cli, "recognise", path, "--json", out_json, "--time-limit", str(limit)],
                           capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "hang", "no exit within %g s" % timeout
    err = r.stderr.decode("utf-8", "replace").strip()
    if r.returncode < 0:
        return "signal", signal.Signals(-r.returncode).name
    if r.returncode == 0:
        return "exit0", ""
    lines = err.splitlines()
    if r.returncode == 1 and len(lines) == 1 and lines[0].startswith("aeronc: error: "):
        return ("limit" if "--time-limit" in lines[0] else "exit1"), lines[0]
    return "unclear", "exit %d: %s" % (r.returncode, err[-300:])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cli")
    ap.add_argument("nist")
    ap.add_argument("--per-part", type=int, default=6)
    ap.add_argument("--seed", type=int, default=15)
    ap.add_argument("--time-limit", type=int, default=60)
    ap.add_argument("--keep", help="folder to keep the files that failed")
    a = ap.parse_args()

    parts = sorted(f for f in os.listdir(a.nist) if f.lower().endswith((".stp", ".step")))
    if not parts:
        print("no STEP parts in %s" % a.nist)
        return 1
    counts, failures = {}, []
    work = tempfile.mkdtemp(prefix="aeronc_step_mutation_")
    started = time.time()
    try:
        for part in parts:
            with open(os.path.join(a.nist, part), "rb") as f:
                text = f.read()
            rng = random.Random("%d:%s" % (a.seed, part))
            for k in range(a.per_part):
                kind, damaged = mutate(text, rng)
                name = "%s.%02d.%s.stp" % (os.path.splitext(part)[0], k, kind)
                path = os.path.join(work, name)
                with open(path, "wb") as f:
                    f.write(damaged)
                verdict, detail = run_case(a.cli, path, os.path.join(work, "out.json"), a.time_limit)
                counts[verdict] = counts.get(verdict, 0) + 1
                if verdict not in ("exit0", "exit1", "limit"):
                    failures.append((name, verdict, detail))
                    print("FAIL %s: %s %s" % (name, verdict, detail))
                    if a.keep:
                        os.makedirs(a.keep, exist_ok=True)
                        shutil.copy(path, os.path.join(a.keep, name))
                os.remove(path)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    total = sum(counts.values())
    print("%d damaged copies of %d parts (seed %d) in %.0f s: %s" % (
        total, len(parts), a.seed, time.time() - started,
        ", ".join("%s %d" % (k, v) for k, v in sorted(counts.items()))))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
