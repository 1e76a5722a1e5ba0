"""AeroNC_EditKnowledgeBase: browse and edit the machining knowledge base."""
import FreeCADGui

from aeronc.commands.base import Command


class EditKnowledgeBase(Command):
    ICON = "KnowledgeBase"
    MENU_TEXT = "Knowledge base..."
    TOOLTIP = ("Browse and edit the machining knowledge base: tools, cutting data, machines, "
               "materials and rules; import and export FreeCAD tool libraries")
    NEEDS_DOCUMENT = False

    def run(self, target):
        from aeronc.panels.knowledge_base_panel import KnowledgeBasePanel
        FreeCADGui.Control.showDialog(KnowledgeBasePanel())
