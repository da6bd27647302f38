#pragma once
// Helpers shared by the dictionary tests: parsing from a string, capturing
// error messages, and scratch directories for #include and file edits.
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/dictionary.hpp"

namespace rockfrac::test {

// Every test dictionary pretends to be this file, so messages are predictable.
inline const std::string testFile = "constant/rockProperties";

inline Dictionary parse(const std::string& text)
{
    return Dictionary::parse(text, testFile);
}

// The message of the UserError that `action` throws; fails the test if none.
template <class Action>
std::string errorOf(Action&& action)
{
    try {
        action();
    } catch (const UserError& error) {
        return error.what();
    }
    FAIL("expected a UserError, but none was thrown");
    return "";
}

inline std::string parseError(const std::string& text)
{
    return errorOf([&] { parse(text); });
}

inline std::string readText(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A fresh directory under the build tree, removed at the end of the test.
class ScratchDir {
public:
    ScratchDir()
    {
        static std::atomic<int> counter{0};
        path_ = std::filesystem::path(ROCKFRAC_BINARY_DIR) / "tests" / "scratch" /
                ("dictionary-" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() { std::filesystem::remove_all(path_); }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

    std::filesystem::path write(const std::string& relative, const std::string& text) const
    {
        const std::filesystem::path file = path_ / relative;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

private:
    std::filesystem::path path_;
};

}  // namespace rockfrac::test
