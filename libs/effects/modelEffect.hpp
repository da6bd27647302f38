#pragma once
// A model effect: a physical mechanism the baseline bonded DEM leaves out, that a
// case can switch on in constant/modelEffects (docs/models/effects/). explainGap
// screens a library of them against measured data; each is one file pair here (the
// class with its EffectDescriptor as a static member) plus one line in effectTable.cpp.
//
// Contract: an effect whose fitted parameter has its neutral value changes nothing,
// bit for bit (the baseline model is the effect switched off).
#include <memory>
#include <string>
#include <vector>

#include "dem/demParameters.hpp"

namespace rockfrac {

class Dictionary;
class DemModel;

// Where the specimen meets the plates at the start (crumbling acts there).
struct EffectContext {
    double lowerPlateZ = 0.0;  // plane of the lower plate [m]
    double upperPlateZ = 0.0;  // plane of the upper plate [m]
};

class ModelEffect {
public:
    virtual ~ModelEffect() = default;
    // Material and contact constants (before the model is built).
    virtual void applyToParameters(DemParameters&) const {}
    // Per-bond or per-interface changes of a built model (before the first step).
    virtual void applyToModel(DemModel&, const EffectContext&) const {}
    // What the machine records as displacement when the plates have approached by
    // `plateApproach` under `force`: elements in series with the specimen add to it.
    virtual double recordedDisplacement(double plateApproach, double /*force*/) const
    {
        return plateApproach;
    }
    // One line for the log: "seatingOffset: depth 0.05 mm, closure force 1 kN".
    virtual std::string describe() const = 0;
};

// How explainGap probes an effect: the entry it fits, its neutral value (the
// baseline), the size of the trial step, and its physical bounds.
enum class ProbeScale {
    absolute,          // probe as given
    peakDisplacement,  // probe x the baseline's displacement at peak [m]
    peakCompliance,    // probe x the baseline's displacement at peak / peak force [m/N]
};

struct EffectDescriptor {
    std::string name;
    std::string physics;    // one sentence: what it is
    std::string signature;  // one sentence: what it does to the measured response
    std::string parameter;  // the fitted entry of the effect's sub-dictionary
    std::string unit;
    double neutral = 0.0;  // the value that switches the effect off
    double probe = 0.0;    // trial step (scaled by probeScale)
    ProbeScale probeScale = ProbeScale::absolute;
    double low = 0.0, high = 0.0;           // bounds of the fitted parameter
    std::vector<std::string> fixedEntries;  // further required entries (not fitted)
    std::unique_ptr<ModelEffect> (*make)(const Dictionary& effectDict) = nullptr;
};

template <class Effect>
std::unique_ptr<ModelEffect> makeEffect(const Dictionary& effectDict)
{
    return std::make_unique<Effect>(effectDict);
}

// Every registered effect, in library order.
const std::vector<EffectDescriptor>& effectLibrary();
// The selection table built from the library (core/selector.hpp).
template <class Base, class... Args>
class Selector;
const Selector<ModelEffect>& effectSelector();
// The descriptor of `name`; UserError listing the known names otherwise (`where` names the file).
const EffectDescriptor& findEffect(const std::string& name, const std::string& where);

// The effects of a case: constant/modelEffects (optional file). Each sub-dictionary
// names an effect; its entries are checked against their bounds.
class ModelEffects {
public:
    ModelEffects() = default;
    static ModelEffects read(const Dictionary& modelEffects);

    bool empty() const { return effects_.empty(); }
    void applyToParameters(DemParameters& parameters) const;
    void applyToModel(DemModel& model, const EffectContext& context) const;
    double recordedDisplacement(double plateApproach, double force) const;
    std::vector<std::string> descriptions() const;

private:
    std::vector<std::unique_ptr<ModelEffect>> effects_;
};

}  // namespace rockfrac
