"""The impeller report: one HTML page on a programmed impeller (aeronc.runs.impeller_run).

Dimensions measured against the generator's truth, the features, the blank, the process route
with its operations, the tools, the cutting data the optimiser chose (next to the knowledge
base's), the gouge and holder checks of the toolpaths and of the program read back, the posted
program's head, and the pictures beside the page (linked by file name).
"""
import os

from aeronc.reports.html import STYLE, esc, num, table, verdict
from aeronc.post.output import write_atomically

LIMIT_GOUGE_MM = 0.01
DIMENSIONS = [("boreDiameter", "bore diameter"), ("boreDepth", "bore depth"), ("filletRadius", "root fillet radius"),
              ("bladeHeight", "main blade height"), ("minChannelWidth", "narrowest channel")]


def _summary(run):
    r, t = run["result"], run["truth"]
    sec = run.get("seconds", {})
    blades = "{} main + {} splitter".format(r["bladeCount"], r["splitterCount"])
    if t:
        blades += " (truth: {} + {})".format(t["bladeCount"], sum(1 for b in t["blades"] if b["splitter"]))
    rows = [("Part", esc(run.get("source") or "impeller")),
            ("Faces", run["faces"]),
            ("Blades", blades),
            ("Material / machine", "{} / {} (Sinumerik 840D, TRAORI)".format(esc(run["material"]), esc(run["machine"]))),
            ("Blank", "outer profile + {} mm, revolved: \u00d8{} x {} mm, {} cm\u00b3".format(
                num(run["blank"]["allowance"], 2), num(run["blank"]["diameter"], 2), num(run["blank"]["length"], 2),
                num(run["blank"]["volume"] / 1000.0, 1))),
            ("Toolpath detail", "{} stations a pass, {} channels".format(
                run["stations"], run["channels"] or "all")),
            ("Times", "; ".join("{} {:.1f} s".format(k, v) for k, v in sec.items())),
            ("Stages", "; ".join("{} {:.1f} s".format(n, s) for n, s in run.get("stages", [])))]
    return "<table class='summary'>{}</table>".format(
        "".join("<tr><td>{}</td><td>{}</td></tr>".format(esc(a), b) for a, b in rows))


def _dimensions(run):
    d, t = run["result"]["dimensions"], run["truth"]
    if not t:
        rows = [(esc(name), num(d.get(key), 6)) for key, name in DIMENSIONS + [
            ("splitterHeight", "splitter height"), ("outerRadius", "outer radius"), ("axialLength", "axial length")]]
        return "<h2>Dimensions</h2>" + table(["dimension", "measured (mm)"], rows, numeric=(1,))
    rows = []
    for key, name in DIMENSIONS:
        diff = abs(float(d[key]) - float(t[key]))
        rows.append((esc(name), num(d[key], 6), num(t[key], 6), "{:.2e}".format(diff), verdict(diff <= 1e-3)))
    for key, name in (("splitterHeight", "splitter height"), ("outerRadius", "outer radius"),
                      ("axialLength", "axial length")):
        rows.append((esc(name), num(d.get(key), 6), "&ndash;", "&ndash;", ""))
    return "<h2>Dimensions against the generator's truth (1e-3 mm)</h2>" + table(
        ["dimension", "measured (mm)", "truth (mm)", "difference", ""], rows, numeric=(1, 2, 3))


