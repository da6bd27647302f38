// caseDict: read and edit case dictionaries from the shell, like OpenFOAM's
// foamDictionary. Reading prints the dictionary as the applications see it
// (#include, $macros and #eval expanded); editing changes one entry in place
// and keeps every other byte of the file (comments, spacing, order).
//
// Sample runs:
//   caseDict -case tutorials/BDT/granite constant/rockProperties
//   caseDict constant/rockProperties -keywords
//   caseDict constant/rockProperties -entry bond/voronoiQNSC/tensileStrength -value
//   caseDict constant/rockProperties -entry bond/voronoiQNSC/tensileStrength -set 28e6
//   caseDict constant/rockProperties -entry bond/voronoiQNSC/cohesion -add 5e6 -comment "from BDT series 3"
//   caseDict constant/rockProperties -entry bond/voronoiQNSC/cohesion -remove
//   caseDict -case tutorials/BDT/granite -check
#include <iostream>

#include "caseCheck.hpp"
#include "core/application.hpp"
#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"

using namespace rockfrac;

namespace {

const AppInfo info = {
    "caseDict",
    "Print or edit a case dictionary. Without -entry, prints the whole dictionary in canonical form with "
    "#include, $macros and #eval expanded. With -entry, prints that entry (-value: only its value); -set, "
    "-add "
    "and -remove change the file in place, atomically, keeping comments and layout. -check (no file) checks "
    "the case's dictionaries for entries no application reads (misspelt ones): it lists each with its "
    "file:line and the nearest known entry and exits 1, or exits 0 when there is none.",
    "[options] <dictionary file, relative to the case> | -check",
    {"caseDict -case tutorials/BDT/granite constant/rockProperties",
     "caseDict constant/rockProperties -keywords",
     "caseDict constant/rockProperties -entry bond/voronoiQNSC/tensileStrength -value",
     "caseDict constant/rockProperties -entry bond/voronoiQNSC/tensileStrength -set 28e6",
     "caseDict constant/rockProperties -entry bond/voronoiQNSC/cohesion -add 5e6 -comment \"from BDT series "
     "3\"",
     "caseDict constant/rockProperties -entry bond/voronoiQNSC/cohesion -remove",
     "caseDict -case tutorials/BDT/granite -check"},
    {
        {"-entry", "key", "select an entry by its slash path, e.g. bond/voronoiQNSC/tensileStrength"},
        {"-value", "", "print only the value of the entry"},
        {"-keywords", "", "list the keywords of the dictionary, or of the sub-dictionary -entry"},
        {"-set", "value", "change the value of an existing entry"},
        {"-add", "value", "add a new entry, creating missing sub-dictionaries"},
        {"-remove", "", "remove the entry"},
        {"-comment", "text", "with -set or -add: write '// text' after the entry"},
        {"-expand", "",
         "print with #include, $macros and #eval expanded (always done; for foamDictionary users)"},
        {"-check", "",
         "check the case's dictionaries for unknown (misspelt) top-level entries; exit 1 listing them"},
    },
    0,
    1,
    false,
};

int editEntry(const Application& app, const std::filesystem::path& file, const std::string& key)
{
    const std::string comment = app.optionIf("-comment").value_or("");
    if (app.has("-remove")) {
        if (!comment.empty()) throw UserError("-comment goes with -set or -add, not -remove");
        editDictionaryFile(
            file,
            [&](const std::string& text, const std::string& name) { return removeEntry(text, key, name); },
            "removing '" + key + "'", app.dryRun());
        return exitSuccess;
    }
    const bool adding = app.has("-add");
    const std::string value = app.option(adding ? "-add" : "-set");
    editDictionaryFile(
        file,
        [&](const std::string& text, const std::string& name) {
            return adding ? addEntry(text, key, value, name, comment)
                          : replaceEntry(text, key, value, name, comment);
        },
        (adding ? "adding '" : "setting '") + key + "' to '" + value + "'", app.dryRun());
    return exitSuccess;
}

void printEntry(const Application& app, const Dictionary& dict, const std::optional<std::string>& key)
{
    if (app.has("-keywords")) {
        for (const std::string& keyword : (key ? dict.subDict(*key) : dict).keys())
            std::cout << keyword << "\n";
        return;
    }
    if (!key) {
        if (app.has("-value")) throw UserError("-value needs -entry <key>: which entry's value to print");
        std::cout << toString(dict);
        return;
    }
    const Entry& entry = dict.entry(*key);
    if (!app.has("-value"))
        std::cout << toString(entry);
    else if (entry.isDict())
        std::cout << toString(*entry.dict);
    else
        std::cout << valueText(entry) << "\n";
}

int check(const Application& app)
{
    if (!app.args().empty())
        throw UserError("-check checks the whole case (-case <dir>); give no dictionary file with it");
    const std::vector<std::string> problems = checkCaseDictionaries(app.casePath());
    for (const std::string& p : problems) std::cout << p << "\n";
    if (problems.empty()) {
        std::cout << "No unknown entries in the dictionaries of " << app.casePath().string() << "\n";
        return exitSuccess;
    }
    throw UserError(problems.front() +
                    (problems.size() == 1
                         ? ""
                         : " (and " + std::to_string(problems.size() - 1) + " more, listed on the output)") +
                    "; correct or remove it (caseDict -check)");
}

int run(Application& app)
{
    if (app.has("-check")) return check(app);
    if (app.args().empty())
        throw UserError("expected a dictionary file, relative to the case (or -check); usage: caseDict " +
                        app.info().usage);
    const std::filesystem::path file = app.path(app.args().front());
    const std::optional<std::string> key = app.optionIf("-entry");
    const int edits = app.has("-set") + app.has("-add") + app.has("-remove");
    if (edits > 1) throw UserError("-set, -add and -remove exclude each other; give one of them");
    if (edits == 1) {
        if (!key) throw UserError("-set, -add and -remove need -entry <key>: which entry to change");
        return editEntry(app, file, *key);
    }
    if (app.has("-comment")) throw UserError("-comment goes with -set or -add");
    printEntry(app, Dictionary::readFile(file), key);
    return exitSuccess;
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, run);
}
