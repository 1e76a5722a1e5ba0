"""One undo step per document change, and nothing left behind when the change fails."""


def in_transaction(doc, title, work):
    """Run work() as one undo step; on failure undo everything it did and re-raise.

    abortTransaction only undoes when the document records undo (freecadcmd documents do
    not by default), so objects work() created are also removed by hand.
    """
    before = set(o.Name for o in doc.Objects)
    doc.openTransaction(title)
    try:
        out = work()
        doc.commitTransaction()
        return out
    except BaseException:
        doc.abortTransaction()
        for name in [o.Name for o in doc.Objects if o.Name not in before]:
            if doc.getObject(name) is not None:
                doc.removeObject(name)
        raise
