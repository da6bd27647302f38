// The bond law selection table: keyword -> law. One line per law.
#include <sstream>
#include <utility>

#include "core/error.hpp"
#include "dem/bondLaw.hpp"
#include "dem/voronoiQnscBond.hpp"

namespace rockfrac {

namespace {

const std::pair<const char*, BondLawRunner> bond_law_table[] = {
    {"voronoiQNSC", &runVoronoiQnscBonds},
};

}  // namespace

std::vector<std::string> bondLawNames()
{
    std::vector<std::string> names;
    for (const auto& entry : bond_law_table) names.emplace_back(entry.first);
    return names;
}

BondLawRunner bondLawRunner(const std::string& name)
{
    for (const auto& entry : bond_law_table)
        if (name == entry.first) return entry.second;
    std::ostringstream message;
    message << "unknown bond law '" << name << "'; known:";
    for (const auto& known : bondLawNames()) message << ' ' << known;
    throw UserError(message.str());
}

}  // namespace rockfrac
