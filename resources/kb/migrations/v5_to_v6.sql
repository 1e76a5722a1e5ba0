-- Migration of a knowledge base from schema version 5 to 6.
--
-- The shop crib (docs/tool-crib.md): a neck on the tool table (a necked tool cuts down to its
-- reach, one layer of its flutes at a time), chamfer and corner-rounding mills, small, necked and
-- long-reach end mills and ball mills, cutting data for end mills below 2 mm, and the long-reach
-- reductions of a_p and f_z. A user's rows are kept (INSERT OR IGNORE). The tools are added only
-- to a file that still carries the shipped crib (one of its end mills): a user's own crib, made
-- without them, stays the user's.

-- A file of the oldest layouts may have no materials or cutting data: it gets the current tables.
CREATE TABLE IF NOT EXISTS workpiece_material (
    id          INTEGER PRIMARY KEY,
    name        TEXT NOT NULL UNIQUE,
    family      TEXT NOT NULL,                    -- 'aluminium', 'titanium', 'steel', ...
    hardness_hb REAL CHECK (hardness_hb IS NULL OR hardness_hb > 0)
);
CREATE TABLE IF NOT EXISTS cutting_condition (
    id                 INTEGER PRIMARY KEY,
    workpiece_material TEXT NOT NULL REFERENCES workpiece_material (name) ON UPDATE CASCADE,
    tool_material      TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    operation          TEXT NOT NULL,             -- 'roughing', 'finishing', 'drilling', ...
    d_min              REAL CHECK (d_min IS NULL OR d_min >= 0),  -- tool diameter range [d_min, d_max);
    d_max              REAL CHECK (d_max IS NULL OR d_max > 0),   -- NULL: open on that side
    vc_m_min           REAL NOT NULL CHECK (vc_m_min > 0),
    fz_mm              REAL NOT NULL CHECK (fz_mm > 0),
    ap_mm              REAL NOT NULL CHECK (ap_mm > 0),
    ae_ratio           REAL NOT NULL CHECK (ae_ratio > 0 AND ae_ratio <= 1),  -- a_e / tool diameter
    c_f                REAL NOT NULL,
    x_f                REAL NOT NULL,
    y_f                REAL NOT NULL,
    u_f                REAL NOT NULL,
    q_f                REAL NOT NULL,
    w_f                REAL NOT NULL,
    k_fc               REAL NOT NULL DEFAULT 1,
    taylor_c           REAL NOT NULL CHECK (taylor_c > 0),
    taylor_m           REAL NOT NULL CHECK (taylor_m > 0),
    CHECK (d_min IS NULL OR d_max IS NULL OR d_min < d_max),
    UNIQUE (workpiece_material, tool_material, operation, d_min)
);

ALTER TABLE tool ADD COLUMN neck_diameter REAL CHECK (neck_diameter IS NULL OR (neck_diameter > 0 AND neck_diameter < diameter));

CREATE TABLE IF NOT EXISTS edge_tool (
    id             TEXT PRIMARY KEY NOT NULL,
    kind           TEXT NOT NULL CHECK (kind IN ('chamfer', 'corner_rounding')),
    tool_material  TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    diameter       REAL NOT NULL CHECK (diameter > 0),
    tip_diameter   REAL NOT NULL CHECK (tip_diameter >= 0 AND tip_diameter < diameter),
    included_angle REAL CHECK (included_angle IS NULL OR (included_angle > 0 AND included_angle < 180)),
    profile_radius REAL CHECK (profile_radius IS NULL OR profile_radius > 0),
    flutes         INTEGER NOT NULL CHECK (flutes > 0),
    reach          REAL NOT NULL CHECK (reach > 0),
    cost           REAL CHECK (cost IS NULL OR cost >= 0),
    CHECK ((kind = 'chamfer' AND included_angle IS NOT NULL AND profile_radius IS NULL) OR
           (kind = 'corner_rounding' AND profile_radius IS NOT NULL AND included_angle IS NULL AND
            2 * profile_radius <= diameter - tip_diameter + 1e-9))
);

