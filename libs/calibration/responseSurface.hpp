#pragma once
// Full quadratic response surfaces (the paper's section 5.2: one expression per
// output of the design of experiments). In k normalised inputs x ∈ [−1, 1]^k
//
//     y(x) = b0 + Σ b_i x_i + Σ_{i<=j} b_ij x_i x_j,
//
// (1 + 2k + k(k−1)/2 coefficients: 10 for k = 3), fitted by least squares. The
// quality of a fit is reported twice: R² on the design itself, and the
// leave-one-out R² (PRESS), which says how well the surface predicts a point
// it was not fitted to — the honest number when the design has few runs.
#include <cstddef>
#include <vector>

namespace rockfrac::calibration {

using Point = std::vector<double>;

// The regressors 1, x_i, x_i x_j (i <= j) of a point, in that order.
std::vector<double> quadraticTerms(const Point& x);
std::size_t quadraticTermCount(std::size_t dimensions);

class QuadraticSurface {
public:
    // UserError when there are fewer points than coefficients.
    static QuadraticSurface fit(const std::vector<Point>& points, const std::vector<double>& values);

    double operator()(const Point& x) const;
    const std::vector<double>& coefficients() const { return coefficients_; }
    std::size_t dimensions() const { return dimensions_; }
    double rSquared() const { return rSquared_; }
    // 1 − PRESS / SS_tot; NaN when a point has leverage 1 (a saturated design).
    double leaveOneOutRSquared() const { return looRSquared_; }
    double rmsResidual() const { return rmsResidual_; }

private:
    std::size_t dimensions_ = 0;
    std::vector<double> coefficients_;
    double rSquared_ = 0.0, looRSquared_ = 0.0, rmsResidual_ = 0.0;
};

// Map between a parameter's physical range [low, high] and x ∈ [−1, 1].
double toUnit(double value, double low, double high);
double fromUnit(double x, double low, double high);

}  // namespace rockfrac::calibration
