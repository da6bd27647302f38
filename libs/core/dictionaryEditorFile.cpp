// Editing dictionary files on disk: read, edit, check, write atomically.
// Kept apart from the text editor so that the fuzz target needs no file I/O.
#include <fstream>
#include <sstream>

#include "core/atomicFile.hpp"
#include "core/dictionary.hpp"
#include "core/dictionaryEditor.hpp"

namespace rockfrac {

namespace {

std::string readWholeFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    if (!in || !std::filesystem::is_regular_file(path, ec))
        throw UserError(path.string() + ": cannot read the file; expected an existing dictionary file");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The edited text must still read as a dictionary before it replaces the
// file: an edit never leaves a case that its applications cannot read.
void checkAndWrite(const std::filesystem::path& path, const std::string& text, const std::string& edit)
{
    try {
        (void)Dictionary::parse(text, path.lexically_normal().string());
    } catch (const UserError& error) {
        throw UserError(std::string(error.what()) + " (after " + edit + "; the file was not changed)");
    }
    writeFileAtomically(path, [&text](std::ostream& out) { out << text; });
}

}  // namespace

void setEntryInFile(const std::filesystem::path& path, const std::string& keyPath,
                    const std::string& newValueText, const std::string& comment)
{
    const std::string name = path.lexically_normal().string();
    const std::string edited = setEntry(readWholeFile(path), keyPath, newValueText, name, comment);
    checkAndWrite(path, edited, "setting '" + keyPath + "' to '" + newValueText + "'");
}

void removeEntryInFile(const std::filesystem::path& path, const std::string& keyPath)
{
    const std::string name = path.lexically_normal().string();
    checkAndWrite(path, removeEntry(readWholeFile(path), keyPath, name), "removing '" + keyPath + "'");
}

}  // namespace rockfrac
