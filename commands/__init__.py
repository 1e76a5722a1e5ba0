"""GUI commands of AeroNC (installed as aeronc.commands). Cheap to import: FreeCAD
registers them at start-up; the work they do is imported when they run."""
import FreeCADGui

COMMANDS = ["AeroNC_RecogniseFeatures"]


def register():
    """Register every AeroNC command with FreeCAD (once)."""
    from aeronc.commands.recognise_features import RecogniseFeatures
    if "AeroNC_RecogniseFeatures" not in FreeCADGui.listCommands():
        FreeCADGui.addCommand("AeroNC_RecogniseFeatures", RecogniseFeatures())
