// The bond law selection table: keyword -> law built from its own sub-dictionary. One line per law.
#include <memory>

#include "core/selector.hpp"
#include "dem/bondLawModel.hpp"
#include "dem/brittleBpmBond.hpp"
#include "dem/voronoiQnscBond.hpp"

namespace rockfrac {

namespace {

template <class Law>
std::unique_ptr<BondLawModel> make(const Dictionary& coefficients)
{
    return std::make_unique<Law>(Law::read(coefficients));
}

}  // namespace

const Selector<BondLawModel>& bondLaws()
{
    static const Selector<BondLawModel> table("bond law", {
                                                              {"voronoiQNSC", &make<VoronoiQnscBondLaw>},
                                                              {"brittleBPM", &make<BrittleBpmBondLaw>},
                                                          });
    return table;
}

std::vector<std::string> bondLawNames()
{
    return bondLaws().names();
}

std::shared_ptr<const BondLawModel> defaultBondLaw()
{
    return std::make_shared<VoronoiQnscBondLaw>();
}

}  // namespace rockfrac
