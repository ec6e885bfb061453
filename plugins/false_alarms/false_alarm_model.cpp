#include "false_alarm_model.hpp"

#include "kestrel/error.hpp"

namespace kestrel::scenario {

FalseAlarmModel::FalseAlarmModel(double rate, FalseAlarmBox box) : rate_(rate), box_(box) {
  if (!(rate >= 0.0)) throw Error("the false-alarm rate must be zero or more");
  if ((box.max - box.min).minCoeff() < 0.0) throw Error("the false-alarm box's max must not be below its min");
}

std::vector<Eigen::Vector3d> FalseAlarmModel::draw(std::mt19937_64& rng) const {
  std::vector<Eigen::Vector3d> out;
  if (rate_ <= 0.0) return out;
  const auto count = std::poisson_distribution<int>(rate_)(rng);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < count; ++i) {
    // z first, in sequence: the order GCC evaluated the old call's arguments in, for every compiler.
    const double uz = unit(rng), uy = unit(rng), ux = unit(rng);
    const Eigen::Vector3d u(ux, uy, uz);
    out.push_back(box_.min + u.cwiseProduct(box_.max - box_.min));
  }
  return out;
}

}  // namespace kestrel::scenario