INSERT OR IGNORE INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost, neck_diameter)
  SELECT * FROM (VALUES
  ('EM-F0.5',    'flat', 'carbide', 0.5,   0,  2,  1.0,  38,   3,  28, 0.46),
  ('EM-F0.8',    'flat', 'carbide', 0.8,   0,  2,  1.6,  38,   4,  28, 0.75),
  ('EM-F1',      'flat', 'carbide',   1,   0,  2,  2.0,  38,   5,  24, 0.95),
  ('EM-F1x10',   'flat', 'carbide',   1,   0,  2,  2.0,  50,  10,  32, 0.95),
  ('EM-F1.5',    'flat', 'carbide', 1.5,   0,  2,  3.0,  38,   8,  24, 1.4),
  ('EM-F2x12',   'flat', 'carbide',   2,   0,  2,  3.0,  50,  12,  30, 1.9),
  ('EM-F2.5',    'flat', 'carbide', 2.5,   0,  2,  4.0,  50,  12,  26, 2.4),
  ('EM-F3x15',   'flat', 'carbide',   3,   0,  3,  4.5,  57,  15,  34, 2.85),
  ('EM-B1R0.2',  'bull', 'carbide',   1, 0.2,  2,  2.0,  38,   5,  28, 0.95),
  ('EM-B2R0.5',  'bull', 'carbide',   2, 0.5,  2,  3.0,  50,  10,  30, 1.9),
  ('EM-BALL0.5', 'ball', 'carbide', 0.5, 0.25, 2,  0.8,  38,   3,  32, 0.46),
  ('EM-BALL1',   'ball', 'carbide',   1, 0.5,  2,  1.5,  38,   5,  26, 0.95),
  ('EM-BALL3',   'ball', 'carbide',   3, 1.5,  2,  5.0,  57,  15,  30, 2.85),
  ('EM-F4x20',   'flat', 'carbide',   4,   0,  3,  6.0,  75,  20,  45, 3.8),
  ('EM-F6x30',   'flat', 'carbide',   6,   0,  3,  9.0,  90,  30,  58, 5.7),
  ('EM-F8x40',   'flat', 'carbide',   8,   0,  3, 12.0, 100,  40,  78, 7.6),
  ('EM-F10x50',  'flat', 'carbide',  10,   0,  3, 15.0, 110,  50, 105, 9.5),
  ('EM-F12x60',  'flat', 'carbide',  12,   0,  3, 18.0, 125,  60, 135, 11.5),
  ('EM-B6R0.5x30','bull','carbide',   6, 0.5,  4,  9.0,  90,  30,  62, 5.7),
  ('EM-B6R1x30', 'bull', 'carbide',   6,   1,  4,  9.0,  90,  30,  62, 5.7),
  ('EM-B8R1x40', 'bull', 'carbide',   8,   1,  4, 12.0, 100,  40,  84, 7.6),
  ('EM-B10R1x50','bull', 'carbide',  10,   1,  4, 15.0, 110,  50, 112, 9.5),
  ('EM-B10R2x50','bull', 'carbide',  10,   2,  4, 15.0, 110,  50, 112, 9.5),
  ('EM-B12R2x60','bull', 'carbide',  12,   2,  4, 18.0, 125,  60, 145, 11.5),
  ('EM-B12R3x60','bull', 'carbide',  12,   3,  4, 18.0, 125,  60, 145, 11.5),
  ('EM-BALL16',  'ball', 'carbide',  16,   8,  2, 32.0,  92,  45,  95, NULL),
  ('EM-BALL4x20','ball', 'carbide',   4,   2,  2,  6.0,  75,  20,  48, 3.8),
  ('EM-BALL6x30','ball', 'carbide',   6,   3,  2,  9.0,  90,  30,  60, 5.7),
  ('EM-BALL8x40','ball', 'carbide',   8,   4,  2, 12.0, 100,  40,  80, 7.6),
  ('EM-BALL10x50','ball','carbide',  10,   5,  2, 15.0, 110,  50, 108, 9.5))
  WHERE EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide')
    AND EXISTS (SELECT 1 FROM tool WHERE id IN ('EM-F6', 'EM-F10', 'EM-B10R1', 'EM-BALL6'));

