"""Pictures of a setup's toolpaths over the part, drawn headless.

Each setup is drawn in its own frame, looking down its tool axis: the part's edges in grey,
rapids as thin dashed lines, cutting moves coloured by tool. Used by the machining-chain
report, where a programmer wants to see at a glance what each tool cuts.
"""
import os

# Distinct, print-safe colours for up to ten tools; more tools cycle.
TOOL_COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                "#17becf", "#8c564b", "#e377c2", "#bcbd22", "#7f7f7f")


def part_edges_in_frame(shape, frame, samples=2000):
    """Polylines (lists of (u, v)) of the part's face edges in a setup frame {u, v, w}."""
    import Part
    u, v = frame["u"], frame["v"]
    step = max(shape.BoundBox.DiagonalLength / samples, 0.05)
    lines = []
    for edge in Part.Compound(shape.Faces).Edges:
        if edge.Degenerated:
            continue
        try:
            pts = edge.discretize(max(2, int(edge.Length / step)))
        except Exception:  # an edge OCCT cannot sample just goes undrawn
            continue
        lines.append([(p.x * u[0] + p.y * u[1] + p.z * u[2], p.x * v[0] + p.y * v[1] + p.z * v[2]) for p in pts])
    return lines


def draw(setups, path, title="", panel_title="setup {} (looking down the tool axis)"):
    """Write one PNG with a panel per setup; returns path.

    setups: [{"name": "+Z", "edges": [[(u, v), ...], ...],
              "toolpaths": [{"tool": "EM-B16R2", "moves": [[kind, u, v, h], ...]}]}]
    Move kinds: 0 rapid, 1 feed, 2 plunge, 3 drill cycle (drawn as a ring)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D

    n = max(1, len(setups))
    fig, axes = plt.subplots(1, n, figsize=(7.0 * n, 6.4), dpi=110, squeeze=False)
    tools = []
    for s in setups:
        for tp in s["toolpaths"]:
            if tp["tool"] not in tools:
                tools.append(tp["tool"])
    colour_of = {t: TOOL_COLOURS[i % len(TOOL_COLOURS)] for i, t in enumerate(tools)}
    for ax, s in zip(axes[0], setups):
        ax.add_collection(LineCollection(s["edges"], colors="#9a9a9a", linewidths=0.6, zorder=1))
        for tp in s["toolpaths"]:
            cuts, rapids, drills = [], [], []
            prev = None
            for m in tp["moves"]:
                p = (m[1], m[2])
                if m[0] == 3:
                    drills.append(p)
                elif prev is not None:
                    (rapids if m[0] == 0 else cuts).append((prev, p))
                prev = p
            c = colour_of[tp["tool"]]
            if cuts:
                ax.add_collection(LineCollection(cuts, colors=c, linewidths=0.7, zorder=3))
            if rapids:
                ax.add_collection(LineCollection(rapids, colors=c, linewidths=0.4, linestyles="dashed",
                                                 alpha=0.5, zorder=2))
            if drills:
                ax.scatter([d[0] for d in drills], [d[1] for d in drills], s=22, facecolors="none",
                           edgecolors=c, linewidths=1.2, zorder=4)
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_title(panel_title.format(s["name"]))
        ax.set_xlabel("u (mm)")
        ax.set_ylabel("v (mm)")
    handles = [Line2D([0], [0], color=colour_of[t], lw=2, label=t) for t in tools]
    handles.append(Line2D([0], [0], color="#555555", lw=1, ls="dashed", label="rapid"))
    fig.legend(handles=handles, loc="lower center", ncol=min(len(handles), 7), frameon=False)
    if title:
        fig.suptitle(title)
    fig.tight_layout(rect=(0, 0.11, 1, 0.95))
    tmp = path + ".part.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, path)
    return path


def draw_leftover(leftover, path, tolerance=0.2, title=""):
    """Write a PNG of the material left above the part after simulation; returns path.

    leftover: {"nx", "ny", "x0", "y0", "cell", "top": [...]} with "top" row-major (ny rows of nx),
    the stock left above the part's upper surface in mm (None or NaN where there is no part)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    nx, ny, cell = int(leftover["nx"]), int(leftover["ny"]), float(leftover["cell"])
    top = np.array([np.nan if t is None else t for t in leftover["top"]], dtype=float).reshape(ny, nx)
    extent = (leftover["x0"], leftover["x0"] + nx * cell, leftover["y0"], leftover["y0"] + ny * cell)
    fig, ax = plt.subplots(figsize=(8, 6.4), dpi=110)
    shown = np.ma.masked_invalid(top)
    # Capped at 25 tolerances: a few mm left on a floor must stand out beside 100 mm of unmachined
    # depth, which reads as "more" anyway.
    highest = float(np.nanmax(top)) if np.isfinite(top).any() else 1.0
    cap = max(tolerance * 5, min(highest, tolerance * 25))
    im = ax.imshow(shown, origin="lower", extent=extent, cmap="magma_r", vmin=0.0, vmax=cap)
    ax.contour(np.where(top > tolerance, 1.0, 0.0), levels=[0.5], origin="lower", extent=extent,
               colors="#00a0ff", linewidths=0.6)
    fig.colorbar(im, ax=ax, label="material left above the part (mm)", extend="max" if highest > cap else "neither")
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title(title or "Material left after simulation (blue: more than {} mm)".format(tolerance))
    fig.tight_layout()
    tmp = path + ".part.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, path)
    return path
