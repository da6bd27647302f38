# Find Voro++ (Debian: voro++-dev). Defines Voro++::Voro++.
find_path(VORO_INCLUDE_DIR NAMES voro++.hh PATH_SUFFIXES voro++)
find_library(VORO_LIBRARY NAMES voro++)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Voro++ REQUIRED_VARS VORO_LIBRARY VORO_INCLUDE_DIR)
if(Voro++_FOUND AND NOT TARGET Voro++::Voro++)
  add_library(Voro++::Voro++ UNKNOWN IMPORTED)
  set_target_properties(Voro++::Voro++ PROPERTIES
    IMPORTED_LOCATION ${VORO_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${VORO_INCLUDE_DIR})
endif()
