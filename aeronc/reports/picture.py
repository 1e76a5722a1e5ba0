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
    zbuf, owner = _zbuffer(px, py, pz, size)
    img = np.ones((size * size, 3))
    hit = owner >= 0
    img[hit] = colours[owner[hit]] * shade[owner[hit], None]
    img = img.reshape(size, size, 3)
    zbuf = zbuf.reshape(size, size)
    if len(edges):
        # Face boundaries: dense samples along each edge, drawn where they are not hidden.
        ex, ey, ez = edges @ right, edges @ up, edges @ eye
        ix = np.clip(((ex - lo[0]) * scale + off[0]).astype(int), 0, size - 1)
        iy = np.clip((size - 1 - ((ey - lo[1]) * scale + off[1])).astype(int), 0, size - 1)
        visible = ez >= zbuf[iy, ix] - span * 4e-3
        img[iy[visible], ix[visible]] *= 0.35
    return img


def _zbuffer(px, py, pz, size, budget=4_000_000):
    """(depth, triangle) per pixel of a size x size image, flattened: the nearest triangle whose
    inside holds the pixel's centre (-inf, -1 where none). All triangles at once, in groups of
    like bounding-box size, each group as one numpy computation of at most `budget` samples."""
    import numpy as np
    x0 = np.maximum(np.floor(px.min(1)).astype(np.int64), 0)
    x1 = np.minimum(np.floor(px.max(1)).astype(np.int64) + 1, size - 1)
    y0 = np.maximum(np.floor(py.min(1)).astype(np.int64), 0)
    y1 = np.minimum(np.floor(py.max(1)).astype(np.int64) + 1, size - 1)
    w, h = x1 - x0 + 1, y1 - y0 + 1
    d = (py[:, 1] - py[:, 2]) * (px[:, 0] - px[:, 2]) + (px[:, 2] - px[:, 1]) * (py[:, 0] - py[:, 2])
    usable = (w > 0) & (h > 0) & (np.abs(d) >= 1e-12)
    extent = np.maximum(w, h)
    pixels, depths, owners = [], [], []
    low = 0
    side = 2
    while low < size:
        group = np.nonzero(usable & (extent > low) & (extent <= side))[0]
        per = max(1, budget // (side * side))
        for start in range(0, len(group), per):
            k = group[start:start + per]
            steps = np.arange(side)
            gx = x0[k, None, None] + steps[None, None, :]
            gy = y0[k, None, None] + steps[None, :, None]
            inbox = (steps[None, None, :] < w[k, None, None]) & (steps[None, :, None] < h[k, None, None])
            cx, cy = gx + 0.5, gy + 0.5
            xs, ys, zs = px[k], py[k], pz[k]
            dk = d[k][:, None, None]
            w0 = ((ys[:, 1, None, None] - ys[:, 2, None, None]) * (cx - xs[:, 2, None, None]) +
                  (xs[:, 2, None, None] - xs[:, 1, None, None]) * (cy - ys[:, 2, None, None])) / dk
            w1 = ((ys[:, 2, None, None] - ys[:, 0, None, None]) * (cx - xs[:, 2, None, None]) +
                  (xs[:, 0, None, None] - xs[:, 2, None, None]) * (cy - ys[:, 2, None, None])) / dk
            w2 = 1 - w0 - w1
            inside = inbox & (w0 >= -1e-6) & (w1 >= -1e-6) & (w2 >= -1e-6)
            depth = w0 * zs[:, 0, None, None] + w1 * zs[:, 1, None, None] + w2 * zs[:, 2, None, None]
            pixels.append((gy * size + gx)[inside])
            depths.append(depth[inside])
            owners.append(np.broadcast_to(k[:, None, None], inside.shape)[inside])
        low, side = side, side * 2
    zbuf = np.full(size * size, -np.inf)
    owner = np.full(size * size, -1, dtype=np.int64)
    if pixels:
        pix, dep, own = np.concatenate(pixels), np.concatenate(depths), np.concatenate(owners)
        if len(pix):
            order = np.lexsort((dep, pix))  # by pixel, nearest last
            pix, dep, own = pix[order], dep[order], own[order]
            last = np.ones(len(pix), dtype=bool)
            last[:-1] = pix[1:] != pix[:-1]
            zbuf[pix[last]], owner[pix[last]] = dep[last], own[last]
    return zbuf, owner


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
