// libFuzzer target: arbitrary bytes as a solver state file (<time>/demState,
// <time>/femState). The trailing checksum would stop almost every mutation at
// the door, so each input is read twice: as it is, and with its last 8 bytes
// replaced by the correct checksum of the rest, which lets the fuzzer reach the
// array parsing behind it.
#include <cstdlib>
#include <cstring>

#include "../common/fuzzTarget.hpp"
#include "core/checksum.hpp"
#include "core/error.hpp"
#include "io/stateFile.hpp"

namespace rockfrac::fuzz {

namespace {

void readOne(const std::string& bytes)
{
    try {
        (void)StateFile::parse(bytes, "fuzzState");
    } catch (const UserError&) {
    }
}

}  // namespace

int fuzzStateFile(const std::uint8_t* data, std::size_t size)
{
    std::string bytes(reinterpret_cast<const char*>(data), size);
    readOne(bytes);
    if (bytes.size() >= 8) {
        const std::uint64_t sum = fnv1a(bytes.data(), bytes.size() - 8);
        std::memcpy(&bytes[bytes.size() - 8], &sum, 8);
        readOne(bytes);
    }
    return 0;
}

}  // namespace rockfrac::fuzz

ROCKFRAC_FUZZ_ENTRY(rockfrac::fuzz::fuzzStateFile)
