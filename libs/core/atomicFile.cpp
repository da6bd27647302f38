// Atomic file writes: temporary name beside the target, then rename.
#include "core/atomicFile.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/error.hpp"
#include "core/faultPoint.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

fs::path temporaryPathFor(const fs::path& path)
{
    // Keep the extension last so that writers choosing a format by extension
    // (VTK's XML writers do not, but others might) still see the right one.
    return path.parent_path() / (".tmp." + std::to_string(::getpid()) + "." + path.filename().string());
}

namespace {

void createParent(const fs::path& path)
{
    if (path.parent_path().empty()) return;
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec)
        throw UserError("cannot create directory '" + path.parent_path().string() + "': " + ec.message() +
                        "; check the permissions and free space of the case directory");
}

void renameOver(const fs::path& from, const fs::path& to)
{
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec) {
        fs::remove(from, ec);
        throw UserError("cannot write '" + to.string() + "': " + ec.message() +
                        "; the previous version of the file is kept");
    }
}

}  // namespace

void writeFileAtomically(const fs::path& path, const std::function<void(std::ostream&)>& writer)
{
    createParent(path);
    const fs::path tmp = temporaryPathFor(path);
    {
        errno = 0;
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            // The stream need not set errno ("Success"): say what the directory allows.
            const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
            const std::string reason = errno != 0                         ? std::strerror(errno)
                                       : ::access(dir.c_str(), W_OK) != 0 ? "its directory is not writable"
                                                                          : "the file cannot be created";
            throw UserError("cannot write '" + path.string() + "': " + reason +
                            "; check the permissions of its directory");
        }
        try {
            writer(out);
        } catch (...) {
            out.close();
            std::error_code ec;
            fs::remove(tmp, ec);
            throw;
        }
        out.flush();
        const std::streamoff written = out ? static_cast<std::streamoff>(out.tellp()) : -1;
        out.close();
        // The stream's state after flush and close, and the size the file system reports:
        // a short write on a full disk is caught here, before the rename.
        std::error_code ec;
        const auto size = fs::file_size(tmp, ec);
        if (!out || written < 0 || ec || static_cast<std::streamoff>(size) != written) {
            fs::remove(tmp, ec);
            throw UserError("cannot write '" + path.string() +
                            "' (disk full or I/O error); the previous version of the file is kept");
        }
    }
    faultPoint("beforeRename");
    renameOver(tmp, path);
}

void writeViaTemporary(const fs::path& path, const std::function<bool(const fs::path&)>& writer)
{
    createParent(path);
    const fs::path tmp = temporaryPathFor(path);
    bool ok = false;
    try {
        ok = writer(tmp);
    } catch (...) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw;
    }
    if (!ok) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw UserError("cannot write '" + path.string() +
                        "' (disk full, permissions or I/O error); the previous version of the file is kept");
    }
    renameOver(tmp, path);
}

bool fileTailContains(const fs::path& path, const std::string& marker, std::size_t window)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size <= 0) return false;
    const std::streamoff n = std::min<std::streamoff>(size, static_cast<std::streamoff>(window));
    in.seekg(size - n);
    std::string tail(static_cast<std::size_t>(n), '\0');
    in.read(tail.data(), n);
    return in && tail.find(marker) != std::string::npos;
}

}  // namespace rockfrac
