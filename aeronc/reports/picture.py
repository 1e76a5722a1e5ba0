"""Pictures of a part coloured by face role, drawn headless.

Faces are tessellated by FreeCAD and rasterised with a depth buffer (numpy), so hidden faces
stay hidden whatever the part's shape; face boundaries are drawn as dark lines. matplotlib
(Agg) lays out the views and the legend. Used by the main job and for reviewing recognition
on real parts without a GUI.
"""
import math
import os

from aeronc.feature_colours import ROLE_COLOURS, UNKNOWN_ROLE

# (label, elevation, azimuth) in degrees: views from above and from below the XY plane.
VIEWS = (("from +Z", 35, -60), ("from -Z", -35, -60))


def _basis(elev, azim):
    import numpy as np
    e, a = math.radians(elev), math.radians(azim)
    eye = np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])  # towards the viewer
    up0 = np.array([0.0, 0.0, 1.0]) if abs(eye[2]) < 0.999 else np.array([0.0, 1.0, 0.0])
    right = np.cross(up0, eye)
    right /= np.linalg.norm(right)
    up = np.cross(eye, right)
    return right, up, eye


def _rasterise(tris, colours, edges, elev, azim, size):
    """RGB image (size x size) of the triangles seen from (elev, azim)."""
    import numpy as np
    right, up, eye = _basis(elev, azim)
    pts = tris.reshape(-1, 3)
    x, y, z = pts @ right, pts @ up, pts @ eye  # larger z = nearer the viewer
    lo = np.array([x.min(), y.min()])
    span = max(x.max() - x.min(), y.max() - y.min()) or 1.0
    scale = (size - 20) / span
    off = (size - np.array([x.max() - x.min(), y.max() - y.min()]) * scale) / 2
    px = ((x - lo[0]) * scale + off[0]).reshape(-1, 3)
    py = (size - 1 - ((y - lo[1]) * scale + off[1])).reshape(-1, 3)
    pz = z.reshape(-1, 3)
    normals = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    nn = np.linalg.norm(normals, axis=1)
    nn[nn == 0] = 1
    light = eye.copy()  # a headlight: what faces the viewer is brightest
    light /= np.linalg.norm(light)
    shade = 0.45 + 0.55 * np.abs((normals / nn[:, None]) @ light)
    img = np.ones((size, size, 3))
    zbuf = np.full((size, size), -np.inf)
    for t in range(len(tris)):
        xs, ys, zs = px[t], py[t], pz[t]
        x0, x1 = max(int(xs.min()), 0), min(int(xs.max()) + 1, size - 1)
        y0, y1 = max(int(ys.min()), 0), min(int(ys.max()) + 1, size - 1)
        if x0 > x1 or y0 > y1:
            continue
        gx, gy = np.meshgrid(np.arange(x0, x1 + 1) + 0.5, np.arange(y0, y1 + 1) + 0.5)
        d = (ys[1] - ys[2]) * (xs[0] - xs[2]) + (xs[2] - xs[1]) * (ys[0] - ys[2])
        if abs(d) < 1e-12:
            continue
        w0 = ((ys[1] - ys[2]) * (gx - xs[2]) + (xs[2] - xs[1]) * (gy - ys[2])) / d
        w1 = ((ys[2] - ys[0]) * (gx - xs[2]) + (xs[0] - xs[2]) * (gy - ys[2])) / d
        w2 = 1 - w0 - w1
        inside = (w0 >= -1e-6) & (w1 >= -1e-6) & (w2 >= -1e-6)
        if not inside.any():
            continue
        depth = w0 * zs[0] + w1 * zs[1] + w2 * zs[2]
        sub = zbuf[y0:y1 + 1, x0:x1 + 1]
        win = inside & (depth > sub)
        sub[win] = depth[win]
        img[y0:y1 + 1, x0:x1 + 1][win] = colours[t] * shade[t]
    if len(edges):
        # Face boundaries: dense samples along each edge, drawn where they are not hidden.
        ex, ey, ez = edges @ right, edges @ up, edges @ eye
        ix = np.clip(((ex - lo[0]) * scale + off[0]).astype(int), 0, size - 1)
        iy = np.clip((size - 1 - ((ey - lo[1]) * scale + off[1])).astype(int), 0, size - 1)
        visible = ez >= zbuf[iy, ix] - span * 4e-3
        img[iy[visible], ix[visible]] *= 0.35
    return img


def render(shape, result, path, title="", views=VIEWS, size=700):
    """Write a PNG of `shape` coloured by `result["faceRoles"]`; returns path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.patches import Patch

    box = shape.BoundBox
    tol = max(box.DiagonalLength * 3e-3, 0.01)  # a picture of 700 pixels needs no finer mesh
    tris, colours, edge_pts = [], [], []
    roles = result["faceRoles"]
    for i, face in enumerate(shape.Faces):
        pts, idx = face.tessellate(tol)
        colour = ROLE_COLOURS.get(roles[i] if i < len(roles) else "unclaimed", UNKNOWN_ROLE)
        p = np.array([tuple(v) for v in pts])
        if len(idx):
            tris.append(p[np.array(idx)])
            colours.extend([colour] * len(idx))
    step = box.DiagonalLength / (size * 1.5)
    import Part
    for edge in Part.Compound(shape.Faces).Edges:  # loose wires in the file are not the part
        if edge.Degenerated:
            continue
        n = max(2, int(edge.Length / step))
        try:
            edge_pts.extend(tuple(v) for v in edge.discretize(n))
        except Exception:  # an edge OCCT cannot sample just goes undrawn
            pass
    tris = np.concatenate(tris) if tris else np.zeros((0, 3, 3))
    colours = np.array(colours)
    edges = np.array(edge_pts) if edge_pts else np.zeros((0, 3))

    fig = plt.figure(figsize=(5.2 * len(views), 5.8), dpi=110)
    for k, (label, elev, azim) in enumerate(views):
        ax = fig.add_subplot(1, len(views), k + 1)
        ax.imshow(_rasterise(tris, colours, edges, elev, azim, size), interpolation="antialiased")
        ax.set_axis_off()
        ax.set_title(label)
    used = sorted(set(roles))
    fig.legend(handles=[Patch(color=ROLE_COLOURS.get(r, UNKNOWN_ROLE), label=r.replace("_", " ")) for r in used],
               loc="lower center", ncol=min(len(used), 7), frameon=False)
    if title:
        fig.suptitle(title)
    fig.tight_layout(rect=(0, 0.08, 1, 0.95))
    tmp = path + ".part.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, path)
    return path
