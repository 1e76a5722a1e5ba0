"""The machining chain against FreeCAD's Pocket Shape on the same pockets (a benchmark, not a test):

    HOME=<a FreeCAD home with AeroNC installed> freecadcmd tools/pocket_shape_compare.py
    (or: cmake --build build --target bench_pocket_compare, after installing to build/stage)

What a user does today without the chain: one FreeCAD Pocket Shape per +Z closed pocket, built
by hand on the pocket's recognised floor faces, with default settings and a 5 mm end mill. On
the sample panel (or the STEP/BREP file in AERONC_BENCH_PART) this script
  1. recognises the part, selects its tools and builds the machining chain (not timed);
  2. in a Job of its own on the part (stock: the recognition blank), makes one Pocket Shape per
     +Z closed pocket on its floor faces, and times their computation (recompute);
     AERONC_BENCH_ADAPTIVE=1 does the same with FreeCAD's Adaptive (about 10 s);
  3. times the chain's own operations of the same pockets: recomputing them (toolpath + Path
     commands) and the toolpath generator alone on their units (_core.toolpaths);
  4. simulates each set of paths alone on the blank (_core.simulate, Z-dexel) against the part
     and reports, for the +Z floors of those pockets, the floor area left more than 0.2 mm above
     its finished height, the largest leftover, and the gouges.
Timings are the best of AERONC_BENCH_REPEAT runs (default 3). AERONC_BENCH_CELL sets the
simulation's cell (default 0.5 mm). AERONC_BENCH_POCKETS=1 also prints each pocket's figures.
"""
import json
import os
import tempfile
import time

MATERIAL, MACHINE, FAMILY = "7050-T7451", "AC-5AX", "integral_panel"
END_MILL_MM = 5.0
ARC_STEP_MM = 0.1  # chords of FreeCAD's arcs: 0.1 mm keeps the sagitta under 0.001 mm for r >= 1.25 mm


def _env_int(name, default):
    return int(os.environ.get(name, str(default)))


def _load_part(doc):
    import Part
    import aeronc
    path = os.environ.get("AERONC_BENCH_PART") or os.path.join(aeronc.PACKAGE_DIR, "resources", "samples",
                                                                 "sample_panel.step")
    part = doc.addObject("Part::Feature", "Part")
    part.Label = os.path.splitext(os.path.basename(path))[0]
    part.Shape = Part.read(path)
    doc.recompute()
    return part, path


def closed_pockets_from_top(result):
    """The +Z setup's id and its closed pockets that have floor faces."""
    top = [s for s in result["setups"] if [round(c, 9) for c in s["direction"]] == [0.0, 0.0, 1.0]]
    if not top:
        raise RuntimeError("the part has no +Z setup")
    sid = top[0]["id"]
    return sid, [e for e in result["elements"]
                 if e["setup"] == sid and e["type"] == "closed_pocket" and e.get("floorFaces")]


def _best(runs, work):
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        work()
        times.append(time.perf_counter() - t0)
    return min(times), times


# --- FreeCAD's operations ---------------------------------------------------------------------

def freecad_job(doc, part, blank):
    """A Job on the part whose only ToolController holds a 5 mm end mill, its stock the blank."""
    from aeronc import pathcompat
    from aeronc.tests.app.support import end_mill
    job = pathcompat.create_job(doc, [part], "FreeCADPockets")
    job.Label = "FreeCAD pockets"
    pathcompat.set_job_stock_box(job, blank)
    defaults = pathcompat.tool_controllers(job)
    tc = pathcompat.create_tool_controller(doc, job, "5 mm end mill", end_mill(END_MILL_MM), 1, 10000, 1200, 400)
    for old in defaults:
        pathcompat.remove_tool_controller(doc, old)
    doc.recompute()
    return job, tc


def freecad_operations(job, tc, pockets, create, prefix):
    """One operation per pocket on its floor faces (of the Job's clone of the part), default
    settings but the ToolController."""
    from aeronc import pathcompat
    model = pathcompat.job_models(job)[0]
    ops = []
    for e in pockets:
        op = create("{}_E{}".format(prefix, e["id"]), job)
        op.Base = [(model, ["Face{}".format(f) for f in e["floorFaces"]])]
        op.ToolController = tc
        ops.append(op)
    return ops


def recompute_all(ops):
    for op in ops:
        op.touch()
    for op in ops:
        op.recompute()


