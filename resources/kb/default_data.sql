-- AeroNC default knowledge base data, for schema version 2 (resources/kb/schema.sql).
--
-- SOURCE AND ASSUMPTIONS. Except where marked, these values are ASSUMED handbook-style
-- defaults, chosen to be plausible for shop use and for the tests; they are not
-- measurements and not vendor data. Check them against your own machines, tool
-- catalogue and cutting-data handbook before trusting a computed feed or speed.
--   * XA5032 limits (n_max 1800 r/min, 7.5 kW, v_f,max 980 mm/min, F 15000 N, efficiency 0.75)
--     are the figures of the impeller paper's worked example (DESIGN.md section 3);
--     its axis travels are typical catalogue values (assumed).
--   * The 5-axis AC table-table machine is a generic example (assumed values).
--   * Tool lengths follow the usual short/standard end-mill series (assumed), costs are
--     indicative list prices (assumed).
--   * Cutting data (v_c, f_z, a_p, a_e) are mid-range handbook-style values per material
--     family (assumed). Force coefficients follow the form of the milling-force formula
--     in DESIGN.md section 3: steel x carbide uses the classic face-milling handbook
--     set C_F=825, x_F=1.0, y_F=0.75, u_F=1.1, q_F=1.3, w_F=0.2; the other rows are
--     scaled from it (aluminium about 0.25x, titanium about 1.1x) and are assumptions.
--     Taylor constants (v_c * T^m = C) are assumed typical values per pair.

PRAGMA foreign_keys = ON;

-- Machines -----------------------------------------------------------------------------
INSERT INTO machine (name, type, kinematics, travel_x, travel_y, travel_z, a_min, a_max, c_min, c_max,
                     max_spindle_rpm, power_kw, max_feed_mm_min, max_force_n, efficiency, tool_change_s)
VALUES
  ('AC-5AX', '5-axis machining centre', 'AC table-table (cradle), Sinumerik 840D',
   650, 650, 500, -120, 120, -360, 360, 18000, 25, 30000, 6000, 0.85, 6),
  ('XA5032', 'vertical knee mill', 'XYZ',
   700, 255, 350, NULL, NULL, NULL, NULL, 1800, 7.5, 980, 15000, 0.75, 60);

-- Materials ----------------------------------------------------------------------------
INSERT INTO workpiece_material (name, family, hardness_hb) VALUES
  ('7050-T7451', 'aluminium', 140),
  ('2024-T351',  'aluminium', 120),
  ('Ti-6Al-4V',  'titanium',  334),
  ('45 steel',   'steel',     200);

INSERT INTO tool_material (name, kind) VALUES
  ('HSS',     'HSS'),
  ('carbide', 'carbide');

-- Tools (mm) ---------------------------------------------------------------------------
-- Ball end mills store their corner radius as half the diameter.
INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost) VALUES
  ('EM-F2',     'flat',  'carbide',   2,   0,   2,   6,  50,  10,  18),
  ('EM-F3',     'flat',  'carbide',   3,   0,   3,   8,  50,  12,  18),
  ('EM-F4',     'flat',  'carbide',   4,   0,   3,  11,  57,  16,  20),
  ('EM-F6',     'flat',  'carbide',   6,   0,   3,  13,  57,  20,  24),
  ('EM-F8',     'flat',  'carbide',   8,   0,   3,  19,  63,  25,  32),
  ('EM-F10',    'flat',  'carbide',  10,   0,   3,  22,  72,  30,  42),
  ('EM-F12',    'flat',  'carbide',  12,   0,   3,  26,  83,  36,  55),
  ('EM-F16',    'flat',  'carbide',  16,   0,   3,  32,  92,  45,  85),
  ('EM-F20',    'flat',  'carbide',  20,   0,   3,  38, 104,  55, 120),
  ('EM-F25',    'flat',  'HSS',      25,   0,   4,  45, 121,  65,  70),
  ('EM-F32',    'flat',  'HSS',      32,   0,   4,  53, 133,  75,  95),
  ('EM-B8R1',   'bull',  'carbide',   8,   1,   4,  19,  63,  25,  38),
  ('EM-B10R1',  'bull',  'carbide',  10,   1,   4,  22,  72,  30,  48),
  ('EM-B12R2',  'bull',  'carbide',  12,   2,   4,  26,  83,  36,  62),
  ('EM-B16R2',  'bull',  'carbide',  16,   2,   4,  32,  92,  45,  95),
  ('EM-B20R3',  'bull',  'carbide',  20,   3,   4,  38, 104,  55, 135),
  ('EM-B25R4',  'bull',  'carbide',  25,   4,   4,  45, 121,  65, 190),
  ('EM-B32R4',  'bull',  'carbide',  32,   4,   4,  53, 133,  75, 260),
  ('EM-BALL2',  'ball',  'carbide',   2,   1,   2,   4,  50,  10,  22),
  ('EM-BALL4',  'ball',  'carbide',   4,   2,   2,   8,  57,  16,  26),
  ('EM-BALL6',  'ball',  'carbide',   6,   3,   2,  12,  57,  20,  30),
  ('EM-BALL8',  'ball',  'carbide',   8,   4,   2,  16,  63,  25,  40),
  ('EM-BALL10', 'ball',  'carbide',  10,   5,   2,  20,  72,  30,  52),
  ('EM-BALL12', 'ball',  'carbide',  12,   6,   2,  24,  83,  36,  68),
  ('DR-5',      'drill', 'HSS',       5,   0,   2,  52,  86,  60,   4),
  ('DR-6.8',    'drill', 'HSS',     6.8,   0,   2,  69, 109,  78,   6),
  ('DR-8.5',    'drill', 'carbide', 8.5,   0,   2,  43, 103,  55,  60),
  ('DR-10.2',   'drill', 'carbide',10.2,   0,   2,  47, 118,  60,  75),
  ('FM-125',    'face',  'carbide', 125,   1,   4,   6,  63,  63, 450);

