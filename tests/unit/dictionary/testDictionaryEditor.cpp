// The editor changes one entry and keeps every other byte of the file.
#include "core/dictionaryEditor.hpp"
#include "dictionaryTestSupport.hpp"

using namespace rockfrac;
using rockfrac::test::errorOf;
using rockfrac::test::readText;
using rockfrac::test::ScratchDir;

namespace {

const std::string rockProperties =
    R"(/*--------------------------------*- C++ -*----------------------------------*\
  rockfrac: rock properties of the granite of the BDT tutorial
\*---------------------------------------------------------------------------*/
FoamFile
{
    format      ascii;
    class       dictionary;
    object      rockProperties;
}

density         2650;       // kg/m^3, measured

bond
{
    // Mode I strength from the Brazilian tests (n = 12)
    tensileStrength 20e6;   // Pa
    shearStrength   (30e6 5e6);
}

// ************************************************************************* //
)";

}  // namespace

TEST_CASE("set an existing entry: only its value changes", "[dictionary][editor]")
{
    const std::string edited =
        setEntry(rockProperties, "bond/tensileStrength", "28e6", "constant/rockProperties");
    std::string expected = rockProperties;
    expected.replace(expected.find("20e6"), 4, "28e6");
    CHECK(edited == expected);
    CHECK(Dictionary::parse(edited, "x").get<double>("bond/tensileStrength") == 28e6);
}

TEST_CASE("set a list value and a top-level value", "[dictionary][editor]")
{
    std::string edited = setEntry(rockProperties, "bond/shearStrength", "(31e6 4e6)", "r");
    edited = setEntry(edited, "density", "2700", "r");
    std::string expected = rockProperties;
    expected.replace(expected.find("(30e6 5e6)"), 10, "(31e6 4e6)");
    expected.replace(expected.find("2650"), 4, "2700");
    CHECK(edited == expected);
}

TEST_CASE("add to a nested dictionary, aligned like its siblings", "[dictionary][editor]")
{
    const std::string edited = setEntry(rockProperties, "bond/cohesion", "5e6", "r");
    std::string expected = rockProperties;
    expected.insert(expected.find("\n}\n\n// ****"), "\n    cohesion        5e6;");
    CHECK(edited == expected);
}

TEST_CASE("add creates missing sub-dictionaries with matching indentation", "[dictionary][editor]")
{
    const std::string edited = setEntry(rockProperties, "bond/damage/model", "linear", "r");
    std::string expected = rockProperties;
    expected.insert(expected.find("\n}\n\n// ****"), "\n    damage\n    {\n        model linear;\n    }");
    CHECK(edited == expected);
    CHECK(Dictionary::parse(edited, "r").get<std::string>("bond/damage/model") == "linear");
}

TEST_CASE("add at the top level goes after the last entry, before the footer", "[dictionary][editor]")
{
    const std::string edited = setEntry(rockProperties, "poissonRatio", "0.25", "r");
    std::string expected = rockProperties;
    expected.insert(expected.find("\n\n// ****"), "\npoissonRatio    0.25;");
    CHECK(edited == expected);
}

TEST_CASE("add into an empty file and an empty dictionary", "[dictionary][editor]")
{
    CHECK(setEntry("", "a", "1", "r") == "a 1;\n");
    CHECK(setEntry("// note", "a/b", "1", "r") == "// note\na\n{\n    b 1;\n}\n");
    CHECK(setEntry("sub {}\n", "sub/x", "2", "r") == "sub {\n    x 2;\n}\n");
    CHECK(setEntry("sub\n{\n}\n", "sub/x", "2", "r") == "sub\n{\n    x 2;\n}\n");
}

TEST_CASE("a trailing comment is added, or replaces the one there", "[dictionary][editor]")
{
    const std::string comment = "calibrated 2026-11-22 from BDT series 3";
    std::string edited = setEntry(rockProperties, "bond/tensileStrength", "28e6", "r", comment);
    CHECK(edited.find("tensileStrength 28e6;   // calibrated 2026-11-22 from BDT series 3\n") !=
          std::string::npos);
    edited = setEntry("a 1;\nb 2;\n", "a", "3", "r", "why");
    CHECK(edited == "a 3; // why\nb 2;\n");
    edited = setEntry("a 1;", "c/d", "3", "r", "new");
    CHECK(edited == "a 1;\nc\n{\n    d 3; // new\n}");
}

TEST_CASE("remove an entry and its line", "[dictionary][editor]")
{
    const std::string edited = removeEntry(rockProperties, "bond/shearStrength", "r");
    std::string expected = rockProperties;
    expected.erase(expected.find("    shearStrength"),
                   std::string("    shearStrength   (30e6 5e6);\n").size());
    CHECK(edited == expected);
    CHECK(removeEntry("a 1; b 2;\n", "b", "r") == "a 1; \n");
    CHECK(removeEntry("a 1;\nb 2;", "b", "r") == "a 1;");
    CHECK(removeEntry("x { y 1; }\nz 2;\n", "x", "r") == "z 2;\n");
}

