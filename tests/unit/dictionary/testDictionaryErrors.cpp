// Malformed input: each error names file:line:column and says what was expected.
// The messages are part of the interface (users read them, scripts grep them),
// so they are checked word for word.
#include "dictionaryTestSupport.hpp"

using namespace rockfrac;
using rockfrac::test::errorOf;
using rockfrac::test::parse;
using rockfrac::test::parseError;
using rockfrac::test::ScratchDir;

TEST_CASE("error: unterminated string", "[dictionary][errors]")
{
    CHECK(parseError("a 1;\nname \"granite;\n") ==
          "constant/rockProperties:2:6: unterminated string; expected a closing '\"' for the string opened "
          "here");
}

TEST_CASE("error: unterminated comment", "[dictionary][errors]")
{
    CHECK(parseError("a 1;\n  /* forgot to close\nb 2;\n") ==
          "constant/rockProperties:2:3: unterminated comment '/*'; expected '*/' to close the comment opened "
          "here");
}

TEST_CASE("error: missing ';' at the end of the file and before the next entry", "[dictionary][errors]")
{
    CHECK(parseError("endTime 10") ==
          "constant/rockProperties:1:11: missing ';' after the value of 'endTime'; expected ';' to end the "
          "entry "
          "before the end of the file");
    CHECK(parseError("endTime 10\ndeltaT 0.1;\n") ==
          "constant/rockProperties:1:11: missing ';' after the value of 'endTime'; expected ';' to end the "
          "entry "
          "before 'deltaT' on the next line");
    CHECK(parseError("bond { E 1 }") ==
          "constant/rockProperties:1:11: missing ';' after the value of 'E'; expected ';' to end the entry "
          "before "
          "'}'");
}

TEST_CASE("error: unbalanced braces", "[dictionary][errors]")
{
    CHECK(parseError("bond\n{\n    E 1;\n") ==
          "constant/rockProperties:2:1: '{' of dictionary 'bond' is never closed; expected a matching '}' "
          "before "
          "the end of the file");
    CHECK(parseError("a 1;\n}\n") ==
          "constant/rockProperties:2:1: unexpected '}' with no matching '{'; expected a keyword, a directive "
          "or "
          "the end of the file");
}

TEST_CASE("error: unbalanced parentheses", "[dictionary][errors]")
{
    CHECK(parseError("points ((0 1) (2 3);\n") ==
          "constant/rockProperties:1:20: unexpected ';' inside the list opened at line 1, column 8; expected "
          "')' "
          "to close the list first");
    CHECK(parseError("points (0 1\n") ==
          "constant/rockProperties:1:8: '(' is never closed; expected a matching ')' before the end of the "
          "file");
    CHECK(parseError("points (0 1));\n") ==
          "constant/rockProperties:1:13: unexpected ')' in the value of 'points'; expected a value or ';' to "
          "end "
          "the entry");
}

TEST_CASE("error: size prefix mismatch", "[dictionary][errors]")
{
    CHECK(parseError("sizes 3(1 2);\n") ==
          "constant/rockProperties:1:7: list size 3 does not match its 2 values; expected a size of 2 or 3 "
          "values "
          "in the list");
}

TEST_CASE("error: bad uniform list", "[dictionary][errors]")
{
    CHECK(
        parseError("field 10{1 2};\n") ==
        "constant/rockProperties:1:12: bad uniform list 10{...}: number 2 after its value; expected a single "
        "value inside the braces, as in 10{0}");
    CHECK(parseError("field 10{};\n") ==
          "constant/rockProperties:1:10: bad uniform list 10{...}: '}' is not a single value; expected a "
          "single "
          "value inside the braces, as in 10{0}");
}

TEST_CASE("error: unknown directive", "[dictionary][errors]")
{
    CHECK(parseError("#inputMode merge\n") ==
          "constant/rockProperties:1:1: unknown directive '#inputMode'; expected #include \"file\", "
          "#includeIfPresent \"file\", or #eval inside a value");
}

TEST_CASE("error: #include of a missing file names the including file and line", "[dictionary][errors]")
{
    ScratchDir scratch;
    const auto file = scratch.write("system/controlDict", "a 1;\n#include \"missingFile\"\n");
    const std::string dir = (scratch.path() / "system").string();
    CHECK(errorOf([&] { Dictionary::readFile(file); }) ==
          dir + "/controlDict:2:10: cannot read included file '" + dir +
              "/missingFile' (no such file); expected an existing file; the path is relative to the "
              "directory of '" +
              dir + "/controlDict'");
}

