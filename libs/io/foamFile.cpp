#include "io/foamFile.hpp"

#include <cstdio>
#include <cstdlib>

#include "core/application.hpp"

namespace rockfrac {

std::string foamFileHeader(const std::string& object, const std::string& note)
{
    std::string text =
        "/*--------------------------------*- C++ -*----------------------------------*\\\n"
        "  Written by " +
        buildString() + "\n";
    if (!note.empty()) text += "  " + note + "\n";
    text +=
        "\\*---------------------------------------------------------------------------*/\n"
        "FoamFile\n{\n    format      ascii;\n    class       dictionary;\n    object      " +
        object + ";\n}\n\n";
    return text;
}

std::string numberText(double value)
{
    // The shortest of %.15g .. %.17g that reads back to the same double.
    char buffer[40];
    for (int precision = 15; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof(buffer), "%.*g", precision, value);
        if (std::strtod(buffer, nullptr) == value) break;
    }
    return buffer;
}

std::string vectorText(const Vec3& v)
{
    return "(" + numberText(v.x) + " " + numberText(v.y) + " " + numberText(v.z) + ")";
}

std::string tensorText(const Mat3& m)
{
    std::string text = "(";
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) text += (i + j ? " " : "") + numberText(m(i, j));
    return text + ")";
}

std::string entryLine(const std::string& keyword, const std::string& value, int indent)
{
    std::string line(static_cast<std::size_t>(4 * indent), ' ');
    line += keyword;
    const std::size_t column = static_cast<std::size_t>(4 * indent) + 20;
    line += line.size() < column ? std::string(column - line.size(), ' ') : " ";
    return line + value + ";\n";
}

}  // namespace rockfrac
