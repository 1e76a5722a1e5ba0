-- Migration of a knowledge base from schema version 8 to 9.
--
-- Micro flat end mills D0.2 and D0.3 on a relieved neck (docs/tool-crib.md), for lettering and
-- engraving whose strokes are 0.25-0.4 mm wide (the real milled parts' lettering, 0.5 mm deep):
-- the D0.5 of version 6 fits in none of them. Flutes 3 x D, so one layer cuts such lettering.
-- A user's rows are kept (INSERT OR IGNORE), and the tools are added only to a file that still
-- carries the shipped crib (one of its end mills): a user's own crib stays the user's.
INSERT OR IGNORE INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost, neck_diameter)
  SELECT * FROM (VALUES
  ('EM-F0.2', 'flat', 'carbide', 0.2, 0, 2, 0.6, 38, 1.0, 32, 0.18),
  ('EM-F0.3', 'flat', 'carbide', 0.3, 0, 2, 0.9, 38, 1.5, 30, 0.28))
  WHERE EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide')
    AND EXISTS (SELECT 1 FROM tool WHERE id IN ('EM-F6', 'EM-F10', 'EM-B10R1', 'EM-BALL6'));
