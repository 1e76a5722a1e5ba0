-- AeroNC machining knowledge base, schema version 11.
--
-- Reviewable source of the database layout. KnowledgeBase::open() runs this text on a new,
-- empty database and then resources/kb/default_data.sql. A database made by an older
-- version is upgraded by the migration steps resources/kb/migrations/v<N>_to_v<N+1>.sql (the
-- build embeds them); when this file changes, bump the version below and add a step there.
--
-- Units: lengths in mm, angles in degrees, speeds in r/min, feeds in mm/min,
-- power in kW, force in N, time in s (tool change) or min (tool life), cost in currency units.

PRAGMA foreign_keys = ON;

CREATE TABLE schema_version (
    version INTEGER NOT NULL
);
INSERT INTO schema_version (version) VALUES (11);

-- Resource facts -----------------------------------------------------------------------

CREATE TABLE machine (
    id              INTEGER PRIMARY KEY,
    name            TEXT NOT NULL UNIQUE,
    type            TEXT NOT NULL,                -- 'vertical mill', '5-axis', ...
    kinematics      TEXT NOT NULL,                -- 'XYZ', 'AC table-table', ...
    travel_x        REAL NOT NULL CHECK (travel_x > 0),
    travel_y        REAL NOT NULL CHECK (travel_y > 0),
    travel_z        REAL NOT NULL CHECK (travel_z > 0),
    a_min           REAL,                         -- NULL: no such rotary axis
    a_max           REAL,
    c_min           REAL,
    c_max           REAL,
    max_spindle_rpm REAL NOT NULL CHECK (max_spindle_rpm > 0),
    power_kw        REAL NOT NULL CHECK (power_kw > 0),
    max_feed_mm_min REAL NOT NULL CHECK (max_feed_mm_min > 0),
    max_force_n     REAL NOT NULL CHECK (max_force_n > 0),
    efficiency      REAL NOT NULL CHECK (efficiency > 0 AND efficiency <= 1),
    tool_change_s   REAL NOT NULL CHECK (tool_change_s >= 0),
    CHECK (a_min IS NULL OR a_max IS NULL OR a_min <= a_max),
    CHECK (c_min IS NULL OR c_max IS NULL OR c_min <= c_max)
);

CREATE TABLE workpiece_material (
    id          INTEGER PRIMARY KEY,
    name        TEXT NOT NULL UNIQUE,
    family      TEXT NOT NULL,                    -- 'aluminium', 'titanium', 'steel', ...
    hardness_hb REAL CHECK (hardness_hb IS NULL OR hardness_hb > 0)
);

CREATE TABLE tool_material (
    id   INTEGER PRIMARY KEY,
    name TEXT NOT NULL UNIQUE,
    kind TEXT NOT NULL                            -- 'HSS', 'carbide', 'ceramic', 'PCD', ...
);

-- A tool the selector may choose. Impossible dimensions are refused by the database too,
-- not only by toolselect::Tool::validate(), so a hand edit cannot store them.
-- 'other' is a tool kept for FreeCAD (chamfer, v-bit, probe, ...) that the selector never picks.
-- reach is the length below the holder that is no wider than the cutter. A necked (long-reach)
-- tool has a relieved neck of neck_diameter behind its flutes: it cuts as deep as its reach, one
-- layer of at most its flute length at a time; a tool without a neck (NULL) is as wide as the
-- cutter behind its flutes and cuts only as deep as its flutes (docs/tool-crib.md).
CREATE TABLE tool (
    id             TEXT PRIMARY KEY NOT NULL,
    type           TEXT NOT NULL CHECK (type IN ('flat', 'bull', 'ball', 'drill', 'face', 'other')),
    tool_material  TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    diameter       REAL NOT NULL CHECK (diameter > 0),
    corner_radius  REAL NOT NULL DEFAULT 0 CHECK (corner_radius >= 0 AND corner_radius <= diameter / 2.0),
    flutes         INTEGER NOT NULL CHECK (flutes > 0),
    flute_length   REAL NOT NULL CHECK (flute_length > 0),
    overall_length REAL CHECK (overall_length IS NULL OR overall_length >= reach),
    reach          REAL NOT NULL CHECK (reach >= flute_length),
    cost           REAL CHECK (cost IS NULL OR cost >= 0),
    neck_diameter  REAL CHECK (neck_diameter IS NULL OR (neck_diameter > 0 AND neck_diameter < diameter))
);