TEST_CASE("set and remove round trip to the original bytes", "[dictionary][editor]")
{
    const std::string added = setEntry(rockProperties, "bond/cohesion", "5e6", "r");
    CHECK(removeEntry(added, "bond/cohesion", "r") == rockProperties);
    const std::string changed = setEntry(rockProperties, "density", "1", "r");
    CHECK(setEntry(changed, "density", "2650", "r") == rockProperties);
}

TEST_CASE("a value can become a dictionary and back", "[dictionary][editor]")
{
    const std::string asDict = setEntry("a 1;\nb 2;\n", "a", "{ c 3; }", "r");
    CHECK(asDict == "a { c 3; }\nb 2;\n");
    CHECK(setEntry(asDict, "a", "4", "r") == "a 4;\nb 2;\n");
}

TEST_CASE("the editor refuses values that are not one value, and bad paths", "[dictionary][editor]")
{
    CHECK(
        errorOf([] { setEntry("a 1;", "a", "1; evil 2", "r"); }) ==
        "new value '1; evil 2' for 'a' has an unexpected ';'; expected value tokens such as 28e6, (0 0 1) or "
        "\"text\", without ';'");
    CHECK(errorOf([] { setEntry("a 1;", "a", "(1 2", "r"); }) ==
          "new value '(1 2' for 'a' has unbalanced brackets; expected value tokens such as 28e6, (0 0 1) or "
          "\"text\", without ';'");
    CHECK(errorOf([] { setEntry("a 1;", "a", " ", "r"); }).rfind("empty new value for 'a'", 0) == 0);
    CHECK(errorOf([] { setEntry("a 1;", "a/b", "2", "system/x"); }) ==
          "system/x:1:1: 'a' is not a dictionary; expected a sub-dictionary 'a { ... }' to hold 'b'");
    CHECK(errorOf([] { setEntry("a 1;", "a//b", "2", "r"); }).rfind("bad entry path 'a//b'", 0) == 0);
    CHECK(errorOf([] { removeEntry("a 1;\ns { }\n", "s/b", "system/x"); }) ==
          "system/x:2:5: no entry 's/b' to remove in dictionary 's'; expected an existing entry (caseDict "
          "-keywords lists them)");
    CHECK(errorOf([] { addEntry("a 1;", "a", "2", "system/x"); }) ==
          "system/x:1:1: entry 'a' exists already; expected a new entry; to change its value, set it instead "
          "(caseDict -set)");
    CHECK(errorOf([] { replaceEntry("a 1;", "b", "2", "system/x"); }) ==
          "system/x:1:5: no entry 'b' in the text of dictionary 'x'; expected an existing entry (caseDict "
          "-keywords lists them), or add it (caseDict -add)");
}

TEST_CASE("the editor keeps #include lines, macros and #eval as written", "[dictionary][editor]")
{
    const std::string text = "#include \"defaults\"\nr 0.1;\narea #eval{ pi*$r^2 };\n$base;\nk 1;\n";
    CHECK(setEntry(text, "k", "2", "r") ==
          "#include \"defaults\"\nr 0.1;\narea #eval{ pi*$r^2 };\n$base;\nk 2;\n");
    CHECK(setEntry(text, "area", "3", "r") == "#include \"defaults\"\nr 0.1;\narea 3;\n$base;\nk 1;\n");
}

TEST_CASE("setEntryInFile writes atomically and refuses edits that break the file", "[dictionary][editor]")
{
    ScratchDir scratch;
    const auto file = scratch.write("constant/rockProperties", rockProperties);
    setEntryInFile(file, "bond/tensileStrength", "28e6");
    CHECK(Dictionary::readFile(file).get<double>("bond/tensileStrength") == 28e6);
    CHECK(errorOf([&] {
              setEntryInFile(file, "density", "$undefinedMacro");
          }).find("undefined variable '$undefinedMacro'") != std::string::npos);
    CHECK(Dictionary::readFile(file).get<double>("density") == 2650);
    removeEntryInFile(file, "bond/shearStrength");
    CHECK(!Dictionary::readFile(file).found("bond/shearStrength"));
    std::string expected = rockProperties;
    expected.replace(expected.find("20e6"), 4, "28e6");
    expected.erase(expected.find("    shearStrength"),
                   std::string("    shearStrength   (30e6 5e6);\n").size());
    CHECK(readText(file) == expected);
}

TEST_CASE("setting a value keeps its dimension set unless a new one is given", "[dictionary][editor]")
{
    CHECK(setEntry("E   [Pa] 77e9; // granite\n", "E", "80e9", "r") == "E   [Pa] 80e9; // granite\n");
    CHECK(setEntry("E   [Pa] 77e9;\n", "E", "[kg/m/s^2] 80e9", "r") == "E   [kg/m/s^2] 80e9;\n");
    CHECK(setEntry("E   77e9;\n", "E", "[Pa] 80e9", "r") == "E   [Pa] 80e9;\n");
}
