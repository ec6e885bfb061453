# Installs the runtime, the CLI, the in-tree plugins and a CMake package, so that
#   find_package(kestrel) + kestrel_add_plugin(...)
# builds a plugin outside this tree.
include(CMakePackageConfigHelpers)

install(TARGETS kestrel kestrel_messages kestrel_plot kestrel_algorithms kestrel_tracking EXPORT kestrelTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS kestrel_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY framework/include/kestrel framework/messages/include/kestrel DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
install(FILES "${CMAKE_BINARY_DIR}/include/kestrel/version.hpp" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/kestrel)

set(KESTREL_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/kestrel")
install(EXPORT kestrelTargets NAMESPACE kestrel:: DESTINATION "${KESTREL_CMAKE_DIR}")
configure_package_config_file(cmake/kestrelConfig.cmake.in "${CMAKE_BINARY_DIR}/kestrelConfig.cmake"
                              INSTALL_DESTINATION "${KESTREL_CMAKE_DIR}")
write_basic_package_version_file("${CMAKE_BINARY_DIR}/kestrelConfigVersion.cmake" COMPATIBILITY SameMajorVersion)
install(FILES "${CMAKE_BINARY_DIR}/kestrelConfig.cmake" "${CMAKE_BINARY_DIR}/kestrelConfigVersion.cmake"
              cmake/KestrelPlugin.cmake
        DESTINATION "${KESTREL_CMAKE_DIR}")
