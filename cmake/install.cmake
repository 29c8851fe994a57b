# cmake --install BUILD --prefix P: the command line (P/bin/swingsim), one static library per
# layer (P/lib/libswingsim_<layer>.a), their headers (P/include/swingsim/<layer>/*.h, so that
# `#include "swing/swing_simulation.h"` works as inside the project) and a CMake package
# (P/lib/cmake/swingsim) whose swingsim::swingsim brings every layer and its dependencies.
# docs/install.md says how a downstream project uses it; tests/install/ checks that one does.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SWINGSIM_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/swingsim)
set(SWINGSIM_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/swingsim)

# The layer libraries as swingsim::<layer>, and swingsim_lib (every layer) as swingsim::swingsim,
# also under that name inside this build.
set(SWINGSIM_INSTALLED_TARGETS swingsim_lib)
foreach(layer ${SWINGSIM_LAYERS})
  if(layer STREQUAL "cli")
    continue()
  endif()
  set_target_properties(swingsim_${layer} PROPERTIES EXPORT_NAME ${layer})
  list(APPEND SWINGSIM_INSTALLED_TARGETS swingsim_${layer})
  install(DIRECTORY src/${layer}/ DESTINATION ${SWINGSIM_INSTALL_INCLUDEDIR}/${layer}
          FILES_MATCHING PATTERN "*.h")
endforeach()
set_target_properties(swingsim_lib PROPERTIES EXPORT_NAME swingsim)
add_library(swingsim::swingsim ALIAS swingsim_lib)

install(TARGETS ${SWINGSIM_INSTALLED_TARGETS} EXPORT swingsimTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${SWINGSIM_INSTALL_INCLUDEDIR})
install(TARGETS swingsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT swingsimTargets NAMESPACE swingsim:: DESTINATION ${SWINGSIM_INSTALL_CMAKEDIR})

configure_package_config_file(cmake/swingsimConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/swingsimConfig.cmake
                              INSTALL_DESTINATION ${SWINGSIM_INSTALL_CMAKEDIR})
# 0.x: a minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/swingsimConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/swingsimConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/swingsimConfigVersion.cmake
        DESTINATION ${SWINGSIM_INSTALL_CMAKEDIR})

# The install test: install this build into a temporary prefix, build tests/install/downstream
# against it and compare its swing time with the installed command line's. Release pass only:
# the downstream build does not carry the sanitizer flags.
if(NOT SWINGSIM_SANITIZE)
  add_test(NAME install_downstream_find_package
           COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR} -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}
                   -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/install_test
                   -DCMAKE_DIR=${SWINGSIM_INSTALL_CMAKEDIR} -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
                   -DCXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/tests/install/check_downstream.cmake)
  set_tests_properties(install_downstream_find_package PROPERTIES TIMEOUT 300)
endif()
