// The contact law selection table: keyword -> law. One line per law.
#include <memory>

#include "core/selector.hpp"
#include "dem/contactLaw.hpp"
#include "dem/hertzMindlinContact.hpp"

namespace rockfrac {

namespace {

// A law without coefficients of its own (its sub-dictionary may be left out; when given it
// must be empty).
template <class Law>
std::unique_ptr<ContactLawModel> makeWithoutCoefficients(const Dictionary& coefficients)
{
    requireKnownEntries(coefficients, {}, "this contact law has no coefficients of its own");
    return std::make_unique<Law>();
}

}  // namespace

const Selector<ContactLawModel>& contactLaws()
{
    static const Selector<ContactLawModel> table(
        "contact law", {
                           {"hertzMindlin", &makeWithoutCoefficients<HertzMindlinContactLaw>, true},
                       });
    return table;
}

std::vector<std::string> contactLawNames()
{
    return contactLaws().names();
}

std::shared_ptr<const ContactLawModel> defaultContactLaw()
{
    return std::make_shared<HertzMindlinContactLaw>();
}

}  // namespace rockfrac