def _features(run):
    r, t = run["result"], run["truth"] or {"blades": []}
    truth_by_shroud = {b["shroud"]: b for b in t["blades"]}
    rows = []
    exact = True
    for i, b in enumerate(r["blades"]):
        tb = truth_by_shroud.get(b["shroud"], {})
        same = bool(tb) and all(b.get(k) == tb.get(k) for k in ("pressure", "suction", "leading", "trailing")) \
            and sorted(b["fillets"]) == sorted(tb.get("fillets", [])) and (b["kind"] == "splitter") == tb.get("splitter")
        exact &= same
        shroud = ", ".join(str(f) for f in (b.get("shroudFaces") or [b["shroud"]]))
        rows.append((i, esc(b["kind"]), num(b.get("angleDeg"), 2), b.get("pressure"), b.get("suction"),
                     b.get("leading"), b.get("trailing"), shroud, ", ".join(str(f) for f in b["fillets"]),
                     verdict(same)))
    singles = [("hub", list(r.get("hubFaces") or [r["hub"]]), [t.get("hub")]), ("bore", [r.get("bore")], [t.get("bore")]),
               ("planes", sorted(r.get("planes", [])), sorted(t.get("planes", [])))]
    other = []
    for name, got, want in singles:
        exact &= got == want
        other.append((esc(name), ", ".join("Face{}".format(f) for f in got), verdict(got == want)))
    if not run["truth"]:
        return ("<h2>Features (FaceN of the part)</h2>" +
                table(["blade", "kind", "angle (deg)", "pressure", "suction", "leading", "trailing", "shroud",
                       "fillets"], [row[:-1] for row in rows], numeric=(0, 2)) +
                table(["feature", "faces"], [row[:-1] for row in other]))
    return ("<h2>Features (FaceN of the part) against the truth: {}</h2>".format(verdict(exact)) +
            table(["blade", "kind", "angle (deg)", "pressure", "suction", "leading", "trailing", "shroud",
                    "fillets", "truth"], rows, numeric=(0, 2)) +
            table(["feature", "faces", "truth"], other))


def _route(run):
    rows = []
    for o in run["operations"]:
        rows.append((o["position"], esc(o["operation"].replace("_", " ")), esc(o["strategy"]), esc(o["tool"] or "-"),
                     "T{}".format(o["toolNumber"]) if o["toolNumber"] else "", num(o["allowance"], 2),
                     "on" if o["active"] else "<span class='muted'>off</span>", o["moves"] or "",
                     num(o["cutLength"], 0) if o["moves"] else "", esc(o["cycleTime"] if o["moves"] else ""),
                     "<span class='small'>{}</span>".format(esc(o["note"]))))
    skipped = run["route"].get("skipped") or []
    return ("<h2>Process route (knowledge base rule library) and the Job's operations</h2>" +
            table(["step", "operation", "strategy", "tool", "T", "allowance (mm)", "active", "moves",
                    "cut length (mm)", "time", "note"], rows, numeric=(0, 5, 7, 8)) +
            ("<p class='small'>Rules that do not apply: {}</p>".format(esc("; ".join(skipped))) if skipped else ""))


def _tools(run):
    rows = [(esc(t["id"]), esc(t.get("type", "")), num(t.get("diameter"), 2), num(t.get("taperDeg"), 1),
             num(t.get("fluteLength"), 1), num(t.get("shankDiameter"), 1), num(t.get("reach"), 1),
             t.get("flutes", ""), ", ".join(str(s) for s in t.get("steps", [])),
             "<span class='small'>{}</span>".format(esc(t.get("reason", ""))))
            for t in run["tools"]]
    return "<h2>Tools</h2>" + table(["id", "type", "\u00d8 (mm)", "taper (deg)", "flute length", "shank \u00d8",
                                      "reach", "flutes", "steps", "why this tool"], rows, numeric=(2, 3, 4, 5, 6, 7))


def _cutting(run):
    rows = []
    for tool, c in run["cutting"].items():
        rows.append((esc(tool), ", ".join(str(s) for s in c.get("steps", [])), esc(c["operation"]),
                     num(c["rpm"], 0), num(c["fz"], 4), num(c["feed"], 0), num(c["plungeFeed"], 0),
                     num(c["ap"], 2), num(c["ae"], 2), num(c["length"], 0), esc(", ".join(c.get("active", []))),
                     num(c.get("kbFz"), 4), num(c.get("kbVc"), 0)))
    return ("<h2>Cutting data from the cutting-parameter optimiser</h2>"
            "<p class='small'>One ToolController per tool; its speeds serve every step it cuts, so the deepest "
            "a<sub>p</sub> and the widest a<sub>e</sub> of those steps meet the limits. The knowledge base's "
            "f<sub>z</sub> and v<sub>c</sub> are shown for comparison.</p>" +
            table(["tool", "steps", "operation", "n (r/min)", "f_z (mm)", "v_f (mm/min)", "plunge (mm/min)",
                    "a_p (mm)", "a_e (mm)", "cut length (mm)", "active limits", "KB f_z", "KB v_c (m/min)"],
                   rows, numeric=(3, 4, 5, 6, 7, 8, 9, 11, 12)))


