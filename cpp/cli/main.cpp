// aeronc: command-line entry to the AeroNC core. `aeronc --help` lists the commands (kCommands
// below: one table, each command with its usage and whether it reads a part).
#include <aeronc/brep/OcctFaults.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/chain/ChainJson.h>
#include <aeronc/core/Error.h>
#include <aeronc/core/TextFile.h>
#include <aeronc/impeller/Blank.h>
#include <aeronc/impeller/BodyFusion.h>
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impellerpath/AxialOperations.h>
#include <aeronc/impellerpath/ImpellerToolpaths.h>
#include <aeronc/kb/ImpellerProgram.h>
#include <aeronc/kb/ImpellerRoute.h>
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/kb/OptimiseParameters.h>
#include <aeronc/kb/ProcessTemplates.h>
#include <aeronc/kb/ToolPlanning.h>
#include <aeronc/kinematics/MachineModel.h>
#include <aeronc/optimise/Report.h>
#include <aeronc/post/Apt.h>
#include <aeronc/post/Post.h>
#include <aeronc/recognition/DomainTreeJson.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/ImpellerGenerator.h>
#include <aeronc/testparts/PanelGenerator.h>
#include <aeronc/toolselect/PlanJson.h>

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

std::vector<aeronc::Vec3> parseDirections(const std::string& s) {
    std::vector<aeronc::Vec3> out;
    if (s == "auto" || s.empty()) return out;
    std::stringstream ss(s);
    std::string tok;
    while (std::getline(ss, tok, ',')) {
        static const std::map<std::string, aeronc::Vec3> named{{"+X", {1, 0, 0}}, {"-X", {-1, 0, 0}},
                                                               {"+Y", {0, 1, 0}}, {"-Y", {0, -1, 0}},
                                                               {"+Z", {0, 0, 1}}, {"-Z", {0, 0, -1}}};
        auto it = named.find(tok);
        if (it != named.end()) {
            out.push_back(it->second);
            continue;
        }
        aeronc::Vec3 v{};
        char c1 = 0, c2 = 0;
        std::stringstream vs(tok);
        if (!(vs >> v[0] >> c1 >> v[1] >> c2 >> v[2]) || c1 != ':' || c2 != ':')
            throw aeronc::inputError("bad direction '" + tok + "': use +Z, -X ... or x:y:z");
        out.push_back(v);
    }
    return out;
}

void writeText(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".part";
    {
        std::ofstream f(tmp, std::ios::binary);
        f << text;
        if (!f) throw aeronc::inputError(path + ": could not be written");
    }
    fs::rename(tmp, path);
}

// stdout when `path` is empty, else the file.
void writeOut(const std::string& path, const std::string& text) {
    if (path.empty()) std::cout << text << "\n";
    else writeText(path, text);
}

using Next = std::function<std::string()>;

// Calls handle(option, next) for every option from argv[first] on (by default, after the part
// argument); `next` takes the option's value. An option handle() does not know is an error.
template <class Handle>
void forEachOption(int argc, char** argv, Handle handle, int first = 3) {
    for (int i = first; i < argc; ++i) {
        const std::string a = argv[i];
        const Next next = [&]() -> std::string {
            if (i + 1 >= argc) throw aeronc::inputError(a + " needs a value");
            return argv[++i];
        };
        if (!handle(a, next)) throw aeronc::inputError("unknown option " + a);
    }
}

// The one way a command reads a part: `work` runs on the shape inside OCCT's fault guard, so an
// OCCT failure in reading or in the work is an error naming the file. faceNames, when given,
// gets each face's STEP name.
void onPart(const std::string& path, const std::function<void(const TopoDS_Shape&)>& work,
            std::vector<std::string>* faceNames = nullptr) {
    aeronc::runCatchingOcctFaults(
        [&] { work(faceNames ? aeronc::loadStepWithFaceNames(path, *faceNames) : aeronc::loadPart(path)); }, path);
}

// The impeller of a part file as one solid. A file of several bodies (exported hub and blades)
// is refused with the reason unless `fuse` is set; then its bodies are fused (BodyFusion.h).
void onImpeller(const std::string& path, bool fuse, const std::function<void(const TopoDS_Shape&)>& work) {
    aeronc::runCatchingOcctFaults(
        [&] {
            const TopoDS_Shape shape = aeronc::loadShape(path);
            const int solids = aeronc::impeller::solidCount(shape);
            if (solids > 1 && !fuse)
                throw aeronc::inputError(path + ": holds " + std::to_string(solids) +
                                         " solids (bodies exported separately, e.g. a hub and its blades); "
                                         "recognition needs one part: add --fuse to fuse the bodies into one solid");
            if (solids > 1) {
                const auto f = aeronc::impeller::fuseBodies(shape);
                std::cerr << path << ": " << f.summary << "\n";
                work(aeronc::validatedSolid(f.solid, path + " (bodies fused)"));
            } else {
                work(aeronc::validatedSolid(shape, path));
            }
        },
        path);
}

