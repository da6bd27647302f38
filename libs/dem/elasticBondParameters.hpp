#pragma once
// The elastic bond of Eqs. 5–8 with a tension cut-off and a Mohr–Coulomb shear strength
// tau-bar = C - mu sigma: the coefficients the shipped bond laws share (a law's Parameters
// start from them), with the paper's Table 2 values as defaults.
#include <string>
#include <vector>

namespace rockfrac {

class Dictionary;

struct ElasticBondParameters {
    double youngs_modulus = 46e9;    // E of Eq. 7 [Pa]
    double poisson_ratio = 0.25;     // nu of Eqs. 7–8 [-]
    double tensile_strength = 28e6;  // sigma-bar of Eq. 12 [Pa]
    double cohesion = 42e6;          // C of tau-bar = C - mu sigma [Pa]
    double friction = 0.8;           // mu = tan(phi) of tau-bar [-]

    double normalModulus() const;  // k_n = E(1-nu)/((1+nu)(1-2nu))  (Eq. 7) [Pa]
    double shearModulus() const;   // k_t = E/(2(1+nu))  (Eq. 8) [Pa]
    // A UserError naming `law` and the first value out of range (laws built in code; a
    // dictionary's entries are checked where they are read, with file and line).
    void check(const char* law) const;
    // E, poissonRatio, tensileStrength, cohesion, frictionCoefficient of a law's sub-dictionary.
    void read(const Dictionary& coefficients);
    static std::vector<std::string> entries();
};

// A law's own value out of range: UserError "bond law <law>: <what> is out of range, got <value>".
void requireLawValue(bool ok, double value, const char* what, const char* law);

}  // namespace rockfrac
