"""The machining-chain report: one HTML page a CAM programmer reads before cutting.

It holds, per setup, the process -> step -> tool -> unit tables with estimated times, the rule
checks and the verification of the posted programs (gouge, coverage, collisions), the travel
saved by sequencing, the elements left unmachined and why, and the pictures. The page is
self-contained apart from its pictures, which sit beside it and are linked by file name.
"""
import os

from aeronc.post.output import write_atomically
from aeronc.reports.html import STYLE, esc, num, verdict

STEP_NAMES = {
    "r": "rough inner and outer shape", "w": "finish webs (floors)", "c": "corners",
    "ss": "semi-finish walls", "sf": "semi-finish flanges", "fs": "finish walls", "ff": "finish flanges",
    "t": "cut off", "d": "drill holes", "h": "mill holes (helical)",
}

def _minutes(m):
    if m is None:
        return "&ndash;"
    return "{:d} min {:02d} s".format(int(m), int(round((m - int(m)) * 60))) if m >= 1 else "{:.0f} s".format(m * 60)


def _machine(run):
    """The machine the programs are for, and why (pipeline.machine_choice)."""
    m = run.get("machine") or {}
    if not m.get("name"):
        return "&ndash;"
    return "<b>{}</b>: {}".format(esc(m["name"]), esc(m.get("why", "")))


def _summary(run):
    chain = run.get("chain", {})
    units = chain.get("units", [])
    ops = run.get("operations", [])
    rows = [("Part", esc(run.get("part", ""))), ("Source", esc(run.get("source", ""))),
            ("Material / machine", "{} on {}".format(esc(chain.get("material", "")), esc(chain.get("machine", "")))),
            ("Process template", esc(chain.get("family", ""))),
            ("Machine chosen", _machine(run)),
            ("Recognised elements", esc(len(run.get("recognition", {}).get("elements", [])))),
            ("Machining units", "{} ({} enabled)".format(len(units), sum(1 for u in units if u.get("enabled", True)))),
            ("Elements not machined", esc(unmachined_text(chain)))]
    total = sum(o.get("minutes") or 0 for o in ops)
    if ops:
        rows.append(("Estimated machining time", _minutes(total) + ' <span class="muted small">(cutting at the '
                     'programmed feeds, rapids at the machine\'s feed limit, tool changes)</span>'))
    travel = chain.get("travel")
    if travel:
        rows.append(("Rapid travel", "{} mm in rule order &rarr; {} mm sequenced ({}% saved)".format(
            num(travel.get("rulesOnly"), 0), num(travel.get("optimised"), 0), num(travel.get("savedPercent"), 1))))
    for p in run.get("programs", []):
        zero = p.get("partZero")
        where = (" &middot; program zero at ({}) from the table's reference point: the blank centred on the "
                 "table".format(", ".join(num(v, 3) for v in zero)) if zero else "")
        left = (' <span class="fail">{} operation(s) left out</span>'.format(len(p["leftOut"]))
                if p.get("leftOut") else "")
        rows.append(("Program " + esc(p.get("setup", "")), '<a href="{0}">{0}</a>{4} <span class="muted small">'
                     '{1} &middot; {2} lines{3}</span>'.format(esc(os.path.basename(p["path"])), esc(p.get("dialect", "")),
                                                             esc(p.get("lines", "")), where, left)))
    for p in run.get("noProgram", []):
        rows.append(("Program " + esc(p.get("setup", "")),
                     '<span class="fail">none: every operation of the setup is left out</span>'))
    for r in run.get("regrown", []):
        rows.append(("Re-made by the gate", "{}: {}".format(esc(r.get("label", "")), esc(r.get("note", "")))))
    body = "".join("<tr><td>{}</td><td>{}</td></tr>".format(k, v) for k, v in rows)
    return '<table class="summary">{}</table>'.format(body)


def _checks(run):
    out = ["<h2>Checks</h2>", "<table><tr><th>check</th><th>node</th><th>result</th><th>detail</th></tr>"]
    for c in run.get("chain", {}).get("checks", []):
        out.append("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>".format(
            esc(c.get("rule", "")), esc(c.get("node", "")), verdict(c.get("ok", False)), esc(c.get("message", ""))))
    for v in run.get("verification", []):
        out.append("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>".format(
            esc(v["check"]), esc(v.get("node", "")), verdict(v["ok"]), esc(v.get("detail", ""))))
    out.append("</table>")
    return "".join(out)


