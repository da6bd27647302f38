#include "explain/chiSquare.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

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

HeldOutTest heldOutTest(const std::vector<double>& z, double significance, double chiSquare)
{
    HeldOutTest t;
    for (double v : z) t.chiSquare += v * v;
    if (chiSquare >= 0.0) t.chiSquare = chiSquare;
    t.degreesOfFreedom = static_cast<int>(z.size());
    t.pValue = z.empty() ? 1.0 : chiSquareSurvival(t.chiSquare, t.degreesOfFreedom);
    t.consistent = t.pValue >= significance;
    std::vector<std::size_t> order(z.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return std::fabs(z[a]) > std::fabs(z[b]); });
    for (std::size_t i : order)
        if (std::fabs(z[i]) > remainingZ) t.remaining.push_back(i);
    if (t.remaining.empty() && !t.consistent && !order.empty()) t.remaining.push_back(order.front());
    return t;
}

}  // namespace rockfrac::explain
