#include "caseCheck.hpp"

#include <algorithm>

#include "calibration/calibrationStudy.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "core/knownEntries.hpp"
#include "core/timeLoop.hpp"
#include "crusher/machineLoading.hpp"
#include "demCase/demCase.hpp"
#include "explain/explainStudy.hpp"
#include "femCase/femCase.hpp"
#include "geometry/crusherGeometry.hpp"
#include "geometry/specimen.hpp"
#include "geometry/tetMesher.hpp"
#include "parallel/decomposition.hpp"
#include "voronoi/seeding.hpp"

namespace rockfrac {

namespace {

// `lists` joined, each keyword once.
std::vector<std::string> unionOf(const std::vector<std::vector<std::string>>& lists)
{
    std::vector<std::string> all;
    for (const auto& list : lists)
        for (const std::string& k : list)
            if (std::find(all.begin(), all.end(), k) == all.end()) all.push_back(k);
    return all;
}

}  // namespace

const std::vector<DeclaredDictionary>& declaredDictionaries()
{
    static const std::vector<DeclaredDictionary> table = {
        {"system/controlDict", unionOf({timeControlEntries(), demControlEntries(), femControlEntries()})},
        {"constant/rockProperties", unionOf({demRockPropertiesEntries(), femRockPropertiesEntries()})},
        {"constant/loading", unionOf({demLoadingEntries(), femLoadingEntries(), machineLoadingEntries()})},
        {"system/meshRockDict", meshRockDictEntries()},
        {"system/feMeshDict", feMeshDictEntries()},
        {"system/voronoiMeshDict", voronoiMeshDictEntries()},
        {"system/meshCrusherDict", meshCrusherDictEntries()},
        {"system/crusherPostDict", crusherPostDictEntries()},
        {"system/decomposeParDict", decomposeParDictEntries()},
        {"system/runCasesDict", calibration::runCasesDictEntries()},
        {"system/calibrationDict", calibration::calibrationDictEntries()},
        {"system/explainGapDict", explain::explainGapDictEntries()},
        {"system/twinDataDict", explain::twinDataDictEntries()},
    };
    return table;
}

std::vector<std::string> checkCaseDictionaries(const std::filesystem::path& caseDir)
{
    std::vector<std::string> found;
    for (const DeclaredDictionary& d : declaredDictionaries()) {
        const std::filesystem::path file = caseDir / d.file;
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec)) continue;
        try {
            const Dictionary dict = Dictionary::readFile(file);
            for (const UnknownEntry& u : unknownEntries(dict, d.entries))
                found.push_back(u.describe(dict.name()));
        } catch (const UserError& e) {
            found.push_back(e.what());
        }
    }
    return found;
}

}  // namespace rockfrac
