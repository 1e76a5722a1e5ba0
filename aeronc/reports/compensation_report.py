"""The compensation report of a compensated drilling operation: one HTML page with

  - the part, the datum and measured sets, the machine, the method used and the one proposed;
  - what is flagged, and why: datum readings left out (out of line with the others, or by
    hand) or put back, holes whose correction departs from their neighbours', holes whose
    correction is longer than the tolerance;
  - every method's leave-one-out error over the datum holes used (each predicted from the others);
  - the datum holes: used or left out, nominal, measured, deviation dP, how far the others
    predict it (miss), what the fit leaves, quality;
  - every hole drilled: nominal position, correction, method, its flags, and a note where the
    seed's method extrapolates;
  - a picture of the deviations (datum holes) and corrections (drilled holes) as arrows, the
    datum holes left out crossed out and named.

The picture is drawn with matplotlib's Agg canvas (headless) and embedded in the page.
"""
import base64
import html
import io
import json
import math

from aeronc.post.output import write_atomically


def report_data(op):
    """Everything the report shows, from the operation and its sets (a dict)."""
    from aeronc.objects import measured_hole_set
    from aeronc.operations import compensated_drilling
    ms, ps = op.MeasuredHoleSet, op.PhotoHoleSet
    result = json.loads(op.Report) if op.Report else {}
    survey = measured_hole_set.result_of(ms) if ms is not None else {}
    by_id = {d["id"]: d for d in result.get("datums", [])}
    datums = []
    if ms is not None:
        for i, hid in enumerate(ms.HoleIds):
            n, m, d = ms.Nominal[i], ms.Measured[i], ms.Deviations[i]
            v = by_id.get(hid, {})
            datums.append({"id": hid, "nominal": (n.x, n.y, n.z), "measured": (m.x, m.y, m.z), "deviation": (d.x, d.y, d.z),
                           "residual": tuple(v.get("residual", (math.nan,) * 3)),
                           "quality": ms.Quality[i] if i < len(ms.Quality) else -1.0,
                           "use": v.get("use", ""), "used": v.get("used", True), "miss": v.get("miss"),
                           "reason": v.get("reason", "")})
    reasons = {}
    for f in result.get("flags", []):
        reasons.setdefault(f["id"], []).append(f)
    holes = []
    nominal = compensated_drilling.nominal_holes(op)
    for h, c in zip(nominal, result.get("holes", [])):
        holes.append({"id": h["id"], "faces": h["faces"], "nominal": tuple(c["nominal"]), "correction": tuple(c["correction"]),
                      "compensated": tuple(c["compensated"]), "beyond": c["exceeds_tolerance"],
                      "against": c["against_neighbours"], "departure": c["neighbour_departure"],
                      "flags": [f["kind"] for f in reasons.get(c["id"], [])], "note": c["note"]})
    check = result.get("check", {})
    return {
        "operation": op.Label, "part": op.Source.Label if op.Source else "", "status": op.Status,
        "photo_set": ps.Label if ps else "", "measured_set": ms.Label if ms else "",
        "file": ms.SourceFile if ms else "", "machine": ms.Machine if ms else "",
        "method": result.get("method", ""), "chosen": ms.Method if ms else "", "proposed": result.get("proposed") or "",
        "tolerance": ms.Tolerance.Value if ms else 0.0, "fit": result.get("fit"),
        "neighbour_tolerance": ms.NeighbourTolerance.Value if ms else 0.0, "check": check,
        "leave_one_out": survey.get("leave_one_out") or result.get("leave_one_out", []),
        "datums": datums, "holes": holes, "flags": result.get("flags", []),
        "flagged": result.get("flagged_holes", 0),
    }


