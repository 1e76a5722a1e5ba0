// The camera's measurement file: reading, the transform chain, and every bad input.
#include "../ErrorOf.h"
#include "Fixtures.h"

#include <aeronc/compensation/MeasurementCsv.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace aeronc::compensation;
using namespace aeronc::compensation::test;
using aeronc::test::inputErrorOf;

namespace {

// The photo-hole set of the curved skin: each datum hole photographed from 60 mm along its
// normal, the camera 90 mm below the gauge point.
std::vector<DatumFrame> frames(const Pattern& p) {
    Mat4 mountFromCamera;
    mountFromCamera << 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, -90, 0, 0, 0, 1;
    Mat4 assemblyFromMachine = Mat4::Identity();
    assemblyFromMachine.topRightCorner<3, 1>() = Vec3(-1000, 200, 50);
    std::vector<DatumFrame> out;
    for (int i : p.datums) {
        DatumFrame f;
        f.id = "DH" + std::to_string(i);
        f.nominal = p.points[static_cast<size_t>(i)];
        f.normal = p.normals[static_cast<size_t>(i)];
        f.chain.mountFromCamera = mountFromCamera;
        f.chain.assemblyFromMachine = assemblyFromMachine;
        // The machine puts the mount where the program asked, in machine coordinates.
        f.chain.machineFromMount = rigidInverse(assemblyFromMachine) * frameAt(f.nominal + 150.0 * f.normal, f.normal, Vec3::UnitX());
        out.push_back(f);
    }
    return out;
}

// A file as the camera writes it for holes that the distortion moved.
std::string cameraFile(const std::vector<DatumFrame>& fs, const Distortion& d, bool header = true) {
    std::string s = "# AeroNC measured datum holes\n";
    if (header) s += "hole,u,v,height,quality\n";
    char b[200];
    for (const auto& f : fs) {
        const Vec3 c = f.chain.toCamera(d(f.nominal));
        std::snprintf(b, sizeof b, "%s,%.9f,%.9f,%.9f,0.97\n", f.id.c_str(), c.x(), c.y(), c.z());
        s += b;
    }
    return s;
}

std::string importError(const std::string& csv, const std::vector<DatumFrame>& fs, ImportOptions o = {}) {
    return inputErrorOf([&] { importMeasurements(readMeasurementCsv(csv), fs, o); });
}

}  // namespace

TEST(MeasurementCsv, ImportPutsEveryDatumHoleWhereTheDistortionDid) {
    const Pattern p = curvedSkin();
    const auto fs = frames(p);
    for (const auto& d : distortions(p)) {
        const auto imported = importMeasurements(readMeasurementCsv(cameraFile(fs, d.apply)), fs);
        ASSERT_EQ(imported.size(), fs.size());
        for (size_t i = 0; i < fs.size(); ++i) {
            EXPECT_EQ(imported[i].datum.id, fs[i].id);
            EXPECT_LT((imported[i].datum.measured - d.apply(fs[i].nominal)).norm(), 1e-8) << d.name;
            ASSERT_TRUE(imported[i].reading.quality);
            EXPECT_DOUBLE_EQ(*imported[i].reading.quality, 0.97);
        }
    }
}

TEST(MeasurementCsv, FormatVariantsAreRead) {
    const auto r = readMeasurementCsv("\xEF\xBB\xBF# c\r\n\r\nHole, U, V, Height\r\nA1, 0.1 ,-0.2,60\r\nA2,1e-3,0,59.5,\r\n  # x\nA3,0,0,61,0.5\n");
    ASSERT_EQ(r.size(), 3u);
    EXPECT_EQ(r[0].id, "A1");
    EXPECT_DOUBLE_EQ(r[0].u, 0.1);
    EXPECT_DOUBLE_EQ(r[0].v, -0.2);
    EXPECT_EQ(r[0].line, 4);
    EXPECT_FALSE(r[1].quality);
    EXPECT_DOUBLE_EQ(*r[2].quality, 0.5);
    EXPECT_EQ(readMeasurementCsv("B,1,2,3").size(), 1u);  // no header, no newline at the end
}

TEST(MeasurementCsv, ANumberTooSmallForADoubleIsReadAsWhatItIs) {
    // It was refused as "not a number"; 1e-320 mm is a measurement of no deviation.
    const auto r = readMeasurementCsv("A1,1e-320,-4.9e-324,60\n");
    ASSERT_EQ(r.size(), 1u);
    EXPECT_LT(std::abs(r[0].u), 1e-300);
    EXPECT_LT(std::abs(r[0].v), 1e-300);
}

