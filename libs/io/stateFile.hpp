#pragma once
// Whole-state files of the solvers: named binary arrays in one file.
//
// A solver writes its complete state at every write time into
// "<case>/<time>/<solver>State" so that `startFrom latestTime` continues
// bitwise identically. Layout (little-endian):
//   magic "RFSTATE\0" | uint32 version | uint32 nArrays
//   per array: uint32 nameLength | name | uint8 type (1 double, 2 int64, 3 uint8) |
//              uint64 count | count values
//   uint64 FNV-1a checksum of everything before it (core/checksum.hpp fnv1a)
// The reader checks every length against the file size, the type codes and
// the checksum, and names the file and the array in its UserError: a torn or
// corrupt file is reported, never trusted.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

class StateFile {
public:
    void put(const std::string& name, std::vector<double> values);
    void put(const std::string& name, std::vector<std::int64_t> values);
    void put(const std::string& name, std::vector<std::uint8_t> values);
    void put(const std::string& name, const std::vector<Vec3>& values);
    void putScalar(const std::string& name, double value) { put(name, std::vector<double>{value}); }

    // Lookups check presence and, when expectedCount >= 0, the length.
    const std::vector<double>& doubles(const std::string& name, long expectedCount = -1) const;
    const std::vector<std::int64_t>& integers(const std::string& name, long expectedCount = -1) const;
    const std::vector<std::uint8_t>& bytes(const std::string& name, long expectedCount = -1) const;
    std::vector<Vec3> vectors(const std::string& name, long expectedCount = -1) const;
    double scalar(const std::string& name) const { return doubles(name, 1)[0]; }
    bool has(const std::string& name) const;
    // Drops an array (e.g. to make the file an older writer would have written).
    void erase(const std::string& name);

    void write(const std::filesystem::path& file) const;  // atomically
    static StateFile read(const std::filesystem::path& file);
    // The same from the file's bytes in memory; `file` only names it in messages.
    static StateFile parse(const std::string& bytes, const std::filesystem::path& file);

private:
    std::filesystem::path source_;  // for messages
    std::map<std::string, std::vector<double>> doubles_;
    std::map<std::string, std::vector<std::int64_t>> integers_;
    std::map<std::string, std::vector<std::uint8_t>> bytes_;
    [[noreturn]] void missing(const std::string& name, const char* kind) const;
    void checkCount(const std::string& name, std::size_t count, long expected) const;
};

}  // namespace rockfrac
