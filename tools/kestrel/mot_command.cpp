// kestrel mot GT TEST [--iou T | --dist D]: CLEAR-MOT and identity metrics for MOTChallenge
// files, so that anyone can check kestrel's metrics against the standard tools.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "command_errors.hpp"
#include "commands.hpp"
#include "kestrel/algorithms/clear_mot.hpp"
#include "kestrel/algorithms/mot_metrics.hpp"
#include "kestrel/error.hpp"
#include "mot_files.hpp"
#include "output_files.hpp"

namespace kestrel::cli {

namespace {

double iou(const MotRow& a, const MotRow& b) {
  const double x1 = std::max(a.left, b.left), y1 = std::max(a.top, b.top);
  const double x2 = std::min(a.left + a.width, b.left + b.width), y2 = std::min(a.top + a.height, b.top + b.height);
  const double inter = std::max(0.0, x2 - x1) * std::max(0.0, y2 - y1);
  const double uni = a.width * a.height + b.width * b.height - inter;
  return uni > 0 ? inter / uni : 0.0;
}

}  // namespace

int mot_command(const MotArgs& args) {
  return run_command_body("mot", [&] {
    if (args.iou && args.distance) throw Error("give --iou or --dist, not both");
    const bool by_iou = !args.distance;
    const double iou_threshold = args.iou.value_or(0.5);
    const MotFrames gt = read_mot(args.ground_truth, true);
    const MotFrames test = read_mot(args.test, false);
    std::map<long, bool> all_frames;
    for (const auto& [f, _] : gt) all_frames[f] = true;
    for (const auto& [f, _] : test) all_frames[f] = true;

    algorithms::ClearMotAccumulator acc;
    const std::vector<MotRow> none;
    for (const auto& [f, _] : all_frames) {
      const auto& objects = gt.count(f) ? gt.at(f) : none;
      const auto& hypotheses = test.count(f) ? test.at(f) : none;
      Eigen::MatrixXd d(static_cast<Eigen::Index>(objects.size()), static_cast<Eigen::Index>(hypotheses.size()));
      for (std::size_t i = 0; i < objects.size(); ++i)
        for (std::size_t j = 0; j < hypotheses.size(); ++j) {
          double v;
          if (by_iou) {
            const double overlap = iou(objects[i], hypotheses[j]);
            v = overlap >= iou_threshold ? 1.0 - overlap : std::numeric_limits<double>::quiet_NaN();
          } else {
            v = (objects[i].point - hypotheses[j].point).norm();
            if (v > *args.distance) v = std::numeric_limits<double>::quiet_NaN();
          }
          d(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = v;
        }
      std::vector<std::uint64_t> oids, hids;
      for (const auto& o : objects) oids.push_back(o.id);
      for (const auto& h : hypotheses) hids.push_back(h.id);
      acc.update(oids, hids, d);
    }
    const auto s = acc.summary();
    std::printf("%-8s %7s %7s %7s %7s %7s %6s %6s %5s %4s %4s %4s %5s %6s\n", "frames", "MOTA", "MOTP", "IDF1", "IDP",
                "IDR", "FP", "FN", "IDSW", "MT", "PT", "ML", "FRAG", "GT");
    std::printf("%-8llu %7.3f %7.3f %7.3f %7.3f %7.3f %6llu %6llu %5llu %4llu %4llu %4llu %5llu %6llu\n",
                static_cast<unsigned long long>(s.frames), s.mota, s.motp, s.idf1, s.idp, s.idr,
                static_cast<unsigned long long>(s.fp), static_cast<unsigned long long>(s.fn),
                static_cast<unsigned long long>(s.idsw), static_cast<unsigned long long>(s.mostly_tracked),
                static_cast<unsigned long long>(s.partially_tracked), static_cast<unsigned long long>(s.mostly_lost),
                static_cast<unsigned long long>(s.fragmentations), static_cast<unsigned long long>(s.objects));
    std::printf("MOTP is the mean %s of matches.\n", by_iou ? "1 - IoU" : "distance");
    if (!args.json.empty()) {
      // The mot_evaluator's keys (kestrel/algorithms/mot_metrics.hpp), so that files and runs
      // compare key by key. MOTP is in metres only when points are matched by distance.
      nlohmann::json j = algorithms::mot_summary_json(s);
      nlohmann::json meta = algorithms::mot_summary_meta("");
      if (by_iou) {
        j.erase("motp_m");
        meta.erase("motp_m");
      }
      j["motp"] = s.motp;  // the matching's own measure: 1 - IoU, or metres
      meta["motp"] = {{"unit", by_iou ? "" : "m"}, {"higher_is_better", false}};
      // The names this command used before, kept for a release (CHANGELOG.md).
      j["mt"] = s.mostly_tracked;
      j["pt"] = s.partially_tracked;
      j["ml"] = s.mostly_lost;
      j["frag"] = s.fragmentations;
      j["metrics_meta"] = meta;
      write_file(args.json, j.dump(2) + "\n");
    }
    return kOk;
  });
}

}  // namespace kestrel::cli
