#pragma once
// The whole content of a text file as a string: "" when the file is missing or
// unreadable (callers that need the file check its existence and say so).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rockfrac {

inline std::string readFileText(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace rockfrac
