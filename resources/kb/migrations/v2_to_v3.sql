-- Migration of a knowledge base from schema version 2 to 3.
--
-- Process templates per part family with their steps (existence, feature types, tool role,
-- allowances) and a chosen step order; sequencing rules as keys with parameters. The version-2
-- templates (a name and a list of step codes) become integral-panel templates whose steps take
-- the shipped integral-panel step of the same code; the version-2 rule texts that are not the
-- shipped ones are kept as disabled notes.

ALTER TABLE process_template RENAME TO process_template_v2;
ALTER TABLE sequencing_rule RENAME TO sequencing_rule_v2;
CREATE TABLE part_family (
    name           TEXT PRIMARY KEY NOT NULL,     -- 'integral_panel', 'frame_beam', 'rib'
    required_steps TEXT NOT NULL DEFAULT '',      -- step codes, space separated
    description    TEXT
);
CREATE TABLE step_order (
    name        TEXT PRIMARY KEY NOT NULL,
    codes       TEXT NOT NULL,                    -- step codes, first to last, space separated
    description TEXT
);
CREATE TABLE process_template (
    name        TEXT PRIMARY KEY NOT NULL,
    family      TEXT NOT NULL REFERENCES part_family (name) ON UPDATE CASCADE,
    step_order  TEXT NOT NULL REFERENCES step_order (name) ON UPDATE CASCADE,
    description TEXT
);
CREATE TABLE template_step (
    id               INTEGER PRIMARY KEY,
    template         TEXT NOT NULL REFERENCES process_template (name) ON UPDATE CASCADE ON DELETE CASCADE,
    position         INTEGER NOT NULL CHECK (position > 0),
    code             TEXT NOT NULL CHECK (code IN ('r', 'w', 'c', 'ss', 'sf', 'fs', 'ff', 't', 'd', 'h')),
    existence        TEXT NOT NULL CHECK (existence IN ('must', 'may', 'must_not')),
    features         TEXT NOT NULL DEFAULT '',    -- feature types, space separated
    tool_role        TEXT CHECK (tool_role IS NULL OR tool_role IN ('roughing', 'finishing', 'corner', 'drilling')),
    radial_allowance REAL NOT NULL DEFAULT 0 CHECK (radial_allowance >= 0),
    axial_allowance  REAL NOT NULL DEFAULT 0 CHECK (axial_allowance >= 0),
    description      TEXT,
    UNIQUE (template, position),
    UNIQUE (template, code)
);
CREATE TABLE sequencing_rule (
    id          INTEGER PRIMARY KEY,
    template    TEXT NOT NULL REFERENCES process_template (name) ON UPDATE CASCADE ON DELETE CASCADE,
    priority    INTEGER NOT NULL,
    rule        TEXT NOT NULL,
    parameters  TEXT NOT NULL DEFAULT '',
    enabled     INTEGER NOT NULL DEFAULT 1 CHECK (enabled IN (0, 1)),
    description TEXT,
    UNIQUE (template, priority)
);
INSERT INTO part_family (name, required_steps, description) VALUES
  ('integral_panel', 'r w fs',    'aircraft integral panel: pockets on one or both faces, ribs, flanges, holes'),
  ('frame_beam',     'r w ss fs', 'frame or beam: deep pockets, thin webs and flanges'),
  ('rib',            'r fs',      'rib: a thin web with pockets on both faces');
INSERT INTO step_order (name, codes, description) VALUES
  ('standard',     'r w c ss sf fs ff d h t', 'WS_r < WS_w < WS_c < WS_ss < WS_sf < WS_fs < WS_ff, then holes and cut-off'),
  ('corners_late', 'r w ss sf c fs ff d h t', 'WS_r < WS_w < WS_ss < WS_sf < WS_c < WS_fs < WS_ff, then holes and cut-off');
CREATE TEMP TABLE shipped_step (template TEXT, position INTEGER, code TEXT, existence TEXT, features TEXT,
                                tool_role TEXT, radial_allowance REAL, axial_allowance REAL, description TEXT);
INSERT INTO shipped_step (template, position, code, existence, features, tool_role, radial_allowance,
                          axial_allowance, description) VALUES
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
INSERT INTO step_order (name, codes, description)
    SELECT 'v2: ' || name, trim(steps), 'the step order of the version-2 template ' || quote(name) FROM process_template_v2;
