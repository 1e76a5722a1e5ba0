-- Migration of a knowledge base from schema version 7 to 8.
--
-- A small long-reach ball end mill, D3 reaching 30 mm on a 2.85 mm neck (docs/tool-crib.md): the
-- channels of an impeller like the shared one (4.5-5 mm wide where they are deep, 26 mm deep) take
-- no other ball of the crib. A user's rows are kept (INSERT OR IGNORE); the tool is added only to a
-- file that still carries the shipped crib (its D3 ball), so a user's own crib stays theirs. Its
-- cutting data are the file's carbide data for tools below 6 mm, with the long-reach reductions
-- (thresholds long_reach_*): a neck 10 diameters long.
INSERT OR IGNORE INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost, neck_diameter)
  SELECT 'EM-BALL3x30', 'ball', 'carbide', 3, 1.5, 2, 4.5, 75, 30, 56, 2.85
  WHERE EXISTS (SELECT 1 FROM tool WHERE id = 'EM-BALL3')
    AND EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide');
