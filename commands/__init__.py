"""GUI commands of AeroNC and the hook into the Path workbench, imported as aeronc.commands.

The folder is commands/ at the top of the source tree; it installs as
<Mod>/AeroNC/aeronc/commands, so that no module with a generic name (commands, panels) lands
on FreeCAD's sys.path. Cheap to import: FreeCAD registers the commands at start-up; the work
they do is imported when they run. base.py holds what every command shares.
"""
import FreeCADGui

COMMANDS = ["AeroNC_RecogniseFeatures", "AeroNC_SelectTools", "AeroNC_OptimiseCutting", "AeroNC_MachiningChain",
            "AeroNC_ProgramImpeller", "AeroNC_EditKnowledgeBase"]
# Datum holes and compensated drilling (commands/datum_holes.py).
DRILLING_COMMANDS = ["AeroNC_DefineDatumHoles", "AeroNC_CameraProgram", "AeroNC_ImportMeasurements",
                     "AeroNC_CompensatedDrilling"]


def register():
    """Register every AeroNC command with FreeCAD (once)."""
    from aeronc.commands.edit_knowledge_base import EditKnowledgeBase
    from aeronc.commands.machining_chain import MachiningChain
    from aeronc.commands.optimise_cutting import OptimiseCutting
    from aeronc.commands.program_impeller import ProgramImpeller
    from aeronc.commands.recognise_features import RecogniseFeatures
    from aeronc.commands.select_tools import SelectTools
    known = FreeCADGui.listCommands()
    for name, command in (("AeroNC_RecogniseFeatures", RecogniseFeatures),
                          ("AeroNC_SelectTools", SelectTools),
                          ("AeroNC_OptimiseCutting", OptimiseCutting),
                          ("AeroNC_MachiningChain", MachiningChain),
                          ("AeroNC_ProgramImpeller", ProgramImpeller),
                          ("AeroNC_EditKnowledgeBase", EditKnowledgeBase)):
        if name not in known:
            FreeCADGui.addCommand(name, command())
    from aeronc.commands.show_setup import ShowSetup
    if "AeroNC_ShowSetup" not in known:  # context menu of a chain's Job only
        FreeCADGui.addCommand("AeroNC_ShowSetup", ShowSetup())
    from aeronc.commands import datum_holes
    for name, command in zip(DRILLING_COMMANDS, (datum_holes.DefineDatumHoles, datum_holes.CameraProgram,
                                                 datum_holes.ImportMeasurements, datum_holes.CompensatedDrilling)):
        if name not in known:
            FreeCADGui.addCommand(name, command())
