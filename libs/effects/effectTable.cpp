// The library of model effects: one line per effect (each effect's descriptor, with its
// probe size — the trial step explainGap uses for its sensitivities, large enough to stand
// out of the scatter of a few Voronoi seeds, small enough to stay near the baseline — is a
// static member of its class).
#include <algorithm>

#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/selector.hpp"
#include "effects/bondStrengthScatter.hpp"
#include "effects/contactCrumbling.hpp"
#include "effects/machineCompliance.hpp"
#include "effects/modelEffect.hpp"
#include "effects/plateFriction.hpp"
#include "effects/rateDamping.hpp"
#include "effects/seatingOffset.hpp"

namespace rockfrac {

const std::vector<EffectDescriptor>& effectLibrary()
{
    static const std::vector<EffectDescriptor> library{
        ContactCrumbling::descriptor,    MachineCompliance::descriptor, SeatingOffset::descriptor,
        BondStrengthScatter::descriptor, RateDamping::descriptor,       PlateFriction::descriptor,
    };
    return library;
}

const Selector<ModelEffect>& effectSelector()
{
    static const Selector<ModelEffect> table("model effect", [] {
        std::vector<Selector<ModelEffect>::Model> models;
        for (const EffectDescriptor& d : effectLibrary()) models.push_back({d.name.c_str(), d.make});
        return models;
    }());
    return table;
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
                            d.parameter + " ...; } (docs/models/effects/" + key + ".md)");
        std::vector<std::string> entries{d.parameter};
        entries.insert(entries.end(), d.fixedEntries.begin(), d.fixedEntries.end());
        requireKnownEntries(modelEffects.subDict(key), entries);
        result.effects_.push_back(effectSelector().make(key, modelEffects.subDict(key)));
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
