// The contact law selection table: keyword -> law. One line per law.
#include <sstream>
#include <utility>

#include "core/error.hpp"
#include "dem/contactLaw.hpp"
#include "dem/hertzMindlinContact.hpp"

namespace rockfrac {

namespace {

const std::pair<const char*, ContactLawRunners> contact_law_table[] = {
    {"hertzMindlin", {&runHertzMindlinPairs, &runHertzMindlinWalls}},
};

}  // namespace

std::vector<std::string> contactLawNames()
{
    std::vector<std::string> names;
    for (const auto& entry : contact_law_table) names.emplace_back(entry.first);
    return names;
}

ContactLawRunners contactLawRunners(const std::string& name)
{
    for (const auto& entry : contact_law_table)
        if (name == entry.first) return entry.second;
    std::ostringstream message;
    message << "unknown contact law '" << name << "'; known:";
    for (const auto& known : contactLawNames()) message << ' ' << known;
    throw UserError(message.str());
}

}  // namespace rockfrac
