# Installs the runtime, the libraries, the CLI, the in-tree plugins, the graphs, the example
# plugin, the docs and a CMake package, so that
#   find_package(kestrel) + kestrel_add_plugin(...)
# builds a plugin outside this tree. The layout and the RPATHs are in KestrelLayout.cmake; the
# runtime's export set is installed by runtime/CMakeLists.txt, each library's by
# kestrel_add_library() (KestrelLibrary.cmake).
include(CMakePackageConfigHelpers)
install(TARGETS kestrel_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Graphs find their includes and plugin_paths relative to their own file, so an installed graph
# runs from any working directory.
install(DIRECTORY graphs/ DESTINATION "${KESTREL_INSTALL_DATADIR}/graphs" FILES_MATCHING PATTERN "*.yaml")
install(DIRECTORY examples/ DESTINATION "${KESTREL_INSTALL_DATADIR}/examples")
install(FILES README.md DESTINATION "${KESTREL_INSTALL_DATADIR}")
install(DIRECTORY docs/ DESTINATION "${KESTREL_INSTALL_DATADIR}/docs")

# The package's components are the libraries, loaded in the order libs/CMakeLists.txt adds them
# (each after those it links). Those whose headers use OpenCV find it when they are asked for.
get_property(KESTREL_LIBRARIES GLOBAL PROPERTY KESTREL_LIBRARIES)
set(KESTREL_OPENCV_COMPONENTS "")
foreach(name IN LISTS KESTREL_LIBRARIES)
  get_target_property(link kestrel_lib_${name} INTERFACE_LINK_LIBRARIES)
  if(link MATCHES "opencv_")
    list(APPEND KESTREL_OPENCV_COMPONENTS ${name})
  endif()
endforeach()
configure_package_config_file(cmake/kestrelConfig.cmake.in "${CMAKE_BINARY_DIR}/kestrelConfig.cmake"
                              INSTALL_DESTINATION "${KESTREL_INSTALL_CMAKEDIR}")
write_basic_package_version_file("${CMAKE_BINARY_DIR}/kestrelConfigVersion.cmake" COMPATIBILITY ${KESTREL_PACKAGE_COMPATIBILITY})
install(FILES "${CMAKE_BINARY_DIR}/kestrelConfig.cmake" "${CMAKE_BINARY_DIR}/kestrelConfigVersion.cmake"
              cmake/KestrelPlugin.cmake
        DESTINATION "${KESTREL_INSTALL_CMAKEDIR}")
# The same package in the build folder, for building plugins against a build without installing
# it: find_package(kestrel) with CMAKE_PREFIX_PATH or kestrel_DIR set to the build folder finds
# kestrelConfig.cmake there, and the targets point at the build's libraries and the source headers.
configure_file(cmake/KestrelPlugin.cmake "${CMAKE_BINARY_DIR}/KestrelPlugin.cmake" COPYONLY)
