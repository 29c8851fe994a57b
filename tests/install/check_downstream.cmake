# The install test (CTest install_downstream_find_package, cmake/install.cmake):
#   cmake -DBUILD_DIR=<swingsim build> -DSOURCE_DIR=<checkout> -DWORK_DIR=<scratch>
#         -DCMAKE_DIR=<the package's folder in the prefix, lib/cmake/swingsim> [-DCXX_COMPILER=...] [-DCXX_COMPILER_LAUNCHER=...] -P check_downstream.cmake
# installs the build into WORK_DIR/prefix, builds tests/install/downstream against that prefix
# only, runs it on participants/p1.yaml and checks that its swing time is the installed
# command line's (`simulate --json`), to the last digit. Any failing step fails the test.
cmake_minimum_required(VERSION 3.22)
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR CMAKE_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "check_downstream.cmake: -D${var}=... is required")
  endif()
endforeach()

set(prefix ${WORK_DIR}/prefix)
set(downstream_build ${WORK_DIR}/downstream-build)
set(participant ${SOURCE_DIR}/participants/p1.yaml)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# Runs one step; stops the test with the step's name, exit status and output if it fails.
function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    list(JOIN ARGN " " command)
    message(FATAL_ERROR "${name} failed (${status}):\n  ${command}\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

set(configure_args -S ${SOURCE_DIR}/tests/install/downstream -B ${downstream_build}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
if(CXX_COMPILER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
if(CXX_COMPILER_LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_COMPILER_LAUNCHER})
endif()
run_step("downstream configure" ${CMAKE_COMMAND} ${configure_args})
# The package must come from the prefix, not from the build tree or the system.
file(STRINGS ${downstream_build}/CMakeCache.txt found_dir REGEX "^swingsim_DIR:")
if(NOT found_dir STREQUAL "swingsim_DIR:PATH=${prefix}/${CMAKE_DIR}")
  message(FATAL_ERROR "downstream found swingsim elsewhere: ${found_dir} (expected ${prefix}/${CMAKE_DIR})")
endif()
run_step("downstream build" ${CMAKE_COMMAND} --build ${downstream_build})

run_step("downstream run" ${downstream_build}/swingsim_downstream ${participant})
if(NOT step_output MATCHES "^swing_time_s ([^\n]+)\n$")
  message(FATAL_ERROR "downstream printed no swing time: '${step_output}'")
endif()
set(downstream_time ${CMAKE_MATCH_1})

run_step("installed swingsim simulate" ${prefix}/bin/swingsim simulate ${participant} --json ${WORK_DIR}/cli.json
         --out ${WORK_DIR}/cli-out)
file(READ ${WORK_DIR}/cli.json cli_json)
# CMake prints a JSON number with 17 significant digits, as the downstream program does.
string(JSON cli_time GET "${cli_json}" swing_time_s)
if(NOT downstream_time STREQUAL cli_time)
  message(FATAL_ERROR "swing time: downstream ${downstream_time} s, installed swingsim ${cli_time} s")
endif()
message(STATUS "swing time ${downstream_time} s from the downstream project and from the installed swingsim")