fs::path executableDir(const char* argv0) {
    std::error_code ec;
    auto self = fs::read_symlink("/proc/self/exe", ec);
    if (ec || self.empty()) self = fs::absolute(argv0, ec);
    return self.parent_path();
}

// The folder holding schema.sql and default_data.sql: --resources, else the install layout
// (<prefix>/AeroNC/bin/aeronc next to <prefix>/AeroNC/aeronc/resources/kb), else the source tree.
fs::path kbResources(const std::string& given, const char* argv0) {
    auto has = [](const fs::path& d) {
        std::error_code ec;
        return fs::is_regular_file(d / "schema.sql", ec) && fs::is_regular_file(d / "default_data.sql", ec);
    };
    if (!given.empty()) {
        if (!has(given))
            throw aeronc::inputError("--resources " + given + ": no schema.sql and default_data.sql there");
        return given;
    }
    std::vector<fs::path> tried{executableDir(argv0) / ".." / "aeronc" / "resources" / "kb"};
#ifdef AERONC_SOURCE_RESOURCES
    tried.emplace_back(AERONC_SOURCE_RESOURCES);
#endif
    std::string list;
    for (const fs::path& d : tried) {
        if (has(d)) return d;
        list += (list.empty() ? "" : ", ") + d.lexically_normal().string();
    }
    throw aeronc::inputError("cannot find the knowledge-base SQL (schema.sql, default_data.sql); tried " + list +
                             "; pass --resources DIR");
}

aeronc::kb::KnowledgeBase openKb(const std::string& path, const std::string& resources, const char* argv0) {
    return aeronc::kb::KnowledgeBase::openWithSqlFolder(path, [&] { return kbResources(resources, argv0).string(); });
}

// Refuses a material the knowledge base does not know, naming those it does.
void checkMaterial(const aeronc::kb::KnowledgeBase& kb, const std::string& material, const std::string& kbPath) {
    const auto known = kb.workpieceMaterials();
    if (std::find(known.begin(), known.end(), material) != known.end()) return;
    std::string list;
    for (const auto& m : known) list += (list.empty() ? "" : ", ") + ("'" + m + "'");
    throw aeronc::inputError("unknown workpiece material '" + material + "' in " + kbPath + " (known: " + list + ")");
}

// --- The commands --------------------------------------------------------------------------

int recogniseCmd(int argc, char** argv) {
    if (argc < 3) throw aeronc::inputError("recognise needs a part file");
    std::string part = argv[2], jsonOut;
    bool faceNames = false;
    std::vector<std::string> names;
    aeronc::recognition::RecogniseOptions opt;
    forEachOption(argc, argv, [&](const std::string& a, const Next& next) {
        if (a == "--json") jsonOut = next();
        else if (a == "--directions") opt.directions = parseDirections(next());
        else if (a == "--allowance") opt.blankAllowance = std::stod(next());
        else if (a == "--tolerance") opt.linearTolerance = std::stod(next());
        else if (a == "--threads") opt.threads = std::stoi(next());
        else if (a == "--face-names") faceNames = true;
        else return false;
        return true;
    });
    aeronc::recognition::DomainTree tree;
    onPart(part, [&](const TopoDS_Shape& solid) { tree = aeronc::recognition::recognise(solid, opt); },
           faceNames ? &names : nullptr);
    std::string text = aeronc::recognition::toJson(tree);
    if (faceNames) {  // the STEP name of each face, for comparing with labelled data
        auto j = nlohmann::json::parse(text);
        j["faceNames"] = names;
        text = j.dump(1);
    }
    writeOut(jsonOut, text);
    std::map<std::string, int> counts;
    for (const auto& e : tree.elements) counts[toString(e.type)]++;
    std::cerr << part << ": " << tree.faceCount << " faces, " << tree.setups.size() << " setup(s), "
              << tree.elements.size() << " element(s):";
    for (auto& kv : counts) std::cerr << " " << kv.second << " " << kv.first;
    std::cerr << "\n";
    for (const auto& w : tree.warnings) std::cerr << "warning: " << w << "\n";
    return 0;
}

