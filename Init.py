# AeroNC App-side start-up, run by FreeCAD (also under freecadcmd) for every Mod folder.
# Nothing to register: the document objects live in the `aeronc` package, which FreeCAD
# imports by module path when a document holding them is opened. Keep this file empty of
# imports so that start-up stays fast.
