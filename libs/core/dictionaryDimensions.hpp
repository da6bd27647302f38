#pragma once
// Dimension sets: the optional `[kg m s K mol A cd]` exponents that may precede
// a value (`E [1 -1 -2 0 0 0 0] 77e9;` or `E [Pa] 77e9;`). Values are always in
// coherent SI units; a dimension set only documents and checks, it never scales.
#include <array>
#include <string>

#include "core/dictionaryToken.hpp"

namespace rockfrac {

struct Dimensions {
    // Exponents in OpenFOAM's order: mass, length, time, temperature, amount, current, luminosity.
    std::array<int, 7> exponents{};

    // From a unit expression such as "Pa", "kg/m^3", "m/s", "1/s" or "-" (none).
    // For code that states what it expects; std::invalid_argument on a typo.
    static Dimensions fromUnits(const std::string& units);

    std::string str() const;         // "[1 -1 -2 0 0 0 0]"
    std::string unitString() const;  // "kg m^-1 s^-2", or "-" when dimensionless

    bool operator==(const Dimensions& other) const { return exponents == other.exponents; }
    bool operator!=(const Dimensions& other) const { return !(*this == other); }
};

// Parse the text between the brackets of a dimension set: seven integers or a
// unit expression. `openBracket` locates the '[' for error messages.
Dimensions parseDimensionSet(const std::string& inside, const SourceLocation& openBracket);

}  // namespace rockfrac
