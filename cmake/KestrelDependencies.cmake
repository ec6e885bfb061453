# The Debian 12 packages the framework and the in-tree plugins build against.
# scripts/install-deps installs them.
find_package(Threads REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(yaml-cpp 0.7 REQUIRED)
find_package(fmt REQUIRED)
find_package(spdlog REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
# Header-only: Boost.Math's Student's t distribution for the CLI's confidence intervals.
find_package(Boost 1.74 REQUIRED)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs calib3d)
find_package(PCL 1.13 REQUIRED COMPONENTS common filters segmentation search kdtree)
# PCL 1.13 makes imported targets (pcl_common, pcl_filters, ...) for the components above.
find_package(mrpt-bayes REQUIRED)
find_package(mrpt-opengl REQUIRED)
if(KESTREL_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(KESTREL_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

