"""Pictures of a part coloured by face role, drawn headless (matplotlib, Agg).

Used by the main job and for reviewing recognition on real parts without a GUI. Each face is
tessellated by FreeCAD and drawn with the colour of its role; one panel per view direction.
"""
import os

from aeronc.feature_colours import ROLE_COLOURS, UNKNOWN_ROLE

VIEWS = (("from +Z", 60, -60), ("from -Z", -60, -60))


def render(shape, result, path, title="", views=VIEWS, deflection=None):
    """Write a PNG of `shape` coloured by `result["faceRoles"]`; returns path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    box = shape.BoundBox
    tol = deflection or max(box.DiagonalLength * 2e-3, 0.01)
    tris, colours = [], []
    roles = result["faceRoles"]
    for i, face in enumerate(shape.Faces):
        pts, idx = face.tessellate(tol)
        colour = ROLE_COLOURS.get(roles[i] if i < len(roles) else "unclaimed", UNKNOWN_ROLE)
        for a, b, c in idx:
            tris.append([tuple(pts[a]), tuple(pts[b]), tuple(pts[c])])
            colours.append(colour)
    fig = plt.figure(figsize=(6.5 * len(views), 6.5), dpi=110)
    for k, (label, elev, azim) in enumerate(views):
        ax = fig.add_subplot(1, len(views), k + 1, projection="3d")
        ax.add_collection3d(Poly3DCollection(tris, facecolors=colours, edgecolors=(0, 0, 0, 0.08),
                                             linewidths=0.2))
        span = max(box.XLength, box.YLength, box.ZLength) / 2
        cx, cy, cz = box.Center.x, box.Center.y, box.Center.z
        ax.set_xlim(cx - span, cx + span)
        ax.set_ylim(cy - span, cy + span)
        ax.set_zlim(cz - span, cz + span)
        ax.view_init(elev=elev, azim=azim)
        ax.set_axis_off()
        ax.set_title(label)
    used = sorted(set(roles))
    fig.legend(handles=[Patch(color=ROLE_COLOURS.get(r, UNKNOWN_ROLE), label=r.replace("_", " ")) for r in used],
               loc="lower center", ncol=min(len(used), 8), frameon=False)
    if title:
        fig.suptitle(title)
    fig.tight_layout(rect=(0, 0.06, 1, 0.95))
    tmp = path + ".part.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, path)
    return path
