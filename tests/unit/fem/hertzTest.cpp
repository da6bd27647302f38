// Hertz contact, coarse (unit label): a/h = 8 at the final load, within 10 %.
// The 5 % check on a refined mesh is tests/unit/fem/validation (label validation).
#include "hertzSphere.hpp"

TEST_CASE("Hertz (coarse): sphere on a rigid plate within 10 % of 4/3 E* sqrt(R) delta^1.5", "[fem][hertz]")
{
    rockfrac::fem::test::HertzSettings settings;
    settings.finestOverContactRadius = 0.125;
    const auto result = rockfrac::fem::test::runHertzSphere(settings);
    CHECK(result.samples > 5);
    CHECK(result.worstError < 0.10);
}
