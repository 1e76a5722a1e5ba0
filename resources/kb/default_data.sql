-- AeroNC default knowledge base data, for schema version 11 (resources/kb/schema.sql).
--
-- SOURCE AND ASSUMPTIONS. Except where marked, these values are ASSUMED handbook-style
-- defaults, chosen to be plausible for shop use and for the tests; they are not
-- measurements and not vendor data. Check them against your own machines, tool
-- catalogue and cutting-data handbook before trusting a computed feed or speed.
--   * XA5032 limits (n_max 1800 r/min, 7.5 kW, v_f,max 980 mm/min, F 15000 N, efficiency 0.75)
--     are the figures of the impeller paper's worked example (DESIGN.md section 3);
--     its axis travels are typical catalogue values (assumed).
--   * The 5-axis AC table-table machines are generic examples (assumed values): AC-5AX, and
--     AC-5AX-L, the same kinematics with a larger table and travel for larger parts.
--   * AC-GANTRY is a generic 5-axis gantry with an AC fork head (assumed values), of the size
--     aircraft skins, spars and frames are cut on: 4000 x 2500 x 1500 mm travel, 24000 r/min,
--     60 kW; the main job takes it for parts whose setups leave the table machines' travel.
--   * Tool lengths follow the usual short/standard end-mill series (assumed), costs are
--     indicative list prices (assumed).
--   * The shop crib of schema version 6 (small, long-reach and necked end mills, ball mills,
--     chamfer and corner-rounding mills, small-tool cutting data, long-reach reductions) follows
--     the ranges of the usual carbide catalogues; docs/tool-crib.md gives them. The same rows are
--     seeded by the migration from schema version 5 (migrations/v5_to_v6.sql).
--   * The jobber drill series follows the diameter steps and the flute and overall lengths
--     of DIN 338 / ISO 235 jobber drills up to 20 mm (22 mm: jobber length extrapolated,
--     assumed); reach (the length out of the chuck) is assumed as the flute length plus a
--     quarter of the shank. The sizes are the usual ones plus the tap-drill sizes
--     (M4 3.3, M5 4.2, M6 5, M8 6.8, M10 8.5, M12 10.2, M16 14, M20 17.5) and the ISO 273
--     clearance sizes (M3 3.4, M4 4.5, M5 5.5, M6 6.4 / 6.6, M8 9, M10 11, M12 13.5,
--     M16 17.5, M20 22).
--   * Process templates, allowances and sequencing rules are assumed shop practice for
--     aluminium structural parts, written after the patent's and the panel paper's rules.
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
   650, 650, 550, -120, 120, -360, 360, 18000, 25, 30000, 6000, 0.85, 6),
  ('XA5032', 'vertical knee mill', 'XYZ',
   700, 255, 350, NULL, NULL, NULL, NULL, 1800, 7.5, 980, 15000, 0.75, 60),
  ('AC-5AX-L', '5-axis machining centre', 'AC table-table (cradle), Sinumerik 840D',
   1000, 1100, 800, -120, 120, -360, 360, 18000, 35, 40000, 8000, 0.85, 8),
  ('AC-GANTRY', '5-axis gantry', 'AC head-head (fork head on a gantry), Sinumerik 840D',
   4000, 2500, 1500, -110, 110, -360, 360, 24000, 60, 40000, 12000, 0.85, 12);

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

-- The shop crib (docs/tool-crib.md): small, necked and long-reach end mills, ball mills.
-- neck_diameter: the relieved neck behind the flutes; such a tool cuts down to its reach.
INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost, neck_diameter) VALUES
-- Small end mills (carbide, 2 flutes): a neck a little below the cutter behind short flutes,
-- on a 3 or 4 mm shank (micro end mill series: flutes 1.5-2 x D, neck 5-10 x D).
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
-- Long-reach (necked) end mills, flat and bull-nose: flutes 1.5 x D, reach 5 x D.
  ('EM-F4x20',   'flat', 'carbide',   4,   0,  3,  6.0,  75,  20,  45, 3.8),
  ('EM-F6x30',   'flat', 'carbide',   6,   0,  3,  9.0,  90,  30,  58, 5.7),
  ('EM-F8x40',   'flat', 'carbide',   8,   0,  3, 12.0, 100,  40,  78, 7.6),
  ('EM-F10x50',  'flat', 'carbide',  10,   0,  3, 15.0, 110,  50, 105, 9.5),
  ('EM-F12x60',  'flat', 'carbide',  12,   0,  3, 18.0, 125,  60, 135, 11.5),
