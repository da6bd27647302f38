#include "core/faultPoint.hpp"

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>

#include "core/error.hpp"

namespace rockfrac {

namespace {

struct KillAt {
    std::string point;  // empty: no fault injection
    long count = 0;
};

KillAt parseKillAt()
{
    const char* text = std::getenv("ROCKFRAC_KILL_AT");
    if (!text || !*text) return {};
    const std::string value = text;
    const auto colon = value.rfind(':');
    char* end = nullptr;
    const long n = colon == std::string::npos ? 0 : std::strtol(value.c_str() + colon + 1, &end, 10);
    if (colon == std::string::npos || colon == 0 || !end || *end != '\0' || n < 1)
        throw UserError("environment variable ROCKFRAC_KILL_AT='" + value +
                        "' is not '<point>:<n>' with n >= 1 (a test's fault injection); unset it");
    return {value.substr(0, colon), n};
}

}  // namespace

void faultPoint(const char* point)
{
    static const KillAt killAt = parseKillAt();
    if (killAt.point.empty() || killAt.point != point) return;
    static std::mutex mutex;
    static long passed = 0;
    std::lock_guard<std::mutex> lock(mutex);
    if (++passed == killAt.count) std::raise(SIGKILL);
}

}  // namespace rockfrac
