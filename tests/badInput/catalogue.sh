# The bad-input catalogue, sourced by runCatalogue.sh. One case per badCase:
#   badCase <name> <base> <what the message names> <expected fragment> <command...> <<'SETUP'
#   <bash run inside a copy of the base to break it>
#   SETUP
# Bases (runCatalogue.sh, prepareBases): disc (pristine BDT granite tutorial),
# meshed (after meshRock), dem (after voronoiMesh, 60 cells), demRun (after a
# 20-step bondedDemFoam run), fem (BDT graniteFEM after meshRock), femNoMesh,
# empty, lab (measurements + a plateForce.dat), crusher (CH660 geometry), crusherFeed (CH660
# tiny after meshCrusher, its feedRock meshed and copied to feedRockB).

# A meshRockDict that reads constant/triSurface/rock.stl.
stlDict='mkdir -p constant/triSurface; cat > system/meshRockDict <<D
FoamFile { format ascii; class dictionary; object meshRockDict; }
geometry stl;
stl { file "constant/triSurface/rock.stl"; scale 1e-3; }
D'
# An ASCII STL facet: facet <x y z> <x y z> <x y z>
facetFn='facet() { printf "facet normal 0 0 0\nouter loop\nvertex %s\nvertex %s\nvertex %s\nendloop\nendfacet\n" "$1" "$2" "$3"; }'

# ---- meshRock: dictionaries ---------------------------------------------------------
badCase noCaseDir empty "nowhere" "does not exist" meshRock -case nowhere <<'SETUP'
SETUP
badCase caseIsAFile empty "notADirectory" "is not a directory" meshRock -case notADirectory <<'SETUP'
touch notADirectory
SETUP
badCase unknownOption disc "-frobnicate" "unknown option" meshRock -case . -frobnicate <<'SETUP'
SETUP
badCase noMeshRockDict disc "meshRockDict" "" meshRock -case . <<'SETUP'
rm system/meshRockDict
SETUP
badCase missingSemicolon disc "meshRockDict" "" meshRock -case . <<'SETUP'
sed -i 's/^geometry *disc;/geometry disc/' system/meshRockDict
SETUP
badCase unclosedBrace disc "meshRockDict" "" meshRock -case . <<'SETUP'
sed -i '/nSegments/{n;d}' system/meshRockDict
SETUP
badCase missingInclude disc "noSuchFile" "" meshRock -case . <<'SETUP'
echo '#include "noSuchFile"' >> system/meshRockDict
SETUP
badCase negativeDiameter disc "meshRockDict" "diameter" meshRock -case . <<'SETUP'
caseDict -case . system/meshRockDict -entry disc/diameter -set -44.8e-3
SETUP
badCase diameterWrongUnits disc "meshRockDict" "diameter" meshRock -case . <<'SETUP'
caseDict -case . system/meshRockDict -entry disc/diameter -set "[kg] 44.8e-3"
SETUP
badCase diameterNotANumber disc "meshRockDict" "diameter" meshRock -case . <<'SETUP'
caseDict -case . system/meshRockDict -entry disc/diameter -set big
SETUP
# A misspelt entry: refused with the nearest known one (it was silently ignored).
badCase misspeltDiscEntry disc "meshRockDict" "did you mean 'nSegments'?" meshRock -case . <<'SETUP'
sed -i 's/nSegments/nSegment/' system/meshRockDict
SETUP
badCase misspeltPlaceOnPlate disc "meshRockDict" "did you mean 'placeOnPlate'?" meshRock -case . <<SETUP
cat > system/meshRockDict <<D
FoamFile { format ascii; class dictionary; object meshRockDict; }
geometry generated;
generated { volume 43.6e-6; seed 107; placeOnPlat yes; }
D
SETUP
badCase nSegmentsHuge disc "meshRockDict" "nSegments" meshRock -case . <<'SETUP'
caseDict -case . system/meshRockDict -entry disc/nSegments -set 1000000000
SETUP
badCase elementSizeTiny femNoMesh "elementSize" "needs an estimated" meshRock -case . <<'SETUP'
caseDict -case . system/feMeshDict -entry elementSize -set 1e-5
SETUP
badCase elementCountHuge femNoMesh "elementCount" "needs an estimated" meshRock -case . <<'SETUP'
caseDict -case . system/feMeshDict -entry elementSize -remove
caseDict -case . system/feMeshDict -entry elementCount -add 2e9
SETUP
badCase mesoConstantTiny meshed "voronoiMeshDict" "mesoConstant" voronoiMesh -case . <<'SETUP'
caseDict -case . system/voronoiMeshDict -entry nCells -remove
caseDict -case . system/voronoiMeshDict -entry mesoConstant -add 1e-30
SETUP
badCase nCellsHuge meshed "nCells" "needs an estimated" voronoiMesh -case . <<'SETUP'
caseDict -case . system/voronoiMeshDict -entry nCells -set 1000000000
caseDict -case . system/voronoiMeshDict -entry pruningDistance -set 0
SETUP
badCase unknownGeometry disc "meshRockDict" "sphere" meshRock -case . <<'SETUP'
caseDict -case . system/meshRockDict -entry geometry -set sphere
SETUP