-- Extra-long neck (8 x D), flat: small deep holes and slots (schema version 7).
  ('EM-F1.5x12', 'flat', 'carbide', 1.5,   0,  2,  2.5,  50,  12,  34, 1.4),
  ('EM-F2x16',   'flat', 'carbide',   2,   0,  2,  3.0,  57,  16,  36, 1.9),
  ('EM-F3x24',   'flat', 'carbide',   3,   0,  3,  4.5,  75,  24,  42, 2.85),
  ('EM-F4x32',   'flat', 'carbide',   4,   0,  3,  6.0,  90,  32,  52, 3.8),
  ('EM-F6x48',   'flat', 'carbide',   6,   0,  3,  9.0, 110,  48,  70, 5.7),
  ('EM-B6R0.5x30','bull','carbide',   6, 0.5,  4,  9.0,  90,  30,  62, 5.7),
  ('EM-B6R1x30', 'bull', 'carbide',   6,   1,  4,  9.0,  90,  30,  62, 5.7),
  ('EM-B8R1x40', 'bull', 'carbide',   8,   1,  4, 12.0, 100,  40,  84, 7.6),
  ('EM-B10R1x50','bull', 'carbide',  10,   1,  4, 15.0, 110,  50, 112, 9.5),
  ('EM-B10R2x50','bull', 'carbide',  10,   2,  4, 15.0, 110,  50, 112, 9.5),
  ('EM-B12R2x60','bull', 'carbide',  12,   2,  4, 18.0, 125,  60, 145, 11.5),
  ('EM-B12R3x60','bull', 'carbide',  12,   3,  4, 18.0, 125,  60, 145, 11.5),
-- Ball end mills for 3-D faces: a larger standard one and long-reach ones.
  ('EM-BALL16',  'ball', 'carbide',  16,   8,  2, 32.0,  92,  45,  95, NULL),
  ('EM-BALL4x20','ball', 'carbide',   4,   2,  2,  6.0,  75,  20,  48, 3.8),
  ('EM-BALL6x30','ball', 'carbide',   6,   3,  2,  9.0,  90,  30,  60, 5.7),
  ('EM-BALL8x40','ball', 'carbide',   8,   4,  2, 12.0, 100,  40,  80, 7.6),
  ('EM-BALL10x50','ball','carbide',  10,   5,  2, 15.0, 110,  50, 108, 9.5),
-- A small long-reach ball for deep narrow channels (schema version 8, migrations/v7_to_v8.sql):
-- an impeller's channels of 4-5 mm width 26 mm deep.
  ('EM-BALL3x30','ball', 'carbide',   3, 1.5,  2,  4.5,  75,  30,  56, 2.85),
-- Micro flat end mills for lettering and engraving 0.25-0.4 mm wide (schema version 9).
  ('EM-F0.2',    'flat', 'carbide', 0.2,   0,  2,  0.6,  38, 1.0,  32, 0.18),
  ('EM-F0.3',    'flat', 'carbide', 0.3,   0,  2,  0.9,  38, 1.5,  30, 0.28),
