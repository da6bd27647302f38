#include "core/memoryLimit.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace rockfrac {

namespace {
const char* const limitVariable = "ROCKFRAC_MEMORY_LIMIT_BYTES";

std::optional<std::uint64_t> memAvailable()
{
    std::ifstream in("/proc/meminfo");
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key;
        std::uint64_t kB = 0;
        if (words >> key >> kB && key == "MemAvailable:") return kB * 1024;
    }
    return std::nullopt;
}
}  // namespace

std::optional<MemoryBudget> memoryBudget()
{
    if (const char* text = std::getenv(limitVariable); text && *text) {
        char* end = nullptr;
        errno = 0;
        const unsigned long long value = std::strtoull(text, &end, 10);
        if (*end != '\0' || text[0] == '-' || errno == ERANGE)
            throw UserError(std::string(limitVariable) + "='" + text +
                            "' is not a number of bytes; unset it or give e.g. 8000000000");
        return MemoryBudget{value, limitVariable};
    }
    if (const auto bytes = memAvailable()) return MemoryBudget{*bytes, "MemAvailable in /proc/meminfo"};
    return std::nullopt;
}

void checkMemoryFits(std::uint64_t estimatedBytes, const std::string& what, const std::string& advice)
{
    const auto budget = memoryBudget();
    if (!budget || estimatedBytes <= budget->bytes) return;
    throw UserError(what + ": the run needs an estimated " + formatBytes(estimatedBytes) +
                    " of memory, only " + formatBytes(budget->bytes) + " are available (" + budget->source +
                    "); " + advice);
}

std::string estimateLine(std::uint64_t estimatedBytes, const std::string& counts)
{
    const auto budget = memoryBudget();
    return "Estimate: " + counts + ", ~" + formatBytes(estimatedBytes) + " peak memory; " +
           (budget ? "available " + formatBytes(budget->bytes) + " (" + budget->source + ")"
                   : std::string("available: unknown (no ROCKFRAC_MEMORY_LIMIT_BYTES, no /proc/meminfo)"));
}

std::string formatBytes(std::uint64_t bytes)
{
    const char* units[] = {"bytes", "kB", "MB", "GB", "TB"};
    double value = static_cast<double>(bytes);
    int unit = 0;
    while (value >= 1000 && unit < 4) value /= 1000, ++unit;
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, unit ? "%.3g %s" : "%.0f %s", value, units[unit]);
    return buffer;
}

}  // namespace rockfrac