# ---- meshRock: STL scans --------------------------------------------------------------
badCase stlMissing disc "rock.stl" "" meshRock -case . <<SETUP
$stlDict
SETUP
badCase stlEmpty disc "rock.stl" "empty" meshRock -case . <<SETUP
$stlDict
: > constant/triSurface/rock.stl
SETUP
badCase stlIsDirectory disc "rock.stl" "it is a directory" meshRock -case . <<SETUP
$stlDict
mkdir constant/triSurface/rock.stl
SETUP
badCase stlIsADevice disc "rock.stl" "not a regular file" meshRock -case . <<SETUP
$stlDict
ln -s /dev/urandom constant/triSurface/rock.stl
SETUP
badCase stlGarbage disc "rock.stl" "" meshRock -case . <<SETUP
$stlDict
echo "this is not an stl" > constant/triSurface/rock.stl
SETUP
badCase stlHole disc "rock.stl" "not a closed surface" meshRock -case . <<SETUP
$stlDict
$facetFn
{ echo "solid hole"; facet "0 0 0" "0 1 0" "1 0 0"; facet "0 0 0" "1 0 0" "0 0 1"; facet "1 0 0" "0 1 0" "0 0 1"; echo "endsolid hole"; } > constant/triSurface/rock.stl
SETUP
badCase stlNaN disc "rock.stl" "non-finite" meshRock -case . <<SETUP
$stlDict
$facetFn
{ echo "solid nan"; facet "0 0 0" "0 1 0" "1 0 0"; facet "0 0 0" "1 0 0" "0 0 nan"; facet "1 0 0" "0 1 0" "0 0 1"; facet "0 0 0" "0 0 1" "0 1 0"; echo "endsolid nan"; } > constant/triSurface/rock.stl
SETUP
badCase stlTruncatedBinary disc "rock.stl" "truncated" meshRock -case . <<SETUP
$stlDict
{ head -c 80 /dev/zero; printf '\x0c\x00\x00\x00'; head -c 100 /dev/zero; } > constant/triSurface/rock.stl
SETUP
# An octahedron of half-diagonal 10 at (dx 0 0): octahedron <dx> [its top vertex "x y z"]
octahedronFn='octahedron() { local d="$1"; local px="$((d + 10)) 0 0" mx="$((d - 10)) 0 0" py="$d 10 0" my="$d -10 0" pz="${2:-$d 0 10}" mz="$d 0 -10"
  facet "$px" "$py" "$pz"; facet "$py" "$mx" "$pz"; facet "$mx" "$my" "$pz"; facet "$my" "$px" "$pz"
  facet "$py" "$px" "$mz"; facet "$mx" "$py" "$mz"; facet "$my" "$mx" "$mz"; facet "$px" "$my" "$mz"; }'
badCase stlTwoShells disc "rock.stl" "2 separate closed surfaces" meshRock -case . <<SETUP
$stlDict
$facetFn
$octahedronFn
{ echo "solid two"; octahedron 0; octahedron 40; echo "endsolid two"; } > constant/triSurface/rock.stl
SETUP
badCase stlCrossesItself disc "rock.stl" "crosses itself" meshRock -case . <<SETUP
$stlDict
$facetFn
$octahedronFn
{ echo "solid crossing"; octahedron 0 "20 0 -2"; echo "endsolid crossing"; } > constant/triSurface/rock.stl
SETUP
# A zero-area needle (three vertices on a line: (5 5 0) on the edge it closes) keeps the
# surface closed but cannot be dropped; a vertex exported twice 1e-9 apart opens it.
badCase stlZeroAreaNeedle disc "rock.stl" "degenerate triangles" meshRock -case . <<SETUP
$stlDict
$facetFn
{ echo "solid needle"; facet "10 0 0" "5 5 0" "0 0 10"; facet "5 5 0" "0 10 0" "0 0 10"; facet "10 0 0" "0 10 0" "5 5 0"
  facet "0 10 0" "-10 0 0" "0 0 10"; facet "-10 0 0" "0 -10 0" "0 0 10"; facet "0 -10 0" "10 0 0" "0 0 10"
  facet "0 10 0" "10 0 0" "0 0 -10"; facet "-10 0 0" "0 10 0" "0 0 -10"; facet "0 -10 0" "-10 0 0" "0 0 -10"
  facet "10 0 0" "0 -10 0" "0 0 -10"; echo "endsolid needle"; } > constant/triSurface/rock.stl
SETUP
badCase stlNearDuplicateVertices disc "rock.stl" "Merge Close Vertices" meshRock -case . <<SETUP
$stlDict
$facetFn
{ echo "solid unwelded"; facet "10 0 0" "0 10 0" "0 0 10.000000001"; facet "0 10 0" "-10 0 0" "0 0 10"
  facet "-10 0 0" "0 -10 0" "0 0 10"; facet "0 -10 0" "10 0 0" "0 0 10"; facet "0 10 0" "10 0 0" "0 0 -10"
  facet "-10 0 0" "0 10 0" "0 0 -10"; facet "0 -10 0" "-10 0 0" "0 0 -10"; facet "10 0 0" "0 -10 0" "0 0 -10"
  echo "endsolid unwelded"; } > constant/triSurface/rock.stl
SETUP
badCase stlFourVertices disc "rock.stl" "" meshRock -case . <<SETUP
$stlDict
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\nendloop\nendfacet\nendsolid x\n' > constant/triSurface/rock.stl
SETUP

