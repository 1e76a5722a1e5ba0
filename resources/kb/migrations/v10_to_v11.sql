-- Migration of a knowledge base from schema version 10 to 11.
--
-- Three catalogue tools the NIST parts ask for (docs/tool-crib.md):
--   * EM-F4x40, a flat end mill D4 on an extra-long neck reaching 40 mm (10 x D): a 5.5 mm
--     flat-bottomed hole 35 mm deep (FTC-10) is milled by helical interpolation only with a
--     cutter below 4.4 mm reaching 35 mm, and the longest D4 reached 32 mm.
--   * CM-90-D25 and CM-90-D32, 90 degree chamfer mills covering chamfers and countersinks up to
--     10.8 and 13.8 mm wide: the countersink of CTC-05 (9.5 mm wide) and the 12.7 mm wide
--     45 degree chamfers of CTC-03 were wider than the D16's cone (5.8 mm).
-- A user's rows are kept (INSERT OR IGNORE), and the tools are added only to a file that still
-- carries the shipped crib (one of its end mills; for the chamfer mills, one of its chamfer
-- mills): a user's own crib stays the user's.
INSERT OR IGNORE INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost, neck_diameter)
  SELECT * FROM (VALUES
  ('EM-F4x40',   'flat', 'carbide',   4,   0,  3,  6.0, 100,  40,  58, 3.8))
  WHERE EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide')
    AND EXISTS (SELECT 1 FROM tool WHERE id IN ('EM-F6', 'EM-F10', 'EM-B10R1', 'EM-BALL6'));
INSERT OR IGNORE INTO edge_tool (id, kind, tool_material, diameter, tip_diameter, included_angle, profile_radius, flutes, reach, cost)
  SELECT * FROM (VALUES
  ('CM-90-D25',  'chamfer',         'carbide', 25, 3.0,   90, NULL, 4, 35, 110),
  ('CM-90-D32',  'chamfer',         'carbide', 32, 4.0,   90, NULL, 4, 40, 150))
  WHERE EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide')
    AND EXISTS (SELECT 1 FROM edge_tool WHERE id IN ('CM-90-D6', 'CM-90-D10', 'CM-90-D16'));
