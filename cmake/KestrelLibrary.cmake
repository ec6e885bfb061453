# kestrel_add_library(NAME
#                     [SOURCES file.cpp...]          (none: a header-only INTERFACE library)
#                     [PUBLIC target...] [PRIVATE target...]
#                     [DESCRIPTION "one line"])
#
# A shared domain library of libs/NAME: target kestrel_lib_NAME (libkestrel_NAME.so; a plugin's
# own target may be kestrel_NAME), alias kestrel::NAME, headers below
# libs/NAME/include/kestrel/NAME/, sources in libs/NAME/src/. It is versioned like the runtime,
# installed with its headers, and exported as the CMake package's component NAME in a file of its
# own (kestrel-NAME-targets.cmake), so that a library that links OpenCV or PCL privately adds
# nothing to the link of a plugin that does not use it. Libraries link the runtime and other
# libraries, never a plugin or a tool (tests/tiers checks it).
function(kestrel_add_library name)
  cmake_parse_arguments(ARG "" "DESCRIPTION" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  set(target kestrel_lib_${name})
  set(include_dir "${CMAKE_CURRENT_SOURCE_DIR}/include")
  if(NOT IS_DIRECTORY "${include_dir}/kestrel/${name}")
    message(FATAL_ERROR "kestrel_add_library(${name}): its headers belong in ${include_dir}/kestrel/${name}")
  endif()
  if(ARG_SOURCES)
    add_library(${target} SHARED ${ARG_SOURCES})
    target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${include_dir}>
                                                $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    target_link_libraries(${target} PUBLIC kestrel::kestrel ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE} kestrel_warnings)
    set_target_properties(${target} PROPERTIES OUTPUT_NAME kestrel_${name} VERSION ${PROJECT_VERSION}
                                               SOVERSION ${KESTREL_SOVERSION} INSTALL_RPATH "${KESTREL_LIBRARY_RPATH}")
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE $<BUILD_INTERFACE:${include_dir}>
                                                   $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    target_link_libraries(${target} INTERFACE kestrel::kestrel ${ARG_PUBLIC})
  endif()
  add_library(kestrel::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  if(ARG_DESCRIPTION)
    set_property(TARGET ${target} PROPERTY KESTREL_DESCRIPTION "${ARG_DESCRIPTION}")
  endif()

  install(TARGETS ${target} EXPORT kestrel-${name}-targets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(DIRECTORY "${include_dir}/kestrel" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
  install(EXPORT kestrel-${name}-targets NAMESPACE kestrel:: DESTINATION "${KESTREL_INSTALL_CMAKEDIR}")
  export(EXPORT kestrel-${name}-targets NAMESPACE kestrel:: FILE "${CMAKE_BINARY_DIR}/kestrel-${name}-targets.cmake")
  set_property(GLOBAL APPEND PROPERTY KESTREL_LIBRARIES ${name})
endfunction()

# kestrel_add_node_folders(): every folder below the current one with a CMakeLists.txt, in name
# order, and its tests/ when tests are built. In-tree only (plugins/, sensors/).
macro(kestrel_add_node_folders)
  file(GLOB _kestrel_folders LIST_DIRECTORIES true RELATIVE "${CMAKE_CURRENT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}/*")
  list(SORT _kestrel_folders)
  foreach(_kestrel_folder IN LISTS _kestrel_folders)
    if(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${_kestrel_folder}/CMakeLists.txt")
      add_subdirectory(${_kestrel_folder})
      if(KESTREL_BUILD_TESTS AND EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${_kestrel_folder}/tests/CMakeLists.txt")
        add_subdirectory(${_kestrel_folder}/tests)
      endif()
    endif()
  endforeach()
endmacro()