TEST_CASE("error: #include cycle", "[dictionary][errors]")
{
    ScratchDir scratch;
    const auto a = scratch.write("a", "x 1;\n#include \"b\"\n");
    scratch.write("b", "y 2;\n\n  #include \"a\"\n");
    const std::string dir = scratch.path().string();
    CHECK(errorOf([&] { Dictionary::readFile(a); }) ==
          dir + "/b:3:3: #include cycle: " + dir + "/a -> " + dir + "/b -> " + dir +
              "/a; expected includes that never lead back to a file "
              "being read");
}

TEST_CASE("error: undefined $var", "[dictionary][errors]")
{
    CHECK(parseError("bond\n{\n    E $Emodulus;\n}\n") ==
          "constant/rockProperties:3:7: undefined variable '$Emodulus'; expected an entry 'Emodulus' defined "
          "above, in this dictionary or an enclosing one");
    CHECK(parseError("E $later;\nlater 1;\n").find("1:3: undefined variable '$later'") != std::string::npos);
}

TEST_CASE("error: bad #eval expression, with the position inside it", "[dictionary][errors]")
{
    CHECK(parseError("r 0.1;\narea #eval \"pi*$r^^2\";\n") ==
          "constant/rockProperties:2:19: unexpected '^' in #eval expression (character 7 of 'pi*$r^^2'); "
          "expected "
          "a number, '(', a function, pi or a $variable");
    CHECK(parseError("x #eval{ sqroot(2) };\n") ==
          "constant/rockProperties:1:10: unknown function 'sqroot' in #eval expression (character 2 of "
          "'sqroot(2)'); expected one of sqrt exp log log10 sin cos tan asin acos atan atan2 pow abs min max "
          "floor "
          "ceil");
    CHECK(parseError("x #eval{ 2 *\n  (1 + 3 };\n") ==
          "constant/rockProperties:2:10: missing ')' in #eval expression (character 15 of '2 *   (1 + 3'); "
          "expected ')' to close the '(' at character 8");
    CHECK(parseError("x #eval{ sqrt(-1) };\n") ==
          "constant/rockProperties:1:10: 'sqrt' of these arguments is not a finite number (character 2 of "
          "'sqrt(-1)'); expected arguments within the domain of the operation");
}

TEST_CASE("error: division by zero in #eval", "[dictionary][errors]")
{
    CHECK(parseError("gap 0;\nk #eval{ 1 / $gap };\n") ==
          "constant/rockProperties:2:12: division by zero in #eval expression (character 4 of '1 / $gap'); "
          "expected a non-zero divisor");
}

TEST_CASE("error: wrong dimension set", "[dictionary][errors]")
{
    CHECK(parseError("E [1 -1 -2 0 0 0] 77e9;\n") ==
          "constant/rockProperties:1:4: dimension set has 6 exponents; expected 7 integer exponents [kg m s "
          "K mol "
          "A cd] or coherent SI units (kg m s K mol A cd N Pa J W Hz rad, combined with * / ^, or '-' for "
          "none)");
    CHECK(parseError("E [1 -1 -2 0 0.5 0 0] 77e9;\n").find("1:14: exponent '0.5' is not a small integer") !=
          std::string::npos);
    CHECK(parseError("E [MPa] 77e3;\n") ==
          "constant/rockProperties:1:4: 'MPa' is not a coherent SI unit; expected SI units without prefixes "
          "(write the value in Pa)");
    CHECK(parseError("E [kg/furlong] 1;\n").find("1:7: unknown unit 'furlong'") != std::string::npos);
    CHECK(parseError("E 77e9 [Pa];\n") ==
          "constant/rockProperties:1:8: dimension set [Pa] after the value; expected the dimension set right "
          "after the keyword, as in 'E [Pa] 77e9;'");
    CHECK(parseError("E [Pa 77e9;\n") ==
          "constant/rockProperties:1:3: unterminated dimension set '['; expected ']' to close it, as in [1 "
          "-1 -2 0 "
          "0 0 0] or [Pa]");
}

TEST_CASE("error: wrong type", "[dictionary][errors]")
{
    const Dictionary dict =
        parse("endTime abc;\norigin (0 1);\nn 2.5;\nseed -1;\nsub { a 1; }\nmulti 1 2;\n");
    CHECK(errorOf([&] { dict.get<double>("endTime"); }) ==
          "constant/rockProperties:1:9: 'endTime' is a word ('abc'); expected a number");
    CHECK(errorOf([&] { dict.get<Vec3>("origin"); }) ==
          "constant/rockProperties:2:8: 'origin' is a list of 2 values; expected a vector of 3 numbers (x y "
          "z)");
    CHECK(errorOf([&] { dict.get<int>("n"); }) ==
          "constant/rockProperties:3:3: 'n' = 2.5 is not a whole number; expected an integer");
    CHECK(errorOf([&] { dict.get<std::uint64_t>("seed"); }) ==
          "constant/rockProperties:4:6: 'seed' = -1 is out of range; expected a non-negative integer in [0, "
          "18446744073709551615]");
    CHECK(errorOf([&] { dict.get<double>("sub"); }) ==
          "constant/rockProperties:5:5: 'sub' is a dictionary; expected a number");
    CHECK(errorOf([&] { dict.get<double>("multi"); }) ==
          "constant/rockProperties:6:9: 'multi' has 2 values; expected a single value: a number");
    CHECK(errorOf([&] { dict.get<std::vector<std::vector<double>>>("origin"); }) ==
          "constant/rockProperties:2:9: item 1 of 'origin' is a number (0); expected a list ( ... ) of "
          "numbers");
    CHECK(errorOf([&] { dict.subDict("endTime"); }) ==
          "constant/rockProperties:1:9: 'endTime' is a value, not a dictionary; expected 'endTime { ... }'");
}

