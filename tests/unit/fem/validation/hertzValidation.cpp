// Hertz contact on a refined mesh (a/h = 16): within 5 % along the loading curve.
// About 70 s on 2 cores in Release, hence the label validation rather than unit.
#include "../hertzSphere.hpp"

TEST_CASE("Hertz: sphere on a rigid plate within 5 % of 4/3 E* sqrt(R) delta^1.5", "[fem][hertz][validation]")
{
    rockfrac::fem::test::HertzSettings settings;
    settings.finestOverContactRadius = 0.0625;
    const auto result = rockfrac::fem::test::runHertzSphere(settings);
    CHECK(result.samples > 5);
    CHECK(result.worstError < 0.05);
}