-- Cutting conditions -------------------------------------------------------------------
-- ae_ratio is a_e / tool diameter; drilling rows use a_p = hole-depth step (peck), ae_ratio 1.
-- Rows with a diameter range [d_min, d_max) take precedence over a row without one. Handbook
-- tables raise f_z and a_p with the diameter (a stiffer tool carries a thicker chip); without
-- that every diameter would take the same time per layer and tool groups would always merge.
INSERT INTO cutting_condition (workpiece_material, tool_material, operation, vc_m_min, fz_mm, ap_mm, ae_ratio,
                               c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m, d_min, d_max) VALUES
  -- 7050-T7451
  ('7050-T7451', 'carbide', 'roughing', 600, 0.04, 1.5, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, NULL, 6),
  ('7050-T7451', 'carbide', 'roughing', 600, 0.06, 3.0, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 6, 10),
  ('7050-T7451', 'carbide', 'roughing', 600, 0.08, 4.0, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 10, 16),
  ('7050-T7451', 'carbide', 'roughing', 600, 0.10, 5.0, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 16, 25),
  ('7050-T7451', 'carbide', 'roughing', 600, 0.12, 6.0, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 25, NULL),
  ('7050-T7451', 'carbide', 'finishing', 800, 0.06, 1.0, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, NULL, NULL),
  ('7050-T7451', 'carbide', 'drilling',  150, 0.08, 5.0, 1.00, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, NULL, NULL),
  ('7050-T7451', 'HSS',     'roughing',  150, 0.08, 3.0, 0.50,  17, 0.86,0.72, 1.0, 0.86,0.0, 1.0,  400, 0.15, NULL, NULL),
  ('7050-T7451', 'HSS',     'finishing', 200, 0.05, 0.8, 0.10,  17, 0.86,0.72, 1.0, 0.86,0.0, 1.0,  400, 0.15, NULL, NULL),
  ('7050-T7451', 'HSS',     'drilling',   60, 0.10, 5.0, 1.00,  17, 0.86,0.72, 1.0, 0.86,0.0, 1.0,  400, 0.15, NULL, NULL),
  -- 2024-T351
  ('2024-T351', 'carbide', 'roughing', 550, 0.04, 1.5, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, NULL, 6),
  ('2024-T351', 'carbide', 'roughing', 550, 0.06, 3.0, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 6, 10),
  ('2024-T351', 'carbide', 'roughing', 550, 0.08, 4.0, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 10, 16),
  ('2024-T351', 'carbide', 'roughing', 550, 0.10, 5.0, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 16, 25),
  ('2024-T351', 'carbide', 'roughing', 550, 0.12, 6.0, 0.50, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 25, NULL),
  ('2024-T351',  'carbide', 'finishing', 750, 0.06, 1.0, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, NULL, NULL),
  ('2024-T351',  'carbide', 'drilling',  140, 0.08, 5.0, 1.00, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, NULL, NULL),
  ('2024-T351',  'HSS',     'roughing',  140, 0.08, 3.0, 0.50,  17, 0.86,0.72, 1.0, 0.86,0.0, 1.0,  380, 0.15, NULL, NULL),
  ('2024-T351',  'HSS',     'finishing', 180, 0.05, 0.8, 0.10,  17, 0.86,0.72, 1.0, 0.86,0.0, 1.0,  380, 0.15, NULL, NULL),
  ('2024-T351',  'HSS',     'drilling',   55, 0.10, 5.0, 1.00,  17, 0.86,0.72, 1.0, 0.86,0.0, 1.0,  380, 0.15, NULL, NULL),
  -- Ti-6Al-4V
  ('Ti-6Al-4V',  'carbide', 'roughing',   50, 0.06, 2.0, 0.30, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, NULL, NULL),
  ('Ti-6Al-4V',  'carbide', 'finishing',  70, 0.04, 0.5, 0.08, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, NULL, NULL),
  ('Ti-6Al-4V',  'carbide', 'drilling',   30, 0.05, 2.0, 1.00, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, NULL, NULL),
  ('Ti-6Al-4V',  'HSS',     'roughing',   15, 0.04, 1.5, 0.30,  75, 0.86,0.72, 1.0, 0.86,0.0, 1.0,   25, 0.10, NULL, NULL),
  ('Ti-6Al-4V',  'HSS',     'finishing',  20, 0.03, 0.4, 0.08,  75, 0.86,0.72, 1.0, 0.86,0.0, 1.0,   25, 0.10, NULL, NULL),
  ('Ti-6Al-4V',  'HSS',     'drilling',   10, 0.04, 2.0, 1.00,  75, 0.86,0.72, 1.0, 0.86,0.0, 1.0,   25, 0.10, NULL, NULL),
  -- 45 steel
  ('45 steel',   'carbide', 'roughing',  120, 0.15, 3.0, 0.50, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, NULL, NULL),
  ('45 steel',   'carbide', 'finishing', 160, 0.08, 0.5, 0.10, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, NULL, NULL),
  ('45 steel',   'carbide', 'drilling',   70, 0.10, 3.0, 1.00, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, NULL, NULL),
  ('45 steel',   'HSS',     'roughing',   25, 0.10, 3.0, 0.50,  68.2, 0.86,0.72, 1.0, 0.86,0.0, 1.0,   70, 0.125, NULL, NULL),
  ('45 steel',   'HSS',     'finishing',  35, 0.06, 0.5, 0.10,  68.2, 0.86,0.72, 1.0, 0.86,0.0, 1.0,   70, 0.125, NULL, NULL),
  ('45 steel',   'HSS',     'drilling',   20, 0.12, 3.0, 1.00,  68.2, 0.86,0.72, 1.0, 0.86,0.0, 1.0,   70, 0.125, NULL, NULL);

