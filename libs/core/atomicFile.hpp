#pragma once
// Atomic file writes: write to a temporary name beside the target, flush, then
// rename over the target. An interrupted run never leaves a torn file: the
// target is either the old complete file or the new complete file.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace rockfrac {

// Write `path` through `writer`; creates parent directories. UserError naming
// the file on any I/O failure (disk full, permissions); the old file is kept.
void writeFileAtomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& writer);

// For writers that insist on a file name (VTK): call `writer(tmpName)` and then
// rename tmpName over `path`. If writer throws or returns false, tmp is removed.
void writeViaTemporary(const std::filesystem::path& path,
                       const std::function<bool(const std::filesystem::path&)>& writer);

// For files a third-party program writes itself (gmsh's .msh, gnuplot's PNG), whose write
// errors it may not report: does the file end in its format's closing marker ("$End..." of
// a .msh section, a PNG's "IEND" chunk) within its last `window` bytes? A file cut short by
// a full disk does not.
bool fileTailContains(const std::filesystem::path& path, const std::string& marker, std::size_t window);

// Temporary name used for `path` (same directory, so rename is atomic).
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);

}  // namespace rockfrac