def picture(data, title=None, size=(9.0, 6.0)):
    """PNG bytes: the holes in plan (part frame X, Y), datum-hole deviations dP (purple, as in
    the 3-D view) and
    drilled-hole corrections (blue) as arrows, scaled up by one factor given in the legend; each
    drilled hole coloured by its correction along Z."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    fig = Figure(figsize=size, dpi=110)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    pts = [d["nominal"] for d in data["datums"]] + [h["nominal"] for h in data["holes"]]
    if not pts:
        ax.text(0.5, 0.5, "no measurements", ha="center", va="center", transform=ax.transAxes)
    else:
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        extent = max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
        longest = max([math.hypot(*d["deviation"][:2]) for d in data["datums"]] +
                      [math.hypot(*h["correction"][:2]) for h in data["holes"]] + [1e-9])
        scale = _round_scale(0.08 * extent / longest)
        hx = [h["nominal"][0] for h in data["holes"]]
        hy = [h["nominal"][1] for h in data["holes"]]
        # In-plane arrows cannot show the correction along Z (the skin's normal, mostly): colour.
        dz = [h["correction"][2] for h in data["holes"]] + [d["deviation"][2] for d in data["datums"]]
        zlim = max([abs(v) for v in dz] + [1e-6])
        dots = ax.scatter(hx, hy, s=16, c=[h["correction"][2] for h in data["holes"]], cmap="coolwarm",
                          vmin=-zlim, vmax=zlim, zorder=2, label="hole drilled (nominal)")
        fig.colorbar(dots, ax=ax, shrink=0.7, pad=0.02).set_label("correction along Z (mm)", fontsize=8)
        if data["holes"]:
            ax.quiver(hx, hy, [h["correction"][0] * scale for h in data["holes"]],
                      [h["correction"][1] * scale for h in data["holes"]], angles="xy", scale_units="xy", scale=1,
                      color="#1f5fbf", width=0.0025, zorder=3, label="correction (x {:g})".format(scale))
        beyond = [h for h in data["holes"] if h["beyond"]]
        if beyond:
            ax.scatter([h["nominal"][0] for h in beyond], [h["nominal"][1] for h in beyond], s=60,
                       facecolors="none", edgecolors="#e08000", linewidths=1.2, zorder=4,
                       label="correction > {:g} mm".format(data["tolerance"]))
        against = [h for h in data["holes"] if h["against"]]
        if against:
            ax.scatter([h["nominal"][0] for h in against], [h["nominal"][1] for h in against], s=110,
                       facecolors="none", edgecolors="#d00000", linewidths=1.6, zorder=4,
                       label="correction against its neighbours' (> {:g} mm)".format(data["neighbour_tolerance"]))
        dx = [d["nominal"][0] for d in data["datums"]]
        dy = [d["nominal"][1] for d in data["datums"]]
        ax.scatter(dx, dy, s=46, marker="s", facecolors="none", edgecolors="#00733a", linewidths=1.4, zorder=4,
                   label="datum hole")
        ax.quiver(dx, dy, [d["deviation"][0] * scale for d in data["datums"]],
                  [d["deviation"][1] * scale for d in data["datums"]], angles="xy", scale_units="xy", scale=1,
                  color="#8c00bf", width=0.004, zorder=5, label="measured deviation dP (x {:g})".format(scale))
        for d in data["datums"]:
            ax.annotate(d["id"] if d["used"] else "{} {}".format(d["id"], d["use"]), (d["nominal"][0], d["nominal"][1]),
                        textcoords="offset points", xytext=(4, -11), fontsize=7 if d["used"] else 8,
                        color="#00733a" if d["used"] else "#d00000", fontweight="normal" if d["used"] else "bold")
        out = [d for d in data["datums"] if not d["used"]]
        if out:
            ax.scatter([d["nominal"][0] for d in out], [d["nominal"][1] for d in out], s=120, marker="x",
                       color="#d00000", linewidths=2.0, zorder=6, label="datum hole left out")
        ax.set_aspect("equal", adjustable="datalim")
        ax.margins(0.08)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=2, fontsize=8, frameon=False)
    ax.set_xlabel("X (mm, part frame)")
    ax.set_ylabel("Y (mm)")
    ax.set_title(title or "{}: {}".format(data["operation"], data["method"] or "not compensated"), fontsize=10)
    ax.grid(True, color="#dddddd", linewidth=0.5)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    return buf.getvalue()


def _round_scale(x):
    """A readable arrow scale (1, 2 or 5 times a power of ten) no larger than x."""
    if x <= 0 or not math.isfinite(x):
        return 1.0
    p = 10 ** math.floor(math.log10(x))
    return max(m * p for m in (1, 2, 5) if m * p <= x)


def _v(v, digits=3):
    return ", ".join("{:.{}f}".format(c, digits) for c in v)


def _table(headers, rows, flag_column=None, flag_class="flag", flagged=bool):
    out = ["<table><tr>" + "".join("<th>{}</th>".format(html.escape(h)) for h in headers) + "</tr>"]
    for r in rows:
        cls = ' class="{}"'.format(flag_class) if flag_column is not None and flagged(r[flag_column]) else ""
        out.append("<tr{}>".format(cls) + "".join("<td>{}</td>".format(html.escape(str(c))) for c in r) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def html_page(data, png):
    e = html.escape
    loo = []
    for f in data["leave_one_out"]:
        mark = []
        if f["method"] == data["proposed"]:
            mark.append("proposed")
        if f["method"] == data["method"]:
            mark.append("used")
        loo.append((f["method"], "{:.4f}".format(f["rms"]) if f["available"] else "-",
                    "{:.4f}".format(f["max"]) if f["available"] else "-",
                    ", ".join(mark) if f["available"] else "not available: " + f["reason"]))
    datums = [(d["id"], d["use"], _v(d["nominal"]), _v(d["measured"]), _v(d["deviation"]),
               "{:.4f}".format(math.sqrt(sum(c * c for c in d["deviation"]))),
               "-" if d["miss"] is None else "{:.4f}".format(d["miss"]), _v(d["residual"], 4),
               "" if d["quality"] < 0 else "{:.3f}".format(d["quality"]), d["reason"]) for d in data["datums"]]
    holes = [(h["id"], " ".join(h["faces"]), _v(h["nominal"]), _v(h["correction"], 4),
              "{:.4f}".format(math.sqrt(sum(c * c for c in h["correction"]))), "{:.4f}".format(h["departure"]),
              _v(h["compensated"]), data["method"], "; ".join(h["flags"]), h["note"]) for h in data["holes"]]
    flags = [(f["id"], f["kind"], f["reason"]) for f in data["flags"]]
    check = data.get("check") or {}
    # Each reading is judged against the typical miss of the others, taken without it (its own
    # limit is in its "why"); the figures here are those of the datum holes finally in use.
    check_text = ("The datum holes in use miss their predictions across their normals by {:.4f} mm typically; "
                  "a reading is out of line when it misses by more than {:g} times the others' typical miss "
                  "and by more than {:g} mm (here about {:.3f} mm).".format(
                      check["typical_miss"], check["factor"], check["minimum"], check["threshold"])
                  if check.get("checked") else
        "Datum readings not checked: {}.".format(check.get("note", "no measurements")))
    fit = data.get("fit") or {}
    fit_text = ""
    if fit and data["method"] != "seed":
        fit_text = "<p>Best fit: scale {:.6f}, translation ({}) mm.</p>".format(fit["scale"], _v(fit["translation"], 4))
    return """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>Compensation report: {op}</title>