# --- paths as the simulation reads them -------------------------------------------------------

def path_moves(commands, arc_step=ARC_STEP_MM):
    """[kind, x, y, z] tool-tip moves (0 rapid, 1 feed) of Path commands, and drill cycles
    [3, x, y, bottom, r, peck, dwell]; XY arcs (G2/G3, I J relative to the start) become chords."""
    from aeronc.pipeline.verification import _arc_points
    pos = [None, None, None]
    moves = []
    for c in commands:
        name, p = c.Name.upper(), c.Parameters
        if name in ("G0", "G00", "G1", "G01", "G2", "G02", "G3", "G03"):
            end = [p.get(k, pos[i]) for i, k in enumerate("XYZ")]
            kind = 0 if name in ("G0", "G00") else 1
            if None in end:  # a coordinate not yet known (a first move along one axis only)
                pos = end
                continue
            if kind == 1 and name not in ("G1", "G01") and None not in pos:
                centre = (pos[0] + p.get("I", 0.0), pos[1] + p.get("J", 0.0))
                turn = -1 if name in ("G2", "G02") else 1
                for q in _arc_points((pos[0], pos[1], pos[2], 0.0, 0.0), (end[0], end[1], end[2], 0.0, 0.0),
                                     centre, turn, arc_step):
                    moves.append([1, q[0], q[1], q[2]])
            else:
                moves.append([kind, end[0], end[1], end[2]])
            pos = end
        elif name in ("G81", "G82", "G83", "G73"):
            x, y = p.get("X", pos[0]), p.get("Y", pos[1])
            moves.append([3, x, y, p["Z"], p.get("R", pos[2]), p.get("Q", 0.0), p.get("P", 0.0)])
            pos = [x, y, p.get("R", pos[2])]
    return moves


def sim_op(label, moves, cutter, radial=0.0, axial=0.0, to_part=None):
    """An op of the simulation's program; to_part maps the Job's frame to the part's."""
    if to_part is not None:
        import FreeCAD
        out = []
        for m in moves:
            v = to_part.multVec(FreeCAD.Vector(m[1], m[2], m[3]))
            out.append([m[0], v.x, v.y, v.z] + list(m[4:]))
        moves = out
    return {"label": label, "axis": [0.0, 0.0, 1.0], "moves": moves,
            "cutter": {"diameter": cutter["diameter"], "cornerRadius": cutter["cornerRadius"]},
            "radialAllowance": radial, "axialAllowance": axial}


def _length(op, prop):
    """A length property of an operation in mm; 0 where it has none (a drilling leaves nothing)."""
    v = getattr(op, prop, 0.0)
    return float(getattr(v, "Value", v))


def floor_figures(part_shape, ops, blank, pockets, cell):
    """Simulate ops on the blank; the +Z floors' figures of the pockets."""
    from aeronc.pipeline import verification
    floors = {f for e in pockets for f in e["floorFaces"]}
    fillets = {f for e in pockets for f in e.get("filletFaces", [])} - floors
    elements = {"E{}".format(e["id"]): list(e["floorFaces"]) for e in pockets}
    t0 = time.perf_counter()
    report = verification.simulate(part_shape, ops, blank, sorted(floors | fillets), elements, cell,
                                   {"leftoverMap": False})
    t_sim = time.perf_counter() - t0
    faces = [f for f in report["coverage"]["faces"] if f["face"] in floors]
    blends = [f for f in report["coverage"]["faces"] if f["face"] in fillets]
    area = sum(f.get("floorArea", 0.0) for f in faces)
    left = sum(f.get("uncoveredArea", 0.0) for f in faces)
    worst_left = max([f.get("maxLeftover") or 0.0 for f in faces] or [0.0])
    gouge = report["gouges"]
    worst = gouge.get("worst") or {}
    return {"area": area, "left": left, "maxLeft": worst_left, "gouges": int(gouge.get("count", 0)),
            "filletArea": sum(f.get("floorArea", 0.0) + f.get("wallArea", 0.0) for f in blends),
            "filletLeft": sum(f.get("uncoveredArea", 0.0) for f in blends),
            "worstCollision": report["collisions"].get("worst") or {},
            "worstGouge": float(worst.get("depth", 0.0)), "worst": worst,
            "gougingOps": [(o["label"], int(o.get("gouges", 0))) for o in report["ops"] if o.get("gouges")],
            "collisions": int(report["collisions"].get("count", 0)),
            "moves": sum(len(o["moves"]) for o in ops), "simSeconds": t_sim,
            "elements": {e["id"]: e for e in report["coverage"]["elements"]}}


