#pragma once
// Writing FoamFile dictionaries that rockfrac generates (geometryProperties,
// time-directory state headers ...). Reading goes through core/dictionary.hpp.
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

// "FoamFile { format ascii; class dictionary; object <object>; }" plus a banner comment.
std::string foamFileHeader(const std::string& object, const std::string& note = "");

// Round-trip exact text for numbers (17 significant digits when needed, shortest otherwise).
std::string numberText(double value);
std::string vectorText(const Vec3& v);  // "(x y z)"
std::string tensorText(const Mat3& m);  // "(xx xy xz yx yy yz zx zy zz)"

// `keyword value;` padded so values line up, as in OpenFOAM's files.
std::string entryLine(const std::string& keyword, const std::string& value, int indent = 0);

}  // namespace rockfrac
