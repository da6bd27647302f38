#pragma once
// Refusing a run that cannot fit in memory, before its big arrays exist.
//
// The solvers estimate what a case needs from its mesh sizes (cells, bonds,
// tetrahedra ...) and compare it with the memory the machine can give: the
// environment variable ROCKFRAC_MEMORY_LIMIT_BYTES when set (a scheduler's
// limit, or a test faking a small machine), else MemAvailable of
// /proc/meminfo. A case that would not fit stops with a UserError giving the
// estimate, instead of being killed by the kernel half-way (or swapping).
// Under -dry-run each application prints its estimate (estimateLine) after
// the check, so a dry run refuses what the run would refuse.
#include <cstdint>
#include <optional>
#include <string>

namespace rockfrac {

struct MemoryBudget {
    std::uint64_t bytes = 0;
    std::string source;  // "ROCKFRAC_MEMORY_LIMIT_BYTES" or "MemAvailable in /proc/meminfo"
};

// The budget, or nothing when neither the variable nor /proc/meminfo tells it
// (the check is then skipped). UserError for a malformed variable.
std::optional<MemoryBudget> memoryBudget();

// UserError "<what>: needs an estimated X of memory, only Y available (source);
// <advice>" when `estimatedBytes` exceeds the budget.
void checkMemoryFits(std::uint64_t estimatedBytes, const std::string& what, const std::string& advice);

// The -dry-run line: "Estimate: <counts>, ~X peak memory; available Y (source)",
// e.g. "Estimate: 119600 cells, ~1.91 GB peak memory; available 20.1 GB (MemAvailable in
// /proc/meminfo)"; "available: unknown" when the budget cannot be told.
std::string estimateLine(std::uint64_t estimatedBytes, const std::string& counts);

// "1.23 GB", "456 MB", "789 kB" (powers of 1000).
std::string formatBytes(std::uint64_t bytes);

}  // namespace rockfrac
