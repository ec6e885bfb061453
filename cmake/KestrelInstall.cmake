# Installs the runtime, the CLI, the in-tree plugins, the graphs, the example plugin, the docs and
# a CMake package, so that
#   find_package(kestrel) + kestrel_add_plugin(...)
# builds a plugin outside this tree. The layout and the RPATHs are in KestrelLayout.cmake.
include(CMakePackageConfigHelpers)

set_target_properties(kestrel kestrel_algorithms kestrel_tracking kestrel_vehicle kestrel_plot kestrel_mcap kestrel_ros2 kestrel_ros2_messages PROPERTIES INSTALL_RPATH
                                                                                  "${KESTREL_LIBRARY_RPATH}")

# Two export sets: kestrelTargets (the runtime, the messages, the algorithms, tracking and vehicle
# libraries) names no OpenCV, PCL or MRPT target; kestrel::plot draws with OpenCV, so it is the
# component `plot`, in kestrelPlotTargets.cmake (kestrelConfig.cmake loads both).
install(TARGETS kestrel kestrel_messages kestrel_algorithms kestrel_tracking kestrel_vehicle kestrel_mcap kestrel_ros2 EXPORT kestrelTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS kestrel_plot EXPORT kestrelPlotTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS kestrel_ros2_messages EXPORT kestrelRos2MessagesTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS kestrel_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY framework/include/kestrel framework/messages/include/kestrel DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
install(FILES "${CMAKE_BINARY_DIR}/include/kestrel/version.hpp" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/kestrel)

# Graphs find their includes and plugin_paths relative to their own file, so an installed graph
# runs from any working directory.
install(DIRECTORY graphs/ DESTINATION "${KESTREL_INSTALL_DATADIR}/graphs" FILES_MATCHING PATTERN "*.yaml")
install(DIRECTORY examples/ DESTINATION "${KESTREL_INSTALL_DATADIR}/examples")
install(FILES README.md DESTINATION "${KESTREL_INSTALL_DATADIR}")
install(DIRECTORY docs/ DESTINATION "${KESTREL_INSTALL_DATADIR}/docs")

install(EXPORT kestrelTargets NAMESPACE kestrel:: DESTINATION "${KESTREL_INSTALL_CMAKEDIR}")
install(EXPORT kestrelPlotTargets NAMESPACE kestrel:: DESTINATION "${KESTREL_INSTALL_CMAKEDIR}")
install(EXPORT kestrelRos2MessagesTargets NAMESPACE kestrel:: DESTINATION "${KESTREL_INSTALL_CMAKEDIR}")
configure_package_config_file(cmake/kestrelConfig.cmake.in "${CMAKE_BINARY_DIR}/kestrelConfig.cmake"
                              INSTALL_DESTINATION "${KESTREL_INSTALL_CMAKEDIR}")
write_basic_package_version_file("${CMAKE_BINARY_DIR}/kestrelConfigVersion.cmake" COMPATIBILITY ${KESTREL_PACKAGE_COMPATIBILITY})
install(FILES "${CMAKE_BINARY_DIR}/kestrelConfig.cmake" "${CMAKE_BINARY_DIR}/kestrelConfigVersion.cmake"
              cmake/KestrelPlugin.cmake
        DESTINATION "${KESTREL_INSTALL_CMAKEDIR}")

# The same package in the build folder, for building plugins against a build without installing
# it: find_package(kestrel) with CMAKE_PREFIX_PATH or kestrel_DIR set to the build folder finds
# kestrelConfig.cmake there, and the targets point at the build's libraries and the source headers.
export(EXPORT kestrelTargets NAMESPACE kestrel:: FILE "${CMAKE_BINARY_DIR}/kestrelTargets.cmake")
export(EXPORT kestrelPlotTargets NAMESPACE kestrel:: FILE "${CMAKE_BINARY_DIR}/kestrelPlotTargets.cmake")
export(EXPORT kestrelRos2MessagesTargets NAMESPACE kestrel:: FILE "${CMAKE_BINARY_DIR}/kestrelRos2MessagesTargets.cmake")
configure_file(cmake/KestrelPlugin.cmake "${CMAKE_BINARY_DIR}/KestrelPlugin.cmake" COPYONLY)
