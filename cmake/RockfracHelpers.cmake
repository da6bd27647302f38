# Helper functions shared by every CMakeLists.txt of rockfrac.

# Warnings and sanitizers for one target.
function(rockfrac_target_options target)
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
      -Wno-unknown-pragmas>)
  if(ROCKFRAC_WERROR)
    target_compile_options(${target} PRIVATE $<$<COMPILE_LANGUAGE:CXX>:-Werror>)
  endif()
endfunction()

# Apply sanitizer flags globally (before targets are made).
# Host code only: nvcc (the CUDA backend, libs/demCuda) takes neither flag.
if(ROCKFRAC_SANITIZE)
  add_compile_options(
    "$<$<COMPILE_LANGUAGE:C,CXX>:-fsanitize=${ROCKFRAC_SANITIZE};-fno-omit-frame-pointer;-fno-sanitize-recover=all>")
  add_link_options(-fsanitize=${ROCKFRAC_SANITIZE})
  # GCC 12's -Wmaybe-uninitialized misfires on libstdc++ (std::regex, std::function)
  # under -fsanitize=address at -O2, which stops the warnings-as-errors sanitize preset
  # in system headers; the release and ci builds keep the warning.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options($<$<COMPILE_LANGUAGE:C,CXX>:-Wno-maybe-uninitialized>)
  endif()
endif()
# Test environment for sanitized builds: third-party leaks are suppressed (not ours).
set(ROCKFRAC_SANITIZER_ENV
  "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/tests/sanitizers/lsan.supp:print_suppressions=0")

