"""Makers: the one place that creates, remakes and removes AeroNC's document objects, each
change one undo step, the view providers given through the registered attacher.

  machining_features   the Machining Features tree of a part (recognition)
  datum_holes          photo-hole sets, measured-hole sets, compensated drilling
"""
from aeronc.makers.machining_features import (create_machining_features, face_links,  # noqa: F401
                                              remove_machining_features, update_machining_features)
