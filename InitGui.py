# AeroNC GUI start-up. FreeCAD exec()s this file inside a function, so keep it to one
# import and one call; everything else lives in the `aeronc` package. Importing the hook
# module is cheap: recognition, the C++ core and the Path modules load on first use.
try:
    import aeronc.commands.path_workbench
    aeronc.commands.path_workbench.install()
except Exception as e:  # never break FreeCAD's start-up because of the addon
    import FreeCAD
    FreeCAD.Console.PrintError("AeroNC: GUI start-up failed: {}\n".format(e))
