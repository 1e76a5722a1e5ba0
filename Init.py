# AeroNC App-side start-up, run by FreeCAD (also under freecadcmd) for every Mod folder.
# Nothing to register: the document objects live in the `aeronc` package, which FreeCAD
# imports by module path when a document holding them is opened. Keep the imports here few
# and cheap so that start-up stays fast.

# The 5-axis posts are listed in the Job's post-processor dropdown only from a folder on
# FreeCAD's post search path: keep their thin *_post.py files in the user macro folder.
try:
    from aeronc.post.install import install_posts
    install_posts()
except Exception as e:  # never stop FreeCAD from starting
    import FreeCAD
    FreeCAD.Console.PrintWarning("AeroNC: the 5-axis posts were not installed: {}\n".format(e))
