"""AeroNC_EditKnowledgeBase: browse and edit the machining knowledge base."""
import FreeCADGui

import aeronc


class EditKnowledgeBase:
    def GetResources(self):
        return {"Pixmap": aeronc.icon("KnowledgeBase"),
                "MenuText": "Knowledge base...",
                "ToolTip": "Browse and edit the machining knowledge base: tools, cutting data, machines, "
                           "materials and rules; import and export FreeCAD tool libraries"}

    def IsActive(self):
        return not FreeCADGui.Control.activeDialog()

    def Activated(self):
        from aeronc.panels.knowledge_base_panel import KnowledgeBasePanel
        FreeCADGui.Control.showDialog(KnowledgeBasePanel())
