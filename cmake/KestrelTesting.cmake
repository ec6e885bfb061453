# How kestrel's tests are declared. A test that exercises one unit (the runtime, a library, a
# plugin, a tool) lives beside it, in its folder's tests/; a test that needs several units
# (whole graphs, installs, interop, fuzzing) lives in the top-level tests/. Both use
# kestrel_add_test(), and every test links the one test-support library, kestrel_test_support
# (tests/support): the plugin-loading helpers, scratch paths, ports and the fakes of hardware.

# Timeouts are there to catch hangs. Sanitizer builds run several times slower (the integration
# tests about three times under ASan), so their tests get three times as long.
set(_kestrel_timeout_scale 1)
if(KESTREL_SANITIZE)
  set(_kestrel_timeout_scale 3)
endif()
math(EXPR KESTREL_TIMEOUT_FRAMEWORK "120 * ${_kestrel_timeout_scale}")
math(EXPR KESTREL_TIMEOUT_UNIT "300 * ${_kestrel_timeout_scale}")
math(EXPR KESTREL_TIMEOUT_LONG "600 * ${_kestrel_timeout_scale}")

# Where the test-only plugins go (the tests and the benchmarks load them from there).
set(KESTREL_TEST_PLUGIN_DIR "${CMAKE_BINARY_DIR}/tests/plugins")
set(KESTREL_BAD_PLUGIN_DIR "${CMAKE_BINARY_DIR}/tests/bad_plugins")

# kestrel_discover_tests(TARGET [TIMEOUT s] [SERIAL] [RESOURCE_LOCK name] LABELS label... [SUITE_LABELS "pattern=label,label" ...])
# registers TARGET's tests: those matching a SUITE_LABELS pattern (gtest filter syntax) with
# that entry's labels, the others with LABELS. Every test is registered exactly once: the last
# discovery takes the tests that match no pattern. The labels are set by a script CTest runs
# after the discovered tests are added (gtest_discover_tests passes a list-valued property on
# as separate words).
function(kestrel_discover_tests target)
  cmake_parse_arguments(ARG "SERIAL" "TIMEOUT;RESOURCE_LOCK" "LABELS;SUITE_LABELS" ${ARGN})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT ${KESTREL_TIMEOUT_UNIT})
  endif()
  set(serial "")
  if(ARG_SERIAL)
    set(serial RUN_SERIAL TRUE)  # alone: a realtime test that needs the machine's cores
  endif()
  set(lock "")
  if(ARG_RESOURCE_LOCK)
    set(lock RESOURCE_LOCK ${ARG_RESOURCE_LOCK})  # never beside a test that takes the same
  endif()
  set(script "")
  set(patterns "")
  set(group 0)
  foreach(entry IN LISTS ARG_SUITE_LABELS)
    string(REPLACE "=" ";" parts "${entry}")
    list(GET parts 0 pattern)
    list(GET parts 1 labels)
    string(REPLACE "," ";" labels "${labels}")
    math(EXPR group "${group} + 1")
    gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "${pattern}" TEST_LIST ${target}_group${group}
                         PROPERTIES TIMEOUT ${ARG_TIMEOUT} ${lock})
    string(APPEND script "if(${target}_group${group})\n"
           "  set_tests_properties(\${${target}_group${group}} PROPERTIES LABELS \"${labels}\")\n"
           "endif()\n")
    list(APPEND patterns "${pattern}")
  endforeach()
  set(filter "")
  if(patterns)
    list(JOIN patterns ":" filter)
    set(filter "-${filter}")
  endif()
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "${filter}" TEST_LIST ${target}_others
                       PROPERTIES TIMEOUT ${ARG_TIMEOUT} ${serial} ${lock})
  string(APPEND script "if(${target}_others)\n"
         "  set_tests_properties(\${${target}_others} PROPERTIES LABELS \"${ARG_LABELS}\")\n"
         "endif()\n")
  set(labels_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_labels.cmake")
  file(WRITE "${labels_file}" "${script}")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${labels_file}")
endfunction()

# kestrel_add_test(NAME SOURCES file.cpp... [LIBRARIES target...] LABELS label...
#                  [SUITE_LABELS "pattern=label,..." ...] [TIMEOUT s] [SERIAL] [RESOURCE_LOCK name]
#                  [LOADS target...] [ASAN_SKIPPED])
#
# A GoogleTest program, registered test by test with CTest. LABELS are the CTest labels of its
# tests (each plugin's tests carry its folder's name); SERIAL runs them alone (realtime tests that
# need the cores); RESOURCE_LOCK never beside another test holding the same name (`dds`: tests
# that talk on DDS domains, chosen from the process id, which two tests could share). LOADS names what the tests load or run at run time without linking it (plugins,
# the CLI, test plugins): they are built first. A target of LOADS that does not exist (a plugin
# folder deleted) is left out, so that the rest still builds; the tests that need it then fail.
# ASAN_SKIPPED: every test of the program is in tests/sanitizers/asan-skip.txt, so the ASan build
# neither builds nor registers it (check_asan_skip.py fails if a test of it is not listed there).
# Test code is built at -O1 even in Release: it compiles about a third faster, and what the tests
# spend their time in (the runtime, the plugins, the libraries) keeps its own -O3.
function(kestrel_add_test name)
  cmake_parse_arguments(ARG "SERIAL;ASAN_SKIPPED" "TIMEOUT;RESOURCE_LOCK" "SOURCES;LIBRARIES;LABELS;SUITE_LABELS;LOADS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES} kestrel_test_support GTest::gmock GTest::gtest_main
                                        kestrel_warnings)
  target_include_directories(${name} PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}")
  target_compile_options(${name} PRIVATE $<$<CONFIG:Release>:-O1>)
  if(ARG_LOADS)
    cmake_language(EVAL CODE "cmake_language(DEFER DIRECTORY [[${CMAKE_SOURCE_DIR}]] CALL kestrel_add_existing_dependencies [[${name}]] ${ARG_LOADS})")
  endif()
  if(ARG_ASAN_SKIPPED AND KESTREL_SANITIZE MATCHES "address")
    set_target_properties(${name} PROPERTIES EXCLUDE_FROM_ALL TRUE)
    set_property(GLOBAL APPEND PROPERTY KESTREL_ASAN_UNBUILT_TESTS ${name})
    return()
  endif()
  set(options "")
  if(ARG_SERIAL)
    list(APPEND options SERIAL)
  endif()
  if(ARG_TIMEOUT)
    list(APPEND options TIMEOUT ${ARG_TIMEOUT})
  endif()
  if(ARG_RESOURCE_LOCK)
    list(APPEND options RESOURCE_LOCK ${ARG_RESOURCE_LOCK})
  endif()
  kestrel_discover_tests(${name} LABELS ${ARG_LABELS} SUITE_LABELS ${ARG_SUITE_LABELS} ${options})
endfunction()

# Dependencies on the targets that exist once every folder has been read.
function(kestrel_add_existing_dependencies target)
  foreach(dependency IN LISTS ARGN)
    if(TARGET ${dependency})
      add_dependencies(${target} ${dependency})
    endif()
  endforeach()
endfunction()

# Every in-tree plugin that ships, for tests that load them all (closed loops, the message
# reference): call it from a deferred context or the top-level tests/, after plugins/ and sensors/.
function(kestrel_shipped_plugins out)
  get_property(plugins GLOBAL PROPERTY KESTREL_SHIPPED_PLUGINS)
  set(${out} ${plugins} PARENT_SCOPE)
endfunction()
