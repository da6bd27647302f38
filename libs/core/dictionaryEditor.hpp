#pragma once
// Editing one entry of a dictionary file in place (caseDict -set/-add/-remove).
//
// The guarantee: every byte outside the edited entry is kept: comments,
// spacing, ordering, #include lines and macros. A new entry goes at the end of
// its sub-dictionary, indented like its siblings; missing sub-dictionaries on
// its path are created. The editor works on the text as written, so it edits
// what the file itself says, never what an #include brought in.
#include <filesystem>
#include <functional>
#include <string>

namespace rockfrac {

// Replace the value of `keyPath` (the tokens between keyword and ';') with
// `newValueText`, or add the entry when it is missing. A non-empty `comment`
// is written after the ';' as "// comment" (replacing a comment already there).
std::string setEntry(const std::string& text, const std::string& keyPath, const std::string& newValueText,
                     const std::string& fileName, const std::string& comment = "");

// Like setEntry, but UserError when the entry exists already (caseDict -add)
// or, for replaceEntry, when it does not (caseDict -set).
std::string addEntry(const std::string& text, const std::string& keyPath, const std::string& newValueText,
                     const std::string& fileName, const std::string& comment = "");
std::string replaceEntry(const std::string& text, const std::string& keyPath, const std::string& newValueText,
                         const std::string& fileName, const std::string& comment = "");

// Remove the entry (its whole line when it has the line to itself). UserError when missing.
std::string removeEntry(const std::string& text, const std::string& keyPath, const std::string& fileName);

// Whether the text itself (not an #include) has the entry.
bool hasTextEntry(const std::string& text, const std::string& keyPath, const std::string& fileName);

// Read `path`, apply `edit` (text, file name) -> new text, check that the
// result still reads as a dictionary, then write it atomically (unless
// `checkOnly`). `description` says what the edit was in error messages.
using DictionaryTextEdit = std::function<std::string(const std::string& text, const std::string& fileName)>;
void editDictionaryFile(const std::filesystem::path& path, const DictionaryTextEdit& edit,
                        const std::string& description, bool checkOnly = false);

// File versions of setEntry and removeEntry.
void setEntryInFile(const std::filesystem::path& path, const std::string& keyPath,
                    const std::string& newValueText, const std::string& comment = "");
void removeEntryInFile(const std::filesystem::path& path, const std::string& keyPath);

}  // namespace rockfrac
