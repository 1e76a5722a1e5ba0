"""AeroNC's 5-axis posts (Sinumerik 840D, LinuxCNC) and APT cutter-location files.

  orientation  how a tool axis travels on a FreeCAD Path command (U V W)
  machines     machine files (resources/machines/<name>.json)
  job          FreeCAD objects -> the sections the C++ core posts
  nc_post      export() of the NC posts, options, atomic output
  apt          APT CL files: write from FreeCAD objects, post an APT file to NC
  install      the thin *_post.py files in FreeCAD's post search folder
The per-move work (parsing, kinematics, formatting) runs in the C++ core (aeronc._core).
Imported as aeronc.post (installed in <Mod>/AeroNC/aeronc/post); runs without FreeCAD too.
"""
from aeronc.errors import PostError  # noqa: F401  (the posts' error, aeronc.post.PostError)