-- Long-reach end mills D16-D32 for deep open regions (schema version 10, migrations/v9_to_v10.sql):
-- a cutter on a relieved neck or a slim shrink-fit extension no wider than the cutter within its
-- reach, 5-6.5 x D; flutes 1.5 x D. Past 4 x D the long-reach reductions of a_p and f_z apply.
  ('EM-F16x80',   'flat', 'carbide', 16,   0, 3, 24.0, 130,  80, 180, 15.0),
  ('EM-F16x100',  'flat', 'carbide', 16,   0, 3, 24.0, 150, 100, 205, 15.0),
  ('EM-F20x100',  'flat', 'carbide', 20,   0, 3, 30.0, 155, 100, 230, 19.0),
  ('EM-F20x130',  'flat', 'carbide', 20,   0, 3, 30.0, 185, 130, 265, 19.0),
  ('EM-F25x125',  'flat', 'carbide', 25,   0, 3, 38.0, 185, 125, 300, 24.0),
  ('EM-F25x160',  'flat', 'carbide', 25,   0, 3, 38.0, 220, 160, 345, 24.0),
  ('EM-F32x160',  'flat', 'carbide', 32,   0, 4, 48.0, 225, 160, 420, 30.0),
  ('EM-B16R2x80', 'bull', 'carbide', 16,   2, 4, 24.0, 130,  80, 195, 15.0),
  ('EM-B20R3x100','bull', 'carbide', 20,   3, 4, 30.0, 155, 100, 250, 19.0),
  ('EM-B25R4x125','bull', 'carbide', 25,   4, 4, 38.0, 185, 125, 325, 24.0),
  ('EM-B32R4x160','bull', 'carbide', 32,   4, 4, 48.0, 225, 160, 455, 30.0),
-- Extra-long neck 10 x D, flat (schema version 11, migrations/v10_to_v11.sql): small flat-bottomed
-- holes 35 mm deep milled by helical interpolation (a 5.5 mm hole needs a cutter below 4.4 mm).
  ('EM-F4x40',   'flat', 'carbide',   4,   0,  3,  6.0, 100,  40,  58, 3.8);

-- Chamfer and corner-rounding mills (docs/tool-crib.md).
INSERT INTO edge_tool (id, kind, tool_material, diameter, tip_diameter, included_angle, profile_radius, flutes, reach, cost) VALUES
  ('CM-90-D6',   'chamfer',         'carbide',  6, 0.5,   90, NULL, 3, 20, 32),
  ('CM-90-D10',  'chamfer',         'carbide', 10, 1.0,   90, NULL, 4, 25, 45),
  ('CM-90-D16',  'chamfer',         'carbide', 16, 2.0,   90, NULL, 4, 30, 70),
  ('CM-45-D6',   'chamfer',         'carbide',  6, 0.5,   45, NULL, 3, 20, 34),
  ('CM-45-D10',  'chamfer',         'carbide', 10, 1.0,   45, NULL, 4, 25, 48),
  ('CR-R1',      'corner_rounding', 'carbide',  6, 4.0, NULL,    1, 4, 20, 38),
  ('CR-R2',      'corner_rounding', 'carbide',  8, 4.0, NULL,    2, 4, 22, 44),
  ('CR-R3',      'corner_rounding', 'carbide', 10, 4.0, NULL,    3, 4, 25, 52),
  ('CR-R4',      'corner_rounding', 'carbide', 12, 4.0, NULL,    4, 4, 28, 60),
  ('CR-R5',      'corner_rounding', 'carbide', 16, 6.0, NULL,    5, 4, 32, 72),
-- Large 90 degree chamfer mills (schema version 11, migrations/v10_to_v11.sql; last, as a
-- migrated file holds them): chamfers and countersinks up to 10.8 and 13.8 mm wide (tip radius
-- + 0.2 mm clearance + width <= radius; toolselect/EdgeTools.h).
  ('CM-90-D25',  'chamfer',         'carbide', 25, 3.0,   90, NULL, 4, 35, 110),
  ('CM-90-D32',  'chamfer',         'carbide', 32, 4.0,   90, NULL, 4, 40, 150);

