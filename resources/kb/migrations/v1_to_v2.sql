-- Migration of a knowledge base from schema version 1 to 2.
--
-- Tool type 'other' (tools kept for FreeCAD only), cutting data by tool diameter range, the
-- FreeCAD tool-bridge tables, and the plunge-feed ratio. SQLite cannot alter a CHECK or UNIQUE
-- constraint, so tool and cutting_condition are rebuilt.

CREATE TABLE tool_v2 (
    id             TEXT PRIMARY KEY NOT NULL,
    type           TEXT NOT NULL CHECK (type IN ('flat', 'bull', 'ball', 'drill', 'face', 'other')),
    tool_material  TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    diameter       REAL NOT NULL CHECK (diameter > 0),
    corner_radius  REAL NOT NULL DEFAULT 0 CHECK (corner_radius >= 0 AND corner_radius <= diameter / 2.0),
    flutes         INTEGER NOT NULL CHECK (flutes > 0),
    flute_length   REAL NOT NULL CHECK (flute_length > 0),
    overall_length REAL CHECK (overall_length IS NULL OR overall_length >= reach),
    reach          REAL NOT NULL CHECK (reach >= flute_length),
    cost           REAL CHECK (cost IS NULL OR cost >= 0)
);
INSERT INTO tool_v2 (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost)
    SELECT id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost FROM tool;
DROP TABLE tool;
ALTER TABLE tool_v2 RENAME TO tool;
CREATE TABLE cutting_condition_v2 (
    id                 INTEGER PRIMARY KEY,
    workpiece_material TEXT NOT NULL REFERENCES workpiece_material (name) ON UPDATE CASCADE,
    tool_material      TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    operation          TEXT NOT NULL,
    d_min              REAL CHECK (d_min IS NULL OR d_min >= 0),
    d_max              REAL CHECK (d_max IS NULL OR d_max > 0),
    vc_m_min           REAL NOT NULL CHECK (vc_m_min > 0),
    fz_mm              REAL NOT NULL CHECK (fz_mm > 0),
    ap_mm              REAL NOT NULL CHECK (ap_mm > 0),
    ae_ratio           REAL NOT NULL CHECK (ae_ratio > 0 AND ae_ratio <= 1),
    c_f REAL NOT NULL, x_f REAL NOT NULL, y_f REAL NOT NULL, u_f REAL NOT NULL, q_f REAL NOT NULL, w_f REAL NOT NULL,
    k_fc               REAL NOT NULL DEFAULT 1,
    taylor_c           REAL NOT NULL CHECK (taylor_c > 0),
    taylor_m           REAL NOT NULL CHECK (taylor_m > 0),
    CHECK (d_min IS NULL OR d_max IS NULL OR d_min < d_max),
    UNIQUE (workpiece_material, tool_material, operation, d_min)
);
INSERT INTO cutting_condition_v2 (id, workpiece_material, tool_material, operation, vc_m_min, fz_mm, ap_mm, ae_ratio,
                                  c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m)
    SELECT id, workpiece_material, tool_material, operation, vc_m_min, fz_mm, ap_mm, ae_ratio,
           c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m FROM cutting_condition;
DROP TABLE cutting_condition;
ALTER TABLE cutting_condition_v2 RENAME TO cutting_condition;
CREATE TABLE freecad_tool_bit (
    tool_id   TEXT PRIMARY KEY NOT NULL REFERENCES tool (id) ON UPDATE CASCADE ON DELETE CASCADE,
    file_name TEXT NOT NULL,
    document  TEXT NOT NULL
);
CREATE TABLE freecad_tool_library (
    name     TEXT PRIMARY KEY NOT NULL,
    version  INTEGER NOT NULL DEFAULT 1,
    document TEXT
);
CREATE TABLE freecad_tool_library_entry (
    library TEXT NOT NULL REFERENCES freecad_tool_library (name) ON UPDATE CASCADE ON DELETE CASCADE,
    nr      INTEGER NOT NULL CHECK (nr >= 0),
    tool_id TEXT NOT NULL REFERENCES tool (id) ON UPDATE CASCADE ON DELETE CASCADE,
    PRIMARY KEY (library, nr)
);
INSERT OR IGNORE INTO threshold (name, value, description) VALUES
    ('plunge_feed_ratio', 0.30, 'vertical (plunge and ramp) feed as a fraction of the horizontal feed');
