// The caseDict utility, run as users run it: print, query, edit, fail cleanly.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>

#include "dictionaryTestSupport.hpp"

using rockfrac::test::readText;
using rockfrac::test::ScratchDir;

namespace {

struct Run {
    int exitCode;
    std::string output;  // stdout and stderr together
};

Run caseDict(const ScratchDir& scratch, const std::string& arguments)
{
    const char* bin = std::getenv("ROCKFRAC_BIN");
    const std::string command = std::string(bin ? bin : ROCKFRAC_BINARY_DIR "/bin") + "/caseDict -case " +
                                scratch.path().string() + " " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::string output;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0;) output.append(buffer, n);
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

const std::string caseDictRockProperties =
    "FoamFile { format ascii; class dictionary; object rockProperties; }\n"
    "// granite\n"
    "E               [Pa] 77e9;\n"
    "r 0.05;\n"
    "bond\n{\n    tensileStrength 20e6;   // Pa\n    area #eval{ pi*$r^2 };\n}\n";

}  // namespace

TEST_CASE("caseDict prints the expanded dictionary, an entry, a value, the keywords",
          "[dictionary][caseDict]")
{
    ScratchDir scratch;
    scratch.write("constant/rockProperties", caseDictRockProperties);
    const Run all = caseDict(scratch, "constant/rockProperties");
    CHECK(all.exitCode == 0);
    CHECK(all.output.find("E               [1 -1 -2 0 0 0 0] 77e9;\n") != std::string::npos);
    CHECK(all.output.find("    area            0.007853981633974483;\n") != std::string::npos);
    CHECK(caseDict(scratch, "constant/rockProperties -entry bond/tensileStrength").output ==
          "tensileStrength 20e6;\n");
    CHECK(caseDict(scratch, "constant/rockProperties -entry bond/tensileStrength -value").output == "20e6\n");
    CHECK(caseDict(scratch, "constant/rockProperties -keywords").output == "E\nr\nbond\n");
    CHECK(caseDict(scratch, "constant/rockProperties -keywords -entry bond").output ==
          "tensileStrength\narea\n");
}

TEST_CASE("caseDict -set, -add, -remove edit in place and keep the rest", "[dictionary][caseDict]")
{
    ScratchDir scratch;
    const auto file = scratch.write("constant/rockProperties", caseDictRockProperties);
    CHECK(caseDict(scratch, "constant/rockProperties -entry bond/tensileStrength -set 28e6").exitCode == 0);
    CHECK(caseDict(scratch, "constant/rockProperties -entry bond/cohesion -add 5e6 -comment 'from BDT 3'")
              .exitCode == 0);
    CHECK(caseDict(scratch, "constant/rockProperties -entry E -remove -dry-run").exitCode == 0);
    // bond/area uses $r: removing r would leave a file the applications cannot read.
    CHECK(caseDict(scratch, "constant/rockProperties -entry r -remove").exitCode == 1);
    std::string expected = caseDictRockProperties;
    expected.replace(expected.find("20e6"), 4, "28e6");
    expected.insert(expected.find("\n}\n"), "\n    cohesion 5e6; // from BDT 3");
    CHECK(readText(file) == expected);
}

TEST_CASE("caseDict fails with exit code 1 and one line", "[dictionary][caseDict]")
{
    ScratchDir scratch;
    const auto file = scratch.write("constant/rockProperties", caseDictRockProperties);
    const std::string path = file.string();
    const Run missing = caseDict(scratch, "constant/rockProperties -entry bond/nothing -set 1");
    CHECK(missing.exitCode == 1);
    CHECK(missing.output ==
          "caseDict: error: " + path +
              ":9:1: no entry 'bond/nothing' in the text of dictionary 'bond'; expected an existing "
              "entry (caseDict -keywords lists them), or add it (caseDict -add)\n");
    const Run broken = caseDict(scratch, "constant/rockProperties -entry r -set '$undefined'");
    CHECK(broken.exitCode == 1);
    CHECK(broken.output.find("undefined variable '$undefined'") != std::string::npos);
    CHECK(readText(file) == caseDictRockProperties);
    CHECK(caseDict(scratch, "constant/rockProperties -set 1").output ==
          "caseDict: error: -set, -add and -remove need -entry <key>: which entry to change\n");
    CHECK(caseDict(scratch, "constant/absent").exitCode == 1);
}
