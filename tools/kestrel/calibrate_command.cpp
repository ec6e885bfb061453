// `kestrel calibrate LEFT RIGHT`: a stereo calibration from chessboard image pairs (two folders or
// two numbered patterns, as stereo_images reads them), written as the ROS camera_info pair the
// drivers read (OUT/left.yaml, OUT/right.yaml), with the errors that say whether it is good.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <kestrel/error.hpp>
#include <sstream>

#include "commands.hpp"
#include "kestrel/stereo_calibration/chessboard_calibration.hpp"
#include "kestrel/stereo_images/pair_source.hpp"

namespace kestrel::cli {

int calibrate_command(const CalibrateArgs& args) {
  try {
    calibration::ChessboardOptions options;
    char x = 0;
    std::istringstream board(args.board);
    if (!(board >> options.inner_corners.width >> x >> options.inner_corners.height) || x != 'x' ||
        options.inner_corners.width < 2 || options.inner_corners.height < 2)
      throw Error("--board '" + args.board + "' is not COLSxROWS of inner corners, such as 8x6");
    if (!(args.square_m > 0)) throw Error("--square must be the side of a square in metres, above 0");
    options.square_m = args.square_m;
    stereo_images::PairSource source({args.left, args.right, "", 0});
    std::vector<std::pair<cv::Mat, cv::Mat>> pairs;
    std::vector<std::string> names;
    while (auto pair = source.next()) {
      pairs.push_back(std::move(*pair));
      names.push_back("pair " + std::to_string(pairs.size() - 1));
    }
    const auto result = calibration::calibrate_stereo(pairs, names, options);
    std::filesystem::create_directories(args.out);
    auto left = result.left, right = result.right;
    left.camera_name = args.name + "/left";
    right.camera_name = args.name + "/right";
    const auto left_file = std::filesystem::path(args.out) / "left.yaml",
               right_file = std::filesystem::path(args.out) / "right.yaml";
    std::ofstream(left_file) << calibration::to_yaml(left);
    std::ofstream(right_file) << calibration::to_yaml(right);
    for (const auto& s : result.skipped) std::cout << "skipped " << s << "\n";
    std::cout << "pairs used: " << result.pairs_used << " of " << pairs.size() << "\n"
              << "reprojection error (stereo): " << result.rms_px << " px\n"
              << "rectified epipolar error: " << result.epipolar.mean_px << " px mean, " << result.epipolar.max_px
              << " px largest\n"
              << "focal length (rectified): " << left.p[0] << " px, baseline: " << -right.p[3] / right.p[0] << " m\n"
              << "wrote " << left_file.string() << " and " << right_file.string() << "\n";
    if (result.epipolar.mean_px > 0.5)
      std::cout << "the epipolar error is large: more pairs, over the whole image, the board held flat and still\n";
    return kOk;
  } catch (const Error& e) {
    std::cerr << "kestrel calibrate: " << e.what() << "\n";
    return kRunFailed;
  }
}

}  // namespace kestrel::cli
