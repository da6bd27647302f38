#include "explain/chiSquare.hpp"

#include <cmath>

namespace rockfrac::explain {

namespace {

double lowerSeries(double a, double x)  // P(a, x) by its power series, x < a + 1
{
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 500; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

double upperFraction(double a, double x)  // Q(a, x) by a continued fraction, x >= a + 1
{
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 500; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double chiSquareSurvival(double x, double k)
{
    if (!(x > 0)) return 1.0;
    const double a = 0.5 * k, y = 0.5 * x;
    return y < a + 1.0 ? 1.0 - lowerSeries(a, y) : upperFraction(a, y);
}

}  // namespace rockfrac::explain