INSERT INTO process_template (name, family, step_order, description)
    SELECT name, 'integral_panel', 'v2: ' || name, 'from the version-2 template ' || quote(steps) FROM process_template_v2;
WITH RECURSIVE split (template, pos, code, rest) AS (
    SELECT name, 0, '', trim(steps) || ' ' FROM process_template_v2
    UNION ALL
    SELECT template, pos + 1, substr(rest, 1, instr(rest, ' ') - 1), ltrim(substr(rest, instr(rest, ' ') + 1))
    FROM split WHERE rest <> '')
INSERT INTO template_step (template, position, code, existence, features, tool_role, radial_allowance,
                           axial_allowance, description)
    SELECT s.template, s.pos, s.code, coalesce(d.existence, 'may'), coalesce(d.features, ''), d.tool_role,
           coalesce(d.radial_allowance, 0), coalesce(d.axial_allowance, 0), d.description
    FROM split s LEFT JOIN shipped_step d ON d.template = 'integral_panel' AND d.code = s.code
    WHERE s.pos > 0;
INSERT OR IGNORE INTO process_template (name, family, step_order, description) VALUES
  ('integral_panel', 'integral_panel', 'standard',     'integral panel: rough, webs, corners, semi-finish and finish the walls, holes'),
  ('frame_beam',     'frame_beam',     'corners_late', 'frame or beam: corners after semi-finishing the walls and flanges'),
  ('rib',            'rib',            'standard',     'rib: no flanges');
INSERT INTO template_step (template, position, code, existence, features, tool_role, radial_allowance,
                           axial_allowance, description)
    SELECT template, position, code, existence, features, tool_role, radial_allowance, axial_allowance, description
    FROM shipped_step d WHERE NOT EXISTS (SELECT 1 FROM template_step t WHERE t.template = d.template);
INSERT INTO sequencing_rule (template, priority, rule, parameters, enabled, description)
    SELECT 'integral_panel', 100 + priority, 'note', '', 0, rule FROM sequencing_rule_v2
    WHERE rule NOT IN ('process with a step that must come earlier first; otherwise larger tool first',
                       'outer contour (m = -1) before inner shape (m = 0)',
                       'of two topologically related units, higher Z first',
                       'feature type order: slot-on-wall (2), pocket (1), bevel face or flange (4), rib (3)',
                       'otherwise low distortion: by symmetry, from the centre out, by user choice');
CREATE TEMP TABLE needs_rules AS
    SELECT name FROM process_template p
    WHERE NOT EXISTS (SELECT 1 FROM sequencing_rule s WHERE s.template = p.name AND s.enabled = 1);
INSERT INTO sequencing_rule (template, priority, rule, parameters, description)
  SELECT name, 1, 'process_order', 'order=larger_tool_first', 'rule 1: a process with a step that must come earlier first; otherwise the larger tool first' FROM needs_rules
  UNION ALL SELECT name, 2, 'outer_before_inner', 'outer=open_pocket,flange', 'rule 2: the outer contour (m = -1) before the inner shape (m = 0)' FROM needs_rules
  UNION ALL SELECT name, 3, 'higher_z_first', '', 'rule 3: of two topologically related units, the higher Z first' FROM needs_rules
  UNION ALL SELECT name, 4, 'feature_type_order', 'order=open_pocket,closed_pocket,flange,opening,hole', 'rule 4: by feature type (slot on a wall, pocket, flange, rib)' FROM needs_rules
  UNION ALL SELECT name, 5, 'centre_out', '', 'rule 5: otherwise for low distortion, symmetric, from the centre out' FROM needs_rules;
DROP TABLE temp.needs_rules;
DROP TABLE temp.shipped_step;
DROP TABLE process_template_v2;
DROP TABLE sequencing_rule_v2;
INSERT OR IGNORE INTO threshold (name, value, description) VALUES
    ('breakthrough_mm', 1.00, 'openings and through holes are cut this far past the part'),
    ('rest_min_area_mm2', 0.50, 'corners get rest machining when the roughing tool leaves more than this area');
