"""The fused copy of a part of several bodies, added to the document as one undo step; the
original object is kept (hidden)."""
import FreeCAD

from aeronc.impeller.body_fusion import fuse_bodies
from aeronc.objects.transaction import in_transaction


def add_fused_part(obj, progress=None):
    """A new Part::Feature holding obj's bodies fused into one solid (body_fusion); obj is
    hidden, not changed. Returns (new object, summary text)."""
    doc = obj.Document
    solid, summary = fuse_bodies(obj.Shape, obj.Label, progress)

    def work():
        fused = doc.addObject("Part::Feature", "FusedPart")
        fused.Label = "{} (fused)".format(obj.Label)
        fused.Shape = solid
        obj.Visibility = False
        doc.recompute()
        return fused

    fused = in_transaction(doc, "Fuse bodies", work)
    FreeCAD.Console.PrintMessage("AeroNC: {}: {}\n".format(obj.Label, summary))
    return fused, summary