def _setup_tables(run):
    chain = run.get("chain", {})
    units = {u["id"]: u for u in chain.get("units", [])}
    op_of = {o["unit"]: o for o in run.get("operations", []) if "unit" in o}
    out = []
    for s in chain.get("setups", []):
        out.append("<h2>Setup {} <span class='muted small'>tool axis {}</span></h2>".format(
            esc(s.get("name", "")), esc(s.get("direction", ""))))
        out.append("<table><tr><th>#</th><th>step</th><th>tool</th><th>unit</th><th>element</th><th>operation</th>"
                   "<th>top</th><th>bottom</th><th>radial / axial allowance</th><th>n (r/min)</th>"
                   "<th>feed (mm/min)</th><th>cut (mm)</th><th>time</th></tr>")
        for p in s.get("processes", []):
            minutes = sum((op_of.get(uid, {}).get("minutes") or 0)
                          for st in p.get("steps", []) for pr in st.get("programs", []) for uid in pr.get("units", []))
            out.append("<tr class='process'><td colspan='13'>process {} &middot; {} &middot; tool {} &middot; {}"
                       "</td></tr>".format(esc(p.get("id", "")), esc(p.get("machine", "")), esc(p.get("tool", "")),
                                           _minutes(minutes)))
            for st in p.get("steps", []):
                for pr in st.get("programs", []):
                    for uid in pr.get("units", []):
                        u = units.get(uid, {})
                        o = op_of.get(uid, {})
                        setting = u.get("setting", {})
                        muted = "" if u.get("enabled", True) else " class='muted'"
                        out.append(
                            "<tr{}><td class='n'>{}</td><td>{} <span class='muted small'>{}</span></td><td>{}</td>"
                            "<td class='n'>{}</td><td class='n'>{}</td><td>{}</td><td class='n'>{}</td>"
                            "<td class='n'>{}</td><td class='n'>{} / {}</td><td class='n'>{}</td><td class='n'>{}</td>"
                            "<td class='n'>{}</td><td class='n'>{}</td></tr>".format(
                                muted, esc(u.get("order", "")), esc(st.get("code", "")),
                                esc(STEP_NAMES.get(st.get("code", ""), "")), esc(pr.get("tool", u.get("tool", ""))),
                                esc(uid), esc(u.get("element", "")),
                                esc(u.get("operation", "")) + ("" if u.get("enabled", True) else " (disabled)"),
                                num(u.get("top"), 2), num(u.get("bottom"), 2), num(u.get("radialAllowance"), 2),
                                num(u.get("axialAllowance"), 2), num(setting.get("spindleRpm"), 0),
                                num(setting.get("feedMmMin"), 0), num(o.get("cutLength"), 0),
                                _minutes(o.get("minutes"))))
        out.append("</table>")
    return "".join(out)


def unmachined_text(chain):
    """'n' elements not machined, and how many more keep only some faces (an entry naming its
    faces: a chamfer, a bevel, an island top): one count per element, not per entry."""
    whole, partly = set(), set()
    for entry in chain.get("unmachined", []):
        (partly if entry.get("faces") else whole).add(entry.get("element"))
    partly -= whole
    return "{}{}".format(len(whole), ", {} more with faces left".format(len(partly)) if partly else "")


def _unmachined(run):
    items = run.get("chain", {}).get("unmachined", [])
    if not items:
        return "<h2>Elements not machined</h2><p class='ok'>Every recognised element is machined by some unit.</p>"
    rows = "".join("<tr><td class='n'>{}</td><td>{}</td><td>{}</td></tr>".format(
        esc(i.get("element")), esc(", ".join(str(f) for f in i.get("faces") or []) or "all"), esc(i.get("reason")))
        for i in items)
    return ("<h2>Elements not machined</h2><table><tr><th>element</th><th>faces left</th><th>why</th></tr>{}</table>"
            .format(rows))


def _remainders(run):
    """What elements keep where no tool of the crib reaches (sharp corners, a floor fillet
    smaller than every reaching tool's corner, the depth under a region roughed as far as the
    longest end mill reaches): listed with the area. Only the last also leaves its element
    among those not machined."""
    from aeronc.pipeline.verification import remainder_text
    items = run.get("chain", {}).get("remainders", [])
    if not items:
        return ""
    rows = "".join("<tr><td class='n'>{}</td><td>{}</td></tr>".format(esc(i.get("element")), esc(remainder_text(i)))
                   for i in items)
    return ("<h2>Left where no tool reaches</h2><table><tr><th>element</th><th>what is left</th></tr>{}</table>"
            .format(rows))


def _banner(run):
    """The report's first line: whether the programs are ready, in words nobody misses."""
    v = run.get("verdict")
    if not v:
        return ""
    return "<p class='banner {}'>{}</p>".format("ready" if v.get("ready") else "notready", esc(v.get("text", "")))


