#include "explain/geometryCheck.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

#include "core/dictionary.hpp"
#include "explain/outliers.hpp"

namespace rockfrac::explain {

namespace {

// The model's value of a quantity: top-level (volume, equivalentDiameter) or in the disc
// sub-dictionary (diameter, thickness); nullopt when the file does not give it.
std::optional<double> modelValue(const Dictionary& d, const std::string& quantity)
{
    if (quantity == "diameter" || quantity == "thickness") {
        if (!d.isDict("disc")) return std::nullopt;
        const Dictionary& disc = d.subDict("disc");
        if (!disc.found(quantity)) return std::nullopt;
        return disc.getScalar(quantity, Bounds::positive());
    }
    if (!d.found(quantity)) return std::nullopt;
    return d.getScalar(quantity, Bounds::positive());
}

}  // namespace

std::vector<GeometryComparison> compareGeometry(const stats::MeasurementSet& measurements,
                                                const std::filesystem::path& geometryProperties)
{
    std::vector<GeometryComparison> result;
    if (!std::filesystem::exists(geometryProperties)) return result;
    const Dictionary model = Dictionary::readFile(geometryProperties);
    using G = stats::SpecimenGeometry;
    const struct {
        const char* name;
        const char* unit;
        std::optional<double> G::*member;
    } quantities[] = {{"diameter", "m", &G::diameter},
                      {"thickness", "m", &G::thickness},
                      {"volume", "m^3", &G::volume},
                      {"equivalentDiameter", "m", &G::equivalentDiameter}};
    for (const auto& q : quantities) {
        std::vector<double> values;
        for (const auto& sp : measurements.specimens)
            if (sp.geometry.*(q.member)) values.push_back(*(sp.geometry.*(q.member)));
        if (values.empty()) continue;
        const std::optional<double> m = modelValue(model, q.name);
        if (!m) continue;
        GeometryComparison c;
        c.quantity = q.name;
        c.unit = q.unit;
        c.measured = medianOf(values);
        c.specimens = static_cast<int>(values.size());
        c.model = *m;
        c.relative = c.measured / c.model - 1.0;
        c.mismatch = std::fabs(c.relative) > geometryTolerance;
        result.push_back(c);
    }
    return result;
}

std::string describeComparison(const GeometryComparison& c)
{
    const bool volume = c.unit == "m^3";
    const double scale = volume ? 1e6 : 1e3;  // cm^3, mm
    const char* unit = volume ? "cm^3" : "mm";
    char b[256];
    std::snprintf(b, sizeof(b), "%s %.4g %s (median of %d specimens) against the model's %.4g %s: %+.1f %%",
                  c.quantity.c_str(), c.measured * scale, unit, c.specimens, c.model * scale, unit,
                  100.0 * c.relative);
    return b;
}

}  // namespace rockfrac::explain
