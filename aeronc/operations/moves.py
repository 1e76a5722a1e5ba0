"""The cycle time of an operation as FreeCAD shows it.

The toolpath generator's moves become the Path's G-code, and their time estimate, in the core
(cpp/include/aeronc/toolpath/PathText.h): rapids G0, feeds and plunges G1 at the
ToolController's horizontal and vertical feed, drill cycles G81/G82/G83 between G99 and G80.
"""


def clock_text(seconds):
    """HH:MM:SS, the form of a Path operation's CycleTime."""
    s = int(round(seconds))
    return "{:02d}:{:02d}:{:02d}".format(s // 3600, (s // 60) % 60, s % 60)
