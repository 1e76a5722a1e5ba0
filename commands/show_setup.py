"""AeroNC_ShowSetup: show one setup's Job of a machining chain, its model turned for the setup,
its stock and its paths, and hide the other setups and the part in its original place.

Each Job of a chain holds the part turned into its own setup frame; drawn together they are a
tangle, and the part in its original place cuts through every stock."""
import FreeCADGui

from aeronc.commands.base import Command


def chain_of_job(job):
    """The MachiningChain whose Jobs hold job, or None."""
    from aeronc.objects import machining_chain
    for obj in job.Document.Objects:
        if machining_chain.is_machining_chain(obj) and job in list(obj.Jobs):
            return obj
    return None


def selected_chain_job():
    """(chain, Job) when the selection is one Job of a machining chain (or an operation in one)."""
    from aeronc import pathcompat
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) != 1:
        return None
    job = sel[0] if pathcompat.is_job(sel[0]) else pathcompat.job_of(sel[0])
    chain = chain_of_job(job) if job is not None else None
    return (chain, job) if chain is not None else None


def _show(obj, visible):
    view = getattr(obj, "ViewObject", None)
    if view is not None:
        view.Visibility = visible


def show_setup(chain, job):
    """Show job's models, stock and operations; hide the other Jobs' and the chain's part and
    Machining Features group."""
    from aeronc import pathcompat
    for j in chain.Jobs:
        mine = j is job
        for m in pathcompat.job_models(j):
            _show(m, mine)
        stock = getattr(j, "Stock", None)
        if stock is not None:
            _show(stock, mine)
        for op in pathcompat.job_operations(j):
            _show(op, mine)
    group = chain.Features
    if group is not None:
        _show(group, False)
        if getattr(group, "Source", None) is not None:
            _show(group.Source, False)


class ShowSetup(Command):
    ICON = "MachiningChain"
    MENU_TEXT = "Show this setup only"
    TOOLTIP = ("Show the selected Job of a machining chain (its model turned for the setup, its stock and its "
               "paths) and hide the other setups and the part in its original place")

    def target(self):
        return selected_chain_job()

    def run(self, found):
        show_setup(*found)
