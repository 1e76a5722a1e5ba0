-- Migration of a knowledge base from schema version 4 to 5.
--
-- The large machine: a 5-axis gantry with a two-axis (AC fork) head, for the parts whose setups
-- leave the table machines' travel (aircraft skins, spars, frames; docs/knowledge-base.md). The
-- main job chooses the smallest machine whose travel holds every setup (docs/machine-choice.md). A user's
-- machine of that name is kept as it is.

-- A file of the oldest layouts may have no machine table: it gets the current one.
CREATE TABLE IF NOT EXISTS machine (
    id              INTEGER PRIMARY KEY,
    name            TEXT NOT NULL UNIQUE,
    type            TEXT NOT NULL,                -- 'vertical mill', '5-axis', ...
    kinematics      TEXT NOT NULL,                -- 'XYZ', 'AC table-table', ...
    travel_x        REAL NOT NULL CHECK (travel_x > 0),
    travel_y        REAL NOT NULL CHECK (travel_y > 0),
    travel_z        REAL NOT NULL CHECK (travel_z > 0),
    a_min           REAL,                         -- NULL: no such rotary axis
    a_max           REAL,
    c_min           REAL,
    c_max           REAL,
    max_spindle_rpm REAL NOT NULL CHECK (max_spindle_rpm > 0),
    power_kw        REAL NOT NULL CHECK (power_kw > 0),
    max_feed_mm_min REAL NOT NULL CHECK (max_feed_mm_min > 0),
    max_force_n     REAL NOT NULL CHECK (max_force_n > 0),
    efficiency      REAL NOT NULL CHECK (efficiency > 0 AND efficiency <= 1),
    tool_change_s   REAL NOT NULL CHECK (tool_change_s >= 0),
    CHECK (a_min IS NULL OR a_max IS NULL OR a_min <= a_max),
    CHECK (c_min IS NULL OR c_max IS NULL OR c_min <= c_max)
);
INSERT OR IGNORE INTO machine (name, type, kinematics, travel_x, travel_y, travel_z, a_min, a_max, c_min, c_max,
                               max_spindle_rpm, power_kw, max_feed_mm_min, max_force_n, efficiency, tool_change_s)
VALUES
  ('AC-GANTRY', '5-axis gantry', 'AC head-head (fork head on a gantry), Sinumerik 840D',
   4000, 2500, 1500, -110, 110, -360, 360, 24000, 60, 40000, 12000, 0.85, 12);
