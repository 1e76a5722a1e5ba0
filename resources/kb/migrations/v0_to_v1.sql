-- Migration of a knowledge base from schema version 0 to 1.
--
-- Version 0 is the layout before versioning: no schema_version table and no tool.cost
-- column. The step adds both, and creates the version-1 tables a version-0 file may lack,
-- seeding the two thresholds the selector needs when they are absent.

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