<style>
body {{ font-family: sans-serif; margin: 1.5em; color: #222; }}
table {{ border-collapse: collapse; margin: 0.6em 0 1.4em 0; font-size: 0.85em; }}
th, td {{ border: 1px solid #bbb; padding: 2px 6px; text-align: left; }}
th {{ background: #eee; }}
tr.flag td {{ background: #fff0d8; }}
tr.out td {{ background: #ffd8d8; }}
</style></head><body>
<h1>Compensation report: {op}</h1>
<p>Part <b>{part}</b>; datum holes <b>{ps}</b>; measurements <b>{ms}</b> ({file}), mapped through the
calibration of machine <b>{machine}</b>.</p>
<p>Method used: <b>{method}</b> (chosen: {chosen}; proposed, lowest leave-one-out error: <b>{proposed}</b>).
<b>{flagged}</b> of {n} holes drilled are flagged. {status}</p>
{fit}
<h2>Flagged: what to look at before drilling</h2>
<p>A datum reading is <i>left out</i> when the other datum holes predict its deviation worse than
the check allows (by the method that predicts it best); it is <i>put back</i> when the user uses
it all the same. A hole drilled is flagged <i>against neighbours</i> when its correction departs
from the linear trend of its neighbours' corrections by more than {ntol:g} mm, and <i>beyond
tolerance</i> when its correction is longer than the tolerance, {tol:g} mm. {check}</p>
{flags}
<h2>Deviations and corrections</h2>
<img src="data:image/png;base64,{png}" alt="deviations as arrows">
<h2>Leave-one-out error over the datum holes used (mm)</h2>
<p>Each datum hole predicted from the others; no single method wins every distortion.</p>
{loo}
<h2>Datum holes (part frame, mm)</h2>
{datums}
<h2>Holes drilled (part frame, mm)</h2>
{holes}
</body></html>
""".format(op=e(data["operation"]), part=e(data["part"]), ps=e(data["photo_set"]), ms=e(data["measured_set"]),
           file=e(data["file"] or "no file"), machine=e(data["machine"]), method=e(data["method"] or "none"),
           chosen=e(data["chosen"]), proposed=e(data["proposed"] or "-"), tol=data["tolerance"],
           flagged=data["flagged"], n=len(data["holes"]), status=e(data["status"]), fit=fit_text,
           ntol=data["neighbour_tolerance"], check=e(check_text),
           flags=_table(["hole", "flag", "why"], flags) if flags else "<p>Nothing flagged.</p>",
           png=base64.b64encode(png).decode("ascii"),
           loo=_table(["method", "RMS", "max", ""], loo),
           datums=_table(["datum hole", "use", "nominal", "measured", "dP", "|dP|", "miss", "left by the fit",
                          "quality", "why"], datums, flag_column=1, flag_class="out",
                         flagged=lambda use: use not in ("used", "")),
           holes=_table(["hole", "faces", "nominal", "correction", "|correction|", "from neighbours'", "compensated",
                         "method", "flags", "note"], holes, flag_column=8))


def write_report(op, html_path, png_path=None):
    """Write the report page (and the picture alone when png_path is given); returns html_path."""
    data = report_data(op)
    png = picture(data)
    if png_path:
        write_atomically(png_path, png)
    write_atomically(html_path, html_page(data, png))
    return html_path
