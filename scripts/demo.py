"""The main job on the embedded sample part, headless, against the installed addon:

    HOME=<a FreeCAD home with AeroNC installed> AERONC_OUT=out/demo freecadcmd scripts/demo.py

(`scripts/run.sh demo` does this.)

Opens resources/samples/sample_panel.step (an integral panel with pockets on both faces,
islands, openings, lightening and bolt holes, a flange and a joggle), recognises its machining
features into a FreeCAD document, selects its tools from the knowledge base (7050-T7451 on
the AC-5AX), which makes the Path Job and its ToolControllers, optimises their spindle speeds
and feeds, and writes to AERONC_OUT:
  sample_panel.FCStd            the document: Machining Features tree, Job, ToolControllers
  recognition.json              the machining-domain tree and the role of every face
  sample_panel_features.png     the part coloured by feature type
  knowledge.sqlite              the knowledge base used (built from resources/kb)
  cutting_optimum.png           the optimisation of the first roughing ToolController
AERONC_PART=<file.step> runs the same on another part. Exit code 0 on success.
"""
import json
import os
import time


def main():
    import FreeCAD
    import Part

    import aeronc
    from aeronc import picture
    from aeronc.post.output import write_atomically
    from aeronc.makers import create_machining_features
    from aeronc.objects import result_of

    part_path = os.environ.get("AERONC_PART") or os.path.join(aeronc.PACKAGE_DIR, "resources", "samples",
                                                               "sample_panel.step")
    out = os.path.abspath(os.environ.get("AERONC_OUT", "out/demo"))
    os.makedirs(out, exist_ok=True)
    name = os.path.splitext(os.path.basename(part_path))[0]

    doc = FreeCAD.newDocument(name)
    shape = Part.read(part_path)
    part = doc.addObject("Part::Feature", "Part")
    part.Label = name
    part.Shape = shape
    doc.recompute()

    t0 = time.perf_counter()
    group = create_machining_features(doc, part)
    seconds = time.perf_counter() - t0
    result = result_of(group)

    from aeronc import cutting_optimisation, optimisation_plot, tool_planning
    kb_path = os.path.join(out, "knowledge.sqlite")
    t0 = time.perf_counter()
    plan, job, tcs = tool_planning.select_tools(group, "7050-T7451", "AC-5AX", kb_path)
    t_tools = time.perf_counter() - t0
    t0 = time.perf_counter()
    proposals = cutting_optimisation.propose(job, kb_path=kb_path, map_points=61)
    written = cutting_optimisation.apply(proposals)
    t_opt = time.perf_counter() - t0

    doc.saveAs(os.path.join(out, name + ".FCStd"))
    write_atomically(os.path.join(out, "recognition.json"), json.dumps(result, indent=1))
    png = picture.render(part.Shape, result, os.path.join(out, name + "_features.png"),
                         title="{}: machining features".format(name))

    print("{}: {} faces recognised into the document in {:.2f} s".format(part_path, result["faceCount"], seconds))
    for setup in result["setups"]:
        mine = [e for e in result["elements"] if e["setup"] == setup["id"]]
        counts = {}
        for e in mine:
            counts[e["type"]] = counts.get(e["type"], 0) + 1
        print("  setup {}: {} element(s): {}".format(
            setup["name"], len(mine), ", ".join("{} {}".format(v, k) for k, v in sorted(counts.items()))))
    for w in result.get("warnings", []):
        print("  warning:", w)
    print("tools selected in {:.2f} s: roughing tool changes {} -> {}, {} ToolControllers in {}".format(
        t_tools, plan["toolChanges"]["before"], plan["toolChanges"]["after"], len(tcs), job.Label))
    print("cutting parameters optimised in {:.2f} s ({} written, one undo step):".format(t_opt, len(written)))
    for p in proposals:
        if p.ok:
            print("  {:28s} n {:7.0f} -> {:7.0f} r/min, feed {:6.0f} -> {:6.0f} mm/min; active: {}".format(
                p.tc.Label, p.current[0], p.spindle_rpm, p.current[1], p.horiz_feed, ", ".join(p.optimum["active"])))
        else:
            print("  {:28s} {}".format(p.tc.Label, p.error))
    shown = next((p for p in proposals if p.ok and p.operation == "roughing"), None)
    plot = optimisation_plot.save(shown.result, os.path.join(out, "cutting_optimum.png"), shown.tc.Label) \
        if shown is not None else "(no roughing ToolController)"
    print("wrote {}, {}, {}, {}".format(os.path.join(out, name + ".FCStd"), os.path.join(out, "recognition.json"),
                                        png, plot))


from aeronc.tests.script import run  # noqa: E402  (on the path from the installed addon)

run(main)