int panelCmd(int argc, char** argv) {
    if (argc < 3) throw aeronc::inputError("panel needs an output STEP path");
    aeronc::testparts::PanelSpec spec;
    std::string out = argv[2], truth;
    forEachOption(argc, argv, [&](const std::string& a, const Next& next) {
        if (a == "--pockets") {
            const std::string v = next();
            if (std::sscanf(v.c_str(), "%dx%d", &spec.pocketsX, &spec.pocketsY) != 2 || spec.pocketsX < 1 ||
                spec.pocketsY < 1)
                throw aeronc::inputError("--pockets wants NXxNY, e.g. 40x25");
        } else if (a == "--floor-fillet") {
            spec.floorFillet = std::stod(next());
        } else if (a == "--truth") {
            truth = next();
        } else if (a == "--plain") {
            spec.lowerRibs = spec.islands = spec.openings = spec.lighteningHoles = spec.boltHoles = false;
            spec.joggles = spec.flange = spec.bottomPockets = false;
        } else {
            return false;
        }
        return true;
    });
    const auto panel = aeronc::testparts::makePanel(spec);
    aeronc::writeStep(panel.shape, out);
    if (!truth.empty()) writeText(truth, aeronc::testparts::truthToJson(panel));
    return 0;
}

// select-tools and chain: a part recognised first (PART), or a stored recognition (--tree FILE);
// the knowledge base, the material and the machine checked before the (slow) recognition.
// select-tools prints the tool plan; chain the machining chain, from the plan of --tool-plan FILE
// (select-tools' JSON) or planning the tools itself.
int planCmd(int argc, char** argv, bool chain) {
    const std::string cmd = chain ? "chain" : "select-tools";
    if (argc < 3) throw aeronc::inputError(cmd + " needs a part file or --tree RECOGNITION.json");
    const bool fromTree = std::string(argv[2]) == "--tree";
    if (fromTree && argc < 4) throw aeronc::inputError("--tree needs a value");
    const std::string input = argv[fromTree ? 3 : 2];
    std::string jsonOut, kbPath, material, resources, machine, family = "integral_panel", toolPlan;
    bool directions = false;
    aeronc::recognition::RecogniseOptions opt;
    forEachOption(
        argc, argv,
        [&](const std::string& a, const Next& next) {
            if (a == "--json") jsonOut = next();
            else if (a == "--kb") kbPath = next();
            else if (a == "--material") material = next();
            else if (a == "--machine") machine = next();
            else if (a == "--directions") {
                opt.directions = parseDirections(next());
                directions = true;
            } else if (a == "--resources") resources = next();
            else if (chain && (a == "--family" || a == "--template")) family = next();
            else if (chain && a == "--tool-plan") toolPlan = next();
            else return false;
            return true;
        },
        fromTree ? 4 : 3);
    if (fromTree && directions)
        throw aeronc::inputError("--directions is for recognising a part; a --tree has its setups already");
    if (kbPath.empty()) throw aeronc::inputError(cmd + " needs --kb KB.sqlite (created when missing)");
    if (material.empty()) throw aeronc::inputError(cmd + " needs --material NAME, e.g. 7050-T7451");

    // Stored input is read first: bad input stops before a knowledge base is made.
    aeronc::recognition::DomainTree tree;
    if (fromTree) {
        const std::string text = aeronc::readTextFile(input, "recognition file");
        try {
            tree = aeronc::recognition::fromJson(text);
        } catch (const aeronc::Error& e) {
            throw aeronc::inputError(input + ": " + e.what());
        }
    }
    const std::string planText = toolPlan.empty() ? "" : aeronc::readTextFile(toolPlan, "tool plan");
    const auto kb = openKb(kbPath, resources, argv[0]);
    // The slow part last: material, machine and template are checked before recognition.
    checkMaterial(kb, material, kbPath);
    if (!machine.empty()) kb.machine(machine);  // an unknown one names the known
    if (chain) aeronc::kb::loadProcessTemplate(kb, family);
    if (!fromTree)
        onPart(input, [&](const TopoDS_Shape& solid) { tree = aeronc::recognition::recognise(solid, opt); });

    if (!chain) {
        const auto plan = aeronc::kb::planTools(tree, kb, material, machine);
        writeOut(jsonOut, aeronc::toolselect::toJson(plan, material));
        int failed = 0;
        for (const auto& c : plan.elements) failed += !c.error.empty();
        for (const auto& h : plan.holes) failed += !h.error.empty();
        std::cerr << input << ": " << plan.elements.size() << " milled element(s), " << plan.holes.size()
                  << " hole(s), " << failed << " without a tool; tool changes " << plan.merge.toolChangesBefore
                  << " -> " << plan.merge.toolChangesAfter << ", roughing time " << plan.merge.timeBefore << " -> "
                  << plan.merge.timeAfter << " min\n";
        for (const auto& c : plan.elements)
            if (!c.error.empty()) std::cerr << "warning: " << c.error << "\n";
        for (const auto& h : plan.holes)
            if (!h.error.empty()) std::cerr << "warning: " << h.error << "\n";
    } else {
        const auto c = planText.empty() ? aeronc::kb::planChain(tree, kb, material, machine, family)
                                        : aeronc::kb::planChain(tree, kb, aeronc::kb::storedToolPlan(kb, planText, material),
                                                                material, machine, family);
        writeOut(jsonOut, aeronc::chain::toJson(c));
        int failed = 0, processes = 0;
        for (const auto& k : c.checks) failed += !k.ok;
        for (const auto& s : c.setups) processes += static_cast<int>(s.processes.size());
        std::cerr << input << ": template " << c.processTemplate.name << ", " << tree.elements.size()
                  << " element(s), " << c.units.size() << " unit(s) in " << processes << " process(es), "
                  << c.unmachined.size() << " unmachined note(s); rapid travel " << c.travel.rulesOnly << " -> "
                  << c.travel.optimised << " mm (" << c.travel.savedPercent << " % saved); " << failed
                  << " rule failure(s)\n";
        for (const auto& m : c.unmachined)
            std::cerr << "unmachined: element " << m.element
                      << (m.step ? std::string(" step ") + toString(*m.step) : "") << ": " << m.reason << "\n";
        for (const auto& r : c.remainders)
            std::cerr << "left: element " << r.element << " step " << toString(r.step) << ": " << r.tool << " leaves the "
                      << (r.kind == "corners" ? "corners" : "floor fillet's foot") << ", " << r.area << " mm2 "
                      << r.depth << " mm deep; it needs " << r.needs << "\n";
        for (const auto& k : c.checks)
            if (!k.ok) std::cerr << "rule " << k.rule << ": " << k.node << ": " << k.message << "\n";
    }
    for (const auto& w : tree.warnings) std::cerr << "warning: " << w << "\n";
    return 0;
}