-- Jobber drills (DIN 338 / ISO 235 lengths), HSS. 5, 6.8, 8.5 and 10.2 mm are above.
INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost) VALUES
  ('DR-1',   'drill', 'HSS',     1,   0,   2,  12,  34,  18,   2),
  ('DR-1.5', 'drill', 'HSS',   1.5,   0,   2,  18,  40,  24,   3),
  ('DR-2',   'drill', 'HSS',     2,   0,   2,  24,  49,  30,   3),
  ('DR-2.5', 'drill', 'HSS',   2.5,   0,   2,  30,  57,  37,   3),
  ('DR-3',   'drill', 'HSS',     3,   0,   2,  33,  61,  40,   4),
  ('DR-3.3', 'drill', 'HSS',   3.3,   0,   2,  36,  65,  43,   4),
  ('DR-3.4', 'drill', 'HSS',   3.4,   0,   2,  36,  65,  43,   5),
  ('DR-3.5', 'drill', 'HSS',   3.5,   0,   2,  39,  70,  47,   5),
  ('DR-4',   'drill', 'HSS',     4,   0,   2,  43,  75,  51,   6),
  ('DR-4.2', 'drill', 'HSS',   4.2,   0,   2,  43,  75,  51,   6),
  ('DR-4.5', 'drill', 'HSS',   4.5,   0,   2,  47,  80,  55,   7),
  ('DR-5.5', 'drill', 'HSS',   5.5,   0,   2,  57,  93,  66,   9),
  ('DR-6',   'drill', 'HSS',     6,   0,   2,  57,  93,  66,  10),
  ('DR-6.4', 'drill', 'HSS',   6.4,   0,   2,  63, 101,  73,  11),
  ('DR-6.6', 'drill', 'HSS',   6.6,   0,   2,  63, 101,  73,  12),
  ('DR-7',   'drill', 'HSS',     7,   0,   2,  69, 109,  79,  13),
  ('DR-8',   'drill', 'HSS',     8,   0,   2,  75, 117,  85,  16),
  ('DR-9',   'drill', 'HSS',     9,   0,   2,  81, 125,  92,  20),
  ('DR-10',  'drill', 'HSS',    10,   0,   2,  87, 133,  99,  24),
  ('DR-11',  'drill', 'HSS',    11,   0,   2,  94, 142, 106,  29),
  ('DR-12',  'drill', 'HSS',    12,   0,   2, 101, 151, 113,  34),
  ('DR-13',  'drill', 'HSS',    13,   0,   2, 101, 151, 113,  40),
  ('DR-13.5', 'drill', 'HSS',  13.5,   0,   2, 108, 160, 121,  43),
  ('DR-14',  'drill', 'HSS',    14,   0,   2, 108, 160, 121,  46),
  ('DR-16',  'drill', 'HSS',    16,   0,   2, 120, 178, 134,  60),
  ('DR-17.5', 'drill', 'HSS',  17.5,   0,   2, 130, 191, 145,  71),
  ('DR-18',  'drill', 'HSS',    18,   0,   2, 130, 191, 145,  75),
  ('DR-20',  'drill', 'HSS',    20,   0,   2, 140, 205, 156,  92),
  ('DR-22',  'drill', 'HSS',    22,   0,   2, 150, 218, 167, 111);

-- Inch jobber drills for parts drawn in inches (ASME): letter K (0.281 in) and number 17
-- (0.173 in), the clearance sizes of the NIST test parts' holes. Lengths as the metric jobber
-- drills of the nearest size (assumed).
INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost) VALUES
  ('DR-K',   'drill', 'HSS', 7.1374,  0,   2,  69, 109,  79,  14),
  ('DR-17',  'drill', 'HSS', 4.3942,  0,   2,  47,  80,  55,   8);

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