def _left_out(run):
    items = run.get("leftOut") or []
    if not items:
        return ""
    rows = "".join("<tr><td>{}</td><td>{}</td><td>{}</td></tr>".format(
        esc(i.get("label")), esc(i.get("setup", "")), esc(i.get("reason"))) for i in items)
    return ("<h2>Operations left out of the programs</h2><p class='small'>Each is marked Failed or No toolpath "
            "on the operation (Check, Note); the programs name them in a comment at their start.</p>"
            "<table><tr><th>operation</th><th>Job</th><th>why</th></tr>{}</table>".format(rows))


def _material_left(run):
    items = run.get("materialLeft")
    if items is None:
        return ""
    if not items:
        return ("<h3>Material left against the part</h3><p class='ok'>Every face of the part inside the blank "
                "is within tolerance after the delivered programs.</p>")
    rows = "".join("<tr><td>{}</td><td>{}</td><td class='n'>{}</td><td class='n'>{}</td><td>{}</td></tr>".format(
        "E{}".format(i["element"]) if i.get("element") is not None else "unclaimed",
        esc(", ".join(str(f) for f in i.get("faces", [])[:12]) + (" ..." if len(i.get("faces", [])) > 12 else "")),
        num(i.get("area"), 0) if i.get("area") is not None else "not measured", num(i.get("maxLeft"), 2),
        esc(i.get("reason", ""))) for i in items)
    return ("<h3>Material left against the part (every face inside the blank, after the delivered programs)</h3>"
            "<table><tr><th>element</th><th>faces</th><th>area left &gt; tolerance (mm&sup2;)</th>"
            "<th>max left (mm)</th><th>why</th></tr>{}</table>".format(rows))


def _failure(run):
    f = run.get("failed")
    if not f:
        return ""
    return "<h2>Run failed</h2><p class='fail'>{}</p>".format(esc(f.get("error", "")))


def _coverage(run):
    rows = run.get("coverage", [])
    if not rows:
        return ""
    out = ["<h3>Material left per element (simulated against the blank)</h3>",
           "<table><tr><th>element</th><th>finished face area (mm&sup2;)</th>"
           "<th>area left &gt; tolerance (mm&sup2;)</th><th>max left (mm)</th></tr>"]
    for r in rows:
        out.append("<tr><td class='n'>{}</td><td class='n'>{}</td><td class='n'>{}</td>"
                   "<td class='n'>{}</td></tr>".format(esc(r.get("element")),
                                                      num(r.get("area"), 0), num(r.get("leftArea"), 0),
                                                      num(r.get("maxLeft"), 2)))
    out.append("</table>")
    return "".join(out)


def _pictures(run):
    out = []
    for caption, name in run.get("pictures", []):
        out.append("<h3>{}</h3><img src='{}' alt='{}'>".format(esc(caption), esc(os.path.basename(name)), esc(caption)))
    return "".join(out)


def _stages(run):
    stages = run.get("stages", [])
    if not stages:
        return ""
    rows = "".join("<tr><td>{}</td><td class='n'>{:.2f} s</td></tr>".format(esc(n), t) for n, t in stages)
    total = sum(t for _, t in stages)
    return ("<h2>Run</h2><table><tr><th>stage</th><th>time</th></tr>{}<tr><td><b>total</b></td>"
            "<td class='n'><b>{:.2f} s</b></td></tr></table>".format(rows, total))


def render(run):
    """The report's HTML text for one run of the machining chain (see write)."""
    title = "AeroNC machining chain: {}".format(run.get("part", ""))
    if run.get("verdict"):
        title = "{} — {}".format(run["verdict"].get("status", ""), title)
    parts = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>{}</title><style>{}</style>"
             "</head><body>".format(esc(title), STYLE),
             _banner(run), "<h1>{}</h1>".format(esc(title)), _failure(run), _summary(run), _checks(run),
             _left_out(run), _material_left(run), _coverage(run), _pictures(run),
             _setup_tables(run), _unmachined(run), _remainders(run), _stages(run), "</body></html>"]
    return "\n".join(parts)


def write(path, run):
    """Write the report of `run` to `path` (temporary name, then renamed); returns path.

    run: {"part", "source", "recognition": result, "chain": chain dict, "operations": [{"unit", "setup",
    "cutLength", "minutes"}], "programs": [{"setup", "dialect", "path", "lines", "partZero", "leftOut"}],
    "noProgram": [{"setup"}], "regrown": [{"label", "note"}] (roughings the gate re-made with grown
    allowances), "machine": {"name", "why"}, "verdict": {"ready", "status", "text"} (the first
    line), "failed": {"stage",
    "error"}, "leftOut": [{"label", "setup", "reason"}], "materialLeft": [{"element", "faces", "area",
    "maxLeft", "reason"}], "verification":
    [{"check", "node", "ok", "detail"}], "coverage": [{"setup", "element", "area", "leftArea", "maxLeft"}],
    "pictures": [(caption, file)], "stages": [(name, seconds)]}"""
    write_atomically(path, render(run))
    return path