int selectToolsCmd(int argc, char** argv) { return planCmd(argc, argv, false); }
int chainCmd(int argc, char** argv) { return planCmd(argc, argv, true); }

int optimiseCmd(int argc, char** argv) {
    if (argc < 3) throw aeronc::inputError("optimise needs a parameter file (JSON), e.g. resources/optimise/*.json");
    std::string file = argv[2], jsonOut, kbPath, resources, method = "nlopt";
    aeronc::optimise::GeneticOptions ga;
    forEachOption(argc, argv, [&](const std::string& a, const Next& next) {
        if (a == "--json") jsonOut = next();
        else if (a == "--method") method = next();
        else if (a == "--kb") kbPath = next();
        else if (a == "--resources") resources = next();
        else if (a == "--seed") {
            const std::string v = next();
            if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos)
                throw aeronc::inputError("--seed wants a whole number, got '" + v + "'");
            ga.seed = std::stoull(v);
        }
        else return false;
        return true;
    });
    const auto how = aeronc::optimise::parseMethod(method);
    nlohmann::json params;
    try {
        params = aeronc::optimise::parameterJson(aeronc::readTextFile(file, "parameter file"));
    } catch (const aeronc::Error& e) {
        throw aeronc::inputError(file + ": " + e.what());
    }
    if (!kbPath.empty()) {
        params = aeronc::kb::withKnowledgeBase(openKb(kbPath, resources, argv[0]), params);
    } else if (params.is_object() && params.contains("kb")) {
        throw aeronc::inputError(file + " names knowledge-base rows (\"kb\"): pass --kb KB.sqlite");
    }
    aeronc::optimise::Parameters p;
    try {
        p = aeronc::optimise::parseParameters(params);
    } catch (const aeronc::Error& e) {
        throw aeronc::inputError(file + ": " + e.what());
    }
    const auto c = aeronc::optimise::compare(p, how, ga);
    std::cout << aeronc::optimise::toText(c);
    if (!jsonOut.empty()) writeText(jsonOut, aeronc::optimise::toJson(c).dump(1));
    return 0;
}