-- Small end mills (below 2 mm; docs/tool-crib.md): catalogue data for micro end mills, a much
-- lower f_z and a_p than the rows above; v_c is what the spindle's speed limit leaves anyway.
INSERT INTO cutting_condition (workpiece_material, tool_material, operation, vc_m_min, fz_mm, ap_mm, ae_ratio,
                               c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m, d_min, d_max) VALUES
  -- 7050-T7451
  ('7050-T7451', 'carbide', 'roughing',  250, 0.005, 0.10, 0.30, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 0, 1),
  ('7050-T7451', 'carbide', 'roughing',  350, 0.015, 0.40, 0.40, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 1, 2),
  ('7050-T7451', 'carbide', 'finishing', 300, 0.004, 0.10, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 0, 1),
  ('7050-T7451', 'carbide', 'finishing', 450, 0.012, 0.40, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1500, 0.30, 1, 2),
  -- 2024-T351
  ('2024-T351',  'carbide', 'roughing',  230, 0.005, 0.10, 0.30, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 0, 1),
  ('2024-T351',  'carbide', 'roughing',  320, 0.015, 0.40, 0.40, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 1, 2),
  ('2024-T351',  'carbide', 'finishing', 280, 0.004, 0.10, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 0, 1),
  ('2024-T351',  'carbide', 'finishing', 420, 0.012, 0.40, 0.10, 206, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0, 1400, 0.30, 1, 2),
  -- Ti-6Al-4V
  ('Ti-6Al-4V',  'carbide', 'roughing',   35, 0.003, 0.05, 0.20, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, 0, 1),
  ('Ti-6Al-4V',  'carbide', 'roughing',   45, 0.008, 0.20, 0.25, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, 1, 2),
  ('Ti-6Al-4V',  'carbide', 'finishing',  45, 0.003, 0.05, 0.05, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, 0, 1),
  ('Ti-6Al-4V',  'carbide', 'finishing',  55, 0.006, 0.20, 0.08, 908, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  120, 0.20, 1, 2),
  -- 45 steel
  ('45 steel',   'carbide', 'roughing',   80, 0.005, 0.10, 0.30, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, 0, 1),
  ('45 steel',   'carbide', 'roughing',  100, 0.012, 0.30, 0.40, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, 1, 2),
  ('45 steel',   'carbide', 'finishing', 100, 0.004, 0.10, 0.10, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, 0, 1),
  ('45 steel',   'carbide', 'finishing', 130, 0.010, 0.30, 0.10, 825, 1.0, 0.75, 1.1, 1.3, 0.2, 1.0,  300, 0.25, 1, 2);

-- Rule knowledge -----------------------------------------------------------------------
INSERT INTO threshold (name, value, description) VALUES
  ('eta_min',        0.85, 'least machinable ratio A_m/A for a roughing tool'),
  ('mu_merge',       0.70, 'merge two tool groups onto the smaller tool when mu exceeds this'),
  ('layer_delta_mm', 0.50, 'delta: a last layer thinner than this is folded into the one above'),
  ('ra_max_um',      3.20, 'default roughness limit R_a for finishing'),
  ('plunge_feed_ratio', 0.30, 'vertical (plunge and ramp) feed as a fraction of the horizontal feed'),
  ('breakthrough_mm',   1.00, 'openings and through holes are cut this far past the part'),
  ('rest_min_area_mm2', 0.50, 'corners get rest machining when the roughing tool leaves more than this area'),
  ('long_reach_ratio',     4.00, 'a necked tool reaching more than this many diameters gets reduced cutting data'),
  ('long_reach_ap_factor', 0.50, 'a_p of a long-reach tool as a fraction of the handbook value'),
  ('long_reach_fz_factor', 0.80, 'f_z of a long-reach tool as a fraction of the handbook value'),
  ('allowance_max_ratio',  0.25, 'a unit leaves at most this times its tool diameter as radial allowance');

-- Process planning (docs/machining-chain.md) --------------------------------------------
-- The same rows are seeded by the migration from schema version 2 (migrations/v2_to_v3.sql).
INSERT INTO part_family (name, required_steps, description) VALUES
  ('integral_panel', 'r w fs',    'aircraft integral panel: pockets on one or both faces, ribs, flanges, holes'),
  ('frame_beam',     'r w ss fs', 'frame or beam: deep pockets, thin webs and flanges'),
  ('rib',            'r fs',      'rib: a thin web with pockets on both faces');

INSERT INTO step_order (name, codes, description) VALUES
  ('standard',     'r w c ss sf fs ff d h t', 'WS_r < WS_w < WS_c < WS_ss < WS_sf < WS_fs < WS_ff, then holes and cut-off'),
  ('corners_late', 'r w ss sf c fs ff d h t', 'WS_r < WS_w < WS_ss < WS_sf < WS_c < WS_fs < WS_ff, then holes and cut-off');

