#include <aeronc/core/Error.h>
#include <aeronc/core/TextFile.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

namespace aeronc {

std::string readTextFile(const std::string& path, const std::string& what) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw inputError(what + " " + path + " is a folder, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw inputError(what + " " + path + " cannot be read (missing or not readable)");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeTextFileAtomically(const std::string& path, const std::string& text) {
    const fs::path target(path);
    std::error_code ec;
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    if (ec) throw inputError("cannot create the folder " + target.parent_path().string() + " (" + ec.message() + ")");
    const std::string tmp = path + ".part";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << text;
        out.flush();
        if (!out) {
            out.close();
            fs::remove(tmp, ec);
            throw inputError("cannot write " + path);
        }
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw inputError("cannot write " + path + " (" + ec.message() + ")");
    }
}

}  // namespace aeronc