# --- the run ----------------------------------------------------------------------------------

def main():
    import FreeCAD
    from aeronc import _core
    from aeronc.pipeline import chain_building, setup_job, tool_planning
    from aeronc.makers import create_machining_features
    from aeronc.objects import result_of
    from aeronc.operations.base import cutter_of
    from aeronc.tests import pathcompat as test_pathcompat

    runs = _env_int("AERONC_BENCH_REPEAT", 3)
    cell = float(os.environ.get("AERONC_BENCH_CELL", "0.5"))
    adaptive = os.environ.get("AERONC_BENCH_ADAPTIVE", "0") not in ("", "0")
    kb_path = os.path.join(tempfile.mkdtemp(prefix="aeronc_bench_"), "kb.sqlite")

    doc = FreeCAD.newDocument("PocketCompare")
    part, path = _load_part(doc)
    t0 = time.perf_counter()
    group = create_machining_features(doc, part)
    result = result_of(group)
    tool_planning.select_tools(group, MATERIAL, MACHINE, kb_path)
    chain_obj = chain_building.build(group, FAMILY, MATERIAL, MACHINE, kb_path)
    t_prepare = time.perf_counter() - t0
    chain = json.loads(chain_obj.Chain)
    sid, pockets = closed_pockets_from_top(result)
    ids = {e["id"] for e in pockets}
    blank = setup_job.blank_box(group)
    print("Machining chain against FreeCAD's Pocket Shape: {}, {} +Z closed pockets, simulated at {} mm cells; "
          "recognise, tools, chain {:.1f} s (not counted)".format(os.path.basename(path), len(pockets), cell, t_prepare))

    # The chain's operations of those pockets, in chain order, in the +Z Job.
    setup = [s for s in chain["setups"] if int(s["id"]) == sid][0]
    to_part = setup_job.frame_placement(setup["frame"]).inverse()
    chain_ops = [op for op in chain_building.chain_operations(chain_obj)
                 if op.SetupId == sid and op.ElementId in ids and op.Active]
    missing = sorted(ids - {op.ElementId for op in chain_ops})
    t_chain_ops, chain_runs = _best(runs, lambda: recompute_all(chain_ops))
    inputs = [json.dumps(i) for op in chain_ops for i in op.Proxy.toolpath_inputs(op)]
    t_chain_core, core_runs = _best(runs, lambda: _core.toolpaths(inputs))
    invalid = [op.Label for op in chain_ops if "Invalid" in op.State]

    # FreeCAD's operations on the same pockets, in a Job of their own.
    job, tc = freecad_job(doc, part, blank)
    cutter = cutter_of(tc)
    methods = []
    kinds = [("Pocket Shape", test_pathcompat.create_pocket_shape, "PocketShape")]
    if adaptive:
        kinds.append(("Adaptive", test_pathcompat.create_adaptive, "Adaptive"))
    for name, create, prefix in kinds:
        ops = freecad_operations(job, tc, pockets, create, prefix)
        t_ops, op_runs = _best(runs if name == "Pocket Shape" else 1, lambda: recompute_all(ops))
        failed = [op.Label for op in ops if "Invalid" in op.State or not op.Path.Commands]
        sim = [sim_op(op.Label, path_moves(op.Path.Commands), cutter) for op in ops]
        methods.append((name, len(ops), t_ops, op_runs, failed, floor_figures(part.Shape, sim, blank, pockets, cell)))

    def chain_sim(ops):
        out = []
        for op in ops:
            if not op.Path.Commands:
                continue
            out.append(sim_op(op.Label, path_moves(op.Path.Commands), cutter_of(op.ToolController),
                              _length(op, "RadialAllowance"), _length(op, "AxialAllowance"), to_part))
        return out

    chain_fig = floor_figures(part.Shape, chain_sim(chain_ops), blank, pockets, cell)
    # The same floors after every operation of the +Z setup, in chain order (not timed).
    setup_ops = [op for op in chain_building.chain_operations(chain_obj) if op.SetupId == sid and op.Active]
    setup_fig = floor_figures(part.Shape, chain_sim(setup_ops), blank, pockets, cell)

    print("  chain operations of those pockets: {} (steps {}){}".format(
        len(chain_ops), ", ".join(sorted({op.Step for op in chain_ops})),
        "; pockets without one: {}".format(missing) if missing else ""))
    if invalid:
        print("  chain operations without a path: {}".format(", ".join(invalid)))
    header = "  {:<28} {:>4} {:>9} {:>8} {:>10} {:>10} {:>6} {:>8} {:>7} {:>9}".format(
        "toolpaths", "ops", "compute s", "moves", "floor mm2", ">0.2 mm", "%", "max left", "gouges", "worst")
    print(header)
    rows = [(n, k, t, fig) for n, k, t, _, _, fig in methods]
    rows.append(("chain: recompute operations", len(chain_ops), t_chain_ops, chain_fig))
    rows.append(("chain: _core.toolpaths", len(inputs), t_chain_core, None))
    rows.append(("chain, whole +Z setup", len(setup_ops), None, setup_fig))
    for n, k, t, fig in rows:
        if fig is None:
            print("  {:<28} {:>4} {:>9.3f}".format(n, k, t))
            continue
        print("  {:<28} {:>4} {:>9} {:>8} {:>10.0f} {:>10.0f} {:>6.1f} {:>8.2f} {:>7} {:>9.3f}".format(
            n, k, "{:.3f}".format(t) if t is not None else "-", fig["moves"], fig["area"], fig["left"], 100.0 * fig["left"] / max(fig["area"], 1e-9),
            fig["maxLeft"], fig["gouges"], fig["worstGouge"]))
    pocket_shape = methods[0]
    print("  Pocket Shape / chain operations: {:.1f}x; Pocket Shape / _core.toolpaths: {:.1f}x".format(
        pocket_shape[2] / max(t_chain_ops, 1e-9), pocket_shape[2] / max(t_chain_core, 1e-9)))
    print("  runs (s): Pocket Shape {}; chain operations {}; _core.toolpaths {}".format(
        ", ".join("{:.3f}".format(t) for t in pocket_shape[3]), ", ".join("{:.3f}".format(t) for t in chain_runs),
        ", ".join("{:.3f}".format(t) for t in core_runs)))
    for name, _, _, _, failed, fig in methods:
        if failed:
            print("  {} operations without a path: {}".format(name, ", ".join(failed)))
    print("  the pockets' floor fillets (mm2 left >0.2 mm of mm2): {}".format(", ".join(
        "{} {:.0f} of {:.0f}".format(n.split(":")[0], fig["filletLeft"], fig["filletArea"])
        for n, _, _, fig in rows if fig is not None)))
    for n, _, _, fig in rows:
        if fig is not None and fig["collisions"]:
            w = fig["worstCollision"]
            print("  {} rapids through material: {} moves; worst {:.3f} mm in {} move {} at {}".format(
                n.split(":")[0], fig["collisions"], w.get("depth", 0.0), w.get("op", ""), w.get("move", ""),
                w.get("position", "")))
    for n, _, _, fig in rows:
        if fig is not None and fig["gouges"]:
            w = fig["worst"]
            print("  {} gouges: worst {:.3f} mm ({}, face {}) in {} move {} at {}; by operation: {}".format(
                n.split(":")[0], w.get("depth", 0.0), w.get("kind", ""), w.get("face", ""), w.get("op", ""),
                w.get("move", ""), w.get("position", ""),
                ", ".join("{} {}".format(label, k) for label, k in fig["gougingOps"])))
    if os.environ.get("AERONC_BENCH_POCKETS", "0") not in ("", "0"):
        print("  per pocket: floor mm2, left >0.2 mm (mm2), max leftover (mm)")
        for e in pockets:
            key = "E{}".format(e["id"])
            cells = []
            for n, _, _, fig in rows:
                if fig is None:
                    continue
                el = fig["elements"].get(key, {})
                cells.append("{} {:.0f} / {:.2f}".format(n.split(":")[0], el.get("uncoveredArea", 0.0),
                                                          el.get("maxLeftover") or 0.0))
            area = rows[0][3]["elements"].get(key, {}).get("area", 0.0)
            print("  {:<5} {:>7.0f}  {}".format(key, area, "; ".join(cells)))
    FreeCAD.closeDocument(doc.Name)


main()