# ---- voronoiMesh ----------------------------------------------------------------------
badCase elementCountNegative femNoMesh "feMeshDict" "elementCount" meshRock -case . <<'SETUP'
caseDict -case . system/feMeshDict -entry elementSize -remove
caseDict -case . system/feMeshDict -entry elementCount -add -5
SETUP
badCase elementCountFraction femNoMesh "feMeshDict" "whole number" meshRock -case . <<'SETUP'
caseDict -case . system/feMeshDict -entry elementSize -remove
caseDict -case . system/feMeshDict -entry elementCount -add 1000.5
SETUP
badCase contactRefinementNotFiner femNoMesh "feMeshDict" "below elementSize" meshRock -case . <<'SETUP'
printf 'contactRefinement { elementSize [m] 10e-3; distance [m] 5e-3; }\n' >> system/feMeshDict
SETUP
badCase contactRefinementNoDistance femNoMesh "feMeshDict" "distance" meshRock -case . <<'SETUP'
printf 'contactRefinement { elementSize [m] 1e-3; }\n' >> system/feMeshDict
SETUP
badCase voronoiBeforeMeshRock disc "geometryProperties" "run meshRock first" voronoiMesh -case . <<'SETUP'
SETUP
badCase oneCell meshed "voronoiMeshDict" "at least 2 cells" voronoiMesh -case . <<'SETUP'
caseDict -case . system/voronoiMeshDict -entry nCells -set 1
SETUP
badCase fractionalCells meshed "voronoiMeshDict" "nCells" voronoiMesh -case . <<'SETUP'
caseDict -case . system/voronoiMeshDict -entry nCells -set 300.5
SETUP
badCase pruningTooLarge meshed "voronoiMeshDict" "pruning distance" voronoiMesh -case . <<'SETUP'
caseDict -case . system/voronoiMeshDict -entry nCells -set 5000
caseDict -case . system/voronoiMeshDict -entry pruningDistance -set 3.5e-3
SETUP
badCase unknownCellOrder meshed "voronoiMeshDict" "cellOrder" voronoiMesh -case . <<'SETUP'
caseDict -case . system/voronoiMeshDict -entry cellOrder -add hilbert
SETUP
# Graded meshes (sizeField): a cell finer than its contact shell, a region off the specimen,
# a grading that never returns to the base size. sizeField <grading> <point> <size>: one region.
sizeFieldFn='sizeField() { printf "sizeField { grading %s; regions { r { type point; point (%s); size %s; } } }\n" \
    "$1" "$2" "$3" >> system/voronoiMeshDict; }'
badCase sizeFieldTooFine meshed "voronoiMeshDict" "below the smallest allowed cell" voronoiMesh -case . <<SETUP
$sizeFieldFn; sizeField 1.3 "0 0 0" 0.2e-3
SETUP
badCase sizeFieldOutside meshed "voronoiMeshDict" "outside the specimen's bounding box" voronoiMesh -case . <<SETUP
$sizeFieldFn; sizeField 1.3 "0 0 1" 3e-3
SETUP
badCase sizeFieldGradingOne meshed "voronoiMeshDict" "not in (1, 2]" voronoiMesh -case . <<SETUP
$sizeFieldFn; sizeField 1 "0 0 0" 3e-3
SETUP
badCase hullZeroNormal meshed "geometryProperties" "zero or non-finite normal" voronoiMesh -case . <<'SETUP'
cat > constant/geometryProperties <<D
FoamFile { format ascii; class dictionary; object geometryProperties; }
type convexHull; source generated; volume 1e-6; centroid (0 0 0);
inertia (1e-12 0 0 0 1e-12 0 0 0 1e-12); principalExtents (0.01 0.01 0.01);
boundsMin (-0.005 -0.005 -0.005); boundsMax (0.005 0.005 0.005);
convexHull { planes ( (0 0 0 1) (1 0 0 0.005) (0 1 0 0.005) (0 0 1 0.005) ); }
D
SETUP
badCase geometryPropertiesTruncated meshed "geometryProperties" "" voronoiMesh -case . <<'SETUP'
head -c 300 constant/geometryProperties > g && mv g constant/geometryProperties
SETUP

# ---- bondedDemFoam: dictionaries ----------------------------------------------------------
badCase demBeforeVoronoi meshed "voronoiMesh" "run voronoiMesh first" bondedDemFoam -case . <<'SETUP'
SETUP
badCase contactModelTypo dem "rockProperties" "hertzMindlin" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry contact/model -set hertzMindlinn
SETUP
badCase negativeStrength dem "rockProperties" "tensileStrength" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry bond/voronoiQNSC/tensileStrength -set -28e6
SETUP
badCase poissonHalf dem "rockProperties" "poissonRatio" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry rock/poissonRatio -set 0.5
SETUP
badCase modulusInMetres dem "rockProperties" "E" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry bond/voronoiQNSC/E -set "[0 1 0 0 0 0 0] 46e9"
SETUP
badCase emptyRockProperties dem "rockProperties" "" bondedDemFoam -case . <<'SETUP'
: > constant/rockProperties
SETUP
badCase bondLawEntryTypo dem "rockProperties" "unknown entry 'tensileStrenght'" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry bond/voronoiQNSC/tensileStrenght -add 28e6
SETUP
badCase bondLawOldLayout dem "rockProperties" "its own sub-dictionary" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry bond/tensileStrength -add 28e6
SETUP
badCase bondLawNoCoefficients dem "rockProperties" "brittleBPM" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry bond/model -set brittleBPM
caseDict -case . constant/rockProperties -entry bond/brittleBPM -remove
SETUP
badCase brittleWithFractureEnergy dem "rockProperties" "unknown entry 'GI'" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry bond/model -set brittleBPM
caseDict -case . constant/rockProperties -entry bond/brittleBPM/GI -add 10
SETUP
badCase contactLawCoefficients dem "rockProperties" "no coefficients of its own" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry contact/hertzMindlin/stiffness -add 1
SETUP
badCase platesAtRest dem "loading" "stop criterion can never be met" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/loading -entry plates/upper/velocity -set "(0 0 0)"
SETUP
badCase velocityScalar dem "loading" "velocity" bondedDemFoam -case . <<'SETUP'
caseDict -case . constant/loading -entry plates/upper/velocity -set -0.25
SETUP
badCase twoTimeSteps dem "controlDict" "exactly one" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry rayleighFraction -add 0.02
SETUP
badCase unstableStep dem "controlDict" "largest stable step" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry deltaT -set 1e-4
SETUP
badCase unknownWriteControl dem "controlDict" "writeControl" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry writeControl -set everyNowAndThen
SETUP
badCase startTimeWithoutDir dem "controlDict" "has no time directory" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry startFrom -set startTime
caseDict -case . system/controlDict -entry startTime -set 1e-3
SETUP
badCase endBeforeStart demRun "controlDict" "raise endTime" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry endTime -set 1e-6
SETUP
# Symbolic link loops where the case's directories are: exit 1 naming the path, not exit 2.
badCase timeDirLinkLoop demRun "0.5" "check that path" bondedDemFoam -case . <<'SETUP'
ln -s 0.5 0.5
SETUP
badCase voronoiMeshLinkLoop dem "voronoiMesh" "" bondedDemFoam -case . <<'SETUP'
rm -rf constant/voronoiMesh && ln -s voronoiMesh constant/voronoiMesh
SETUP
badCase postProcessingLinkLoop dem "postProcessing" "" bondedDemFoam -case . <<'SETUP'
rm -rf postProcessing && ln -s postProcessing postProcessing
SETUP
# More steps than a run can count: was "(-9223372036854775808 steps)" and exit 0.
badCase endTimeTooManySteps dem "controlDict" "lower endTime or raise deltaT" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry endTime -set 1e300
SETUP
badCase femEndTimeTooManySteps fem "controlDict" "lower endTime or raise deltaT" feFractureSolver -case . <<'SETUP'
caseDict -case . system/controlDict -entry endTime -set 1e300
SETUP
# Time directory names cut at 63 characters: was a misleading restart failure.
badCase writePrecisionTooHigh dem "controlDict" "writePrecision 60 is outside [1, 17]" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry writePrecision -set 60
SETUP
# backend cuda where there is none: a build without CUDA, or no visible device
# (CUDA_VISIBLE_DEVICES=-1 hides any GPU, so the case fails the same way everywhere).
badCase cudaBackendUnavailable dem "controlDict" "backend cuda is not available" env CUDA_VISIBLE_DEVICES=-1 bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry backend -add cuda
SETUP
badCase unknownBackend dem "controlDict" "cpu, cuda" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry backend -add opencl
SETUP
badCase demMemoryLimit dem "meshInfo" "estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 bondedDemFoam -case . <<'SETUP'
SETUP
badCase memoryLimitNotANumber dem "ROCKFRAC_MEMORY_LIMIT_BYTES" "not a number" env ROCKFRAC_MEMORY_LIMIT_BYTES=8GB bondedDemFoam -case . <<'SETUP'
SETUP

