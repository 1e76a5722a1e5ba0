// Recognition time against face count for generated panels of 10 to 1,000 pockets,
// beside the STEP import time of the same file and the peak memory; or, with --parts, the
// same for given STEP files (automatic setup directions).
// Usage: aeronc_bench [--sizes 10,100,1000] [--dir FOLDER]
//        aeronc_bench --parts A.stp B.stp ...
// Each size or part runs in a child process so its peak memory is its own.
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>

#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {
using Clock = std::chrono::steady_clock;
double secs(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

std::pair<int, int> grid(int pockets) {
    int nx = static_cast<int>(std::ceil(std::sqrt(pockets * 1.6)));
    int ny = std::max(1, (pockets + nx - 1) / nx);
    while (nx * ny > pockets && nx > 1 && (nx - 1) * ny >= pockets) --nx;
    return {nx, ny};
}

double importSeconds(const std::string& path, TopoDS_Shape& shape) {
    const auto t0 = Clock::now();
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error("cannot read " + path);
    reader.TransferRoots();
    shape = reader.OneShape();
    return secs(t0);
}

// One STEP part: import, then recognition with automatic setups (best of `runs`).
void measurePart(const std::string& path, int runs) {
    TopoDS_Shape shape;
    double tImport = importSeconds(path, shape);
    for (int r = 1; r < runs; ++r) tImport = std::min(tImport, importSeconds(path, shape));
    const TopoDS_Shape solid = aeronc::validatedSolid(shape, path);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    double tRec = 1e300;
    std::size_t elements = 0, setups = 0;
    for (int r = 0; r < runs; ++r) {
        const auto t1 = Clock::now();
        const auto tree = aeronc::recognition::recognise(solid);
        tRec = std::min(tRec, secs(t1));
        elements = tree.elements.size(), setups = tree.setups.size();
    }
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    std::printf("%-30s %6d %9.3f %11.3f %7.2f %6zu %8zu %9.1f\n",
                std::filesystem::path(path).filename().string().c_str(), faces.Extent(), tImport, tRec, tRec / tImport,
                setups, elements, ru.ru_maxrss / 1024.0);
    std::fflush(stdout);
}

void measure(int pockets, const std::string& dir) {
    const auto [nx, ny] = grid(pockets);
    const std::string path = dir + "/panel_" + std::to_string(nx) + "x" + std::to_string(ny) + ".step";
    if (!std::filesystem::exists(path)) {
        // Generated in a child so the measuring process never holds the generator's memory.
        const pid_t pid = fork();
        if (pid == 0) {
            aeronc::testparts::PanelSpec s;
            s.pocketsX = nx, s.pocketsY = ny;
            aeronc::writeStep(aeronc::testparts::makePanel(s).shape, path);
            _exit(0);
        }
        int st = 0;
        waitpid(pid, &st, 0);
    }
    const auto t0 = Clock::now();
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
        std::printf("%8d  cannot read %s\n", nx * ny, path.c_str());
        return;
    }
    reader.TransferRoots();
    const TopoDS_Shape shape = reader.OneShape();
    const double tImport = secs(t0);
    const TopoDS_Shape solid = aeronc::validatedSolid(shape, path);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    aeronc::recognition::RecogniseOptions o;
    o.directions = {{0, 0, 1}, {0, 0, -1}};
    const auto t1 = Clock::now();
    const auto tree = aeronc::recognition::recognise(solid, o);
    const double tRec = secs(t1);
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    std::printf("%8d %8d %10.3f %12.3f %7.2f %9zu %10.1f\n", nx * ny, faces.Extent(), tImport, tRec, tRec / tImport,
                tree.elements.size(), ru.ru_maxrss / 1024.0);
    std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));  // keep the table clean
    std::vector<int> sizes{10, 50, 100, 250, 500, 1000};
    std::string dir = (std::filesystem::temp_directory_path() / "aeronc-bench").string();
    if (argc > 1 && !std::strcmp(argv[1], "--parts")) {
        std::printf("# recognition (automatic setups) vs STEP import, best of 3 runs each\n");
        std::printf("%-30s %6s %9s %11s %7s %6s %8s %9s\n", "# part", "faces", "import_s", "recognise_s", "ratio",
                    "setups", "elements", "peak_MiB");
        std::fflush(stdout);
        for (int i = 2; i < argc; ++i) {
            const pid_t pid = fork();
            if (pid == 0) {
                try {
                    measurePart(argv[i], 3);
                } catch (const std::exception& e) {
                    std::printf("%-30s error: %s\n", argv[i], e.what());
                }
                std::fflush(stdout);
                _exit(0);
            }
            int st = 0;
            waitpid(pid, &st, 0);
        }
        return 0;
    }
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--sizes")) {
            sizes.clear();
            std::stringstream ss(argv[i + 1]);
            std::string t;
            while (std::getline(ss, t, ',')) sizes.push_back(std::stoi(t));
        } else if (!std::strcmp(argv[i], "--dir")) {
            dir = argv[i + 1];
        }
    }
    std::filesystem::create_directories(dir);
    std::printf("# recognition vs STEP import, generated panels (setups +Z,-Z)\n");
    std::printf("# pockets    faces  import_s  recognise_s   ratio  elements  peak_MiB\n");
    std::fflush(stdout);
    for (int n : sizes) {
        const pid_t pid = fork();
        if (pid == 0) {
            try {
                measure(n, dir);
            } catch (const std::exception& e) {
                std::printf("%8d  error: %s\n", n, e.what());
            }
            std::fflush(stdout);
            _exit(0);
        }
        int st = 0;
        waitpid(pid, &st, 0);
    }
    return 0;
}