-- Edge tools: chamfer mills (a cone of included_angle from tip_diameter up to diameter) and
-- corner-rounding mills (a concave quarter circle of profile_radius between tip_diameter and
-- diameter). Kept for edge chamfers and outer rounds; the selector does not pick them yet.
CREATE TABLE edge_tool (
    id             TEXT PRIMARY KEY NOT NULL,
    kind           TEXT NOT NULL CHECK (kind IN ('chamfer', 'corner_rounding')),
    tool_material  TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    diameter       REAL NOT NULL CHECK (diameter > 0),
    tip_diameter   REAL NOT NULL CHECK (tip_diameter >= 0 AND tip_diameter < diameter),
    included_angle REAL CHECK (included_angle IS NULL OR (included_angle > 0 AND included_angle < 180)),
    profile_radius REAL CHECK (profile_radius IS NULL OR profile_radius > 0),
    flutes         INTEGER NOT NULL CHECK (flutes > 0),
    reach          REAL NOT NULL CHECK (reach > 0),
    cost           REAL CHECK (cost IS NULL OR cost >= 0),
    CHECK ((kind = 'chamfer' AND included_angle IS NOT NULL AND profile_radius IS NULL) OR
           (kind = 'corner_rounding' AND profile_radius IS NOT NULL AND included_angle IS NULL AND
            2 * profile_radius <= diameter - tip_diameter + 1e-9))
);

-- Material x tool material x operation [x tool diameter range] -> cutting data and the
-- empirical coefficients of
--   F_c = 9.81 * c_f * ap^x_f * fz^y_f * ae^u_f * Z / (d0^q_f * n^w_f) * k_fc   [N]
--   Taylor: v_c * T^taylor_m = taylor_c                                          [T in min]
CREATE TABLE cutting_condition (
    id                 INTEGER PRIMARY KEY,
    workpiece_material TEXT NOT NULL REFERENCES workpiece_material (name) ON UPDATE CASCADE,
    tool_material      TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
    operation          TEXT NOT NULL,             -- 'roughing', 'finishing', 'drilling', ...
    d_min              REAL CHECK (d_min IS NULL OR d_min >= 0),  -- tool diameter range [d_min, d_max);
    d_max              REAL CHECK (d_max IS NULL OR d_max > 0),   -- NULL: open on that side
    vc_m_min           REAL NOT NULL CHECK (vc_m_min > 0),
    fz_mm              REAL NOT NULL CHECK (fz_mm > 0),
    ap_mm              REAL NOT NULL CHECK (ap_mm > 0),
    ae_ratio           REAL NOT NULL CHECK (ae_ratio > 0 AND ae_ratio <= 1),  -- a_e / tool diameter
    c_f                REAL NOT NULL,
    x_f                REAL NOT NULL,
    y_f                REAL NOT NULL,
    u_f                REAL NOT NULL,
    q_f                REAL NOT NULL,
    w_f                REAL NOT NULL,
    k_fc               REAL NOT NULL DEFAULT 1,
    taylor_c           REAL NOT NULL CHECK (taylor_c > 0),
    taylor_m           REAL NOT NULL CHECK (taylor_m > 0),
    CHECK (d_min IS NULL OR d_max IS NULL OR d_min < d_max),
    UNIQUE (workpiece_material, tool_material, operation, d_min)
);