-- Rule knowledge -----------------------------------------------------------------------
INSERT INTO threshold (name, value, description) VALUES
  ('eta_min',        0.85, 'least machinable ratio A_m/A for a roughing tool'),
  ('mu_merge',       0.70, 'merge two tool groups onto the smaller tool when mu exceeds this'),
  ('layer_delta_mm', 0.50, 'delta: a last layer thinner than this is folded into the one above'),
  ('ra_max_um',      3.20, 'default roughness limit R_a for finishing'),
  ('plunge_feed_ratio', 0.30, 'vertical (plunge and ramp) feed as a fraction of the horizontal feed');

-- Step codes (DESIGN.md section 3): r rough, w webs, c corners, ss/sf semi-finish walls/flanges,
-- fs/ff finish walls/flanges, t cut off.
INSERT INTO process_template (name, steps) VALUES
  ('panel: corners before semi-finishing', 'r w c ss sf fs ff'),
  ('panel: corners after semi-finishing',  'r w ss sf c fs ff');

INSERT INTO sequencing_rule (priority, rule) VALUES
  (1, 'process with a step that must come earlier first; otherwise larger tool first'),
  (2, 'outer contour (m = -1) before inner shape (m = 0)'),
  (3, 'of two topologically related units, higher Z first'),
  (4, 'feature type order: slot-on-wall (2), pocket (1), bevel face or flange (4), rib (3)'),
  (5, 'otherwise low distortion: by symmetry, from the centre out, by user choice');