TEST(MeasurementCsv, MalformedFilesAreRefusedNamingTheLine) {
    struct Case {
        const char* text;
        const char* says;
    } cases[] = {
        {"", "no measurements"},
        {"# only a comment\n\n", "no measurements"},
        {"hole,u,v,height\n", "no measurements"},
        {"A1;0.1;0.2;60\n", "separated by commas"},
        {"A1,0.1,0.2\n", "line 1: 3 fields"},
        {"hole,u,v,height\nA1,0.1,0.2,60,0.9,7\n", "line 2: 6 fields"},
        {"A1,0.1,x,60\n", "line 1: v 'x' is not a number"},
        {"A1,0.1,0.2mm,60\n", "'0.2mm' is not a number"},
        {"A1,,0.2,60\n", "u is empty"},
        {",0.1,0.2,60\n", "hole id is empty"},
        {"A1,nan,0.2,60\n", "u is NaN"},
        {"A1,0.1,0.2,NaN\n", "height is NaN"},
        {"A1,0.1,inf,60\n", "not finite"},
        {"A1,0.1,0.2,1e999\n", "line 1: height '1e999' is out of range"},
        {"A1,-1e400,0.2,60\n", "line 1: u '-1e400' is out of range"},
        {"A1,0.1,0.2,-60\n", "height must be positive"},
        {"hole,x,y,z\nA1,0.1,0.2,60\n", "expected 'u'"},
        {"A1,0.1,0.2,60\nA2,0,0,60\nA1,0,0,60\n", "hole A1 is measured twice (lines 1 and 3)"},
        {"A1,0.1,0.2,60,good\n", "quality 'good' is not a number"},
    };
    for (const auto& c : cases) {
        const auto msg = inputErrorOf([&] { readMeasurementCsv(c.text); });
        EXPECT_NE(msg.find(c.says), std::string::npos) << "input: " << c.text << "\nmessage: " << msg;
    }
}

TEST(MeasurementCsv, BadMeasurementsAreRefusedAndNothingIsImported) {
    const Pattern p = flatSkin();
    const auto fs = frames(p);
    const auto d = distortions(p)[0].apply;
    const std::string good = cameraFile(fs, d);
    ASSERT_NO_THROW(importMeasurements(readMeasurementCsv(good), fs));

    // Unknown ids.
    std::string msg = importError(good + "XX9,0,0,60\n", fs);
    EXPECT_NE(msg.find("unknown hole ids"), std::string::npos) << msg;
    EXPECT_NE(msg.find("XX9 (line"), std::string::npos) << msg;
    // Missing datum holes.
    const auto firstLine = good.find("DH");
    const auto secondLine = good.find('\n', firstLine) + 1;
    msg = importError(good.substr(0, firstLine) + good.substr(secondLine), fs);
    EXPECT_NE(msg.find("datum holes not measured: " + fs[0].id), std::string::npos) << msg;
    // Outliers beyond the tolerance, and below it with a larger tolerance.
    const auto far = [&](const Vec3& x) { return Vec3(x == fs[3].nominal ? d(x) + Vec3(0, 7, 0) : d(x)); };
    msg = importError(cameraFile(fs, far), fs);
    EXPECT_NE(msg.find("outliers beyond 5 mm"), std::string::npos) << msg;
    EXPECT_NE(msg.find(fs[3].id + " "), std::string::npos) << msg;
    EXPECT_EQ(msg.find(fs[2].id + " "), std::string::npos) << msg;
    ImportOptions loose;
    loose.maxDeviation = 10.0;
    EXPECT_NO_THROW(importMeasurements(readMeasurementCsv(cameraFile(fs, far)), fs, loose));
    // Low quality.
    ImportOptions strict;
    strict.minQuality = 0.99;
    msg = importError(good, fs, strict);
    EXPECT_NE(msg.find("quality below 0.99"), std::string::npos) << msg;
    // Fewer than two datum holes in the set.
    const std::vector<DatumFrame> one(fs.begin(), fs.begin() + 1);
    msg = importError(cameraFile(one, d), one);
    EXPECT_NE(msg.find("fewer than two datum holes"), std::string::npos) << msg;
    // A transform of the chain that is not rigid.
    auto bent = fs;
    bent[2].chain.assemblyFromMachine(0, 1) = 0.3;
    msg = importError(good, bent);
    EXPECT_NE(msg.find(fs[2].id + ": machine -> assembly is not a rigid transform"), std::string::npos) << msg;
}