TEST_CASE("error: out of range", "[dictionary][errors]")
{
    const Dictionary dict = parse("// elastic\n\n\n\n\n\n\n\n\n\n\npoissonRatio     0.5;\n");
    CHECK(errorOf([&] { dict.getScalar("poissonRatio", Bounds::closedOpen(0, 0.5)); }) ==
          "constant/rockProperties:12:18: poissonRatio = 0.5 is out of range; expected a value in [0, 0.5)");
}

TEST_CASE("error: missing required entry points at the closing brace or the file end", "[dictionary][errors]")
{
    const Dictionary dict = Dictionary::parse("startTime 0;\n\nbond\n{\n    E 1;\n}\n", "system/controlDict");
    CHECK(errorOf([&] { dict.get<double>("endTime"); }) ==
          "system/controlDict:7:1: missing required entry 'endTime' in dictionary 'controlDict'; expected a "
          "line "
          "'endTime <value>;' in it");
    CHECK(errorOf([&] { dict.get<double>("bond/tensileStrength"); }) ==
          "system/controlDict:6:1: missing required entry 'tensileStrength' in dictionary 'bond'; expected a "
          "line "
          "'tensileStrength <value>;' in it");
    CHECK(errorOf([&] { dict.get<double>("contact/k"); }) ==
          "system/controlDict:7:1: missing required sub-dictionary 'contact' in dictionary 'controlDict'; "
          "expected "
          "a sub-dictionary 'contact { ... }' in it");
}

TEST_CASE("error: a keyword written twice in one dictionary", "[dictionary][errors]")
{
    CHECK(parseError("bond\n{\n    E 1;\n    nu 0.2;\n    E 2;\n}\n") ==
          "constant/rockProperties:5:5: duplicate entry 'E' in dictionary 'bond' (first defined at "
          "constant/rockProperties:3:5); expected each keyword once; remove or rename one of them");
}

TEST_CASE("error: bad boolean", "[dictionary][errors]")
{
    const Dictionary dict = parse("writeCompressed maybe;\nflag 1;\n");
    CHECK(errorOf([&] { dict.get<bool>("writeCompressed"); }) ==
          "constant/rockProperties:1:17: 'writeCompressed' is a word ('maybe'); expected a boolean: "
          "true/false, "
          "on/off or yes/no");
    CHECK(errorOf([&] { dict.get<bool>("flag"); }) ==
          "constant/rockProperties:2:6: 'flag' is a number (1); expected a boolean: true/false, on/off or "
          "yes/no");
}

TEST_CASE("error: other malformed input", "[dictionary][errors]")
{
    CHECK(parseError("big 1e999;\n") ==
          "constant/rockProperties:1:5: number 1e999 is too large; expected a magnitude below 1.8e308");
    CHECK(parseError("a\x01 1;\n") ==
          "constant/rockProperties:1:2: unexpected control character (byte 0x01); expected plain text; "
          "remove the "
          "character");
    CHECK(
        parseError("3 1;\n") ==
        "constant/rockProperties:1:1: unexpected number 3; expected a keyword, a directive such as #include, "
        "or '}'");
    CHECK(parseError("x #include \"y\";\n") ==
          "constant/rockProperties:1:3: directive '#include' inside a value; expected #eval here, or "
          "#include on a "
          "line of its own between entries");
    CHECK(parseError("a 1;\nb { $a; }\n") ==
          "constant/rockProperties:2:5: '$a' names a value where an entry was expected; expected a "
          "dictionary to "
          "merge here, or 'keyword $a;' to copy a value");
    CHECK(parseError("a ];") ==
          "constant/rockProperties:1:3: unexpected ']' with no matching '['; expected a dimension set to "
          "look like "
          "[1 -1 -2 0 0 0 0]");
    CHECK(errorOf([] { Dictionary::readFile("/nonexistent/rockfrac/dict"); }) ==
          "/nonexistent/rockfrac/dict: cannot read file '/nonexistent/rockfrac/dict' (no such file); "
          "expected an "
          "existing dictionary file; check the case directory and the file name");
}
