"""The picture of one cutting-parameter optimisation: the combined objective over (n, f_z) on
log axes, the infeasible part greyed out, every limit's boundary (active ones bold), and the
optimum, the genetic algorithm's point, the knowledge base's baseline and the current setting.

Drawn with matplotlib's Agg canvas (no pyplot, no GUI toolkit), so it works headless and in
the task panel alike; the result is PNG bytes.
"""
import io
import math

# The f_z search range is a box, not a physical limit: not drawn.
_SEARCH_RANGE = "search range"


def _boundary(limit, ns):
    """(n, f_z) points of value == limit for a monomial limit, or None when it is a vertical line."""
    c, a, b, lim = limit["coefficient"], limit["n_exp"], limit["fz_exp"], limit["limit"]
    if abs(b) < 1e-12:
        return None
    return [(n, (lim / (c * n ** a)) ** (1.0 / b)) for n in ns]


def _plain_log_ticks(axis, low, high):
    """Log-axis labels as plain numbers (200, 0.15): at 1, 2 and 5 of each decade, or at every
    digit when the axis spans less than a decade."""
    from matplotlib import ticker
    shown = (1.0, 2.0, 5.0) if high / low >= 10 else (1.0, 2.0, 3.0, 5.0, 7.0)

    def label(v, _pos):
        mantissa = v / 10 ** math.floor(math.log10(v) + 1e-9) if v > 0 else 0
        return "{:g}".format(float("{:.3g}".format(v))) if round(mantissa, 6) in shown else ""

    axis.set_major_formatter(ticker.FuncFormatter(label))
    axis.set_minor_formatter(ticker.FuncFormatter(label))


def render(result, title="", width_in=6.0, height_in=4.6, dpi=90):
    """PNG bytes of the map in result (the core's answer, made with map_points > 0)."""
    from matplotlib.figure import Figure
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib import colors
    import numpy as np

    m = result["map"]
    ns, fzs = np.array(m["n_rpm"]), np.array(m["f_z_mm"])
    f = np.array(m["objective"], dtype=float)
    ok = np.array(m["feasible"], dtype=bool)
    fig = Figure(figsize=(width_in, height_in), dpi=dpi)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(111)
    ax.set_xscale("log")
    ax.set_yscale("log")

    best = m["optimum"]["objective"]
    shown = np.where(ok, f, np.nan)
    finite = shown[np.isfinite(shown)]
    top = float(np.percentile(finite, 95)) if finite.size else best * 2
    levels = np.geomspace(best, max(top, best * 1.001), 12)
    cs = ax.contourf(ns, fzs, np.clip(shown, best, levels[-1]), levels=levels, cmap="viridis_r",
                     norm=colors.LogNorm(vmin=best, vmax=levels[-1]), extend="neither")
    fig.colorbar(cs, ax=ax, label="f = w1 t/t_min + w2 C/C_min", format="%.3f")
    ax.contourf(ns, fzs, (~ok).astype(float), levels=[0.5, 1.5], colors=["#8c8c8c"], alpha=0.55)
    ax.contourf(ns, fzs, (~ok).astype(float), levels=[0.5, 1.5], colors="none", hatches=["//"])

    opt = result.get("deterministic", result.get("genetic"))["optimum"]
    active = set(opt["active"])
    for limit in m["limits"]:
        if _SEARCH_RANGE in limit["name"]:
            continue
        name = "{} {}".format(limit["name"], limit["symbol"])
        bold = name in active
        style = dict(color="#c0392b" if bold else "#34495e", lw=2.2 if bold else 1.0, ls="-" if bold else "--")
        pts = _boundary(limit, ns)
        if pts is None:
            n0 = (limit["limit"] / limit["coefficient"]) ** (1.0 / limit["n_exp"])
            if ns[0] <= n0 <= ns[-1]:
                ax.axvline(n0, **style)
                ax.annotate(limit["symbol"], (n0, fzs[-1]), fontsize=7, color=style["color"], ha="right",
                            va="top", rotation=90)
            continue
        xs = [p[0] for p in pts if fzs[0] <= p[1] <= fzs[-1]]
        ys = [p[1] for p in pts if fzs[0] <= p[1] <= fzs[-1]]
        if xs:
            ax.plot(xs, ys, **style)
            ax.annotate(limit["symbol"], (xs[-1], ys[-1]), fontsize=7, color=style["color"], ha="right",
                        va="bottom")
    for step in m.get("spindle_steps_rpm", []):
        if ns[0] <= step <= ns[-1]:
            ax.axvline(step, color="#7f8c8d", lw=0.6, ls=":")

    def mark(point, marker, colour, label, size=90):
        n, fz = point["n_rpm"], point["f_z_mm"]
        if ns[0] <= n <= ns[-1] and fzs[0] <= fz <= fzs[-1]:
            ax.scatter([n], [fz], marker=marker, s=size, c=colour, edgecolors="black", zorder=5, label=label)

    for ref in result.get("references", []):
        mark(ref, "X", "#f39c12", ref.get("label", "reference"), 70)
    if "baseline" in result:
        mark(result["baseline"], "s", "#ecf0f1", "knowledge base", 50)
    if "genetic" in result and "deterministic" in result:
        mark(result["genetic"]["optimum"], "D", "#9b59b6", "genetic algorithm", 50)
    mark(opt, "*", "#e74c3c", "optimum n {:.0f}, f_z {:.4f}".format(opt["n_rpm"], opt["f_z_mm"]), 220)

    ax.set_xlabel("spindle speed n (r/min)")
    ax.set_ylabel("feed per tooth f_z (mm)")
    ax.set_title(title + ("\n" if title else "") + "active: " + (", ".join(sorted(active)) or "none"), fontsize=9)
    ax.legend(loc="lower left", fontsize=7, framealpha=0.85)
    ax.set_xlim(ns[0], ns[-1])
    ax.set_ylim(fzs[0], fzs[-1])
    _plain_log_ticks(ax.xaxis, ns[0], ns[-1])
    _plain_log_ticks(ax.yaxis, fzs[0], fzs[-1])
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    return buf.getvalue()


def save(result, path, title=""):
    """Write the picture to path (through a temporary file, then renamed); returns path."""
    from aeronc.post.output import write_atomically
    write_atomically(path, render(result, title))
    return path