INSERT OR IGNORE INTO edge_tool (id, kind, tool_material, diameter, tip_diameter, included_angle, profile_radius, flutes, reach, cost)
  SELECT * FROM (VALUES
  ('CM-90-D6',   'chamfer',         'carbide',  6, 0.5,   90, NULL, 3, 20, 32),
  ('CM-90-D10',  'chamfer',         'carbide', 10, 1.0,   90, NULL, 4, 25, 45),
  ('CM-90-D16',  'chamfer',         'carbide', 16, 2.0,   90, NULL, 4, 30, 70),
  ('CM-45-D6',   'chamfer',         'carbide',  6, 0.5,   45, NULL, 3, 20, 34),
  ('CM-45-D10',  'chamfer',         'carbide', 10, 1.0,   45, NULL, 4, 25, 48),
  ('CR-R1',      'corner_rounding', 'carbide',  6, 4.0, NULL,    1, 4, 20, 38),
  ('CR-R2',      'corner_rounding', 'carbide',  8, 4.0, NULL,    2, 4, 22, 44),
  ('CR-R3',      'corner_rounding', 'carbide', 10, 4.0, NULL,    3, 4, 25, 52),
  ('CR-R4',      'corner_rounding', 'carbide', 12, 4.0, NULL,    4, 4, 28, 60),
  ('CR-R5',      'corner_rounding', 'carbide', 16, 6.0, NULL,    5, 4, 32, 72))
  WHERE EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide')
    AND EXISTS (SELECT 1 FROM tool WHERE id IN ('EM-F6', 'EM-F10', 'EM-B10R1', 'EM-BALL6'));

-- Small-tool data for the materials the file knows, beside the crib it adds them with.
INSERT OR IGNORE INTO cutting_condition (workpiece_material, tool_material, operation, vc_m_min, fz_mm, ap_mm, ae_ratio,
                               c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m, d_min, d_max)
  SELECT * FROM (VALUES
  ('7050-T7451', 'carbide', 'roughing',  250, 0.005, 0.10, 0.30, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 0, 1),
  ('7050-T7451', 'carbide', 'roughing',  350, 0.015, 0.40, 0.40, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 1, 2),
  ('7050-T7451', 'carbide', 'finishing', 300, 0.004, 0.10, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 0, 1),
  ('7050-T7451', 'carbide', 'finishing', 450, 0.012, 0.40, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 1, 2),
  ('2024-T351',  'carbide', 'roughing',  230, 0.005, 0.10, 0.30, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 0, 1),
  ('2024-T351',  'carbide', 'roughing',  320, 0.015, 0.40, 0.40, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 1, 2),
  ('2024-T351',  'carbide', 'finishing', 280, 0.004, 0.10, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 0, 1),
  ('2024-T351',  'carbide', 'finishing', 420, 0.012, 0.40, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 1, 2),
  ('Ti-6Al-4V',  'carbide', 'roughing',   35, 0.003, 0.05, 0.20, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, 0, 1),
  ('Ti-6Al-4V',  'carbide', 'roughing',   45, 0.008, 0.20, 0.25, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, 1, 2),
  ('Ti-6Al-4V',  'carbide', 'finishing',  45, 0.003, 0.05, 0.05, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, 0, 1),
  ('Ti-6Al-4V',  'carbide', 'finishing',  55, 0.006, 0.20, 0.08, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, 1, 2),
  ('45 steel',   'carbide', 'roughing',   80, 0.005, 0.10, 0.30, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, 0, 1),
  ('45 steel',   'carbide', 'roughing',  100, 0.012, 0.30, 0.40, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, 1, 2),
  ('45 steel',   'carbide', 'finishing', 100, 0.004, 0.10, 0.10, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, 0, 1),
  ('45 steel',   'carbide', 'finishing', 130, 0.010, 0.30, 0.10, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, 1, 2))
  WHERE column1 IN (SELECT name FROM workpiece_material)
    AND EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide')
    AND EXISTS (SELECT 1 FROM tool WHERE id IN ('EM-F6', 'EM-F10', 'EM-B10R1', 'EM-BALL6'));

INSERT OR IGNORE INTO threshold (name, value, description) VALUES
  ('long_reach_ratio',     4.00, 'a necked tool reaching more than this many diameters gets reduced cutting data'),
  ('long_reach_ap_factor', 0.50, 'a_p of a long-reach tool as a fraction of the handbook value'),
  ('long_reach_fz_factor', 0.80, 'f_z of a long-reach tool as a fraction of the handbook value'),
  ('allowance_max_ratio',  0.25, 'a unit leaves at most this times its tool diameter as radial allowance');