int impellerCmd(int argc, char** argv) {
    if (argc < 3) throw aeronc::inputError("impeller needs a part file");
    const std::string part = argv[2];
    std::string jsonOut;
    bool fuse = false;
    forEachOption(argc, argv, [&](const std::string& a, const Next& next) {
        if (a == "--json") jsonOut = next();
        else if (a == "--fuse") fuse = true;
        else return false;
        return true;
    });
    aeronc::impeller::ImpellerFeatures f;
    aeronc::impeller::ImpellerDimensions d;
    onImpeller(part, fuse, [&](const TopoDS_Shape& solid) {
        f = aeronc::impeller::recogniseImpeller(solid);
        d = aeronc::impeller::measureImpeller(solid, f);
    });
    writeOut(jsonOut, aeronc::impeller::impellerToJson(f, d));
    std::cerr << part << ": " << f.faceCount << " faces, " << f.bladeCount << " main and " << f.splitterCount
              << " splitter blades; bore " << d.boreDiameter << " x " << d.boreDepth << " mm, channel "
              << d.minChannelWidth << " mm, fillet " << d.filletRadius << " mm, blade height " << d.bladeHeight
              << " mm\n";
    return 0;
}

int impellerPartCmd(int argc, char** argv) {
    if (argc < 3) throw aeronc::inputError("impeller-part needs an output path (.step or .brep)");
    const std::string out = argv[2];
    std::string spec, truth;
    forEachOption(argc, argv, [&](const std::string& a, const Next& next) {
        if (a == "--spec") spec = next();
        else if (a == "--truth") truth = next();
        else return false;
        return true;
    });
    const auto imp = aeronc::testparts::makeImpeller(aeronc::testparts::impellerSpecFromJson(spec));
    const std::string ext = fs::path(out).extension().string();
    if (ext == ".brep") aeronc::writeBrep(imp.shape, out);
    else aeronc::writeStep(imp.shape, out);
    if (!truth.empty()) writeText(truth, aeronc::testparts::truthToJson(imp.truth));
    return 0;
}

nlohmann::json cuttingToJson(const std::vector<aeronc::kb::ToolCutting>& cutting) {
    auto out = nlohmann::json::array();
    for (const auto& c : cutting)
        out.push_back({{"tool", c.tool}, {"operation", c.operation}, {"rpm", c.rpm}, {"feed", c.feed},
                       {"plungeFeed", c.plungeFeed}, {"fz", c.fz}, {"ap", c.ap}, {"ae", c.ae},
                       {"length", c.length}, {"active", c.active}, {"steps", c.steps}});
    return out;
}

