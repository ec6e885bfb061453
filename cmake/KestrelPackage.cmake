# `make package`: a Debian package of the install (CPack, DEB generator), installed under /usr:
#   /usr/bin/kestrel, /usr/lib/libkestrel*.so.*, /usr/lib/kestrel/plugins/, /usr/include/kestrel/,
#   /usr/lib/cmake/kestrel/, /usr/share/kestrel/{graphs,examples,docs}
# so `kestrel` is on PATH and find_package(kestrel) needs no hint. Every binary finds kestrel's
# libraries through $ORIGIN RPATHs (KestrelLayout.cmake), so the same tree also runs unpacked
# anywhere (dpkg -x into a scratch root). Runtime dependencies come from dpkg-shlibdeps (dpkg-dev),
# plus what is loaded at run time without being linked: Mesa's software EGL for the headless
# renderer of sim_stereo.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME kestrel)
set(CPACK_PACKAGE_VENDOR kestrel)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "Runs YAML graphs of shared-library plugins: simulated stereo, depth, detection, tracking and their \
evaluation. Holds the kestrel command, the in-tree plugins, the example graphs, and the headers and CMake \
package to build plugins (find_package(kestrel) + kestrel_add_plugin).")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "kestrel developers <kestrel@localhost>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl-mesa0, libgl1-mesa-dri")
# Building plugins against the package also needs a compiler and the headers kestrel's use.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "cmake, g++, libeigen3-dev, libfmt-dev, nlohmann-json3-dev")
include(CPack)