# ---- bondedDemFoam: corrupt mesh and state files ---------------------------------------------
badCase meshInfoTruncated dem "meshInfo" "voronoiMesh" bondedDemFoam -case . <<'SETUP'
head -c 400 constant/voronoiMesh/meshInfo > m && mv m constant/voronoiMesh/meshInfo
SETUP
badCase meshInfoHugeCount dem "meshInfo" "" bondedDemFoam -case . <<'SETUP'
sed -i 's/^nCells .*/nCells          2000000000;/' constant/voronoiMesh/meshInfo
SETUP
badCase cellsTruncated dem "cells" "truncated" bondedDemFoam -case . <<'SETUP'
head -c 1000 constant/voronoiMesh/cells > c && mv c constant/voronoiMesh/cells
SETUP
badCase facesMissing dem "faces" "run voronoiMesh first" bondedDemFoam -case . <<'SETUP'
rm constant/voronoiMesh/faces
SETUP
badCase bondsBitFlip dem "bonds" "checksum" bondedDemFoam -case . <<'SETUP'
printf '\x7f' | dd of=constant/voronoiMesh/bonds bs=1 seek=70 conv=notrunc status=none
SETUP
badCase verticesFromOtherMesh dem "vertices" "" bondedDemFoam -case . <<'SETUP'
cp ../../bases/meshed/constant/geometryProperties constant/voronoiMesh/vertices
SETUP
badCase stateTruncated demRun "demState" "restart from an earlier time directory" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry endTime -set 4e-6
latest=$(ls -d [0-9]* | sort -g | tail -1)
head -c 2000 "$latest/demState" > s && mv s "$latest/demState"
SETUP
badCase stateGarbage demRun "demState" "not a rockfrac state file" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry endTime -set 4e-6
latest=$(ls -d [0-9]* | sort -g | tail -1)
echo "garbage" > "$latest/demState"
SETUP
badCase stateOfFemSolver demRun "demState" "" bondedDemFoam -case . <<'SETUP'
caseDict -case . system/controlDict -entry endTime -set 4e-6
latest=$(ls -d [0-9]* | sort -g | tail -1)
python3 -c "
import struct
b = b'RFSTATE\0' + struct.pack('<II', 1, 0)
h = 0xcbf29ce484222325
for x in b: h = ((h ^ x) * 0x100000001b3) & 0xffffffffffffffff
open('$latest/demState', 'wb').write(b + struct.pack('<Q', h))"
SETUP

# ---- feFractureSolver ----------------------------------------------------------------
badCase femBeforeMeshRock femNoMesh "specimen.msh" "run meshRock" feFractureSolver -case . <<'SETUP'
SETUP
badCase femMaterialTypo fem "rockProperties" "kstDfh" feFractureSolver -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry material -set kstDFH
SETUP
badCase weibullModulusZero fem "rockProperties" "weibullModulus" feFractureSolver -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry kstDfh/dfh/weibullModulus -set 0
SETUP
badCase femOldLayout fem "rockProperties" "kstDfh { kst { ... } dfh { ... } }" feFractureSolver -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry dfh/seed -add 1
SETUP
badCase femCoefficientTypo fem "rockProperties" "unknown entry 'weibulModulus'" feFractureSolver -case . <<'SETUP'
caseDict -case . constant/rockProperties -entry kstDfh/dfh/weibulModulus -add 7
SETUP
badCase plateNeverTouches fem "loading" "never touches the specimen" feFractureSolver -case . <<'SETUP'
caseDict -case . constant/loading -entry plates/startGap -set 1
SETUP
badCase mshTruncated fem "specimen.msh" "" feFractureSolver -case . <<'SETUP'
head -c 2000 constant/feMesh/specimen.msh > m && mv m constant/feMesh/specimen.msh
SETUP
badCase mshEmpty fem "specimen.msh" "" feFractureSolver -case . <<'SETUP'
: > constant/feMesh/specimen.msh
SETUP
badCase femMemoryLimit fem "specimen.msh" "estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 feFractureSolver -case . <<'SETUP'
SETUP