int impellerProgramCmd(int argc, char** argv) {
    using namespace aeronc;
    if (argc < 3) throw inputError("impeller-program needs a part file");
    const std::string part = argv[2];
    std::string kbPath, out, resources;
    bool fuse = false;
    kb::ImpellerProgramOptions opt;
    forEachOption(argc, argv, [&](const std::string& a, const Next& next) {
        if (a == "--kb") kbPath = next();
        else if (a == "--fuse") fuse = true;
        else if (a == "--out") out = next();
        else if (a == "--resources") resources = next();
        else if (a == "--material") opt.material = next();
        else if (a == "--machine") opt.machine = next();
        else if (a == "--stations") opt.paths.stations = std::stoi(next());
        else if (a == "--channels") opt.paths.channels = std::stoi(next());
        else return false;
        return true;
    });
    if (kbPath.empty() || out.empty()) throw inputError("impeller-program needs --kb and --out");
    if (opt.paths.stations < 2 || opt.paths.stations > 200) throw inputError("--stations wants 2 to 200");
    const auto kbDir = kbResources(resources, argv[0]);
    const auto kb = kb::KnowledgeBase::openWithSqlFolder(kbPath, [&] { return kbDir.string(); });
    checkMaterial(kb, opt.material, kbPath);
    kb.machine(opt.machine);  // its limits; an unknown one names the known
    // The machine's kinematics for the post: the machine file of the same name.
    const fs::path machineFile = kbDir / ".." / "machines" / (opt.machine + ".json");
    if (!fs::is_regular_file(machineFile))
        throw inputError("machine " + opt.machine + ": no machine file " + machineFile.lexically_normal().string());
    const auto machine = kinematics::loadMachineFile(machineFile.string());
    fs::create_directories(out);
    using Clock = std::chrono::steady_clock;
    auto secs = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    impeller::ImpellerFeatures f;
    impeller::ImpellerDimensions d;
    impeller::ProcessRoute route;
    kb::ImpellerProgramming prog;
    impellerpath::CheckResult again, rapids;
    nlohmann::json opChecks = nlohmann::json::array();  // the re-read check of each 5-axis operation
    double tRecognise = 0, tPaths = 0, tCheck = 0;
    std::string apt, axialApt;
    onImpeller(part, fuse, [&](const TopoDS_Shape& solid) {
        auto t0 = Clock::now();
        f = impeller::recogniseImpeller(solid);
        d = impeller::measureImpeller(solid, f);
        tRecognise = secs(t0);
        route = kb::planImpellerRoute(kb, f, d);
        t0 = Clock::now();
        prog = kb::programImpeller(solid, f, d, route.steps, kb, opt);
        tPaths = secs(t0);
        apt = post::writeApt(impellerpath::toClProgram(prog.fiveAxis, "IMPELLER"));
        // The program as posted, read back and checked again: the gouge and holder check, the
        // rapids against the blank.
        t0 = Clock::now();
        std::vector<impellerpath::CutterShape> cutters;
        for (const auto& op : prog.fiveAxis.operations) cutters.push_back(op.cutter);
        const auto reread = impellerpath::movesOf(post::readApt(apt), cutters);
        // Operation by operation, so that what gouges or collides is named.
        for (size_t i = 0; i < reread.size(); ++i) {
            const auto& op = reread[i];
            const auto c = impellerpath::checkProgram(solid, f, {op});
            opChecks.push_back({{"operation", prog.fiveAxis.operations.at(i).name}, {"tool", op.first.id},
                                {"positions", c.positions}, {"maxGougeMm", c.maxGouge},
                                {"holderCollisions", c.holderCollisions}, {"minHolderGapMm", c.minHolderGap},
                                {"worstAt", {c.worstAt[0], c.worstAt[1], c.worstAt[2]}}});
            again.positions += c.positions;
            again.holderCollisions += c.holderCollisions;
            again.minHolderGap = std::min(again.minHolderGap, c.minHolderGap);
            if (c.maxGouge > again.maxGouge) again.maxGouge = c.maxGouge, std::copy(c.worstAt, c.worstAt + 3, again.worstAt);
        }
        rapids = impellerpath::checkRapids(impeller::outerProfile(solid, f, opt.paths.blankAllowance), f, reread,
                                           opt.paths.rapidClearance - 1e-6);
        tCheck = secs(t0);
        // The steps about and along the axis (lathe, facing, drilling, boring): checked, written as APT.
        impellerpath::ImpellerProgram axial;
        axial.operations = prog.axial.operations;
        axialApt = post::writeApt(impellerpath::toClProgram(axial, "IMPELLER_AXIAL"));
    });
    post::NcOptions nc;
    nc.programName = "IMPELLER";
    const auto posted = post::postApt(apt, machine, nc, {});
    const auto& ops = prog.fiveAxis.operations;
    auto doc = nlohmann::json::parse(impeller::impellerToJson(f, d));
    doc["route"] = nlohmann::json::parse(impeller::routeToJson(route));
    size_t moves = 0;
    for (const auto& op : ops) moves += op.moves.size();
    auto cutterJson = [](const impellerpath::CutterShape& c) {
        return nlohmann::json{{"id", c.id}, {"number", c.number}, {"rpm", c.rpm}, {"feed", c.feed}};
    };
    doc["toolpaths"] = {{"moves", moves},
                        {"positionsChecked", again.positions},
                        {"maxGougeMm", again.maxGouge},
                        {"holderCollisions", again.holderCollisions},
                        {"minHolderGapMm", again.minHolderGap},
                        {"operations", opChecks},
                        {"tilted", prog.fiveAxis.check.tilted},
                        {"leftOut", prog.fiveAxis.check.leftOut},
                        {"links", prog.fiveAxis.check.links},
                        {"linkCollisions", prog.fiveAxis.check.linkCollisions},
                        {"rapidsChecked", rapids.links},
                        {"rapidCollisions", rapids.linkCollisions},
                        {"seconds", {{"recognise", tRecognise}, {"toolpaths", tPaths}, {"recheck", tCheck}}},
                        {"rougher", cutterJson(ops.at(0).cutter)},
                        {"finisher", cutterJson(ops.at(1).cutter)}};
    doc["machine"] = opt.machine;
    doc["cutting"] = cuttingToJson(prog.cutting);
    nlohmann::json axialOps = nlohmann::json::object();
    for (const auto& op : prog.axial.operations) {
        int cutting = 0;
        for (const auto& m : op.moves) cutting += !m.rapid;
        axialOps[op.name] = {{"tool", op.cutter.id}, {"moves", op.moves.size()}, {"cutting", cutting}};
    }
    doc["axialOperations"] = {{"operations", axialOps},
                              {"positionsChecked", prog.axial.check.positions},
                              {"maxGougeMm", prog.axial.check.maxGouge},
                              {"holderCollisions", prog.axial.check.holderCollisions},
                              {"notes", prog.axial.notes}};
    const fs::path dir(out);
    writeText((dir / "impeller.json").string(), doc.dump(1));
    writeText((dir / "IMPELLER.apt").string(), apt);
    writeText((dir / "IMPELLER.mpf").string(), posted.text);
    writeText((dir / "IMPELLER_AXIAL.apt").string(), axialApt);
    std::cerr << part << ": " << f.bladeCount << " + " << f.splitterCount << " blades, recognised in " << tRecognise
              << " s; " << moves << " moves in " << tPaths << " s; re-read program: " << again.positions
              << " positions, deepest gouge " << again.maxGouge << " mm, " << again.holderCollisions
              << " holder collisions, " << prog.fiveAxis.check.tilted << " tilted; " << rapids.links << " rapids, "
              << rapids.linkCollisions << " into the blank; " << posted.lines << " lines of 840D for the "
              << opt.machine << " in " << (dir / "IMPELLER.mpf").string() << "\n";
    return again.maxGouge <= 0.01 && again.holderCollisions == 0 && rapids.linkCollisions == 0 &&
                   prog.fiveAxis.check.linkCollisions == 0 && prog.axial.check.maxGouge <= 0.01 &&
                   prog.axial.check.holderCollisions == 0
               ? 0
               : 1;
}

