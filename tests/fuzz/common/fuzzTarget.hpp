#pragma once
// Shared by the libFuzzer targets under tests/fuzz/: each target defines one
// function `int fuzz<Reader>(const std::uint8_t*, std::size_t)` with the
// promise it checks, and ROCKFRAC_FUZZ_ENTRY turns it into libFuzzer's entry
// point. The same functions are compiled into the unit test fuzzRegressions
// (with ROCKFRAC_FUZZ_NO_MAIN), which replays every saved input through the
// ordinary, non-instrumented readers so that a crash once fixed stays fixed.
//
// The promise of every reader: for any bytes, it returns a value or throws a
// UserError. Anything else - a crash, a sanitizer report, another exception,
// a hang, an allocation beyond what the input holds - is a bug.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#ifdef ROCKFRAC_FUZZ_NO_MAIN
#define ROCKFRAC_FUZZ_ENTRY(function)
#else
#define ROCKFRAC_FUZZ_ENTRY(function)                                                 \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) \
    {                                                                                 \
        return function(data, size);                                                  \
    }
#endif

namespace rockfrac::fuzz {

int fuzzStl(const std::uint8_t* data, std::size_t size);
int fuzzStateFile(const std::uint8_t* data, std::size_t size);
int fuzzVoronoiMesh(const std::uint8_t* data, std::size_t size);
int fuzzMeasurements(const std::uint8_t* data, std::size_t size);
int fuzzDictionary(const std::uint8_t* data, std::size_t size);

// A scratch directory private to this process (under /dev/shm when it exists,
// so the targets that must go through files do not wear the disk), created on
// first use and removed at exit.
const std::filesystem::path& scratchDirectory();

// Write `bytes` to `path` (plain write: the scratch directory is private).
void writeBytes(const std::filesystem::path& path, const std::string& bytes);

}  // namespace rockfrac::fuzz
