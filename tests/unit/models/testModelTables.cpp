// The run-time selection tables (core/selector.hpp) against the reference pages: every model a
// case can select by keyword has docs/models/<family>/<keyword>.md, and every page there names
// a registered model (no page for a model that does not exist).
#include <catch2/catch.hpp>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/dictionary.hpp"
#include "core/selector.hpp"
#include "dem/bondLawModel.hpp"
#include "dem/contactLaw.hpp"
#include "effects/modelEffect.hpp"
#include "fem/femMaterial.hpp"
#include "parallel/decomposition.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

std::set<std::string> pagesIn(const std::string& family)
{
    std::set<std::string> pages;
    for (const auto& entry : fs::directory_iterator(fs::path(ROCKFRAC_SOURCE_DIR) / "docs/models" / family))
        if (entry.path().extension() == ".md" && entry.path().stem() != "README")
            pages.insert(entry.path().stem().string());
    return pages;
}

void requirePages(const std::string& family, const std::vector<std::string>& names)
{
    const std::set<std::string> pages = pagesIn(family);
    for (const std::string& name : names) {
        INFO(family << " model " << name);
        CHECK(pages.count(name) == 1);
    }
    for (const std::string& page : pages) {
        INFO("docs/models/" << family << "/" << page << ".md");
        CHECK(std::find(names.begin(), names.end(), page) != names.end());
    }
}

}  // namespace

TEST_CASE("every selectable model has its reference page, and every page its model", "[models][docs]")
{
    requirePages("bond", bondLawNames());
    requirePages("contact", contactLawNames());
    requirePages("fem", fem::femMaterialNames());
    std::vector<std::string> effects;
    for (const EffectDescriptor& d : effectLibrary()) effects.push_back(d.name);
    requirePages("effects", effects);
    CHECK(effectSelector().names() == effects);
    requirePages("decomposition", decompositionMethods().names());
}

TEST_CASE("the selection tables hold the shipped models", "[models]")
{
    CHECK(bondLawNames() == std::vector<std::string>{"voronoiQNSC", "brittleBPM"});
    CHECK(contactLawNames() == std::vector<std::string>{"hertzMindlin"});
    CHECK(fem::femMaterialNames() == std::vector<std::string>{"linearElastic", "kstDfh"});
    CHECK(effectLibrary().size() == 6);
    CHECK(decompositionMethods().names() == std::vector<std::string>{"rcb"});
}

TEST_CASE("a model without coefficients may leave its sub-dictionary out, not fill it", "[models]")
{
    const Dictionary contact = Dictionary::parse("model hertzMindlin;\n", "rockProperties");
    CHECK(std::string(contactLaws().select(contact, "model")->type()) == "hertzMindlin");
    const Dictionary filled =
        Dictionary::parse("model hertzMindlin;\nhertzMindlin { stiffness 1; }\n", "rockProperties");
    CHECK_THROWS_WITH(contactLaws().select(filled, "model"),
                      Catch::Contains("rockProperties:2") && Catch::Contains("unknown entry 'stiffness'"));
    const Dictionary elastic = Dictionary::parse("material linearElastic;\n", "rockProperties");
    CHECK(fem::femMaterials().select(elastic, "material")->type() == "linearElastic");
    // A model with coefficients needs its sub-dictionary.
    const Dictionary kst = Dictionary::parse("material kstDfh;\n", "rockProperties");
    CHECK_THROWS_WITH(fem::femMaterials().select(kst, "material"), Catch::Contains("kstDfh"));
}