# ---- caseDict ---------------------------------------------------------------------------
badCase caseDictNoFile disc "constant/nothing" "" caseDict -case . constant/nothing <<'SETUP'
SETUP
badCase caseDictNoEntry disc "rockProperties" "tensileStrenght" caseDict -case . constant/rockProperties -entry bond/tensileStrenght -value <<'SETUP'
SETUP
badCase caseDictSetInBroken disc "rockProperties" "" caseDict -case . constant/rockProperties -entry bond/voronoiQNSC/E -set 1 <<'SETUP'
echo "bond { E 46e9" >> constant/rockProperties
SETUP

# ---- measured data and plots -------------------------------------------------------------
badCase plotCdfNoMeasurements lab "nothing" "" plotCdf -case . -measured nothing <<'SETUP'
SETUP
badCase measurementsEmpty lab "measurements" "" plotCdf -case . -measured measurements <<'SETUP'
: > measurements
SETUP
badCase measurementsNoSpecimens lab "measurements" "no specimens" plotCdf -case . -measured measurements <<'SETUP'
printf 'FoamFile { format ascii; class dictionary; object measurements; }\nspecimens { }\n' > measurements
SETUP
badCase measurementsNoUnit lab "measurements" "dimension set" plotCdf -case . -measured measurements <<'SETUP'
sed -i 's/failureLoad \[N\] 10.9e3/failureLoad 10.9e3/' measurements
SETUP
badCase measurementsKiloNewton lab "measurements" "failureLoad" plotCdf -case . -measured measurements <<'SETUP'
sed -i 's/failureLoad \[N\] 10.9e3/failureLoad [kg m^2 s^-2] 10.9/' measurements
SETUP
badCase curveEmpty lab "empty.dat" "" plotCdf -case . -measured measurements <<'SETUP'
: > empty.dat
sed -i 's/failureLoad \[N\] 10.9e3;/curve "empty.dat";/' measurements
SETUP
badCase plotEmptyDat lab "plateForce.dat" "" plotTimeSeries -case . -y force plateForce.dat <<'SETUP'
: > plateForce.dat
SETUP
badCase plotNoColumn lab "plateForce.dat" "stress" plotTimeSeries -case . -y stress plateForce.dat <<'SETUP'
SETUP
badCase plotBadRow lab "plateForce.dat" "" plotTimeSeries -case . -y force plateForce.dat <<'SETUP'
printf '1e-5\tforty-two\n' >> plateForce.dat
SETUP

# ---- fragments, crusher, rendering, studies ----------------------------------------------------
badCase psdNoState dem "" "demState" fragmentPSD -case . <<'SETUP'
SETUP
badCase psdNoSuchTime demRun "7" "" fragmentPSD -case . -time 7 <<'SETUP'
SETUP
badCase crusherNoDict crusher "meshCrusherDict" "" meshCrusher -case . <<'SETUP'
rm system/meshCrusherDict
SETUP
# The crusher's feed: one template (rock) or one per size class (classes), never both nor neither;
# classes by increasing upTo, each taking some sizes, the last reaching sizeRange max, all meshed.
# feedClasses '<classes>': CH660 tiny's `rock "feedRock";` replaced by `classes { <classes> }`.
feedClasses() { sed -i "s|^ *rock  *\"feedRock\";.*|    classes { $1 }|" constant/loading; }
badCase feedRockAndClasses crusherFeed "loading" "feed has both rock and classes" bondedDemFoam -case . -dry-run <<'SETUP'
sed -i 's|^ *rock  *"feedRock";.*|&\n    classes { small { rock "feedRock"; upTo 0.018; } }|' constant/loading
SETUP
badCase feedNoRock crusherFeed "loading" "feed has neither rock nor classes" bondedDemFoam -case . -dry-run <<'SETUP'
sed -i '/^ *rock  *"feedRock";/d' constant/loading
SETUP
badCase feedClassesEmpty crusherFeed "loading" "feed/classes has no class" bondedDemFoam -case . -dry-run <<'SETUP'
feedClasses ''
SETUP
badCase feedClassesNotDict crusherFeed "loading" "feed/classes must be a sub-dictionary" bondedDemFoam -case . -dry-run <<'SETUP'
sed -i 's|^ *rock  *"feedRock";.*|    classes 0.018;|' constant/loading
SETUP
badCase feedClassNotDict crusherFeed "loading" "feed/classes/small must be a sub-dictionary" bondedDemFoam -case . -dry-run <<'SETUP'
feedClasses 'small "feedRock";'
SETUP
badCase feedClassesUnsorted crusherFeed "loading" "feed/classes/large/upTo 0.015 is not above" bondedDemFoam -case . -dry-run <<'SETUP'
feedClasses 'small { rock "feedRock"; upTo 0.016; } large { rock "feedRockB"; upTo 0.015; }'
SETUP
badCase feedClassesShort crusherFeed "loading" "feed/classes/large/upTo 0.017 is below sizeRange max" bondedDemFoam -case . -dry-run <<'SETUP'
feedClasses 'small { rock "feedRock"; upTo 0.016; } large { rock "feedRockB"; upTo 0.017; }'
SETUP
badCase feedClassBelowMin crusherFeed "loading" "feed/classes/small/upTo 0.012 is below sizeRange min" bondedDemFoam -case . -dry-run <<'SETUP'
feedClasses 'small { rock "feedRock"; upTo 0.012; } large { rock "feedRockB"; upTo 0.018; }'
SETUP
badCase feedClassNeverUsed crusherFeed "loading" "feed/classes/large/upTo 0.02: no rock would be" bondedDemFoam -case . -dry-run <<'SETUP'
feedClasses 'small { rock "feedRock"; upTo 0.018; } large { rock "feedRockB"; upTo 0.02; }'
SETUP
badCase feedClassNotMeshed crusherFeed "loading" "feed/classes/large/rock" bondedDemFoam -case . -dry-run <<'SETUP'
feedClasses 'small { rock "feedRock"; upTo 0.016; } large { rock "feedRockC"; upTo 0.018; }'
SETUP
badCase renderNoFile dem "VTK/none.vtu" "" renderVtk -case . VTK/none.vtu <<'SETUP'
SETUP
badCase renderNotVtk dem "VTK/broken.vtu" "" renderVtk -case . VTK/broken.vtu <<'SETUP'
echo "<VTKFile" > VTK/broken.vtu
SETUP
badCase runCasesNoDict empty "runCasesDict" "" runCases -case . <<'SETUP'
SETUP
badCase calibrateNoDict empty "calibrationDict" "" calibrateModel -case . <<'SETUP'
SETUP

