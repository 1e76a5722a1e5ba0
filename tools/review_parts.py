"""Recognise a set of parts and draw each coloured by feature type, for review.

    AERONC_PARTS="a.stp b.stp" AERONC_OUT=docs/recognition freecadcmd tools/review_parts.py

Writes <name>.png per part and summary.md (elements per type and setup, faces per role,
time). Runs headless against the installed addon.
"""
import os
import time


def main():
    import Part
    from aeronc.reports import picture
    from aeronc.pipeline import recognition

    out = os.path.abspath(os.environ.get("AERONC_OUT", "out/review"))
    os.makedirs(out, exist_ok=True)
    rows = ["| part | faces | setups | closed pockets | open pockets | openings | holes | unrecognised faces | time (s) |",
            "|---|---|---|---|---|---|---|---|---|"]
    for path in os.environ["AERONC_PARTS"].split():
        name = os.path.splitext(os.path.basename(path))[0]
        shape = Part.read(path)
        t0 = time.perf_counter()
        try:
            r = recognition.recognise(shape)
        except recognition.RecognitionError as e:
            rows.append("| {} | error: {} |".format(name, e))
            continue
        dt = time.perf_counter() - t0
        count = {}
        for e in r["elements"]:
            count[e["type"]] = count.get(e["type"], 0) + 1
        picture.render(shape, r, os.path.join(out, name + ".png"),
                       title="{}: {} setup directions, {} elements".format(name, len(r["setups"]), len(r["elements"])))
        rows.append("| {} | {} | {} | {} | {} | {} | {} | {} | {:.2f} |".format(
            name, r["faceCount"], len(r["setups"]), count.get("closed_pocket", 0), count.get("open_pocket", 0),
            count.get("opening", 0), count.get("hole", 0), sum(1 for x in r["faceRoles"] if x in ("stock", "unclaimed")),
            dt))
        print(rows[-1])
    with open(os.path.join(out, "summary.md.part"), "w") as f:
        f.write("\n".join(rows) + "\n")
    os.replace(os.path.join(out, "summary.md.part"), os.path.join(out, "summary.md"))


from aeronc.tests.script import run  # noqa: E402

run(main)