def _checks(run):
    c, a = run["check"], run["recheck"]
    parts = c.get("parts") or {}
    five, axial, rapids = parts.get("fiveAxis") or c, parts.get("axial") or {}, parts.get("rapids") or {}
    rows = [("5-axis operations as computed (every channel kind)", five["positions"],
             "{:.5f}".format(five["maxGougeMm"]), five["holderCollisions"], five.get("tilted", 0),
             "{} / {}".format(five.get("links", 0), five.get("linkCollisions", 0)),
             verdict(five["maxGougeMm"] <= LIMIT_GOUGE_MM and five["holderCollisions"] == 0
                      and not five.get("linkCollisions"))),
            ("their rapids against the blank", "&ndash;", "&ndash;", "&ndash;", "&ndash;",
             "{} / {}".format(rapids.get("checked", 0), rapids.get("collisions", 0)),
             verdict(not rapids.get("collisions")))]
    if axial:
        rows.append(("turning, facing, drilling, boring as computed (against every face)", axial["positions"],
                     "{:.5f}".format(axial["maxGougeMm"]), axial["holderCollisions"], "&ndash;", "&ndash;",
                     verdict(axial["maxGougeMm"] <= LIMIT_GOUGE_MM and axial["holderCollisions"] == 0)))
    rows.append(("the Job's program (posted operations), written as APT and read back", a["positions"],
                 "{:.5f}".format(a["maxGougeMm"]), a["holderCollisions"], "&ndash;", "&ndash;",
                 verdict(a["maxGougeMm"] <= LIMIT_GOUGE_MM and a["holderCollisions"] == 0)))
    notes = parts.get("axialNotes") or []
    return ("<h2>Gouge, holder and link checks (OCCT distance queries; gouge limit {} mm)</h2>".format(
                LIMIT_GOUGE_MM) +
            table(["program", "cutting positions", "deepest gouge (mm)", "holder collisions", "tilted",
                    "links checked / touching", ""], rows, numeric=(1, 2, 3, 4)) +
            "<p class='small'>Feed links are checked against the part, rapids against the blank. The read-back "
            "check measures every cutting position of the posted operations against the blades and the hub."
            "{}</p>".format("".join(" " + esc(n) + "." for n in notes)))


def _program(run):
    p = run["program"]
    return ("<h2>Posted program</h2><p>{} ({} lines), AeroNC's 840D post for {}: simultaneous moves under "
            "TRAORI with the tool axis of every move.</p><pre class='small'>{}\n...</pre>".format(
                esc(os.path.basename(p["file"] or "")), p["lines"], esc(run["machine"]), esc("\n".join(p["head"]))))


def _pictures(run):
    return "".join("<h2>{}</h2><img src='{}' alt='{}'>".format(esc(c), esc(os.path.basename(p)), esc(c))
                   for c, p in run["pictures"])


def _display_note():
    return ("<h2>What FreeCAD shows</h2><p class='small'>Each operation's Path holds G0/G1 moves to the tool tip "
            "(X Y Z) with the tool axis as U V W on every move; FreeCAD saves them with the document and AeroNC's "
            "posts read the axis from there. FreeCAD's 3-D view draws the tool tip's path only, not the axis; "
            "FreeCAD's own posts and simulator ignore U V W. Every step has its toolpath; the lathe's turning moves "
            "and what is cut from the back face in a second setup (facing, drilling, boring from the back) are "
            "operations switched off and not posted, with the reason in their Note.</p>")


def render(run):
    return "".join(["<!DOCTYPE html><html><head><meta charset='utf-8'><title>AeroNC impeller run</title>",
                    "<style>{}</style></head><body>".format(STYLE), "<h1>AeroNC impeller run</h1>",
                    _summary(run), _checks(run), _dimensions(run), _features(run), _route(run), _tools(run),
                    _cutting(run), _pictures(run), _program(run), _display_note(), "</body></html>"])


def write(path, run):
    write_atomically(path, render(run))
    return path
