-- Migration of a knowledge base from schema version 9 to 10.
--
-- Long-reach end mills D16-D32 reaching 80-160 mm (docs/tool-crib.md), flat and bull-nose: the
-- deep open regions of the real and NIST parts (60-130 mm deep from the side setups) take no
-- end mill of the crib, whose longest reach was 60 mm. A cutter on a relieved neck or a slim
-- shrink-fit extension no wider than the cutter within its reach; flutes 1.5 x D, so the chain's
-- layers stay within the flutes, and the long-reach reductions of a_p and f_z apply past 4 x D.
-- A user's rows are kept (INSERT OR IGNORE), and the tools are added only to a file that still
-- carries the shipped crib (one of its end mills): a user's own crib stays the user's.
INSERT OR IGNORE INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost, neck_diameter)
  SELECT * FROM (VALUES
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
  ('EM-B32R4x160','bull', 'carbide', 32,   4, 4, 48.0, 225, 160, 455, 30.0))
  WHERE EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide')
    AND EXISTS (SELECT 1 FROM tool WHERE id IN ('EM-F6', 'EM-F10', 'EM-B10R1', 'EM-BALL6'));
