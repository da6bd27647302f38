// Editing dictionary files on disk: read, edit, check, write atomically.
// Kept apart from the text editor so that the fuzz target needs no file I/O.
#include <fstream>
#include <sstream>

#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"

namespace rockfrac {

namespace {

std::string readWholeFile(const std::filesystem::path& path, const std::string& shownName)
{
    std::error_code ec;
    std::ifstream in;
    if (std::filesystem::is_regular_file(path, ec)) in.open(path, std::ios::binary);
    if (!in.is_open())
        throw UserError(shownName + ": cannot read the file; expected an existing dictionary file");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

// The edited text must still read as a dictionary before it replaces the
// file: an edit never leaves a case that its applications cannot read.
void editDictionaryFile(const std::filesystem::path& path, const DictionaryTextEdit& edit,
                        const std::string& description, bool checkOnly)
{
    const std::string name = path.lexically_normal().string();
    const std::string edited = edit(readWholeFile(path, name), name);
    try {
        (void)Dictionary::parse(edited, name);
    } catch (const UserError& error) {
        throw UserError(std::string(error.what()) + " (after " + description + "; the file was not changed)");
    }
    if (!checkOnly) writeFileAtomically(path, [&edited](std::ostream& out) { out << edited; });
}

void setEntryInFile(const std::filesystem::path& path, const std::string& keyPath,
                    const std::string& newValueText, const std::string& comment)
{
    editDictionaryFile(
        path,
        [&](const std::string& text, const std::string& name) {
            return setEntry(text, keyPath, newValueText, name, comment);
        },
        "setting '" + keyPath + "' to '" + newValueText + "'");
}

void removeEntryInFile(const std::filesystem::path& path, const std::string& keyPath)
{
    editDictionaryFile(
        path,
        [&](const std::string& text, const std::string& name) { return removeEntry(text, keyPath, name); },
        "removing '" + keyPath + "'");
}

}  // namespace rockfrac