# ---- unknown entries (issue 41 item 8) ---------------------------------------------------------
# A misspelt entry is a warning by default (it is ignored); -strict makes it this one-line error,
# with the nearest known entry. caseDict -check lists them and exits 1.
badCase strictControlDictTypo dem "controlDict" "did you mean 'writeInterval'?" bondedDemFoam -case . -dry-run -strict <<'SETUP'
sed -i 's/^writeInterval /writeIntervall /' system/controlDict
SETUP
badCase strictControlDictExtra dem "controlDict" "did you mean 'purgeWrite'?" bondedDemFoam -case . -dry-run -strict <<'SETUP'
echo 'purgWrite 2;' >> system/controlDict
SETUP
badCase strictFunctionName dem "controlDict" "did you mean 'plateForce'?" bondedDemFoam -case . -dry-run -strict <<'SETUP'
echo 'functions { plateForc { writeInterval 5; } }' >> system/controlDict
SETUP
badCase strictFunctionEntry dem "controlDict" "did you mean 'writeInterval'?" bondedDemFoam -case . -dry-run -strict <<'SETUP'
echo 'functions { plateForce { writeIntervall 5; } }' >> system/controlDict
SETUP
badCase strictLoadingTop dem "loading" "did you mean 'gravity'?" bondedDemFoam -case . -dry-run -strict <<'SETUP'
sed -i 's/^gravity /gravty /' constant/loading
SETUP
badCase strictLoadingStop dem "loading" "did you mean 'maxDisplacement'?" bondedDemFoam -case . -dry-run -strict <<'SETUP'
sed -i 's/forceDropFraction *0.3;/forceDropFraction 0.3; maxDisplacment 1e-3;/' constant/loading
SETUP
badCase strictLoadingPlate dem "loading" "did you mean 'velocity'?" bondedDemFoam -case . -dry-run -strict <<'SETUP'
sed -i '0,/normal      (0 0 1);/s//normal (0 0 1); velocty (0 0 0);/' constant/loading
SETUP
badCase strictRockPropertiesTop dem "rockProperties" "did you mean 'steel'?" bondedDemFoam -case . -dry-run -strict <<'SETUP'
echo 'steal { E 1; }' >> constant/rockProperties
SETUP
badCase strictFemControlDict fem "controlDict" "did you mean 'massDamping'?" feFractureSolver -case . -dry-run -strict <<'SETUP'
sed -i 's/^massDamping /massDampng /' system/controlDict
SETUP
badCase strictFemLoading fem "loading" "did you mean 'length'?" feFractureSolver -case . -dry-run -strict <<'SETUP'
sed -i 's/^\( *\)length \( *\)20e-3;/\1lenght\2 20e-3;/' constant/loading
SETUP
badCase strictFemCentreStress fem "controlDict" "did you mean 'radius'?" feFractureSolver -case . -dry-run -strict <<'SETUP'
sed -i 's/^\( *\)plateForce  { writeInterval 20; }/&\n    centreStress { radus 5e-3; }/' system/controlDict
SETUP
badCase strictMeshRockDictTop disc "meshRockDict" "did you mean 'disc'?" meshRock -case . -dry-run -strict <<'SETUP'
echo 'discs { }' >> system/meshRockDict
SETUP
badCase strictFeMeshDict femNoMesh "feMeshDict" "did you mean 'optimise'?" meshRock -case . -dry-run -strict <<'SETUP'
sed -i 's/^optimise /optimize /' system/feMeshDict
SETUP
badCase strictVoronoiMeshDict meshed "voronoiMeshDict" "did you mean 'dilationFraction'?" voronoiMesh -case . -dry-run -strict <<'SETUP'
sed -i 's/^dilationFraction /dilationFration /' system/voronoiMeshDict
SETUP
badCase strictMeshCrusherDict crusher "meshCrusherDict" "did you mean 'nSegments'?" meshCrusher -case . -dry-run -strict <<'SETUP'
sed -i 's/^nSegments /nSegment /' system/meshCrusherDict
SETUP
badCase strictCalibrationDict empty "calibrationDict" "did you mean 'model'?" calibrateModel -case . -strict <<'SETUP'
mkdir -p system; echo 'modle dem;' > system/calibrationDict
SETUP
badCase strictRunCasesDict empty "runCasesDict" "did you mean 'template'?" runCases -case . -strict <<'SETUP'
mkdir -p system; echo 'templte "../case";' > system/runCasesDict
SETUP
badCase strictExplainGapDict empty "explainGapDict" "did you mean 'command'?" explainGap -case . -strict <<'SETUP'
mkdir -p system; echo 'comand "bondedDemFoam";' > system/explainGapDict
SETUP
badCase caseDictCheckTypo disc "controlDict" "did you mean 'writeInterval'?" caseDict -case . -check <<'SETUP'
sed -i 's/^writeInterval /writeIntervall /' system/controlDict
SETUP
badCase caseDictCheckLoading dem "loading" "did you mean 'settling'?" caseDict -case . -check <<'SETUP'
echo 'setling { duration 1e-4; }' >> constant/loading
SETUP
# ---- estimates and messages (issue 41 items 3 and 7) ----------------------------------------
# A generated rock (a convex hull) after meshRock, and awk editing plane 0 of its
# geometryProperties: $1 the awk expression printing the new plane from $1..$4.
hullRock='cat > system/meshRockDict <<D
FoamFile { format ascii; class dictionary; object meshRockDict; }
geometry generated;
generated { volume 43.6e-6; seed 107; placeOnPlate yes; }
D
meshRock -case .'
editPlane0='editPlane0() { awk -v OFS=" " "f==2 { gsub(/[()]/, \"\"); printf \"        (\"; printf $1; print \")\"; f=3; next } /^ *planes/ { f=1 } f==1 && /^ *\\(\$/ { f=2 } { print }" constant/geometryProperties > g && mv g constant/geometryProperties; }'
# Every application refuses a machine too small for its estimate, with -dry-run too.
badCase surfaceMemoryLimit disc "meshRockDict" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 meshRock -case . <<'SETUP'
SETUP
badCase dryRunSurfaceLimit disc "meshRockDict" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 meshRock -case . -dry-run <<'SETUP'
SETUP
badCase dryRunTetsLimit femNoMesh "feMeshDict" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 meshRock -case . -dry-run <<'SETUP'
SETUP
badCase dryRunVoronoiLimit meshed "voronoiMeshDict" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 voronoiMesh -case . -dry-run <<'SETUP'
SETUP
badCase dryRunDemLimit dem "meshInfo" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 bondedDemFoam -case . -dry-run <<'SETUP'
SETUP
badCase dryRunFemLimit fem "specimen.msh" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 feFractureSolver -case . -dry-run <<'SETUP'
SETUP
badCase psdMemoryLimit demRun "meshInfo" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 fragmentPSD -case . <<'SETUP'
SETUP
badCase dryRunPsdLimit demRun "meshInfo" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 fragmentPSD -case . -dry-run <<'SETUP'
SETUP
badCase crusherMemoryLimit crusher "meshCrusherDict" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 meshCrusher -case . <<'SETUP'
SETUP
badCase dryRunCrusherLimit crusher "meshCrusherDict" "needs an estimated" env ROCKFRAC_MEMORY_LIMIT_BYTES=1000000 meshCrusher -case . -dry-run <<'SETUP'
SETUP
badCase crusherSegmentsHuge crusher "meshCrusherDict" "use fewer nSegments" meshCrusher -case . <<'SETUP'
caseDict -case . system/meshCrusherDict -entry nSegments -set 1000000
SETUP
badCase crusherSegmentsIntMax crusher "meshCrusherDict" "use fewer nSegments" meshCrusher -case . -dry-run <<'SETUP'
caseDict -case . system/meshCrusherDict -entry nSegments -set 2147483647
SETUP
badCase memoryLimitZero meshed "voronoiMeshDict" "only 0 bytes are available (ROCKFRAC_MEMORY_LIMIT_BYTES)" env ROCKFRAC_MEMORY_LIMIT_BYTES=0 voronoiMesh -case . <<'SETUP'
SETUP
badCase memoryLimitNegative meshed "ROCKFRAC_MEMORY_LIMIT_BYTES" "not a number" env ROCKFRAC_MEMORY_LIMIT_BYTES=-5 voronoiMesh -case . -dry-run <<'SETUP'
SETUP
badCase memoryLimitOverflow meshed "ROCKFRAC_MEMORY_LIMIT_BYTES" "not a number" env ROCKFRAC_MEMORY_LIMIT_BYTES=99999999999999999999999 voronoiMesh -case . -dry-run <<'SETUP'
SETUP
# A hull plane turned inside out names its line and says to flip it (it blamed
# voronoiMeshDict: "0 cell(s) requested").
badCase hullPlaneFlipped meshed "geometryProperties:30:" "flip its normal" voronoiMesh -case . <<SETUP
$hullRock
$editPlane0
editPlane0 '"%.17g %.17g %.17g %.17g", -\$1, -\$2, -\$3, -\$4'
SETUP
badCase hullPlaneFlippedDryRun meshed "geometryProperties:30:" "flip its normal" voronoiMesh -case . -dry-run <<SETUP
$hullRock
$editPlane0
editPlane0 '"%.17g %.17g %.17g %.17g", -\$1, -\$2, -\$3, -\$4'
SETUP
# Its normal negated but not its offset: another (smaller) rock was meshed without a word.
badCase hullPlaneNormalNegated meshed "geometryProperties" "were changed after meshRock" voronoiMesh -case . <<SETUP
$hullRock
$editPlane0
editPlane0 '"%.17g %.17g %.17g %.17g", -\$1, -\$2, -\$3, \$4'
SETUP
badCase hullPlaneMoved meshed "geometryProperties" "were changed after meshRock" voronoiMesh -case . <<SETUP
$hullRock
$editPlane0
editPlane0 '"%.17g %.17g %.17g %.17g", \$1, \$2, \$3, 0.8 * \$4'
SETUP
badCase hullVolumeEdited meshed "geometryProperties" "were changed after meshRock" voronoiMesh -case . <<SETUP
$hullRock
caseDict -case . constant/geometryProperties -entry volume -set 5e-5
SETUP
badCase hullPlaneThreeValues meshed "geometryProperties" "4 values" voronoiMesh -case . <<SETUP
$hullRock
$editPlane0
editPlane0 '"%.17g %.17g %.17g", \$1, \$2, \$3'
SETUP
badCase hullThreePlanes meshed "geometryProperties" "at least 4 planes" voronoiMesh -case . <<'SETUP'
cat > constant/geometryProperties <<D
FoamFile { format ascii; class dictionary; object geometryProperties; }
type convexHull; source generated; volume 1e-6; centroid (0 0 0);
inertia (1e-12 0 0 0 1e-12 0 0 0 1e-12); principalExtents (0.01 0.01 0.01);
boundsMin (-0.005 -0.005 -0.005); boundsMax (0.005 0.005 0.005);
convexHull { planes ( (1 0 0 0.005) (0 1 0 0.005) (0 0 1 0.005) ); }
D
SETUP
badCase hullUnbounded meshed "geometryProperties" "bounded" voronoiMesh -case . <<'SETUP'
cat > constant/geometryProperties <<D
FoamFile { format ascii; class dictionary; object geometryProperties; }
type convexHull; source generated; volume 1e-6; centroid (0 0 0);
inertia (1e-12 0 0 0 1e-12 0 0 0 1e-12); principalExtents (0.01 0.01 0.01);
boundsMin (-0.005 -0.005 -0.005); boundsMax (0.005 0.005 0.005);
convexHull { planes ( (1 0 0 0.005) (-1 0 0 0.005) (0 1 0 0.005) (0 -1 0 0.005) (0 0 1 0.005) ); }
D
SETUP
# A flat STL is told it is flat (it was told to flip its normals); an inside-out one to flip them.
badCase stlFlatSheet disc "rock.stl" "the scan is flat" meshRock -case . <<SETUP
$stlDict
$facetFn
{ echo "solid sheet"; facet "0 0 0" "10 0 0" "0 10 0"; facet "0 0 0" "0 10 0" "10 0 0"; echo "endsolid sheet"; } > constant/triSurface/rock.stl
SETUP
badCase stlFlatTetrahedron disc "rock.stl" "the scan is flat" meshRock -case . -dry-run <<SETUP
$stlDict
$facetFn
{ echo "solid flat"; facet "0 0 0" "0 10 0" "10 0 0"; facet "0 0 0" "10 0 0" "10 10 0"; facet "0 0 0" "10 10 0" "0 10 0"; facet "10 0 0" "0 10 0" "10 10 0"; echo "endsolid flat"; } > constant/triSurface/rock.stl
SETUP
badCase stlInsideOut disc "rock.stl" "flip its normals" meshRock -case . <<SETUP
$stlDict
$facetFn
{ echo "solid inverted"; facet "0 0 0" "10 0 0" "0 10 0"; facet "0 0 0" "0 0 10" "10 0 0"; facet "0 0 0" "0 10 0" "0 0 10"; facet "10 0 0" "0 0 10" "0 10 0"; echo "endsolid inverted"; } > constant/triSurface/rock.stl
SETUP

