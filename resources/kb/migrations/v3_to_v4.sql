-- Migration of a knowledge base from schema version 3 to 4.
--
-- Impeller programming: tapered ball end mills and the impeller rule library (route steps with
-- their tool rules), seeded with the shipped rows.

-- Tapered ball end mills for the blades and the hub of impellers: a ball tip of tip_diameter on
-- a cone of half angle taper_deg; the diameter at a height h above the tip's centre is
-- tip_diameter + 2 h tan(taper_deg).
CREATE TABLE tapered_ball_tool (
    id             TEXT PRIMARY KEY NOT NULL,
    tool_material  TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    tip_diameter   REAL NOT NULL CHECK (tip_diameter > 0),
    taper_deg      REAL NOT NULL CHECK (taper_deg > 0 AND taper_deg < 15),
    flutes         INTEGER NOT NULL CHECK (flutes > 0),
    flute_length   REAL NOT NULL CHECK (flute_length > 0),
    shank_diameter REAL NOT NULL CHECK (shank_diameter >= tip_diameter),
    reach          REAL NOT NULL CHECK (reach >= flute_length),
    cost           REAL CHECK (cost IS NULL OR cost >= 0)
);

-- The impeller rule library: a route is its steps in order. A step applies when the part has
-- the features its operation machines (planes, turned faces, a bore, blades, splitters' channels,
-- the hub, root fillets). tool_rule says how its tool is chosen from the measured dimensions:
--   face_mill                the largest face mill
--   none                     no milling tool (the step is done on the lathe)
--   drill_in_bore            the largest drill at most the bore diameter - 2 x allowance, reaching
--                            through the bore
--   end_mill_in_bore         the largest flat end mill at most 0.8 x the bore diameter, reaching
--                            through it (helical interpolation)
--   ball_in_channel          the largest ball end mill at most the minimum channel width
--                            - 2 x allowance - clearance, reaching the blade height + clearance
--   tapered_ball_in_channel  the tapered ball whose tip radius is at most the root fillet radius
--                            and whose diameter at the blade height + clearance is at most the
--                            channel width - clearance; the largest tip, then the largest taper
--   ball_in_fillet           the largest ball end mill whose radius is at most the root fillet
--                            radius, reaching the blade height + clearance
-- allowance is the stock the step leaves (mm); clearance the gap kept to the walls (mm).
CREATE TABLE impeller_route_step (
    id          INTEGER PRIMARY KEY,
    route       TEXT NOT NULL,
    position    INTEGER NOT NULL CHECK (position > 0),
    operation   TEXT NOT NULL CHECK (operation IN ('face', 'turn', 'drill', 'bore', 'rough_channels',
                                                   'finish_blades', 'finish_hub', 'finish_fillets')),
    tool_rule   TEXT NOT NULL CHECK (tool_rule IN ('face_mill', 'none', 'drill_in_bore', 'end_mill_in_bore',
                                                   'ball_in_channel', 'tapered_ball_in_channel',
                                                   'ball_in_fillet')),
    strategy    TEXT NOT NULL DEFAULT '',         -- 'layers', 'flank', 'point', 'interpolated', ...
    allowance   REAL NOT NULL DEFAULT 0 CHECK (allowance >= 0),
    clearance   REAL NOT NULL DEFAULT 0 CHECK (clearance >= 0),
    description TEXT,
    UNIQUE (route, position)
);
-- The shipped tools are carbide: added only where that tool material is (still) known.
INSERT OR IGNORE INTO tapered_ball_tool (id, tool_material, tip_diameter, taper_deg, flutes, flute_length, shank_diameter, reach, cost)
  SELECT * FROM (VALUES
  ('TB-2-1',  'carbide', 2, 1.0, 3, 16, 6, 40, 48),
  ('TB-2-3',  'carbide', 2, 3.0, 3, 16, 6, 40, 52),
  ('TB-3-2',  'carbide', 3, 2.0, 3, 20, 6, 45, 55),
  ('TB-4-1',  'carbide', 4, 1.0, 4, 20, 8, 50, 60),
  ('TB-4-2',  'carbide', 4, 2.0, 4, 25, 8, 50, 64),
  ('TB-4-3',  'carbide', 4, 3.0, 4, 25, 10, 50, 70),
  ('TB-6-1.5','carbide', 6, 1.5, 4, 30, 10, 60, 78))
  WHERE EXISTS (SELECT 1 FROM tool_material WHERE name = 'carbide');
INSERT OR IGNORE INTO impeller_route_step (route, position, operation, tool_rule, strategy, allowance, clearance, description) VALUES
  ('impeller', 1, 'turn',           'none',                    'outer diameter',  0.0, 0.0, 'turn the outer diameter and the faces of revolution (lathe, before the 5-axis setup)'),
  ('impeller', 2, 'face',           'face_mill',               'planes',          0.0, 0.0, 'face the planes'),
  ('impeller', 3, 'drill',          'drill_in_bore',           'through',         0.5, 0.0, 'drill the bore, leaving stock for boring'),
  ('impeller', 4, 'bore',           'end_mill_in_bore',        'helical',         0.0, 0.0, 'bore the centre hole to size'),
  ('impeller', 5, 'rough_channels', 'ball_in_channel',         'layers',          0.5, 0.5, 'rough each channel between adjacent blades in layers from the shroud down to the hub'),
  ('impeller', 6, 'finish_blades',  'tapered_ball_in_channel', 'flank',           0.0, 0.5, 'finish the blade walls, the tool axis along the rulings'),
  ('impeller', 7, 'finish_hub',     'tapered_ball_in_channel', 'interpolated',    0.0, 0.5, 'finish the hub, the tool axis interpolated between the two blades'),
  ('impeller', 8, 'finish_fillets', 'ball_in_fillet',          'along the root',  0.0, 0.2, 'finish the root fillets with a ball that fits them');
