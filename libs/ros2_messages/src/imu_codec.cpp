// kestrel.Imu: sensor_msgs/msg/Imu on /NODE/PORT and, when the sensor measures it,
// sensor_msgs/msg/MagneticField on /NODE/PORT/mag with the same stamp, as ROS 2 IMU drivers
// publish them. Covariances are unknown: 0, and -1 in the orientation's first element when there
// is no orientation, as sensor_msgs/Imu specifies. Whether gravity was removed, and whether a
// magnetic field follows, travel in the channels' metadata.
#include <kestrel/messages/imu.hpp>
#include <map>

#include "fields.hpp"

namespace kestrel::ros2::detail {

// Named, so that the codecs, which use the same names for their parts, can share a translation unit.
namespace imu {

enum Part : std::size_t { kImu, kMag };
const char* const kGravityRemoved = "kestrel.gravity_removed";
const char* const kMagnetometer = "kestrel.magnetic_field";

std::vector<ChannelSpec> channels(const std::string& topic) {
  std::string mag = topic;  // append: GCC 12 warns falsely of overlap on topic + "/mag" at -O3
  mag.append("/mag");
  return {{topic, "sensor_msgs/msg/Imu", false}, {std::move(mag), "sensor_msgs/msg/MagneticField", false, true}};
}

Encoded encode(const void* message, const std::string&) {
  const auto& m = *static_cast<const msg::Imu*>(message);
  CdrWriter w;
  write_header(w, m.stamp, m.frame);
  write_quaternion(w, m.orientation.value_or(Eigen::Quaterniond::Identity()));
  for (int i = 0; i < 9; ++i) w.f64(i == 0 && !m.orientation ? -1.0 : 0.0);
  write_xyz(w, m.angular_velocity);
  for (int i = 0; i < 9; ++i) w.f64(0.0);
  write_xyz(w, m.linear_acceleration);
  for (int i = 0; i < 9; ++i) w.f64(0.0);
  Encoded out;
  out.messages.push_back({kImu, w.take(), std::nullopt});
  if (m.magnetic_field) {
    CdrWriter mag;
    write_header(mag, m.stamp, m.frame);
    write_xyz(mag, *m.magnetic_field);
    for (int i = 0; i < 9; ++i) mag.f64(0.0);
    out.messages.push_back({kMag, mag.take(), std::nullopt});
  }
  out.metadata[kGravityRemoved] = std::to_string(int{m.gravity_removed});
  out.metadata[kMagnetometer] = std::to_string(int{m.magnetic_field.has_value()});
  return out;
}

class ImuDecoder final : public Decoder {
 public:
  std::vector<ChannelSpec> inputs() const override { return channels(""); }
  std::shared_ptr<const void> feed(std::size_t input, std::span<const std::uint8_t> cdr, std::uint32_t,
                                   const ChannelMetadata& metadata) override {
    CdrReader r(cdr);
    if (input == kImu) {
      auto m = std::make_shared<msg::Imu>();
      const Header h = read_header(r);
      m->stamp = h.stamp;
      m->frame = h.frame_id;
      const Eigen::Quaterniond q = read_quaternion(r);
      const double first_covariance = r.f64();
      for (int i = 1; i < 9; ++i) r.f64();
      if (first_covariance != -1.0) m->orientation = q;
      m->angular_velocity = read_xyz(r);
      for (int i = 0; i < 9; ++i) r.f64();
      m->linear_acceleration = read_xyz(r);
      for (int i = 0; i < 9; ++i) r.f64();
      expect_end(r, "sensor_msgs/msg/Imu");
      m->gravity_removed = flag(metadata, kGravityRemoved);
      // Another driver's bag says nothing of a magnetometer: its Imu messages stand alone.
      if (!flag(metadata, kMagnetometer)) return m;
      return pair(m->stamp, [&](Pending& p) { p.imu = m; });
    }
    if (input != kMag) throw Error("an IMU message has no input " + std::to_string(input));
    const Header h = read_header(r);
    const Eigen::Vector3d field = read_xyz(r);
    for (int i = 0; i < 9; ++i) r.f64();
    expect_end(r, "sensor_msgs/msg/MagneticField");
    return pair(h.stamp, [&](Pending& p) { p.field = field; });
  }
  std::uint64_t unpaired() const override { return dropped_ + pending_.size(); }

 private:
  struct Pending {
    std::shared_ptr<msg::Imu> imu;
    std::optional<Eigen::Vector3d> field;
  };
  static bool flag(const ChannelMetadata& metadata, const char* key) {
    const auto it = metadata.find(key);
    return it != metadata.end() && it->second == "1";
  }
  template <class Fill>
  std::shared_ptr<const void> pair(Time stamp, Fill fill) {
    while (pending_.size() >= 16 && !pending_.count(stamp)) {  // an older part whose partner never came
      pending_.erase(pending_.begin());
      ++dropped_;
    }
    Pending& p = pending_[stamp];
    fill(p);
    if (!p.imu || !p.field) return nullptr;
    p.imu->magnetic_field = p.field;
    std::shared_ptr<const void> out = p.imu;
    pending_.erase(stamp);
    return out;
  }
  std::map<Time, Pending> pending_;
  std::uint64_t dropped_ = 0;
};

}  // namespace imu

TypeCodec imu_codec() {
  using namespace imu;
  return {MessageTraits<msg::Imu>::name, channels, encode,
          [] { return std::unique_ptr<Decoder>(std::make_unique<ImuDecoder>()); }};
}

}  // namespace kestrel::ros2::detail
