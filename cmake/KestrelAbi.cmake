# kestrel_write_version_header(OUTPUT file VERSION x.y.z INCLUDE_DIRS dir... [TEMPLATE file])
#
# Writes kestrel/version.hpp: the version and KESTREL_API_HASH, the hash of the token stream of
# every plugin-facing header below INCLUDE_DIRS (abi_hash.py), which KESTREL_ABI_TAG carries. A
# comment or whitespace edit keeps the hash; a declaration change moves it.
#
# kestrel's own build calls the function at configure time (runtime/CMakeLists.txt). Run as a
# script, it does the same for any include tree, for instance an installed one:
#   cmake -DOUTPUT=inc/kestrel/version.hpp -DVERSION=0.1.0 -DINCLUDE_DIRS=inc -P KestrelAbi.cmake
set(_KESTREL_ABI_DIR "${CMAKE_CURRENT_LIST_DIR}")

# kestrel_abi_version(OUT version): the version policy in one place. From 1.0 on, releases with
# the same major version are compatible (ABI version = SONAME = MAJOR). Before 1.0 every minor
# release may break, so the ABI version is 0.MINOR: the SONAME, the CMake package's compatibility
# rule and the plugin handshake all follow it.
function(kestrel_abi_version out version)
  string(REGEX MATCH "^([0-9]+)\\.([0-9]+)" _ "${version}")
  if(CMAKE_MATCH_1 EQUAL 0)
    set(${out} "0.${CMAKE_MATCH_2}" PARENT_SCOPE)
  else()
    set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
  endif()
endfunction()

function(kestrel_write_version_header)
  cmake_parse_arguments(ARG "" "OUTPUT;VERSION;TEMPLATE" "INCLUDE_DIRS" ${ARGN})
  if(NOT ARG_OUTPUT OR NOT ARG_INCLUDE_DIRS)
    message(FATAL_ERROR "kestrel_write_version_header: OUTPUT and INCLUDE_DIRS are required")
  endif()
  if(NOT ARG_VERSION MATCHES "^([0-9]+)\\.([0-9]+)\\.([0-9]+)$")
    message(FATAL_ERROR "kestrel_write_version_header: VERSION '${ARG_VERSION}' is not MAJOR.MINOR.PATCH")
  endif()
  # The names version.hpp.in uses.
  set(PROJECT_VERSION "${ARG_VERSION}")
  set(PROJECT_VERSION_MAJOR "${CMAKE_MATCH_1}")
  set(PROJECT_VERSION_MINOR "${CMAKE_MATCH_2}")
  set(PROJECT_VERSION_PATCH "${CMAKE_MATCH_3}")
  kestrel_abi_version(KESTREL_ABI_VERSION "${ARG_VERSION}")
  if(NOT ARG_TEMPLATE)
    set(ARG_TEMPLATE "${_KESTREL_ABI_DIR}/../runtime/include/kestrel/version.hpp.in")
  endif()

  if(Python3_EXECUTABLE)
    set(python "${Python3_EXECUTABLE}")
  else()
    find_program(KESTREL_PYTHON3 python3 REQUIRED)
    set(python "${KESTREL_PYTHON3}")
  endif()
  execute_process(COMMAND "${python}" "${_KESTREL_ABI_DIR}/abi_hash.py" ${ARG_INCLUDE_DIRS}
                  OUTPUT_VARIABLE KESTREL_API_HASH OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
  configure_file("${ARG_TEMPLATE}" "${ARG_OUTPUT}" @ONLY)
  set(KESTREL_API_HASH "${KESTREL_API_HASH}" PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  kestrel_write_version_header(OUTPUT "${OUTPUT}" VERSION "${VERSION}" INCLUDE_DIRS ${INCLUDE_DIRS})
  message(STATUS "KESTREL_API_HASH ${KESTREL_API_HASH} written to ${OUTPUT}")
endif()
