#pragma once
// The host side of a bond law: the object constant/rockProperties selects by
// `bond { model <keyword>; <keyword> { coefficients } }`, which reads and owns the law's
// coefficients and runs its kernel (bondLaw.hpp) over the interfaces.
//
// Every law has the linear elastic bond of Eqs. 5–8 until it fails (k_n, k_t per unit
// area and length): the stable step, the dashpot of Eqs. 18–19 (`bond/damping`) and the
// size effect (`bond/sizeEffect`, which scales the law's strengths) are the same for all.
#include <memory>
#include <string>
#include <vector>

#include "dem/bondLaw.hpp"

namespace rockfrac {

class Dictionary;
template <class Base, class... Args>
class Selector;

class BondLawModel {
public:
    virtual ~BondLawModel() = default;

    // The keyword that selects it.
    virtual const char* type() const = 0;
    // k_n = E(1-nu)/((1+nu)(1-2nu)) and k_t = E/(2(1+nu)) of Eqs. 7–8 [Pa].
    virtual double normalModulus() const = 0;
    virtual double shearModulus() const = 0;
    // The noise floor of the energy check (DemModel::status): the energy one bond of the
    // model's mean area releases when it breaks [J], from the bonds' total area and count.
    virtual double energyFloor(double total_bond_area, int n_bonds, double mean_length) const = 0;
    // The law over the interfaces of `args` (OpenMP, deterministic block sums).
    virtual void run(const BondKernelArgs& args) const = 0;
    // One line for the log: "voronoiQNSC: E 46 GPa, sigma-bar 28 MPa, ...".
    virtual std::string describe() const = 0;
};

// The table of bond laws (bondLawTable.cpp): keyword -> law built from its coefficients.
const Selector<BondLawModel>& bondLaws();
std::vector<std::string> bondLawNames();

// The paper's law with its Table 2 values (what DemParameters starts from).
std::shared_ptr<const BondLawModel> defaultBondLaw();

}  // namespace rockfrac
