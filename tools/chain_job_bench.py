"""The machining chain's Jobs inside FreeCAD (a benchmark, not a test):

    HOME=<a FreeCAD home with AeroNC installed> freecadcmd tools/chain_job_bench.py

On the sample panel and on generated double-sided panels of AERONC_BENCH_GRIDS pockets per side
(default "3,8": 3 x 3 and 8 x 8), times
  chain     the core's build_chain on the stored domain tree (compute());
  build     build(): the Jobs, their ToolControllers and an operation per unit, paths included;
  paths     recomputing every operation's path again (toolpath generator + Path commands);
  core      the toolpath generator alone on the same units (_core.toolpaths);
  update    update() after disabling one unit (the Jobs brought in line, nothing rebuilt).
Recognition is not counted.
"""
import json
import os
import tempfile
import time


def _panel(doc, n):
    import Part
    from aeronc import _core
    spec = {"pocketsX": n, "pocketsY": n, "bottomPockets": True}
    shape = Part.Shape()
    shape.importBrepFromString(_core.make_panel(json.dumps(spec))[0])
    part = doc.addObject("Part::Feature", "Panel{}x{}".format(n, n))
    part.Shape = shape
    return part


def _sample(doc):
    import Part
    import aeronc
    part = doc.addObject("Part::Feature", "SamplePanel")
    part.Shape = Part.read(os.path.join(aeronc.PACKAGE_DIR, "resources", "samples", "sample_panel.step"))
    return part


def run(name, make, kb_path):
    import FreeCAD
    from aeronc import _core, makers
    from aeronc.pipeline import chain_edits, chain_building
    doc = FreeCAD.newDocument("ChainBench")
    doc.UndoMode = 1
    part = make(doc)
    doc.recompute()
    group = makers.create_machining_features(doc, part)
    t0 = time.perf_counter()
    built = chain_building.compute(group, "integral_panel", "7050-T7451", kb_path=kb_path)
    t_chain = time.perf_counter() - t0
    t0 = time.perf_counter()
    chain = chain_building.build(group, "integral_panel", "7050-T7451", kb_path=kb_path, built=built)
    t_build = time.perf_counter() - t0
    ops = chain_building.chain_operations(chain)
    t0 = time.perf_counter()
    for op in ops:
        op.touch()
    doc.recompute()
    t_paths = time.perf_counter() - t0
    inputs = [json.dumps(op.Proxy.toolpath_input(op)) for op in ops]
    good = []
    for text in inputs:  # the ones the generator accepts (a refused unit is reported by build)
        try:
            _core.toolpath(text)
            good.append(text)
        except RuntimeError:
            pass
    t0 = time.perf_counter()
    _core.toolpaths(good)
    t_core = time.perf_counter() - t0
    edits = chain_edits.with_enabled({}, ops[-1].UnitId, False)
    t0 = time.perf_counter()
    chain_building.update(chain, edits)
    t_update = time.perf_counter() - t0
    commands = sum(len(op.Path.Commands) for op in ops)
    failed = sum(1 for op in ops if "Invalid" in op.State)
    print("{:<14} {:>5} units {:>2} Jobs {:>8} commands {:>3} without path | chain {:6.2f} s  build {:6.2f} s  "
          "paths {:6.2f} s  core {:6.2f} s  update {:6.2f} s".format(
              name, len(ops), len(chain.Jobs), commands, failed, t_chain, t_build, t_paths, t_core, t_update))
    FreeCAD.closeDocument(doc.Name)


def main():
    kb_path = os.path.join(tempfile.mkdtemp(prefix="aeronc_bench_"), "kb.sqlite")
    grids = [int(g) for g in os.environ.get("AERONC_BENCH_GRIDS", "3,8").split(",") if g]
    print("Machining chain Jobs in FreeCAD (freecadcmd, one run each)")
    run("sample panel", _sample, kb_path)
    for n in grids:
        run("panel {}x{}".format(n, n), lambda doc, n=n: _panel(doc, n), kb_path)


main()
