// libFuzzer target: a `measurements` dictionary (docs/file-formats.md,
// "Measured data") and one force-displacement curve file.
//
// Input layout: the dictionary text, then optionally a NUL byte and the
// contents of the curve file, which the dictionary can name as
// `curve "c.dat";`. The dictionary is parsed without #include, and inputs
// that could name a device or leave the scratch directory ("dev", "..") are
// skipped: the fuzzer must only read what it wrote. A set that reads has at least one specimen, each
// with a positive, finite failure load.
#include <cmath>
#include <cstdlib>

#include "../common/fuzzTarget.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "stats/measurements.hpp"

namespace rockfrac::fuzz {

int fuzzMeasurements(const std::uint8_t* data, std::size_t size)
{
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = input.find('\0');
    const std::string text = input.substr(0, nul);
    if (text.find("dev") != std::string::npos || text.find("..") != std::string::npos) return 0;
    const std::filesystem::path dir = scratchDirectory();
    writeBytes(dir / "c.dat", nul == std::string::npos ? std::string() : input.substr(nul + 1));

    ParseLimits limits;
    limits.maxValues = 100000;
    limits.allowIncludes = false;
    try {
        const Dictionary dict = Dictionary::parse(text, (dir / "measurements").string(), limits);
        const stats::MeasurementSet set = stats::readMeasurements(dict, dir / "measurements");
        if (set.specimens.empty()) std::abort();
        for (const auto& specimen : set.specimens)
            if (!(specimen.failureLoad > 0) || !std::isfinite(specimen.failureLoad)) std::abort();
    } catch (const UserError&) {
    }
    return 0;
}

}  // namespace rockfrac::fuzz

ROCKFRAC_FUZZ_ENTRY(rockfrac::fuzz::fuzzMeasurements)
