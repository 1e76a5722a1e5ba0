#include <aeronc/core/Error.h>
#include <aeronc/kb/KnowledgeBase.h>

#include "Sqlite.h"
#include "ToolRow.h"

#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <utility>

namespace fs = std::filesystem;

namespace aeronc::kb {

using toolselect::Tool;
using namespace detail;

namespace {

// Wait this long for another connection's lock before reporting "locked".
constexpr int kBusyTimeoutMs = 250;

// One migration step per old version: the SQL that turns a version-N database into a
// version-(N+1) one. All steps from the file's version up run in one transaction, then
// schema_version is set to KnowledgeBase::kSchemaVersion. Steps must keep user rows.
//
// Version 0 is the layout before versioning: no schema_version table and no tool.cost
// column. The step adds both, and creates the version-1 tables a version-0 file may lack,
// seeding the two thresholds the selector needs when they are absent.
const std::map<int, const char*> kMigrations = {
    {0, R"sql(
ALTER TABLE tool ADD COLUMN cost REAL CHECK (cost IS NULL OR cost >= 0);
CREATE TABLE schema_version (version INTEGER NOT NULL);
INSERT INTO schema_version (version) VALUES (0);
CREATE TABLE IF NOT EXISTS threshold (
    name TEXT PRIMARY KEY NOT NULL, value REAL NOT NULL, description TEXT);
INSERT OR IGNORE INTO threshold (name, value, description) VALUES
    ('eta_min', 0.85, 'least machinable ratio A_m/A for a roughing tool'),
    ('mu_merge', 0.70, 'merge two tool groups onto the smaller tool when mu exceeds this');
CREATE TABLE IF NOT EXISTS machine (
    id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, type TEXT NOT NULL, kinematics TEXT NOT NULL,
    travel_x REAL NOT NULL CHECK (travel_x > 0), travel_y REAL NOT NULL CHECK (travel_y > 0),
    travel_z REAL NOT NULL CHECK (travel_z > 0), a_min REAL, a_max REAL, c_min REAL, c_max REAL,
    max_spindle_rpm REAL NOT NULL CHECK (max_spindle_rpm > 0), power_kw REAL NOT NULL CHECK (power_kw > 0),
    max_feed_mm_min REAL NOT NULL CHECK (max_feed_mm_min > 0), max_force_n REAL NOT NULL CHECK (max_force_n > 0),
    efficiency REAL NOT NULL CHECK (efficiency > 0 AND efficiency <= 1),
    tool_change_s REAL NOT NULL CHECK (tool_change_s >= 0));
CREATE TABLE IF NOT EXISTS workpiece_material (
    id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, family TEXT NOT NULL,
    hardness_hb REAL CHECK (hardness_hb IS NULL OR hardness_hb > 0));
CREATE TABLE IF NOT EXISTS cutting_condition (
    id INTEGER PRIMARY KEY,
    workpiece_material TEXT NOT NULL REFERENCES workpiece_material (name) ON UPDATE CASCADE,
    tool_material TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    operation TEXT NOT NULL, vc_m_min REAL NOT NULL, fz_mm REAL NOT NULL, ap_mm REAL NOT NULL,
    ae_ratio REAL NOT NULL, c_f REAL NOT NULL, x_f REAL NOT NULL, y_f REAL NOT NULL, u_f REAL NOT NULL,
    q_f REAL NOT NULL, w_f REAL NOT NULL, k_fc REAL NOT NULL DEFAULT 1, taylor_c REAL NOT NULL,
    taylor_m REAL NOT NULL, UNIQUE (workpiece_material, tool_material, operation));
CREATE TABLE IF NOT EXISTS process_template (
    id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, steps TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS sequencing_rule (
    id INTEGER PRIMARY KEY, priority INTEGER NOT NULL UNIQUE, rule TEXT NOT NULL);
)sql"},
    // Version 1 -> 2: tool type 'other' (tools kept for FreeCAD only), cutting data by tool
    // diameter range, the FreeCAD tool-bridge tables, and the plunge-feed ratio. SQLite cannot
    // alter a CHECK or UNIQUE constraint, so tool and cutting_condition are rebuilt.
    {1, R"sql(
CREATE TABLE tool_v2 (
    id             TEXT PRIMARY KEY NOT NULL,
    type           TEXT NOT NULL CHECK (type IN ('flat', 'bull', 'ball', 'drill', 'face', 'other')),
    tool_material  TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    diameter       REAL NOT NULL CHECK (diameter > 0),
    corner_radius  REAL NOT NULL DEFAULT 0 CHECK (corner_radius >= 0 AND corner_radius <= diameter / 2.0),
    flutes         INTEGER NOT NULL CHECK (flutes > 0),
    flute_length   REAL NOT NULL CHECK (flute_length > 0),
    overall_length REAL CHECK (overall_length IS NULL OR overall_length >= reach),
    reach          REAL NOT NULL CHECK (reach >= flute_length),
    cost           REAL CHECK (cost IS NULL OR cost >= 0)
);
INSERT INTO tool_v2 (id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost)
    SELECT id, type, tool_material, diameter, corner_radius, flutes, flute_length, overall_length, reach, cost FROM tool;
DROP TABLE tool;
ALTER TABLE tool_v2 RENAME TO tool;
CREATE TABLE cutting_condition_v2 (
    id                 INTEGER PRIMARY KEY,
    workpiece_material TEXT NOT NULL REFERENCES workpiece_material (name) ON UPDATE CASCADE,
    tool_material      TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    operation          TEXT NOT NULL,
    d_min              REAL CHECK (d_min IS NULL OR d_min >= 0),
    d_max              REAL CHECK (d_max IS NULL OR d_max > 0),
    vc_m_min           REAL NOT NULL CHECK (vc_m_min > 0),
    fz_mm              REAL NOT NULL CHECK (fz_mm > 0),
    ap_mm              REAL NOT NULL CHECK (ap_mm > 0),
    ae_ratio           REAL NOT NULL CHECK (ae_ratio > 0 AND ae_ratio <= 1),
    c_f REAL NOT NULL, x_f REAL NOT NULL, y_f REAL NOT NULL, u_f REAL NOT NULL, q_f REAL NOT NULL, w_f REAL NOT NULL,
    k_fc               REAL NOT NULL DEFAULT 1,
    taylor_c           REAL NOT NULL CHECK (taylor_c > 0),
    taylor_m           REAL NOT NULL CHECK (taylor_m > 0),
    CHECK (d_min IS NULL OR d_max IS NULL OR d_min < d_max),
    UNIQUE (workpiece_material, tool_material, operation, d_min)
);
INSERT INTO cutting_condition_v2 (id, workpiece_material, tool_material, operation, vc_m_min, fz_mm, ap_mm, ae_ratio,
                                  c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m)
    SELECT id, workpiece_material, tool_material, operation, vc_m_min, fz_mm, ap_mm, ae_ratio,
           c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m FROM cutting_condition;
DROP TABLE cutting_condition;
ALTER TABLE cutting_condition_v2 RENAME TO cutting_condition;
CREATE TABLE freecad_tool_bit (
    tool_id   TEXT PRIMARY KEY NOT NULL REFERENCES tool (id) ON UPDATE CASCADE ON DELETE CASCADE,
    file_name TEXT NOT NULL,
    document  TEXT NOT NULL
);
CREATE TABLE freecad_tool_library (
    name     TEXT PRIMARY KEY NOT NULL,
    version  INTEGER NOT NULL DEFAULT 1,
    document TEXT
);
CREATE TABLE freecad_tool_library_entry (
    library TEXT NOT NULL REFERENCES freecad_tool_library (name) ON UPDATE CASCADE ON DELETE CASCADE,
    nr      INTEGER NOT NULL CHECK (nr >= 0),
    tool_id TEXT NOT NULL REFERENCES tool (id) ON UPDATE CASCADE ON DELETE CASCADE,
    PRIMARY KEY (library, nr)
);
INSERT OR IGNORE INTO threshold (name, value, description) VALUES
    ('plunge_feed_ratio', 0.30, 'vertical (plunge and ramp) feed as a fraction of the horizontal feed');
)sql"},
    // Version 2 -> 3: process templates per part family with their steps (existence, feature
    // types, tool role, allowances) and a chosen step order; sequencing rules as keys with
    // parameters. The version-2 templates (a name and a list of step codes) become integral-
    // panel templates whose steps take the shipped integral-panel step of the same code; the
    // version-2 rule texts that are not the shipped ones are kept as disabled notes.
    {2, R"sql(
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
)sql"},
    // Version 3 -> 4: impeller programming: tapered ball end mills and the impeller rule
    // library (route steps with their tool rules), seeded with the shipped rows.
    {3, R"sql(
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
)sql"},
};

std::unique_ptr<sqlite3, KnowledgeBase::Closer> openConnection(const std::string& path, int flags) {
    sqlite3* raw = nullptr;
    const int rc = sqlite3_open_v2(path.c_str(), &raw, flags | SQLITE_OPEN_NOMUTEX, nullptr);
    std::unique_ptr<sqlite3, KnowledgeBase::Closer> db(raw);
    if (rc != SQLITE_OK) fail(raw, rc, path, "opening");
    sqlite3_extended_result_codes(raw, 1);
    sqlite3_busy_timeout(raw, kBusyTimeoutMs);
    exec(raw, path, "PRAGMA foreign_keys = ON", "enabling foreign keys");
    return db;
}

bool hasTable(sqlite3* db, const std::string& path, const char* name) {
    Statement s(db, path, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?");
    s.bind(1, std::string(name));
    return s.step("reading the schema");
}

// -1: an empty database (no tables at all).
int detectVersion(sqlite3* db, const std::string& path) {
    // The first read: a corrupt, foreign or locked file fails here.
    Statement count(db, path, "SELECT count(*) FROM sqlite_master");
    count.step("reading the schema");
    if (count.integer(0) == 0) return -1;
    if (hasTable(db, path, "schema_version")) {
        Statement s(db, path, "SELECT max(version) FROM schema_version");
        if (!s.step("reading the schema version") || s.optReal(0) == std::nullopt)
            throw inputError("knowledge base " + quoted(path) + ": the schema_version table is empty");
        return s.integer(0);
    }
    if (hasTable(db, path, "tool")) return 0;
    throw inputError("knowledge base " + quoted(path) +
                     ": the file is an SQLite database but not an AeroNC knowledge base (no tool table)");
}

void populate(sqlite3* db, const std::string& path, const std::string& schemaSql, const std::string& dataSql) {
    Transaction t(db, path, "creating the knowledge base");
    exec(db, path, schemaSql, "running the schema SQL");
    exec(db, path, dataSql, "running the default data SQL");
    t.commit();
}

void migrate(sqlite3* db, const std::string& path, int from) {
    Transaction t(db, path, "migrating from schema version " + std::to_string(from));
    for (int v = from; v < KnowledgeBase::kSchemaVersion; ++v) {
        const auto step = kMigrations.find(v);
        if (step == kMigrations.end())
            throw inputError("knowledge base " + quoted(path) + ": no migration from schema version " +
                             std::to_string(v));
        exec(db, path, step->second,
             "migrating from schema version " + std::to_string(v) + " to " + std::to_string(v + 1));
    }
    exec(db, path, "UPDATE schema_version SET version = " + std::to_string(KnowledgeBase::kSchemaVersion),
         "recording the schema version");
    // A migration must leave the references intact.
    Statement fk(db, path, "PRAGMA foreign_key_check");
    if (fk.step("checking foreign keys"))
        throw inputError("knowledge base " + quoted(path) + ": migration left a broken reference in table '" +
                         fk.text(0) + "'");
    t.commit();
}

}  // namespace

void KnowledgeBase::Closer::operator()(sqlite3* db) const { sqlite3_close_v2(db); }

KnowledgeBase::KnowledgeBase(std::unique_ptr<sqlite3, Closer> db, std::string path)
    : db_(std::move(db)), path_(std::move(path)) {}
KnowledgeBase::KnowledgeBase(KnowledgeBase&&) noexcept = default;
KnowledgeBase& KnowledgeBase::operator=(KnowledgeBase&&) noexcept = default;
KnowledgeBase::~KnowledgeBase() = default;

KnowledgeBase KnowledgeBase::openWithSqlFolder(const std::string& path,
                                               const std::function<std::string()>& sqlFolder) {
    std::error_code ec;
    const bool build = !fs::exists(path, ec) || (fs::is_regular_file(path, ec) && fs::file_size(path, ec) == 0);
    if (!build) return open(path, "", "");
    const fs::path folder = sqlFolder();
    auto read = [&](const char* name) {
        const fs::path p = folder / name;
        std::ifstream in(p, std::ios::binary);
        if (!in) throw inputError("knowledge-base SQL " + p.string() + " cannot be read");
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    };
    const std::string schema = read("schema.sql");
    return open(path, schema, read("default_data.sql"));
}

KnowledgeBase KnowledgeBase::open(const std::string& path, const std::string& schemaSql,
                                  const std::string& defaultDataSql) {
    const fs::path file(path);
    const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw inputError("knowledge base " + quoted(path) + ": the directory " + quoted(dir.string()) +
                         " does not exist");
    if (fs::is_directory(file, ec))
        throw inputError("knowledge base " + quoted(path) + ": is a directory, not a database file");

    if (!fs::exists(file, ec)) {
        // Build under a temporary name and rename, so `path` is either complete or absent.
        const std::string tmp = path + ".creating";
        fs::remove(tmp, ec);
        fs::remove(tmp + "-journal", ec);
        try {
            auto db = openConnection(tmp, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
            populate(db.get(), tmp, schemaSql, defaultDataSql);
        } catch (...) {
            fs::remove(tmp, ec);
            fs::remove(tmp + "-journal", ec);
            throw;
        }
        fs::rename(tmp, file, ec);
        if (ec) {
            fs::remove(tmp, ec);
            throw inputError("knowledge base " + quoted(path) + ": cannot create the file (" + ec.message() + ")");
        }
    }

    auto db = openConnection(path, SQLITE_OPEN_READWRITE);
    const int version = detectVersion(db.get(), path);
    if (version == -1) {
        // An empty file (zero bytes, or a database without tables): fill it in place.
        populate(db.get(), path, schemaSql, defaultDataSql);
    } else if (version > kSchemaVersion) {
        throw inputError("knowledge base " + quoted(path) + ": schema version " + std::to_string(version) +
                         " is newer than this AeroNC understands (" + std::to_string(kSchemaVersion) +
                         "); update AeroNC");
    } else if (version < kSchemaVersion) {
        // Keep the old file: a migration is the one write a user cannot redo by hand.
        const std::string backup = path + ".v" + std::to_string(version) + ".bak";
        fs::copy_file(file, backup, fs::copy_options::overwrite_existing, ec);
        migrate(db.get(), path, version);
    }
    return KnowledgeBase(std::move(db), path);
}

int KnowledgeBase::schemaVersion() const {
    Statement s(db_.get(), path_, "SELECT max(version) FROM schema_version");
    s.step("reading the schema version");
    return s.integer(0);
}

std::vector<Tool> KnowledgeBase::tools() const {
    Statement s(db_.get(), path_,
                (std::string("SELECT ") + kToolColumns + " FROM tool ORDER BY diameter DESC, id").c_str());
    std::vector<Tool> out;
    while (s.step("reading the tools")) out.push_back(toolFromRow(s, path_));
    return out;
}

void KnowledgeBase::addTool(const Tool& tool, std::optional<double> cost) {
    insertTools({tool}, {cost});
}

void KnowledgeBase::importTools(const std::vector<Tool>& tools) {
    insertTools(tools, std::vector<std::optional<double>>(tools.size()));
}

void KnowledgeBase::insertTools(const std::vector<Tool>& tools, const std::vector<std::optional<double>>& costs) {
    // Check everything before touching the file.
    for (const Tool& t : tools) t.validate();
    for (const auto& c : costs)
        if (c && !(*c >= 0)) throw inputError("tool cost must not be negative");

    sqlite3* db = db_.get();
    Transaction tx(db, path_, tools.size() == 1 ? "adding tool " + quoted(tools[0].id) : "importing tools");
    Statement s(db, path_,
                "INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach, cost) "
                "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
    for (std::size_t i = 0; i < tools.size(); ++i) {
        const Tool& t = tools[i];
        s.reset();
        s.bind(1, t.id).bind(2, t.type).bind(3, t.material).bind(4, t.diameter).bind(5, t.cornerRadius);
        s.bind(6, t.flutes).bind(7, t.fluteLength).bind(8, t.reach).bind(9, costs[i]);
        const int rc = s.tryStep();
        if (rc == SQLITE_DONE) continue;
        const int ext = sqlite3_extended_errcode(db);
        const std::string who = "tool " + quoted(t.id) + ": ";
        const std::string detail = sqlite3_errmsg(db);
        const std::string batch = tools.size() > 1 ? " (nothing was imported)" : "";
        switch (ext) {
        case SQLITE_CONSTRAINT_CHECK:
            throw inputError(who + "impossible dimensions rejected by the knowledge base (" + detail + ")" + batch);
        case SQLITE_CONSTRAINT_PRIMARYKEY:
        case SQLITE_CONSTRAINT_UNIQUE:
            throw inputError(who + "a tool with this id already exists" + batch);
        case SQLITE_CONSTRAINT_FOREIGNKEY:
            throw inputError(who + "unknown tool material " + quoted(t.material) + " (known: " +
                             joined(names(db, path_, "SELECT name FROM tool_material ORDER BY name")) + ")" +
                             batch);
        default:
            fail(db, ext, path_, "adding tool " + quoted(t.id));
        }
    }
    tx.commit();
}

std::optional<double> KnowledgeBase::findThreshold(const std::string& name) const {
    Statement s(db_.get(), path_, "SELECT value FROM threshold WHERE name = ?");
    s.bind(1, name);
    if (!s.step("reading a threshold")) {
        checkIntact(db_.get(), path_);
        return std::nullopt;
    }
    s.about("threshold " + quoted(name));
    return s.real(0);
}

double KnowledgeBase::threshold(const std::string& name) const {
    if (const auto v = findThreshold(name)) return *v;
    throw inputError("knowledge base " + quoted(path_) + ": unknown threshold " + quoted(name) + " (known: " +
                     joined(names(db_.get(), path_, "SELECT name FROM threshold ORDER BY name")) + ")");
}

CuttingCondition KnowledgeBase::cuttingCondition(const std::string& workpieceMaterial,
                                                 const std::string& toolMaterial, const std::string& operation,
                                                 std::optional<double> toolDiameter) const {
    if (auto c = findCuttingCondition(workpieceMaterial, toolMaterial, operation, toolDiameter)) return *c;
    sqlite3* db = db_.get();
    Statement ranged(db, path_,
                     "SELECT count(*) FROM cutting_condition WHERE workpiece_material = ? AND tool_material = ? "
                     "AND operation = ?");
    ranged.bind(1, workpieceMaterial).bind(2, toolMaterial).bind(3, operation);
    ranged.step();
    if (ranged.integer(0) > 0) {
        std::ostringstream d;
        if (toolDiameter) d << "a " << *toolDiameter << " mm tool";
        else d << "a tool of unknown diameter (the rows are by diameter range)";
        throw inputError("no cutting condition for " + quoted(workpieceMaterial) + " with " + quoted(toolMaterial) +
                         " tools and operation " + quoted(operation) + " covers " + d.str());
    }
    Statement ops(db, path_,
                  "SELECT operation FROM cutting_condition WHERE workpiece_material = ? AND tool_material = ? "
                  "ORDER BY operation");
    ops.bind(1, workpieceMaterial).bind(2, toolMaterial);
    std::vector<std::string> known;
    while (ops.step()) known.push_back(ops.text(0));
    throw inputError("no cutting condition for " + quoted(workpieceMaterial) + " with " + quoted(toolMaterial) +
                     " tools and operation " + quoted(operation) + " (operations known for this pair: " +
                     (known.empty() ? std::string("none") : joined(known)) + ")");
}

std::optional<CuttingCondition> KnowledgeBase::findCuttingCondition(const std::string& workpieceMaterial,
                                                                    const std::string& toolMaterial,
                                                                    const std::string& operation,
                                                                    std::optional<double> toolDiameter) const {
    sqlite3* db = db_.get();
    {
        Statement s(db, path_, "SELECT 1 FROM workpiece_material WHERE name = ?");
        s.bind(1, workpieceMaterial);
        if (!s.step())
            notFound(db, path_,
                     "unknown workpiece material " + quoted(workpieceMaterial) + " (known: " +
                         joined(workpieceMaterials()) + ")");
    }
    {
        Statement s(db, path_, "SELECT 1 FROM tool_material WHERE name = ?");
        s.bind(1, toolMaterial);
        if (!s.step())
            notFound(db, path_,
                     "unknown tool material " + quoted(toolMaterial) + " (known: " +
                         joined(names(db, path_, "SELECT name FROM tool_material ORDER BY name")) + ")");
    }
    // ?4 NULL (no diameter) matches only rows without a range; ranged rows sort first.
    Statement s(db, path_,
                "SELECT vc_m_min, fz_mm, ap_mm, ae_ratio, c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m, "
                "d_min, d_max FROM cutting_condition WHERE workpiece_material = ? AND tool_material = ? "
                "AND operation = ? AND ((d_min IS NULL AND d_max IS NULL) OR (?4 IS NOT NULL "
                "AND (d_min IS NULL OR d_min <= ?4) AND (d_max IS NULL OR ?4 < d_max))) "
                "ORDER BY (d_min IS NULL AND d_max IS NULL), d_min DESC LIMIT 1");
    s.bind(1, workpieceMaterial).bind(2, toolMaterial).bind(3, operation).bind(4, toolDiameter);
    if (!s.step("reading cutting conditions")) {
        checkIntact(db, path_);
        return std::nullopt;
    }
    s.about("cutting condition " + quoted(workpieceMaterial) + "/" + quoted(toolMaterial) + "/" + quoted(operation));
    CuttingCondition c;
    c.workpieceMaterial = workpieceMaterial;
    c.toolMaterial = toolMaterial;
    c.operation = operation;
    c.vc = s.real(0);
    c.fz = s.real(1);
    c.ap = s.real(2);
    c.aeRatio = s.real(3);
    c.cF = s.real(4);
    c.xF = s.real(5);
    c.yF = s.real(6);
    c.uF = s.real(7);
    c.qF = s.real(8);
    c.wF = s.real(9);
    c.kFc = s.real(10);
    c.taylorC = s.real(11);
    c.taylorM = s.real(12);
    c.dMin = s.optReal(13);
    c.dMax = s.optReal(14);
    const std::string who = "knowledge base " + quoted(path_) + ": cutting condition " + quoted(workpieceMaterial) + "/" +
                            quoted(toolMaterial) + "/" + quoted(operation) + ": ";
    const std::pair<double, const char*> positive[] = {{c.vc, "vc_m_min"}, {c.fz, "fz_mm"},       {c.ap, "ap_mm"},
                                                       {c.cF, "c_f"},      {c.kFc, "k_fc"},       {c.taylorC, "taylor_c"},
                                                       {c.taylorM, "taylor_m"}, {c.aeRatio, "ae_ratio"}};
    for (const auto& [v, name] : positive)
        if (!(v > 0)) throw inputError(who + name + " must be positive, not " + std::to_string(v));
    if (c.aeRatio > 1) throw inputError(who + "ae_ratio must be at most 1, not " + std::to_string(c.aeRatio));
    return c;
}

Machine KnowledgeBase::machine(const std::string& name) const {
    Statement s(db_.get(), path_,
                "SELECT name, type, kinematics, travel_x, travel_y, travel_z, a_min, a_max, c_min, c_max, "
                "max_spindle_rpm, power_kw, max_feed_mm_min, max_force_n, efficiency, tool_change_s "
                "FROM machine WHERE name = ?");
    s.bind(1, name);
    if (!s.step("reading a machine"))
        notFound(db_.get(), path_, "unknown machine " + quoted(name) + " (known: " + joined(machineNames()) + ")");
    s.about("machine " + quoted(name));
    Machine m;
    m.name = s.text(0);
    m.type = s.text(1);
    m.kinematics = s.text(2);
    m.travelX = s.real(3);
    m.travelY = s.real(4);
    m.travelZ = s.real(5);
    m.aMin = s.optReal(6);
    m.aMax = s.optReal(7);
    m.cMin = s.optReal(8);
    m.cMax = s.optReal(9);
    m.maxSpindleRpm = s.real(10);
    m.powerKw = s.real(11);
    m.maxFeedMmMin = s.real(12);
    m.maxForceN = s.real(13);
    m.efficiency = s.real(14);
    m.toolChangeS = s.real(15);
    const std::string who = "knowledge base " + quoted(path_) + ": machine " + quoted(name) + ": ";
    const std::pair<double, const char*> positive[] = {{m.travelX, "travel_x"}, {m.travelY, "travel_y"},
                                                       {m.travelZ, "travel_z"}, {m.maxSpindleRpm, "max_spindle_rpm"},
                                                       {m.powerKw, "power_kw"}, {m.maxFeedMmMin, "max_feed_mm_min"},
                                                       {m.maxForceN, "max_force_n"}, {m.efficiency, "efficiency"}};
    for (const auto& [v, column] : positive)
        if (!(v > 0)) throw inputError(who + column + " must be positive, not " + std::to_string(v));
    if (m.efficiency > 1) throw inputError(who + "efficiency must be at most 1, not " + std::to_string(m.efficiency));
    if (m.toolChangeS < 0) throw inputError(who + "tool_change_s must not be negative");
    return m;
}

std::vector<std::string> KnowledgeBase::workpieceMaterials() const {
    return names(db_.get(), path_, "SELECT name FROM workpiece_material ORDER BY name");
}

std::vector<std::string> KnowledgeBase::machineNames() const {
    return names(db_.get(), path_, "SELECT name FROM machine ORDER BY name");
}

}  // namespace aeronc::kb
