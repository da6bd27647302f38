#pragma once
// The two calibration procedures (docs/calibration.md):
//
// DEM, on the Brazilian disc (the paper's section 5.2): the peak force of each
// run and the plate approach at that peak are compared with the measured mean
// failure load (and a measured displacement at peak, when there is one) by the
// weighted sum of squared relative errors. Either a design of experiments over
// the bond parameters, one quadratic response surface per output and the
// minimum of the surfaces' objective (method responseSurface, then one
// confirmation run), or BOBYQA on the simulated objective itself (bobyqa).
//
// FEM: the Weibull parameters of DFH are chosen so that the failure loads of
// one run per seed match the measured failure-load distribution (Wasserstein-1
// relative to the measured mean, or Kolmogorov–Smirnov), by BOBYQA.
#include <string>
#include <utility>
#include <vector>

#include "calibration/calibrationStudy.hpp"

namespace rockfrac::calibration {

struct PeakResponse {
    double force = 0.0;         // [N] maximum of the force column
    double displacement = 0.0;  // [m] the displacement column at that row
};
// UserError naming the file when it or a column is missing or it has no rows.
PeakResponse readPeakResponse(const std::filesystem::path& file, const std::string& forceColumn,
                              const std::string& displacementColumn);

// The objective of the DEM calibration at normalised point x with response r.
struct PeakErrors {
    double force = 0.0;         // (F − F*) / F*
    double displacement = 0.0;  // (d − d*) / d*, 0 without a displacement target
    double objective = 0.0;     // w_F e_F² + w_d e_d² (+ λ |x − x_ref|² when force only)
};
PeakErrors peakErrors(const CalibrationStudy& study, const std::vector<double>& x, const PeakResponse& r);

struct CalibrationOutcome {
    std::string method;
    std::vector<double> values;  // physical, one per parameter
    double objective = 0.0;
    std::size_t simulations = 0;  // runs made or reused by this method
    double wallSeconds = 0.0;
    // Lines for the log and for the calibratedValues file: (keyword, value, comment).
    std::vector<std::vector<std::string>> report;
    std::string comment;  // one line for the entries written into rockProperties
};

CalibrationOutcome calibrate(const CalibrationStudy& study, int jobs);

// Write the calibrated values (and tied entries) into the target case's files
// with `comment` (unless !intoCase), and the report <study>/calibratedValues.<method>.
void writeCalibratedValues(const CalibrationStudy& study, const CalibrationOutcome& outcome,
                           bool intoCase = true);

}  // namespace rockfrac::calibration