INSERT INTO process_template (name, family, step_order, description) VALUES
  ('integral_panel', 'integral_panel', 'standard',     'integral panel: rough, webs, corners, semi-finish and finish the walls, holes'),
  ('frame_beam',     'frame_beam',     'corners_late', 'frame or beam: corners after semi-finishing the walls and flanges'),
  ('rib',            'rib',            'standard',     'rib: no flanges');

INSERT INTO template_step (template, position, code, existence, features, tool_role, radial_allowance, axial_allowance, description) VALUES
  ('integral_panel', 1, 'r',  'must',     'closed_pocket open_pocket flange opening', 'roughing',  1.0, 0.5, 'rough the inner and outer shape, leaving the allowances'),
  ('integral_panel', 2, 'w',  'must',     'closed_pocket open_pocket flange',         'finishing', 0.5, 0.0, 'finish the webs (floors)'),
  ('integral_panel', 3, 'c',  'may',      'closed_pocket open_pocket flange opening', 'corner',    0.5, 0.0, 'rest-machine the corners the roughing tool cannot reach'),
  ('integral_panel', 4, 'ss', 'may',      'closed_pocket open_pocket opening',        'finishing', 0.2, 0.0, 'semi-finish the walls'),
  ('integral_panel', 5, 'sf', 'may',      'flange',                                   'finishing', 0.2, 0.0, 'semi-finish the flanges'),
  ('integral_panel', 6, 'fs', 'must',     'closed_pocket open_pocket opening',        'finishing', 0.0, 0.0, 'finish the walls'),
  ('integral_panel', 7, 'ff', 'may',      'flange',                                   'finishing', 0.0, 0.0, 'finish the flanges'),
  ('integral_panel', 8, 'd',  'may',      'hole',                                     'drilling',  0.0, 0.0, 'drill the holes a drill fits'),
  ('integral_panel', 9, 'h',  'may',      'hole',                                     'finishing', 0.0, 0.0, 'mill the other holes by helical interpolation'),
  ('frame_beam',     1, 'r',  'must',     'closed_pocket open_pocket flange opening', 'roughing',  1.5, 0.5, 'rough the inner and outer shape, leaving the allowances'),
  ('frame_beam',     2, 'w',  'must',     'closed_pocket open_pocket flange',         'finishing', 0.5, 0.0, 'finish the webs (floors)'),
  ('frame_beam',     3, 'ss', 'must',     'closed_pocket open_pocket opening',        'finishing', 0.3, 0.0, 'semi-finish the walls, releasing distortion'),
  ('frame_beam',     4, 'sf', 'may',      'flange',                                   'finishing', 0.3, 0.0, 'semi-finish the flanges'),
  ('frame_beam',     5, 'c',  'may',      'closed_pocket open_pocket flange opening', 'corner',    0.3, 0.0, 'rest-machine the corners the roughing tool cannot reach'),
  ('frame_beam',     6, 'fs', 'must',     'closed_pocket open_pocket opening',        'finishing', 0.0, 0.0, 'finish the walls'),
  ('frame_beam',     7, 'ff', 'may',      'flange',                                   'finishing', 0.0, 0.0, 'finish the flanges'),
  ('frame_beam',     8, 'd',  'may',      'hole',                                     'drilling',  0.0, 0.0, 'drill the holes a drill fits'),
  ('frame_beam',     9, 'h',  'may',      'hole',                                     'finishing', 0.0, 0.0, 'mill the other holes by helical interpolation'),
  ('rib',            1, 'r',  'must',     'closed_pocket open_pocket opening',        'roughing',  1.0, 0.5, 'rough the inner and outer shape, leaving the allowances'),
  ('rib',            2, 'w',  'may',      'closed_pocket open_pocket',                'finishing', 0.3, 0.0, 'finish the webs (floors)'),
  ('rib',            3, 'c',  'may',      'closed_pocket open_pocket opening',        'corner',    0.3, 0.0, 'rest-machine the corners the roughing tool cannot reach'),
  ('rib',            4, 'ss', 'must_not', '',                                         NULL,        0.0, 0.0, 'a rib is too thin to semi-finish'),
  ('rib',            5, 'sf', 'must_not', '',                                         NULL,        0.0, 0.0, 'a rib has no flanges'),
  ('rib',            6, 'fs', 'must',     'closed_pocket open_pocket opening',        'finishing', 0.0, 0.0, 'finish the walls'),
  ('rib',            7, 'ff', 'must_not', '',                                         NULL,        0.0, 0.0, 'a rib has no flanges'),
  ('rib',            8, 'd',  'may',      'hole',                                     'drilling',  0.0, 0.0, 'drill the holes a drill fits'),
  ('rib',            9, 'h',  'may',      'hole',                                     'finishing', 0.0, 0.0, 'mill the other holes by helical interpolation');