// --- The table ------------------------------------------------------------------------------

struct Command {
    const char* name;
    const char* alias;  // another spelling, or null
    // Reads a part (its first argument, unless --tree names a stored recognition): runs in a
    // child process that a fault or --time-limit ends without taking this process along.
    bool readsPart;
    int (*run)(int argc, char** argv);
    const char* usage;
};

const Command kCommands[] = {
    {"recognise", "recognize", true, recogniseCmd,
     "  aeronc recognise PART [--json OUT] [--directions auto|+Z,-Z|x:y:z,...] [--allowance MM] [--tolerance MM]\n"
     "                   [--threads N] [--face-names] [--time-limit S]\n"},
    {"panel", nullptr, false, panelCmd,
     "  aeronc panel OUT.step [--pockets NXxNY] [--floor-fillet R] [--truth TRUTH.json] [--plain]\n"},
    {"select-tools", nullptr, true, selectToolsCmd,
     "  aeronc select-tools PART|--tree RECOGNITION.json --kb KB.sqlite --material NAME [--machine NAME]\n"
     "                      [--directions auto|+Z,-Z|x:y:z,...] [--json OUT] [--resources DIR] [--time-limit S]\n"
     "      (PART is recognised first; --tree plans a stored recognition, e.g. recognise's --json;\n"
     "       a missing KB file is created from DIR/schema.sql and DIR/default_data.sql)\n"},
    {"optimise", "optimize", false, optimiseCmd,
     "  aeronc optimise PARAMS.json [--json OUT] [--method nlopt|ga|both] [--seed N] [--kb KB.sqlite] [--resources DIR]\n"
     "      (cutting-parameter optimisation; with --kb, PARAMS names KB rows in a \"kb\" section)\n"},
    {"chain", nullptr, true, chainCmd,
     "  aeronc chain PART|--tree RECOGNITION.json --kb KB.sqlite --material NAME [--machine NAME]\n"
     "               [--family F | --template T] [--tool-plan TOOLS.json] [--directions auto|+Z,-Z|x:y:z,...]\n"
     "               [--json OUT] [--resources DIR] [--time-limit S]\n"
     "      (the NC machining chain: units, order, travel, rule checks; family default integral_panel;\n"
     "       --tool-plan: the tools select-tools planned (its --json), else the tools are planned here)\n"},
    {"impeller", nullptr, true, impellerCmd,
     "  aeronc impeller PART [--fuse] [--json OUT] [--time-limit S]\n"
     "      (impeller recognition by rules and its dimensions, docs/impeller.md; --fuse: a part of\n"
     "       several bodies, e.g. hub and blades exported apart, is fused into one solid first)\n"},
    {"impeller-part", nullptr, false, impellerPartCmd,
     "  aeronc impeller-part OUT.step|OUT.brep [--spec JSON] [--truth TRUTH.json]\n"
     "      (a generated impeller; JSON keys as ImpellerSpec, e.g. '{\"bladeCount\": 7}')\n"},
    {"impeller-program", nullptr, true, impellerProgramCmd,
     "  aeronc impeller-program PART --kb KB.sqlite --out DIR [--fuse] [--material NAME] [--machine NAME] [--stations N]\n"
     "                          [--channels N] [--resources DIR] [--time-limit S]\n"
     "      (recognition, route, 5-axis toolpaths checked for gouges and holder collisions, cutting data,\n"
     "       APT and the 840D program under TRAORI for the machine (default AC-5AX), in DIR; docs/impeller.md)\n"},
};

