# The Debian 12 packages the framework and the in-tree plugins build against.
# scripts/install-deps installs them.

# find_package, but a missing package stops the configure with its Debian package's name and the
# command that installs it, instead of CMake's generic search report.
macro(kestrel_require package debian)
  find_package(${package} ${ARGN} QUIET)
  if(NOT ${package}_FOUND)
    message(FATAL_ERROR "kestrel needs ${package} (Debian package ${debian}), which was not found. "
                        "Run `make deps` (scripts/install-deps) to install every dependency, then build again.")
  endif()
endmacro()

kestrel_require(Threads libc6-dev)
kestrel_require(Eigen3 libeigen3-dev 3.4 NO_MODULE)
kestrel_require(yaml-cpp libyaml-cpp-dev 0.7)
kestrel_require(fmt libfmt-dev)
kestrel_require(spdlog libspdlog-dev)
kestrel_require(nlohmann_json nlohmann-json3-dev 3)
kestrel_require(CLI11 libcli11-dev)
# Header-only: Boost.Math's Student's t distribution for the CLI's confidence intervals, and
# Boost.Beast (with Asio) for the live view's WebSocket server.
kestrel_require(Boost libboost-dev 1.74)
kestrel_require(OpenCV libopencv-dev 4 COMPONENTS core imgproc imgcodecs calib3d videoio)
# PCL 1.13 makes imported targets (pcl_common, pcl_filters, ...) for these components.
kestrel_require(PCL libpcl-dev 1.13 COMPONENTS common filters segmentation search kdtree)
# MCAP recordings: CRC-32, and zstd and LZ4-frame chunk compression.
kestrel_require(ZLIB zlib1g-dev)
kestrel_require(zstd libzstd-dev 1.4)
kestrel_require(PkgConfig pkg-config)
pkg_check_modules(LZ4 QUIET IMPORTED_TARGET liblz4)
if(NOT LZ4_FOUND)
  message(FATAL_ERROR "kestrel needs liblz4 (Debian package liblz4-dev), which was not found. "
                      "Run `make deps` (scripts/install-deps) to install every dependency, then build again.")
endif()
# MAVLink 2 signing: SHA-256 and the random source for keys (libcrypto).
kestrel_require(OpenSSL libssl-dev 3 COMPONENTS Crypto)
# DDS as ROS 2 speaks it (dds_bridge, kestrel dds): Eclipse Cyclone DDS, ROS 2 Humble's rmw_cyclonedds.
kestrel_require(CycloneDDS cyclonedds-dev 0.10)
kestrel_require(mrpt-bayes libmrpt-bayes-dev)
kestrel_require(mrpt-opengl libmrpt-opengl-dev)
if(KESTREL_BUILD_TESTS)
  kestrel_require(GTest googletest)
endif()
if(KESTREL_BUILD_BENCH)
  kestrel_require(benchmark libbenchmark-dev)
endif()
