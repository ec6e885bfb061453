#include "kestrel/vehicle/wind.hpp"

#include <cmath>

namespace kestrel::vehicle {

Wind::Wind(Eigen::Vector3d mean_m_s, double gust_std_m_s, double gust_time_constant_s, std::uint64_t seed)
    : mean_(std::move(mean_m_s)), std_(gust_std_m_s), time_constant_(gust_time_constant_s), random_(seed) {
  if (std_ > 0.0)  // start in the stationary distribution, not calm
    for (int i = 0; i < 3; ++i) gust_(i) = std_ * normal_(random_);
}

Eigen::Vector3d Wind::advance(double dt) {
  if (std_ > 0.0) {
    const double decay = std::exp(-dt / time_constant_);
    const double spread = std_ * std::sqrt(1.0 - decay * decay);
    for (int i = 0; i < 3; ++i) gust_(i) = decay * gust_(i) + spread * normal_(random_);
  }
  return current();
}

}  // namespace kestrel::vehicle
