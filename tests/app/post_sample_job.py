"""The sample Job of the posts on the embedded sample panel, imported as
aeronc.tests.app.post_sample_job (test_post_sample.py checks it; scripts/post_sample.py posts
it to out/post).

A Path Job on resources/samples/sample_panel.step (top setup) with
  1. Profile       FreeCAD's own 3-axis Profile of the outline (tool T1),
  2. EndBevels     30-degree bevels of the two short top edges, one indexed (3+2) plane each,
  3. EdgeChamfer   a 45-degree chamfer round the top edge, the tool turning round each corner
                   (simultaneous 5-axis),
  4. Holes         the recognised 6.6 mm holes drilled along their axes (tool T2),
in AeroNC's tool-axis convention (U V W on every move, docs/post.md); and the APT file of a
camera program over datum holes.
"""
import math

CHAMFER_TILT = 45.0
BEVEL_TILT = 30.0


def _axis(polar, azimuth):
    p, a = math.radians(polar), math.radians(azimuth)
    return (math.sin(p) * math.cos(a), math.sin(p) * math.sin(a), math.cos(p))


def _box(shape):
    b = shape.BoundBox
    return b.XMin, b.YMin, b.ZMin, b.XMax, b.YMax, b.ZMax


def chamfer_commands(shape, feed):
    """Round the top edge, the tool tilted 45 degrees outwards, turning about each corner."""
    from aeronc.post.orientation import oriented_command
    x0, y0, _, x1, y1, z1 = _box(shape)
    c = 0.5  # chamfer leg, mm
    # Edges counter-clockwise from the front (outward azimuth -90), each with its corner turn.
    edges = [((x0, y0), (x1, y0), -90.0), ((x1, y0), (x1, y1), 0.0), ((x1, y1), (x0, y1), 90.0), ((x0, y1), (x0, y0), 180.0)]
    cmds = []
    start_axis = _axis(CHAMFER_TILT, -90.0)
    first = (x0, y0 + c, z1 - c)
    cmds.append(oriented_command("G0", {"X": first[0], "Y": first[1], "Z": z1 + 30}, start_axis))
    cmds.append(oriented_command("G1", {"X": first[0], "Y": first[1], "Z": first[2], "F": feed}, start_axis))
    for (a, b, az) in edges:
        out = (math.cos(math.radians(az)), math.sin(math.radians(az)))
        end = (b[0] - out[0] * c, b[1] - out[1] * c, z1 - c)
        cmds.append(oriented_command("G1", {"X": end[0], "Y": end[1], "Z": end[2], "F": feed}, _axis(CHAMFER_TILT, az)))
        for k in range(1, 10):  # turn about the corner: the tip stays, the axis sweeps 90 degrees
            cmds.append(oriented_command("G1", {"X": end[0], "Y": end[1], "Z": end[2], "F": feed},
                                         _axis(CHAMFER_TILT, az + 10.0 * k)))
    last = cmds[-1].Parameters
    up = _axis(CHAMFER_TILT, 270.0)
    cmds.append(oriented_command("G0", {"X": last["X"] + 30 * up[0], "Y": last["Y"] + 30 * up[1],
                                        "Z": last["Z"] + 30 * up[2]}, up))
    return cmds


def bevel_commands(shape, feed):
    """A 30-degree bevel of each short top edge, each in its own indexed plane."""
    from aeronc.post.orientation import oriented_command
    x0, y0, _, x1, y1, z1 = _box(shape)
    cmds = []
    for x, az in ((x0, 180.0), (x1, 0.0)):
        u = _axis(BEVEL_TILT, az)
        inward = -math.copysign(1.0, math.cos(math.radians(az)))
        tip = (x + inward * 0.8, y0 - 5, z1 - 0.8)
        above = tuple(t + 25 * a for t, a in zip(tip, u))
        cmds.append(oriented_command("G0", {"X": above[0], "Y": above[1], "Z": above[2]}, u))
        cmds.append(oriented_command("G1", {"X": tip[0], "Y": tip[1], "Z": tip[2], "F": feed}, u))
        cmds.append(oriented_command("G1", {"X": tip[0], "Y": y1 + 5, "Z": tip[2], "F": feed}, u))
        cmds.append(oriented_command("G0", {"X": above[0], "Y": y1 + 5 + 25 * u[1], "Z": above[2]}, u))
    return cmds


