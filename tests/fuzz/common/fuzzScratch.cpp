#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "fuzzTarget.hpp"

namespace rockfrac::fuzz {

namespace fs = std::filesystem;

namespace {
struct Scratch {
    fs::path dir;
    Scratch()
    {
        const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
        dir = base / ("rockfrac-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(dir);
    }
    ~Scratch()
    {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};
}  // namespace

const fs::path& scratchDirectory()
{
    static const Scratch scratch;
    return scratch.dir;
}

void writeBytes(const fs::path& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) std::abort();  // the scratch directory must be writable: not a reader bug, but fatal
}

}  // namespace rockfrac::fuzz