std::string usage() {
    std::string text = "usage:\n";
    for (const Command& c : kCommands) text += c.usage;
    text += "  --time-limit S: give up reading and recognising the part after S seconds\n";
    return text;
}

const Command* findCommand(const std::string& name) {
    for (const Command& c : kCommands)
        if (name == c.name || (c.alias && name == c.alias)) return &c;
    return nullptr;
}

// One command, every failure a one-line message: exit 1 for an error.
int runCommand(const Command& cmd, int argc, char** argv) {
    try {
        return cmd.run(argc, argv);
    } catch (const aeronc::Error& e) {
        std::cerr << "aeronc: error: " << e.what() << "\n";
        return 1;
    } catch (const Standard_Failure& f) {
        std::cerr << "aeronc: error: OpenCASCADE: " << f.GetMessageString() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "aeronc: error: " << e.what() << "\n";
        return 1;
    }
}

// OCCT's STEP reader and writer print statistics on stdout, which is the JSON's channel.
void quietOcct() {
    const Handle(Message_Messenger)& m = Message::DefaultMessenger();
    m->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
}

// The last line of defence for the commands that read a part: a fault the OCCT handlers cannot
// turn into an error (one in another thread, one that breaks the handler itself) kills only a
// child process; this process reports it in one line and exits 1, never with a signal.
// timeLimit > 0: the child is stopped after that many seconds (OCCT's shape healing can loop
// for good on a damaged file, and takes no request to stop).
int inChildProcess(const std::function<int()>& command, const std::string& input, unsigned timeLimit) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid < 0) return command();  // no child to be had: run here
    if (pid == 0) {
        if (timeLimit > 0) alarm(timeLimit);
        const int code = command();
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        _exit(code);  // no static destructors after a fault the handlers caught
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) {
            std::cerr << "aeronc: error: lost the process reading " << input << "\n";
            return 1;
        }
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    if (sig == SIGALRM) {
        std::cerr << "aeronc: error: " << input << ": reading or recognising the part took longer than --time-limit "
                  << timeLimit << " s; the file is probably damaged\n";
        return 1;
    }
    std::cerr << "aeronc: error: " << input << ": reading or recognising the part failed with signal " << sig << " ("
              << strsignal(sig) << "); the file is probably damaged\n";
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    quietOcct();
    if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
        std::cerr << usage();
        return argc < 2 ? 2 : 0;
    }
    const Command* cmd = findCommand(argv[1]);
    if (!cmd) {
        std::cerr << "aeronc: unknown command '" << argv[1] << "'\n" << usage();
        return 2;
    }
    const bool readsPart = cmd->readsPart && argc > 2 && std::string(argv[2]) != "--tree";
    if (!readsPart) return runCommand(*cmd, argc, argv);
    // --time-limit SECONDS belongs to the child process, not to the command.
    std::vector<char*> args;
    unsigned timeLimit = 0;
    for (int i = 0; i < argc; ++i) {
        if (std::string(argv[i]) != "--time-limit") {
            args.push_back(argv[i]);
            continue;
        }
        const std::string v = i + 1 < argc ? argv[++i] : "";
        if (v.empty() || v.size() > 6 || v.find_first_not_of("0123456789") != std::string::npos || std::stoul(v) == 0) {
            std::cerr << "aeronc: error: --time-limit wants a whole number of seconds from 1 to 999999\n";
            return 1;
        }
        timeLimit = static_cast<unsigned>(std::stoul(v));
    }
    args.push_back(nullptr);
    const int n = static_cast<int>(args.size()) - 1;
    return inChildProcess([&] { return runCommand(*cmd, n, args.data()); }, argv[2], timeLimit);
}