def hole_commands(holes, feed, top_z):
    """Each hole drilled along its own axis: rapid to 10 mm above the part on the hole axis,
    then G81 (or G83 when deep), returning there (G98) before the next hole."""
    from aeronc.post.orientation import oriented_command
    import Path
    cmds = [Path.Command("G98")]
    for h in holes:
        u, top, depth, d = h["axis"], h["location"], h["depth"], h["diameter"]
        bottom = [t - (depth + 1.0) * a for t, a in zip(top, u)]  # through, 1 mm beyond
        lift = (top_z + 10.0 - top[2]) / u[2] if u[2] > 0.5 else 10.0  # clear of the whole part
        above = [t + lift * a for t, a in zip(top, u)]
        cmds.append(oriented_command("G0", {"X": above[0], "Y": above[1], "Z": above[2]}, u))
        p = {"X": bottom[0], "Y": bottom[1], "Z": bottom[2], "R": bottom[2] + depth + 1.0 + 3.0, "F": feed}
        if depth > 3 * d:
            p["Q"] = d
        cmds.append(oriented_command("G83" if "Q" in p else "G81", p, u))
    cmds.append(Path.Command("G80"))
    return cmds


def _add_op(doc, job, label, commands, tc):
    import Path
    op = doc.addObject("Path::FeaturePython", label)
    op.Label = label
    op.addProperty("App::PropertyLink", "ToolController", "Path", "Tool controller of the operation")
    op.addProperty("App::PropertyEnumeration", "CoolantMode", "Path", "Coolant")
    op.CoolantMode = ["None", "Flood", "Mist"]
    op.CoolantMode = "Flood"
    op.ToolController = tc
    op.Path = Path.Path(commands)
    job.Operations.addObject(op)
    return op


def build_job(doc, part):
    """The sample Job on `part`; returns (job, recognised 6.6 mm holes)."""
    from aeronc import pathcompat
    from aeronc.pipeline import recognition
    from aeronc.tests import pathcompat as test_pathcompat

    job = pathcompat.create_job(doc, [part])
    doc.recompute()
    mill = job.Tools.Group[0]
    mill.Label = "TC: 5 mm end mill"
    mill.HorizFeed, mill.VertFeed, mill.SpindleSpeed = "1500 mm/min", "400 mm/min", 12000
    # FreeCAD 0.20 asks which tool to use (a dialog) when a Job has several: profile first.
    profile = test_pathcompat.create_profile("Profile")
    profile.ToolController = mill
    doc.recompute()
    drill = test_pathcompat.add_tool_controller(job, "TC: 6.6 mm drill", 2)
    drill.Tool.Diameter = 6.6
    drill.Tool.Label = "Drill 6.6"
    drill.HorizFeed, drill.VertFeed, drill.SpindleSpeed = "300 mm/min", "300 mm/min", 4000

    shape = part.Shape
    feed = mill.HorizFeed.Value  # mm/s, FreeCAD's unit
    _add_op(doc, job, "EndBevels", bevel_commands(shape, feed), mill)
    _add_op(doc, job, "EdgeChamfer", chamfer_commands(shape, feed), mill)
    result = recognition.recognise(part, directions=[(0, 0, 1)])
    holes = sorted((e["hole"] for e in result["elements"] if e.get("hole") and abs(e["hole"]["diameter"] - 6.6) < 1e-6),
                   key=lambda h: (h["location"][1], h["location"][0]))
    _add_op(doc, job, "Holes", hole_commands(holes, drill.VertFeed.Value, _box(shape)[5]), drill)
    doc.recompute()
    return job, holes


def camera_apt(holes, standoff=60.0):
    """APT CL file of a camera program: above each datum hole, normal to the surface."""
    lines = ["$$ AeroNC camera program: datum holes, camera axis normal to the surface",
             "PARTNO/CAMERA", "UNITS/MM", "MULTAX/ON", "PPRINT/OPERATION Datum holes", "LOADTL/20,LENGTH,150",
             "PPRINT/TOOL NAME Camera", "FEDRAT/3000,MMPM"]
    for h in holes:
        u, p = h["axis"], h["location"]
        q = [c + standoff * a for c, a in zip(p, u)]
        lines += ["RAPID", "GOTO/{:.4f},{:.4f},{:.4f},{:.6f},{:.6f},{:.6f}".format(*(q + list(u))), "DELAY/0.5"]
    lines.append("FINI")
    return "\n".join(lines) + "\n"
