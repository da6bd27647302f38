// Weibull maximum likelihood: recovery from synthetic draws, the likelihood
// equation at the estimate, and the likelihood-ratio bounds.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "stats/weibull.hpp"
#include "statsTestSupport.hpp"

using namespace rockfrac::stats;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("Weibull MLE recovers m and sigma_w from 10^4 draws within 2 %", "[stats]")
{
    const double m = 7.0, sigmaW = 21e6, sigma0 = sigmaW / std::tgamma(1.0 + 1.0 / m);
    const WeibullFit fit = fitWeibull(testing::weibullSample(10000, m, sigma0, 42), 0.95);
    CHECK_THAT(fit.modulus, WithinRel(m, 0.02));
    CHECK_THAT(fit.mean, WithinRel(sigmaW, 0.02));
    CHECK_THAT(fit.scale, WithinRel(sigma0, 0.02));
    CHECK(fit.modulusBounds.contains(m));
    CHECK(fit.meanBounds.contains(sigmaW));
    CHECK(fit.scaleBounds.contains(sigma0));
    CHECK(fit.modulusBounds.upper - fit.modulusBounds.lower < 0.05 * m);
}

TEST_CASE("Weibull MLE solves the likelihood equations for the granite BDT loads", "[stats]")
{
    const Sample x = testing::graniteBdtLoads();
    const WeibullFit fit = fitWeibull(x, 0.90);
    // ∂lnL/∂m = 0 ⇔ Σ x^m ln x / Σ x^m − 1/m − mean(ln x) = 0, and σ_0 = (Σ x^m / n)^(1/m).
    double sumPower = 0, sumPowerLog = 0, sumLog = 0;
    for (double v : x) {
        const double p = std::pow(v / 1e4, fit.modulus);
        sumPower += p, sumPowerLog += p * std::log(v), sumLog += std::log(v);
    }
    CHECK_THAT(sumPowerLog / sumPower - 1.0 / fit.modulus - sumLog / 10.0, WithinAbs(0.0, 1e-9));
    CHECK_THAT(fit.scale, WithinRel(1e4 * std::pow(sumPower / 10.0, 1.0 / fit.modulus), 1e-9));
    CHECK_THAT(fit.mean, WithinRel(fit.scale * std::tgamma(1.0 + 1.0 / fit.modulus), 1e-12));
    // A sd of 12 % of the mean is a modulus near 9–10; the mean close to the sample mean.
    CHECK(fit.modulus > 8.0);
    CHECK(fit.modulus < 11.0);
    CHECK_THAT(fit.mean, WithinRel(13.19e3, 0.01));
}

TEST_CASE("likelihood-ratio bounds: nested in the level, around the estimate, at the chi-square drop",
          "[stats]")
{
    const Sample x = testing::graniteBdtLoads();
    const WeibullFit f90 = fitWeibull(x, 0.90), f95 = fitWeibull(x, 0.95);
    for (const WeibullFit* f : {&f90, &f95}) {
        CHECK(f->modulusBounds.lower < f->modulus);
        CHECK(f->modulus < f->modulusBounds.upper);
        CHECK(f->meanBounds.contains(f->mean));
        CHECK(f->scaleBounds.contains(f->scale));
    }
    CHECK(f95.modulusBounds.lower < f90.modulusBounds.lower);
    CHECK(f95.modulusBounds.upper > f90.modulusBounds.upper);
    CHECK(f95.meanBounds.upper > f90.meanBounds.upper);
    // Profile of m: ln L(m, σ_0(m)) at the upper 90 % bound is 2.7055/2 below the maximum.
    auto profile = [&](double m) {
        double sumPower = 0, sumLog = 0;
        for (double v : x) sumPower += std::pow(v / 1e4, m), sumLog += std::log(v / 1e4);
        const double s = std::pow(sumPower / 10.0, 1.0 / m);
        return 10.0 * std::log(m) - 10.0 * m * std::log(s) + (m - 1.0) * sumLog - 10.0;
    };
    CHECK_THAT(profile(f90.modulus) - profile(f90.modulusBounds.upper), WithinAbs(2.705543 / 2, 1e-4));
    CHECK_THAT(profile(f90.modulus) - profile(f90.modulusBounds.lower), WithinAbs(2.705543 / 2, 1e-4));
}

TEST_CASE("Weibull fit refuses samples it cannot fit", "[stats]")
{
    CHECK_THROWS_AS(fitWeibull({5.0}), rockfrac::UserError);
    CHECK_THROWS_AS(fitWeibull({5.0, 5.0, 5.0}), rockfrac::UserError);
    CHECK_THROWS_AS(fitWeibull({5.0, -1.0, 3.0}), rockfrac::UserError);
}

TEST_CASE("Weibull CDF and quantile are inverse", "[stats]")
{
    CHECK_THAT(weibullCdf(weibullQuantile(0.3, 7.0, 2.0), 7.0, 2.0), WithinAbs(0.3, 1e-14));
    CHECK_THAT(weibullCdf(2.0, 7.0, 2.0), WithinAbs(1.0 - std::exp(-1.0), 1e-15));
    CHECK(weibullCdf(-1.0, 7.0, 2.0) == 0.0);
}
