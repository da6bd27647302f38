// The memory budget, the refusal and the -dry-run line of core/memoryLimit: the budget comes
// from ROCKFRAC_MEMORY_LIMIT_BYTES when set, and every message names it with its source.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "core/memoryLimit.hpp"

using namespace rockfrac;

namespace {
// Sets the variable for one scope, and restores what was there.
struct LimitVariable {
    explicit LimitVariable(const char* value)
    {
        if (const char* old = std::getenv("ROCKFRAC_MEMORY_LIMIT_BYTES")) saved = old, had = true;
        setenv("ROCKFRAC_MEMORY_LIMIT_BYTES", value, 1);
    }
    ~LimitVariable()
    {
        if (had)
            setenv("ROCKFRAC_MEMORY_LIMIT_BYTES", saved.c_str(), 1);
        else
            unsetenv("ROCKFRAC_MEMORY_LIMIT_BYTES");
    }
    std::string saved;
    bool had = false;
};
}  // namespace

TEST_CASE("formatBytes: powers of 1000, three digits", "[memoryLimit]")
{
    CHECK(formatBytes(0) == "0 bytes");
    CHECK(formatBytes(999) == "999 bytes");
    CHECK(formatBytes(1000000) == "1 MB");
    CHECK(formatBytes(34800000) == "34.8 MB");
    CHECK(formatBytes(1880000000) == "1.88 GB");
}

TEST_CASE("the budget from ROCKFRAC_MEMORY_LIMIT_BYTES, refused when not a number of bytes", "[memoryLimit]")
{
    {
        const LimitVariable limit("2000000");
        const auto budget = memoryBudget();
        REQUIRE(budget);
        CHECK(budget->bytes == 2000000);
        CHECK(budget->source == "ROCKFRAC_MEMORY_LIMIT_BYTES");
    }
    for (const char* bad : {"8GB", "-5", "1e9", "99999999999999999999999"}) {
        const LimitVariable limit(bad);
        CHECK_THROWS_WITH(memoryBudget(), Catch::Contains("is not a number of bytes"));
    }
}

TEST_CASE("checkMemoryFits names the estimate and the budget with its source", "[memoryLimit]")
{
    const LimitVariable limit("1000000");
    CHECK_NOTHROW(checkMemoryFits(1000000, "x", "y"));
    CHECK_THROWS_WITH(
        checkMemoryFits(34800000, "system/voronoiMeshDict: 300 cells", "request fewer cells"),
        "system/voronoiMeshDict: 300 cells: the run needs an estimated 34.8 MB of memory, only 1 MB "
        "are available (ROCKFRAC_MEMORY_LIMIT_BYTES); request fewer cells");
}

TEST_CASE("estimateLine: the counts, the estimate and the budget in one line", "[memoryLimit]")
{
    const LimitVariable limit("20100000000");
    CHECK(estimateLine(1880000000, "119600 cells") ==
          "Estimate: 119600 cells, ~1.88 GB peak memory; available 20.1 GB (ROCKFRAC_MEMORY_LIMIT_BYTES)");
}
