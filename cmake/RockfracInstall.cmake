# cmake --install <build> --prefix <prefix>: rockfrac usable outside its source tree.
#
#   <prefix>/bin/                     the applications (every target under applications/,
#                                     installed by rockfrac_add_application)
#   <prefix>/etc/bashrc               the environment: source it (PATH, ROCKFRAC_BIN,
#                                     ROCKFRAC_DIR, ROCKFRAC_TUTORIALS)
#   <prefix>/share/rockfrac/          ROCKFRAC_DIR: utilities/RunFunctions, tutorials/ and
#                                     cases/ (the measured data, the calibration studies) in
#                                     the source tree's layout, so that every relative path
#                                     between them holds in both
#   <prefix>/share/doc/rockfrac/      README.md, CHANGELOG.md and docs/ (their links hold)
#
# The tutorials and cases are installed as inputs only: whatever a run in the source tree
# wrote (the outputs each Allclean removes, and .gitignore lists) stays behind.
# tests/case/install checks the installed tree against the source's files.

install(FILES ${PROJECT_SOURCE_DIR}/etc/bashrc DESTINATION etc)
install(FILES ${PROJECT_SOURCE_DIR}/utilities/RunFunctions DESTINATION share/rockfrac/utilities)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION share/doc/rockfrac)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs DESTINATION share/doc/rockfrac)

# Outputs of the applications and of the tutorials' scripts, as full-path regular
# expressions (directories exclude all they hold).
set(rockfrac_run_outputs
  # any case: logs, time directories (complete, being written, replaced), VTK, time series
  "/log\\.[^/]*$" "/[0-9][^/]*$" "/\\.(tmp|old)\\.[^/]*$" "/VTK$" "/postProcessing$"
  "/constant/(voronoiMesh|feMesh|geometryProperties)$" "/constant/triSurface/(specimen|scan)\\.stl$"
  # cases made by the tutorials' Allrun: SPB rocks, meshConvergence, loadingRate, twoRates
  "/tutorials/SPB/[^/]+/rock[0-9]+(\\.new)?$" "/tutorials/BDT/meshConvergence/cells[^/]*$"
  "/tutorials/BDT/loadingRate/speed[^/]*$" "/tutorials/explainGap/twoRates/(slow|fast)$"
  # the crusher: liners, kinematics and the feed rock's meshes (meshCrusher, meshRock)
  "/tutorials/CH660/[^/]+/constant/(triSurface|crusherKinematics)$"
  "/tutorials/CH660/[^/]+/feedRock[A-Za-z]*/constant$" "/tutorials/CH660/geometry/constant$"
  # explainGap, makeTwinData, calibrateModel, runCases: runs, twin data, tables, plots, reports
  "/(runs|simulations|augmentedCase|measured|results)$" "/hiddenLabel$"
  "/tutorials/explainGap/.*/(explainGap\\.[^/]*|[^/]*\\.dat|[^/]*\\.png[^/]*)$"
  "/tutorials/explainGap/(paperBDT|paperSPB[^/]*/study)/measurements$")
set(rockfrac_excludes)
foreach(regex ${rockfrac_run_outputs})
  list(APPEND rockfrac_excludes REGEX "${regex}" EXCLUDE)
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/tutorials ${PROJECT_SOURCE_DIR}/cases
        DESTINATION share/rockfrac USE_SOURCE_PERMISSIONS ${rockfrac_excludes})
