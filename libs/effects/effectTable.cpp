// The library of model effects: one line per effect. Probe sizes are the trial
// steps explainGap uses for its sensitivities (large enough to stand out of the
// scatter of a few Voronoi seeds, small enough to stay near the baseline).
#include <algorithm>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "effects/modelEffect.hpp"

namespace rockfrac {

std::unique_ptr<ModelEffect> makeContactCrumbling(const Dictionary&);
std::unique_ptr<ModelEffect> makeMachineCompliance(const Dictionary&);
std::unique_ptr<ModelEffect> makeSeatingOffset(const Dictionary&);
std::unique_ptr<ModelEffect> makeBondStrengthScatter(const Dictionary&);
std::unique_ptr<ModelEffect> makeRateDamping(const Dictionary&);
std::unique_ptr<ModelEffect> makePlateFriction(const Dictionary&);

const std::vector<EffectDescriptor>& effectLibrary()
{
    static const std::vector<EffectDescriptor> library = [] {
        std::vector<EffectDescriptor> l;
        l.push_back({"contactCrumbling",
                     "the rock under each plate crushes early (weakened bonds within a contact zone)",
                     "soft start that stiffens (toe), larger displacement at peak, lower peak",
                     "strengthLoss",
                     "-",
                     0.0,
                     0.6,
                     ProbeScale::absolute,
                     0.0,
                     0.95,
                     {"depth"},
                     makeContactCrumbling});
        l.push_back({"machineCompliance",
                     "a linear spring in series with the specimen (frame, platens)",
                     "uniformly softer curve, larger displacement at peak, same peak and shape",
                     "compliance",
                     "m/N",
                     0.0,
                     0.5,
                     ProbeScale::peakCompliance,
                     0.0,
                     1e-6,
                     {},
                     makeMachineCompliance});
        l.push_back({"seatingOffset",
                     "a seating gap that closes under a small force (toe region)",
                     "toe at the start, displacement at peak up by the gap, same stiffness and peak",
                     "depth",
                     "m",
                     0.0,
                     0.3,
                     ProbeScale::peakDisplacement,
                     0.0,
                     1e-3,
                     {"closureForce"},
                     makeSeatingOffset});
        l.push_back({"bondStrengthScatter",
                     "random bond strengths with a Weibull size effect",
                     "wider spread and lower mean of the failure loads, same stiffness",
                     "inverseModulus",
                     "-",
                     0.0,
                     0.3,
                     ProbeScale::absolute,
                     0.0,
                     1.0,
                     {"seed"},
                     makeBondStrengthScatter});
        l.push_back({"rateDamping",
                     "more rate dependence: the bond damping beta scaled",
                     "more gradual softening after the peak",
                     "betaFactor",
                     "-",
                     1.0,
                     4.0,
                     ProbeScale::absolute,
                     0.05,
                     10.0,
                     {},
                     makeRateDamping});
        l.push_back({"plateFriction",
                     "the rock-steel friction at the plates scaled",
                     "a more or less confined contact zone (shape dependent)",
                     "frictionFactor",
                     "-",
                     1.0,
                     -0.75,
                     ProbeScale::absolute,
                     0.0,
                     2.0,
                     {},
                     makePlateFriction});
        return l;
    }();
    return library;
}

const EffectDescriptor& findEffect(const std::string& name, const std::string& where)
{
    for (const auto& e : effectLibrary())
        if (e.name == name) return e;
    std::string known;
    for (const auto& e : effectLibrary()) known += (known.empty() ? "" : ", ") + e.name;
    throw UserError(where + ": unknown model effect '" + name + "'; the library has: " + known);
}

ModelEffects ModelEffects::read(const Dictionary& modelEffects)
{
    ModelEffects result;
    for (const std::string& key : modelEffects.keys()) {
        const EffectDescriptor& d = findEffect(key, modelEffects.fileName());
        if (!modelEffects.isDict(key))
            throw UserError(modelEffects.fileName() + ": '" + key + "' must be a sub-dictionary { " +
                            d.parameter + " ...; } (docs/user-guide.md, model effects)");
        result.effects_.push_back(d.make(modelEffects.subDict(key)));
    }
    return result;
}

void ModelEffects::applyToParameters(DemParameters& parameters) const
{
    for (const auto& e : effects_) e->applyToParameters(parameters);
}

void ModelEffects::applyToModel(DemModel& model, const EffectContext& context) const
{
    for (const auto& e : effects_) e->applyToModel(model, context);
}

double ModelEffects::recordedDisplacement(double plateApproach, double force) const
{
    double d = plateApproach;
    for (const auto& e : effects_) d = e->recordedDisplacement(d, force);
    return d;
}

std::vector<std::string> ModelEffects::descriptions() const
{
    std::vector<std::string> lines;
    for (const auto& e : effects_) lines.push_back(e->describe());
    return lines;
}

}  // namespace rockfrac
