"""The toolpath generator's moves as Path commands.

The core gives moves in the setup frame, which is the Job's frame: [kind, u, v, h] with kind 0
rapid, 1 feed, 2 plunge, or [3, u, v, h_bottom, r_plane, q_peck, dwell] for a drill cycle.
Rapids become G0, feeds and plunges G1 with the ToolController's horizontal and vertical feed
(FreeCAD's mm/s), drill cycles G81/G82/G83 with X Y Z R (Q, P) and the vertical feed, between
G99 (each cycle ends at its R plane, as the generator plans) and G80, the words FreeCAD's own
Drilling writes, so every post reads them alike.
"""
import math

RAPID, FEED, PLUNGE, DRILL = 0, 1, 2, 3


def drill_command(move, feed):
    """(name, parameters) of one drill cycle: G83 with a peck, else G82 with a dwell, else G81."""
    _, u, v, bottom, r_plane = move[:5]
    peck = move[5] if len(move) > 5 else 0.0
    dwell = move[6] if len(move) > 6 else 0.0
    params = {"X": u, "Y": v, "Z": bottom, "R": r_plane, "F": feed}
    if peck and peck > 0:
        params["Q"] = peck
        return "G83", params
    if dwell and dwell > 0:
        params["P"] = dwell
        return "G82", params
    return "G81", params


def commands_of(moves, horiz_feed, vert_feed, label=None):
    """Path commands (name, parameters) of a move list; feeds in mm/s."""
    out = [("({})".format(label), {})] if label else []
    in_cycle = False
    for m in moves:
        kind = int(m[0])
        if kind == DRILL:
            if not in_cycle:
                out.append(("G99", {}))  # each cycle retracts to its R plane
                in_cycle = True
            out.append(drill_command(m, vert_feed))
            continue
        if in_cycle:
            out.append(("G80", {}))
            in_cycle = False
        xyz = {"X": m[1], "Y": m[2], "Z": m[3]}
        if kind == RAPID:
            out.append(("G0", xyz))
        elif kind == FEED:
            xyz["F"] = horiz_feed
            out.append(("G1", xyz))
        elif kind == PLUNGE:
            xyz["F"] = vert_feed
            out.append(("G1", xyz))
        else:
            raise ValueError("unknown move kind {} in the toolpath".format(kind))
    if in_cycle:
        out.append(("G80", {}))
    return out


def estimate_seconds(moves, horiz_feed, vert_feed, horiz_rapid=0.0, vert_rapid=0.0):
    """Machining time of a move list (feeds and rapids in mm/s; a rapid rate of 0 leaves rapids
    out, as FreeCAD does when the ToolController has none). A drill cycle feeds from R to the
    bottom and rapids back."""
    seconds = 0.0
    pos = None
    for m in moves:
        kind = int(m[0])
        if kind == DRILL:
            depth = abs(m[4] - m[3])
            seconds += depth / vert_feed if vert_feed > 0 else 0.0
            seconds += depth / vert_rapid if vert_rapid > 0 else 0.0
            pos = (m[1], m[2], m[4])
            continue
        p = (m[1], m[2], m[3])
        if pos is not None:
            horiz = math.hypot(p[0] - pos[0], p[1] - pos[1])
            vert = abs(p[2] - pos[2])
            if kind == RAPID:
                if horiz > 0 and horiz_rapid > 0:
                    seconds += horiz / horiz_rapid
                if vert > 0 and vert_rapid > 0:
                    seconds += vert / vert_rapid
            else:
                rate = vert_feed if kind == PLUNGE else horiz_feed
                if rate > 0:
                    seconds += math.hypot(horiz, vert) / rate
        pos = p
    return seconds


def clock_text(seconds):
    """HH:MM:SS, the form of a Path operation's CycleTime."""
    s = int(round(seconds))
    return "{:02d}:{:02d}:{:02d}".format(s // 3600, (s // 60) % 60, s % 60)
