#pragma once
// Run-time selection of models (OpenFOAM's run-time selection tables, without macros or
// self-registering statics): a family's table maps each keyword to a factory that builds
// the model from its own coefficient sub-dictionary, the one named after the keyword.
//
//     bond
//     {
//         model   voronoiQNSC;             // the keyword: which model
//         voronoiQNSC { E [Pa] 46e9; ... } // its coefficients, read by the model itself
//     }
//
//     const Selector<BondLawModel>& laws = bondLaws();  // the family's table (one line per model)
//     std::shared_ptr<BondLawModel> law = laws.select(rockProperties.subDict("bond"), "model");
//
// A new model is its own file pair plus one line in its family's table. Messages name the
// file, the line and the known keywords (the table's, sorted as registered).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/dictionary.hpp"
#include "core/error.hpp"

namespace rockfrac {

template <class Base, class... Args>
class Selector {
public:
    // Builds the model from its coefficient dictionary and the family's extra arguments.
    using Factory = std::unique_ptr<Base> (*)(const Dictionary& coefficients, Args... args);

    struct Model {
        const char* name;
        Factory make;
        // The model has no coefficients of its own: its sub-dictionary may be left out.
        bool coefficientsOptional = false;
    };

    Selector(std::string family, std::vector<Model> models)
        : family_(std::move(family)), models_(std::move(models))
    {
    }

    // "bond law": for messages.
    const std::string& family() const { return family_; }

    std::vector<std::string> names() const
    {
        std::vector<std::string> result;
        for (const Model& m : models_) result.emplace_back(m.name);
        return result;
    }

    bool has(const std::string& name) const { return find(name) != nullptr; }

    // The model `name` built from `coefficients`; a UserError listing the known names otherwise.
    std::unique_ptr<Base> make(const std::string& name, const Dictionary& coefficients, Args... args) const
    {
        const Model* m = find(name);
        if (!m) {
            std::string known;
            for (const std::string& n : names()) known += (known.empty() ? "" : ", ") + n;
            throw UserError("unknown " + family_ + " '" + name + "'; known: " + known);
        }
        return m->make(coefficients, std::forward<Args>(args)...);
    }

    // The keyword `selectorKey` of `dict` names the model (an unknown word is an error at its
    // line listing the known ones); the model reads its coefficients from dict/<keyword>, which
    // is required unless the model has none (an empty dictionary then stands for it).
    std::unique_ptr<Base> select(const Dictionary& dict, const std::string& selectorKey, Args... args) const
    {
        const std::string name = dict.getWord(selectorKey, names());
        if (find(name)->coefficientsOptional && !dict.found(name))
            return make(name, Dictionary(name, dict.fileName()), std::forward<Args>(args)...);
        return make(name, dict.subDict(name), std::forward<Args>(args)...);
    }

private:
    const Model* find(const std::string& name) const
    {
        for (const Model& m : models_)
            if (name == m.name) return &m;
        return nullptr;
    }

    std::string family_;
    std::vector<Model> models_;
};

// Refuse entries of `dict` that none of `known` names: a misspelt optional entry would
// otherwise be silently ignored. The message names the file and line of the entry, the known
// entries and, when given, a hint ("the law's coefficients belong in ...").
void requireKnownEntries(const Dictionary& dict, const std::vector<std::string>& known,
                         const std::string& hint = "");

// The known keyword nearest `word` (case-insensitive edit distance at most max(2, |word| / 4)),
// or "" when none is that close: the "did you mean" of the messages.
std::string nearestKeyword(const std::string& word, const std::vector<std::string>& known);

}  // namespace rockfrac