# rockfrac_add_library(<name> SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# Creates target rockfrac_<name> with alias rockfrac::<name>; include root is libs/.
function(rockfrac_add_library name)
  cmake_parse_arguments(A "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(rockfrac_${name} STATIC ${A_SOURCES})
  add_library(rockfrac::${name} ALIAS rockfrac_${name})
  target_include_directories(rockfrac_${name} PUBLIC ${PROJECT_SOURCE_DIR}/libs)
  target_link_libraries(rockfrac_${name} PUBLIC ${A_PUBLIC_DEPS} PRIVATE ${A_PRIVATE_DEPS})
  set_target_properties(rockfrac_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  rockfrac_target_options(rockfrac_${name})
endfunction()

# rockfrac_add_application(<name> SOURCES ... DEPS ...)
# An application under applications/ is installed into <prefix>/bin (cmake/RockfracInstall.cmake);
# elsewhere (bench/) it is not.
function(rockfrac_add_application name)
  cmake_parse_arguments(A "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${A_SOURCES})
  target_link_libraries(${name} PRIVATE ${A_DEPS})
  rockfrac_target_options(${name})
  string(FIND "${CMAKE_CURRENT_SOURCE_DIR}/" "${PROJECT_SOURCE_DIR}/applications/" position)
  if(position EQUAL 0)
    install(TARGETS ${name} RUNTIME DESTINATION bin)
  endif()
endfunction()

# rockfrac_set_test_cost(<test> "<first>;<second>" <use second: ON|OFF>): the COST
# property (measured seconds, used by ctest to start the longest tests first); no
# values, no property.
function(rockfrac_set_test_cost name costs useSecond)
  if(NOT costs)
    return()
  endif()
  list(LENGTH costs n)
  if(NOT n EQUAL 2)
    message(FATAL_ERROR "${name}: COST takes two values (seconds), got '${costs}'")
  endif()
  list(GET costs 0 cost)
  if(useSecond)
    list(GET costs 1 cost)
  endif()
  set_tests_properties(${name} PROPERTIES COST ${cost})
endfunction()

# rockfrac_add_unit_test(<name> SOURCES ... DEPS ... [LABELS ...]
#                        [COST <s in a Release build> <s under the sanitizers>])
# A Catch2 (v2) executable whose test cases run as one ctest entry. COST: measured
# seconds, the first of a Release build, the second of a sanitized one (ordering only,
# as for rockfrac_add_case_test below).
function(rockfrac_add_unit_test name)
  cmake_parse_arguments(A "" "" "SOURCES;DEPS;LABELS;COST" ${ARGN})
  if(NOT A_LABELS)
    set(A_LABELS unit)
  endif()
  add_executable(test_${name} ${A_SOURCES})
  target_link_libraries(test_${name} PRIVATE rockfrac_catch_main Catch2::Catch2 ${A_DEPS})
  target_compile_definitions(test_${name} PRIVATE
    ROCKFRAC_SOURCE_DIR="${PROJECT_SOURCE_DIR}" ROCKFRAC_BINARY_DIR="${PROJECT_BINARY_DIR}")
  # Unity build: a module's test files compiled a few at a time as one translation unit,
  # so catch.hpp (and Eigen, gmsh ...) are parsed once per batch, not once per file:
  # the test sources were 40 % of the build's CPU time. Catch2 names its test cases with
  # __COUNTER__, so they do not clash; helpers live in per-file anonymous namespaces and
  # must have distinct names within a module.
  set_target_properties(test_${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests
    UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 4)
  rockfrac_target_options(test_${name})
  add_test(NAME ${name} COMMAND test_${name})
  set_tests_properties(${name} PROPERTIES LABELS "${A_LABELS}"
    ENVIRONMENT "OMP_NUM_THREADS=2;OMP_WAIT_POLICY=PASSIVE;ROCKFRAC_BIN=${PROJECT_BINARY_DIR}/bin;${ROCKFRAC_SANITIZER_ENV}")
  set(second OFF)
  if(ROCKFRAC_SANITIZE)
    set(second ON)
  endif()
  rockfrac_set_test_cost(${name} "${A_COST}" ${second})
endfunction()

# rockfrac_add_case_test(<name> SCRIPT <file.sh> [LABELS ...] [TIMEOUT s]
#                        [COST <s at full size> <s at small size>])
# A shell script run with the built applications first on PATH, in a scratch dir.
# One OpenMP thread unless the script asks for more: ctest runs as many tests at
# once as there are cores, and a second thread per test would only oversubscribe
# them (the tests that compare thread counts set OMP_NUM_THREADS themselves).
# COST is the test's measured time (a Release build at full size, the ci-sanitize
# build at the small one): ctest starts the longest tests first, which on a fresh
# clone, with no timing history yet, it cannot otherwise know.
function(rockfrac_add_case_test name)
  cmake_parse_arguments(A "" "SCRIPT;TIMEOUT" "LABELS;COST" ${ARGN})
  if(NOT A_LABELS)
    set(A_LABELS case)
  endif()
  if(NOT A_TIMEOUT)
    set(A_TIMEOUT 600)
  endif()
  set(work ${PROJECT_BINARY_DIR}/caseTests/${name})
  add_test(NAME ${name}
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/${A_SCRIPT} ${work})
  set_tests_properties(${name} PROPERTIES LABELS "${A_LABELS}" TIMEOUT ${A_TIMEOUT}
    ENVIRONMENT "PATH=${PROJECT_BINARY_DIR}/bin:$ENV{PATH};ROCKFRAC_SOURCE_DIR=${PROJECT_SOURCE_DIR};ROCKFRAC_BINARY_DIR=${PROJECT_BINARY_DIR};ROCKFRAC_BUILD_DIR=${PROJECT_BINARY_DIR};ROCKFRAC_SHARED_DIR=${PROJECT_SOURCE_DIR}/../shared;OMP_NUM_THREADS=1;OMP_WAIT_POLICY=PASSIVE;ROCKFRAC_CASE_SIZE=${ROCKFRAC_CASE_SIZE};${ROCKFRAC_SANITIZER_ENV}")
  set(second OFF)
  if(ROCKFRAC_CASE_SIZE STREQUAL "small")
    set(second ON)
  endif()
  rockfrac_set_test_cost(${name} "${A_COST}" ${second})
endfunction()

# Add every immediate or nested subdirectory of <dir> that has a CMakeLists.txt,
# so a new application or test module needs no edit elsewhere.
function(rockfrac_add_subdirectories dir)
  if(dir STREQUAL "")
    set(root ${CMAKE_CURRENT_SOURCE_DIR})
  else()
    set(root ${CMAKE_CURRENT_SOURCE_DIR}/${dir})
  endif()
  file(GLOB_RECURSE lists CONFIGURE_DEPENDS ${root}/*/CMakeLists.txt)
  list(SORT lists)
  foreach(l ${lists})
    get_filename_component(d ${l} DIRECTORY)
    add_subdirectory(${d})
  endforeach()
endfunction()

# rockfrac_add_fuzz_target(<name> SOURCES ... [DEPS ...])
# A libFuzzer executable (only with -DROCKFRAC_FUZZ=ON and clang; the `fuzz`
# preset). The reader under test is listed in SOURCES so that it carries the
# fuzzer's coverage instrumentation; DEPS are linked as they are (they must not
# contain those sources again).
function(rockfrac_add_fuzz_target name)
  cmake_parse_arguments(A "" "" "SOURCES;DEPS" ${ARGN})
  if(NOT (ROCKFRAC_FUZZ AND CMAKE_CXX_COMPILER_ID MATCHES "Clang"))
    return()
  endif()
  add_executable(${name} ${A_SOURCES})
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/libs)
  target_link_libraries(${name} PRIVATE ${A_DEPS})
  set(fuzz_flags -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_compile_options(${name} PRIVATE ${fuzz_flags})
  target_link_options(${name} PRIVATE ${fuzz_flags})
  rockfrac_target_options(${name})
endfunction()
