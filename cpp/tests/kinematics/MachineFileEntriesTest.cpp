// Machine-file entries of the wrong kind are errors naming the entry, never ignored, never a
// library exception without the file's name.
#include <aeronc/kinematics/MachineModel.h>

#include <gtest/gtest.h>

#include <string>

using namespace aeronc::kinematics;

namespace {

const std::string kAxes =
    R"("rotaryAxes":[{"name":"A","carrier":"table","direction":[1,0,0],"point":[0,0,0],"min":-90,"max":90},)"
    R"({"name":"C","carrier":"table","direction":[0,0,1],"point":[0,0,0],"min":-360,"max":360}])";

// The aeronc::Error message for a machine file with `extra` entries; "no error" when it is read.
std::string errorFor(const std::string& extra) {
    try {
        machineFromJson(R"({"name":"M",)" + kAxes + extra + "}", "m.json");
    } catch (const aeronc::Error& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("not an aeronc::Error: ") + e.what();
    }
    return "no error";
}

void expectNamed(const std::string& extra, const std::string& entry) {
    const std::string e = errorFor(extra);
    EXPECT_EQ(e.rfind("m.json: ", 0), 0u) << extra << " -> " << e;
    EXPECT_NE(e.find(entry), std::string::npos) << extra << " -> " << e;
}

}  // namespace

TEST(MachineFileEntries, ASinumerikEntryThatIsNoObjectIsRefused) {
    // Once ignored: CYCLE800 then named the default swivel data record.
    for (const char* s : {R"("TC2")", "5", "[1]", "null", "true"})
        expectNamed(std::string(R"(,"sinumerik":)") + s, "\"sinumerik\"");
    expectNamed(R"(,"sinumerik":{"swivelDataRecord":5})", "sinumerik.swivelDataRecord");
    expectNamed(R"(,"sinumerik":{"swivelDataRecord":""})", "sinumerik.swivelDataRecord");
    // Found by fuzzing: the name is written inside CYCLE800("..."); a quote or a line break
    // there wrote words of its own into the program.
    for (const char* name : {R"x("TC1\nM30")x", R"x("TC1\",0,57)")x", R"x(" T1C")x", R"x("TC1;")x"})
        expectNamed(std::string(R"(,"sinumerik":{"swivelDataRecord":)") + name + "}", "sinumerik.swivelDataRecord");
    expectNamed(R"(,"sinumerik":{"directionReference":["A"]})", "sinumerik.directionReference");
    expectNamed(R"(,"sinumerik":{"swivelRecord":"TC1"})", "sinumerik.swivelRecord");
    EXPECT_EQ(errorFor(R"(,"sinumerik":{"swivelDataRecord":"HEAD2","directionReference":"C"})"), "no error");
    const MachineModel m =
        machineFromJson(R"({"name":"M",)" + kAxes + R"(,"sinumerik":{"swivelDataRecord":"HEAD2","directionReference":"C"}})");
    EXPECT_EQ(m.swivelDataRecord, "HEAD2");
    EXPECT_EQ(m.directionReference, 1);
}

TEST(MachineFileEntries, EntriesOfTheWrongTypeAreNamed) {
    expectNamed(R"(,"description":7)", "\"description\"");
    expectNamed(R"(,"controller":[1])", "\"controller\"");
    expectNamed(R"(,"linearTravel":[1,2])", "\"linearTravel\"");
    expectNamed(R"(,"maxFeed":-1)", "\"maxFeed\"");
    expectNamed(R"(,"maxFeed":"fast")", "\"maxFeed\"");
    expectNamed(R"(,"maxSpindleSpeed":0)", "\"maxSpindleSpeed\"");
    expectNamed(R"(,"maxSpindleSpeed":1e300)", "\"maxSpindleSpeed\"");
    expectNamed(R"(,"rotaryAxes":[1,2])", "rotaryAxes[0]");
    expectNamed(R"(,"retractDistance":1e400)", "not valid JSON");
}

TEST(MachineFileEntries, FeedAndSpindleLimitsAreRead) {
    const MachineModel m = machineFromJson(R"({"name":"M",)" + kAxes + R"(,"maxFeed":12000,"maxSpindleSpeed":24000})");
    ASSERT_TRUE(m.maxFeed && m.maxSpindleSpeed);
    EXPECT_EQ(*m.maxFeed, 12000);
    EXPECT_EQ(*m.maxSpindleSpeed, 24000);
    const MachineModel open = machineFromJson(R"({"name":"M",)" + kAxes + "}");
    EXPECT_FALSE(open.maxFeed || open.maxSpindleSpeed);
}

TEST(MachineFileEntries, DeeplyNestedJsonIsRefusedWithoutRecursion) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    expectNamed(R"(,"notes":)" + deep, "nested");
}
