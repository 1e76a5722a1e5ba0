-- Migration of a knowledge base from schema version 6 to 7.
--
-- The extra-long-neck series of the micro end-mill catalogues (docs/tool-crib.md): flat end mills
-- reaching 8 x D (D1.5 x 12 to D6 x 48), for the small, deep flat-bottomed holes and narrow slots
-- of the NIST test parts and of real frames (6.65 mm x 25 mm, 7.9 mm x 30.5 mm, 2.5 mm x 12 mm).
-- A user's rows are kept (INSERT OR IGNORE), and the tools are added only to a file that still
-- carries the shipped crib (one of its end mills): a user's own crib stays the user's.

INSERT OR IGNORE INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost, neck_diameter)
  SELECT * FROM (VALUES
  ('EM-F1.5x12', 'flat', 'carbide', 1.5,   0,  2,  2.5,  50,  12,  34, 1.4),
  ('EM-F2x16',   'flat', 'carbide',   2,   0,  2,  3.0,  57,  16,  36, 1.9),
  ('EM-F3x24',   'flat', 'carbide',   3,   0,  3,  4.5,  75,  24,  42, 2.85),
  ('EM-F4x32',   'flat', 'carbide',   4,   0,  3,  6.0,  90,  32,  52, 3.8),
  ('EM-F6x48',   'flat', 'carbide',   6,   0,  3,  9.0, 110,  48,  70, 5.7))
  WHERE EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide')
    AND EXISTS (SELECT 1 FROM tool WHERE id IN ('EM-F6', 'EM-F10', 'EM-B10R1', 'EM-BALL6'));
