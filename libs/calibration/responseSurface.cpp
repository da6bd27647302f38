#include "calibration/responseSurface.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace rockfrac::calibration {

std::size_t quadraticTermCount(std::size_t dimensions)
{
    return 1 + dimensions + dimensions * (dimensions + 1) / 2;
}

std::vector<double> quadraticTerms(const Point& x)
{
    std::vector<double> terms{1.0};
    for (double xi : x) terms.push_back(xi);
    for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = i; j < x.size(); ++j) terms.push_back(x[i] * x[j]);
    return terms;
}

QuadraticSurface QuadraticSurface::fit(const std::vector<Point>& points, const std::vector<double>& values)
{
    if (points.empty() || points.size() != values.size())
        throw UserError("response surface: no design points to fit");
    const std::size_t k = points.front().size(), p = quadraticTermCount(k), n = points.size();
    if (n < p)
        throw UserError("response surface: " + std::to_string(n) + " design points for " + std::to_string(p) +
                        " coefficients of a quadratic in " + std::to_string(k) +
                        " inputs; use a design with at least that many runs (3 levels per parameter)");
    Eigen::MatrixXd a(n, p);
    Eigen::VectorXd y(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto terms = quadraticTerms(points[i]);
        for (std::size_t j = 0; j < p; ++j) a(i, j) = terms[j];
        y(i) = values[i];
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    if (qr.rank() < static_cast<Eigen::Index>(p))
        throw UserError("response surface: the design cannot identify a quadratic (rank " +
                        std::to_string(qr.rank()) + " of " + std::to_string(p) +
                        "); use at least 3 distinct levels per parameter");
    const Eigen::VectorXd b = qr.solve(y);

    QuadraticSurface s;
    s.dimensions_ = k;
    s.coefficients_.assign(b.data(), b.data() + b.size());
    const Eigen::VectorXd residual = y - a * b;
    const double mean = y.mean();
    const double ssTot = (y.array() - mean).square().sum();
    const double ssRes = residual.squaredNorm();
    s.rSquared_ = ssTot > 0 ? 1.0 - ssRes / ssTot : 1.0;
    s.rmsResidual_ = std::sqrt(ssRes / static_cast<double>(n));
    // Leverages h_ii of the hat matrix A (AᵀA)⁻¹ Aᵀ; PRESS = Σ (e_i / (1 − h_ii))².
    const Eigen::MatrixXd gramInverse = (a.transpose() * a).inverse();
    double press = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double h = a.row(i).dot(gramInverse * a.row(i).transpose());
        if (1.0 - h < 1e-10) {
            press = std::numeric_limits<double>::quiet_NaN();
            break;
        }
        press += std::pow(residual(i) / (1.0 - h), 2);
    }
    s.looRSquared_ = ssTot > 0 ? 1.0 - press / ssTot : std::numeric_limits<double>::quiet_NaN();
    return s;
}

double QuadraticSurface::operator()(const Point& x) const
{
    const auto terms = quadraticTerms(x);
    double y = 0.0;
    for (std::size_t j = 0; j < terms.size(); ++j) y += coefficients_[j] * terms[j];
    return y;
}

double toUnit(double value, double low, double high)
{
    return high > low ? 2.0 * (value - low) / (high - low) - 1.0 : 0.0;
}

double fromUnit(double x, double low, double high)
{
    return low + 0.5 * (x + 1.0) * (high - low);
}

}  // namespace rockfrac::calibration
