// Machining-chain figures for generated double-sided panels of 10 to 1,000 pockets: recognition
// and tool planning (the chain's inputs) apart, then the chain itself: fusing (units, with the
// machinable-region checks of rest machining), sequencing (rules and travel optimisation), the
// seven-level tree and the rule checks. Toolpaths are not part of it.
//   aeronc_chain_bench [--sizes 10,100,1000] [--material 7050-T7451]
#include <aeronc/chain/ConstructionRules.h>
#include <aeronc/chain/Fusing.h>
#include <aeronc/chain/Sequencing.h>
#include <aeronc/core/Error.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/kb/ProcessTemplates.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>
#include <aeronc/kb/ToolPlanning.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The same grid as the recognition bench: about 1.6 times as wide as deep.
std::pair<int, int> grid(int pockets) {
    int nx = static_cast<int>(std::ceil(std::sqrt(pockets * 1.6)));
    int ny = std::max(1, (pockets + nx - 1) / nx);
    while (nx * ny > pockets && nx > 1 && (nx - 1) * ny >= pockets) --nx;
    return {nx, ny};
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> sizes = {10, 100, 1000};
    std::string material = "7050-T7451";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--sizes" && i + 1 < argc) {
            sizes.clear();
            std::stringstream ss(argv[++i]);
            for (std::string t; std::getline(ss, t, ',');) sizes.push_back(std::stoi(t));
        } else if (a == "--material" && i + 1 < argc) {
            material = argv[++i];
        } else {
            std::cerr << "usage: aeronc_chain_bench [--sizes 10,100,1000] [--material NAME]\n";
            return 2;
        }
    }
    try {
        const auto dir = std::filesystem::temp_directory_path() / ("aeronc_chain_bench_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        const auto kb = aeronc::kb::KnowledgeBase::openWithSqlFolder(
            (dir / "kb.sqlite").string(), [] { return std::string(AERONC_RESOURCES "/kb"); });
        const auto tmpl = aeronc::kb::loadProcessTemplate(kb, "integral_panel");
        const auto options = aeronc::kb::chainOptions(kb, material, "");

        std::printf("%8s %9s %6s | %11s %8s | %7s %9s %7s %7s %7s | %12s %12s %6s %5s\n", "pockets", "elements",
                    "units", "recognise_s", "tools_s", "fuse_s", "sequence_s", "tree_s", "rules_s", "chain_s",
                    "travel_rules", "travel_opt", "saved%", "fails");
        for (int pockets : sizes) {
            const auto [nx, ny] = grid(pockets);
            aeronc::testparts::PanelSpec spec;  // every feature kind, pockets on both faces
            spec.pocketsX = nx;
            spec.pocketsY = ny;
            const auto panel = aeronc::testparts::makePanel(spec);
            const TopoDS_Shape solid = aeronc::validatedSolid(panel.shape, "panel");
            aeronc::recognition::RecogniseOptions ro;
            ro.directions = {{0, 0, 1}, {0, 0, -1}};

            auto t = Clock::now();
            const auto tree = aeronc::recognition::recognise(solid, ro);
            const double recognise = since(t);
            t = Clock::now();
            const auto plan = aeronc::kb::planTools(tree, kb, material, options.machine);
            const double tools = since(t);

            const auto settings = aeronc::kb::toolSettings(kb, plan.tools, material, options.machine);
            const auto start = Clock::now();
            t = start;
            auto chain = aeronc::chain::fuse(tree, plan, tmpl, options, settings);
            const double fuse = since(t);
            t = Clock::now();
            aeronc::chain::sequence(chain, options.optimiseTravel);
            const double sequence = since(t);
            t = Clock::now();
            aeronc::chain::arrange(chain);
            const double arrange = since(t);
            t = Clock::now();
            chain.checks = aeronc::chain::checkRules(chain);
            const double rules = since(t);
            const double total = since(start);

            int fails = 0;
            for (const auto& c : chain.checks) fails += !c.ok;
            std::printf("%8d %9zu %6zu | %11.3f %8.3f | %7.3f %9.3f %7.3f %7.3f %7.3f | %12.0f %12.0f %6.1f %5d\n",
                        nx * ny, tree.elements.size(), chain.units.size(), recognise, tools, fuse, sequence, arrange,
                        rules, total, chain.travel.rulesOnly, chain.travel.optimised, chain.travel.savedPercent,
                        fails);
            std::fflush(stdout);
        }
        std::filesystem::remove_all(dir);
    } catch (const aeronc::Error& e) {
        std::cerr << "aeronc_chain_bench: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