# ---- scheduler entries of a study (issue 43) --------------------------------------------
# A valid two-member study; each case appends a bad scheduler entry to its runCasesDict.
studySetup='mkdir -p system template/system
echo "x 0;" > template/system/params
cat > system/runCasesDict <<D
FoamFile { format ascii; class dictionary; object runCasesDict; }
template "template"; command "true";
parameters { x { file system/params; entry x; values (1 2); } }
D'
badCase schedulerUnknown empty "runCasesDict" "not a valid choice" runCases -case . <<SETUP
$studySetup
echo 'scheduler pbs;' >> system/runCasesDict
SETUP
badCase slurmWithoutScheduler empty "runCasesDict" "the scheduler is local" runCases -case . <<SETUP
$studySetup
echo 'slurm { partition short; }' >> system/runCasesDict
SETUP
badCase slurmNotDictionary empty "runCasesDict" "must be a dictionary" runCases -case . <<SETUP
$studySetup
echo 'scheduler slurm; slurm short;' >> system/runCasesDict
SETUP
badCase slurmBadTime empty "runCasesDict" "not a Slurm time limit" runCases -case . <<SETUP
$studySetup
echo 'scheduler slurm; slurm { time 1:2:3:4; }' >> system/runCasesDict
SETUP
badCase slurmCpusZero empty "runCasesDict" "cpusPerTask" runCases -case . <<SETUP
$studySetup
echo 'scheduler slurm; slurm { cpusPerTask 0; }' >> system/runCasesDict
SETUP
badCase slurmCpusFraction empty "runCasesDict" "whole number" runCases -case . <<SETUP
$studySetup
echo 'scheduler slurm; slurm { cpusPerTask 1.5; }' >> system/runCasesDict
SETUP
badCase slurmExtraArray empty "runCasesDict" "which runCases sets itself" runCases -case . <<SETUP
$studySetup
echo 'scheduler slurm; slurm { extra "--qos=short --array=0-3"; }' >> system/runCasesDict
SETUP
badCase strictSlurmTypo empty "runCasesDict" "did you mean 'partition'?" runCases -case . -strict <<SETUP
$studySetup
echo 'scheduler slurm; slurm { partiton short; }' >> system/runCasesDict
SETUP
# Slurm's commands are looked for at run time only: without sbatch on PATH, one line says so
# (before the study's lock file is made).
badCase slurmNoSbatch empty "sbatch" "is not on PATH" env "PATH=$(dirname "$(command -v runCases)")" runCases -case . <<SETUP
$studySetup
echo 'scheduler slurm;' >> system/runCasesDict
SETUP
