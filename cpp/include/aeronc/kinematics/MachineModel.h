#pragma once
// The geometry of a 5-axis machine: two rotary axes with their directions, the points they
// pass through (pivot and offset vectors), their limits, and the linear travel. Read from a
// reviewable machine file (resources/machines/<name>.json, format in docs/post.md).
#include <aeronc/kinematics/Types.h>

#include <optional>
#include <string>
#include <vector>

namespace aeronc::kinematics {

// What a rotary axis moves: the table (it turns the workpiece) or the head (it turns the tool).
enum class Carrier { Table, Head };

struct RotaryAxis {
    std::string name;            // NC address: "A", "C"
    Carrier carrier = Carrier::Table;
    Vec3 direction = Vec3::UnitZ();  // unit vector, machine frame, all axes at zero; a positive
                                     // angle turns the carried part right-handed about it
    // A point on the axis with all axes at zero. Table axes: relative to the table reference
    // point (the machine's rotary centre on the table surface). Head axes: relative to the
    // spindle gauge point (the tool holder face on the spindle axis).
    Vec3 point = Vec3::Zero();
    double min = -360.0, max = 360.0;  // degrees
};

struct LinearTravel {
    Vec3 min = Vec3::Constant(-1e9), max = Vec3::Constant(1e9);
};

struct MachineModel {
    std::string name;
    std::string description;
    std::string controller;
    // Rotary axes in chain order: table axes from the machine bed outwards (the first one
    // carries the second), head axes from the ram outwards. Exactly two.
    std::vector<RotaryAxis> rotary;
    Vec3 toolDirection = Vec3::UnitZ();  // tool axis (tip -> spindle) with the head at zero
    // Program zero (G54) relative to the table reference point, all axes at zero: where the
    // part is clamped. A setup quantity; the post can override it.
    Vec3 partZero = Vec3::Zero();
    // Travel of the controlled point in machine coordinates (mm), relative to the program zero
    // with all axes at zero. Absent in the file: not checked.
    std::optional<LinearTravel> travel;
    double retractDistance = 50.0;  // mm along the tool axis for a branch change
    double maxRotaryFeed = 3600.0;  // deg/min, the time of a pure reorientation
    // The programmed feed (mm/min) and spindle speed (r/min) the machine takes; the posts refuse
    // more. Absent in the file: only the NC words' own range is checked.
    std::optional<double> maxFeed, maxSpindleSpeed;
    // Sinumerik CYCLE800: swivel data record name and which rotary axis gives the preferred
    // direction (_DIR).
    std::string swivelDataRecord = "TC1";
    int directionReference = 0;  // index into rotary

    int axisIndex(const std::string& name) const;  // -1 when absent
    std::string kinematicsName() const;             // "table-table", "head-head", "head-table"
};

// Parses a machine file; every missing or inconsistent entry is an error naming the file entry.
MachineModel machineFromJson(const std::string& jsonText, const std::string& sourceName = "machine file");
MachineModel loadMachineFile(const std::string& path);

}  // namespace aeronc::kinematics
