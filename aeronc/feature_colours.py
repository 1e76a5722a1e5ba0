"""One colour per face role of the recognition result, shared by the 3D view and pictures."""

# (r, g, b) per face role of the core's result.
ROLE_COLOURS = {
    "floor": (0.20, 0.40, 0.95),             # blue
    "counterbore_floor": (0.50, 0.35, 0.90),   # violet
    "wall": (0.85, 0.70, 0.45),              # tan: not FreeCAD's selection green
    "island_wall": (0.95, 0.85, 0.15),       # yellow
    "hole_wall": (0.90, 0.15, 0.15),         # red
    "countersink": (0.95, 0.45, 0.45),
    "floor_fillet": (0.15, 0.85, 0.90),      # cyan
    "corner_fillet": (0.55, 0.95, 0.95),
    "chamfer": (0.90, 0.20, 0.85),           # magenta
    "open_bevel": (0.95, 0.55, 0.10),        # orange
    "closed_bevel": (0.70, 0.35, 0.05),
    "rib_top": (0.75, 0.80, 0.90),
    "top": (0.80, 0.80, 0.80),
    "stock": (0.55, 0.55, 0.55),             # grey
    "unclaimed": (0.10, 0.10, 0.10),         # near black: stands out as "not recognised"
}
# Impeller roles (aeronc.impeller.recognition.face_role_names).
ROLE_COLOURS.update({
    "main_blade": (0.25, 0.45, 0.95),        # blue
    "splitter_blade": (0.55, 0.35, 0.85),    # violet
    "root_fillet": (0.15, 0.85, 0.90),       # cyan
    "shroud": (0.95, 0.55, 0.10),            # orange
    "hub": (0.95, 0.85, 0.15),               # yellow
    "bore": (0.90, 0.15, 0.15),              # red
    "plane": (0.80, 0.80, 0.80),
    "turned": (0.60, 0.55, 0.70),
})
UNKNOWN_ROLE = (1.0, 1.0, 1.0)