-- FreeCAD tool bridge ------------------------------------------------------------------
-- The tool-bit document (.fctb JSON) a tool came from, kept whole so that exporting gives
-- back what was imported; the dimensions in `tool` are the ones that count, and an export
-- writes them back into the document's parameters when they were edited.
CREATE TABLE freecad_tool_bit (
    tool_id   TEXT PRIMARY KEY NOT NULL REFERENCES tool (id) ON UPDATE CASCADE ON DELETE CASCADE,
    file_name TEXT NOT NULL,                      -- e.g. '5mm_Endmill.fctb'
    document  TEXT NOT NULL                       -- the .fctb JSON text
);

-- A FreeCAD tool library (.fctl): numbered tools.
CREATE TABLE freecad_tool_library (
    name     TEXT PRIMARY KEY NOT NULL,           -- the .fctl file name without extension
    version  INTEGER NOT NULL DEFAULT 1,
    document TEXT                                 -- the .fctl JSON text as imported; NULL if made here
);

CREATE TABLE freecad_tool_library_entry (
    library TEXT NOT NULL REFERENCES freecad_tool_library (name) ON UPDATE CASCADE ON DELETE CASCADE,
    nr      INTEGER NOT NULL CHECK (nr >= 0),     -- FreeCAD's tool number
    tool_id TEXT NOT NULL REFERENCES tool (id) ON UPDATE CASCADE ON DELETE CASCADE,
    PRIMARY KEY (library, nr)
);

-- Rule knowledge -----------------------------------------------------------------------

CREATE TABLE threshold (
    name        TEXT PRIMARY KEY NOT NULL,        -- 'eta_min', 'mu_merge', ...
    value       REAL NOT NULL,
    description TEXT
);

-- Process planning (the machining chain, docs/machining-chain.md) ------------------------
-- Step codes (DESIGN.md section 3): r rough, w finish webs (floors), c corners, ss/sf
-- semi-finish walls/flanges, fs/ff finish walls/flanges, t cut off, d drill, h mill a hole
-- (helical interpolation). Feature types: closed_pocket, open_pocket, opening, hole, flange
-- (a pocket carrying a flange).

-- A part family and the steps every one of its templates must contain as must-steps.
CREATE TABLE part_family (
    name           TEXT PRIMARY KEY NOT NULL,     -- 'integral_panel', 'frame_beam', 'rib'
    required_steps TEXT NOT NULL DEFAULT '',      -- step codes, space separated
    description    TEXT
);

-- A priority order of the step codes within a setup: the patent's
-- r < w < c < ss < sf < fs < ff or its alternative r < w < ss < sf < c < fs < ff.
CREATE TABLE step_order (
    name        TEXT PRIMARY KEY NOT NULL,
    codes       TEXT NOT NULL,                    -- step codes, first to last, space separated
    description TEXT
);

-- A process template: the steps a part of the family goes through, in the priority order
-- it chooses. The template named like its family is that family's default.
CREATE TABLE process_template (
    name        TEXT PRIMARY KEY NOT NULL,
    family      TEXT NOT NULL REFERENCES part_family (name) ON UPDATE CASCADE,
    step_order  TEXT NOT NULL REFERENCES step_order (name) ON UPDATE CASCADE,
    description TEXT
);

-- One step of a template: whether it must, may or must not exist, the feature types it
-- machines, the tool it takes (roughing, finishing, corner or drilling tool of the element)
-- and the allowances it leaves on the walls (radial) and floors (axial).
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

-- Sequencing rules of a template (integral-panel paper section 2.4), applied in ascending
-- priority. rule is a key; parameters are 'name=value' words:
--   process_order      order=larger_tool_first|smaller_tool_first
--   outer_before_inner outer=<feature types, comma separated>
--   higher_z_first     (none): of a parent and child element, the higher unit first
--   feature_type_order order=<feature types, comma separated>
--   centre_out         (none): otherwise symmetric, from the centre of the setup out
-- A disabled rule (enabled = 0) is kept for review and not applied.
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

-- Impeller programming (impeller paper §2, docs/impeller.md) ---------------------------------

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
