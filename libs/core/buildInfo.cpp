// Build identification for banners and result provenance.
#include <string>

#include "core/application.hpp"

#ifndef ROCKFRAC_GIT_COMMIT
#define ROCKFRAC_GIT_COMMIT "unknown"
#endif
#ifndef ROCKFRAC_BUILD_TYPE
#define ROCKFRAC_BUILD_TYPE "unknown"
#endif
#ifndef ROCKFRAC_VERSION
#define ROCKFRAC_VERSION "0.0.0"
#endif

namespace rockfrac {

std::string buildString()
{
    return std::string("rockfrac ") + ROCKFRAC_VERSION + " (" + ROCKFRAC_GIT_COMMIT + ", " +
           ROCKFRAC_BUILD_TYPE + ")";
}

}  // namespace rockfrac