INSERT INTO sequencing_rule (template, priority, rule, parameters, description)
  SELECT name, 1, 'process_order', 'order=larger_tool_first', 'rule 1: a process with a step that must come earlier first; otherwise the larger tool first' FROM process_template
  UNION ALL SELECT name, 2, 'outer_before_inner', 'outer=open_pocket,flange', 'rule 2: the outer contour (m = -1) before the inner shape (m = 0)' FROM process_template
  UNION ALL SELECT name, 3, 'higher_z_first', '', 'rule 3: of two topologically related units, the higher Z first' FROM process_template
  UNION ALL SELECT name, 4, 'feature_type_order', 'order=open_pocket,closed_pocket,flange,opening,hole', 'rule 4: by feature type (slot on a wall, pocket, flange, rib)' FROM process_template
  UNION ALL SELECT name, 5, 'centre_out', '', 'rule 5: otherwise for low distortion, symmetric, from the centre out' FROM process_template;

-- Impeller programming (docs/impeller.md). The same rows are seeded by the migration from
-- schema version 3 (migrations/v3_to_v4.sql).
INSERT OR IGNORE INTO tapered_ball_tool (id, tool_material, tip_diameter, taper_deg, flutes, flute_length, shank_diameter, reach, cost) VALUES
  ('TB-2-1',  'carbide', 2, 1.0, 3, 16, 6, 40, 48),
  ('TB-2-3',  'carbide', 2, 3.0, 3, 16, 6, 40, 52),
  ('TB-3-2',  'carbide', 3, 2.0, 3, 20, 6, 45, 55),
  ('TB-4-1',  'carbide', 4, 1.0, 4, 20, 8, 50, 60),
  ('TB-4-2',  'carbide', 4, 2.0, 4, 25, 8, 50, 64),
  ('TB-4-3',  'carbide', 4, 3.0, 4, 25, 10, 50, 70),
  ('TB-6-1.5','carbide', 6, 1.5, 4, 30, 10, 60, 78);
INSERT OR IGNORE INTO impeller_route_step (route, position, operation, tool_rule, strategy, allowance, clearance, description) VALUES
  ('impeller', 1, 'turn',           'none',                    'outer diameter',  0.0, 0.0, 'turn the outer diameter and the faces of revolution (lathe, before the 5-axis setup)'),
  ('impeller', 2, 'face',           'face_mill',               'planes',          0.0, 0.0, 'face the planes'),
  ('impeller', 3, 'drill',          'drill_in_bore',           'through',         0.5, 0.0, 'drill the bore, leaving stock for boring'),
  ('impeller', 4, 'bore',           'end_mill_in_bore',        'helical',         0.0, 0.0, 'bore the centre hole to size'),
  ('impeller', 5, 'rough_channels', 'ball_in_channel',         'layers',          0.5, 0.5, 'rough each channel between adjacent blades in layers from the shroud down to the hub'),
  ('impeller', 6, 'finish_blades',  'tapered_ball_in_channel', 'flank',           0.0, 0.5, 'finish the blade walls, the tool axis along the rulings'),
  ('impeller', 7, 'finish_hub',     'tapered_ball_in_channel', 'interpolated',    0.0, 0.5, 'finish the hub, the tool axis interpolated between the two blades'),
  ('impeller', 8, 'finish_fillets', 'ball_in_fillet',          'along the root',  0.0, 0.2, 'finish the root fillets with a ball that fits them');
