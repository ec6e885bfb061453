// The `ocams_imu` node: the oCamS's inertial sensor on its serial port, as kestrel Imu messages
// stamped on the run clock. Bad lines are counted in the report, not fatal; an unplugged port is
// reopened when it returns (docs/hardware.md).
#include <fmt/format.h>

#include <kestrel/plugin.hpp>

#include "imu_stream.hpp"

namespace kestrel::ocams {

struct OcamsImuConfig {
  std::string port = "/dev/ttyACM0";
  std::int64_t baud = 115200;
  std::string format = "AMGQUA";
  std::string frame = "ocams_imu";
  double poll_rate_hz = 200.0;
  double silence_timeout_s = 1.0;
  bool reconnect = true;
};

class OcamsImuNode final : public Node {
 public:
  static constexpr Output<msg::Imu> kImu{"imu"};

  static NodeSpec spec() {
    using C = OcamsImuConfig;
    ConfigSpec<C> c;
    c.param("port", &C::port).describe("serial port of the IMU (a CDC-ACM device, or its udev name)");
    c.param("baud", &C::baud).describe("baud rate: 115200 for the oCamS");
    c.param("format", &C::format)
        .one_of({"AMGQUA", "AMGEUL", "LMGQUA", "LMGEUL", "QUATIMU"})
        .describe(
            "output asked for: AMG with gravity, LMG without it, QUA quaternion, EUL Euler angles (the oCamS's); "
            "QUATIMU for a myAHRS+ board");
    c.param("frame", &C::frame).describe("frame_id of the measurements");
    c.param("poll_rate_hz", &C::poll_rate_hz)
        .with_unit("Hz")
        .range(10.0, 2000.0)
        .describe("how often the port is read; samples that arrived since are published, each with its own stamp");
    c.param("silence_timeout_s", &C::silence_timeout_s)
        .with_unit("s")
        .range(0.05, 60.0)
        .describe("a port silent this long is reopened (reconnect) or stops the run");
    c.param("reconnect", &C::reconnect).describe("reopen the port when it hangs up or falls silent");
    return NodeSpec("ocams_imu", "The oCamS-1CGN-U's IMU on its serial port")
        .details(
            "Opens the port (termios, raw 8N1), asks for the format and parses each line: the oCamS's BNO055 integers "
            "scaled to SI units, or a myAHRS+ board's checksummed lines. Publishes orientation, angular rate, "
            "acceleration and magnetic field with the device's clock mapped onto the run's.")
        .needs_executor(ExecutorNeed::realtime, "it reads a real device")
        .output(kImu, "inertial measurements")
        .config(std::move(c));
  }

  explicit OcamsImuNode(NodeInit& init) : cfg_(init.config<OcamsImuConfig>()) {
    ImuStreamOptions o;
    o.port = cfg_.port;
    o.baud = static_cast<int>(cfg_.baud);
    o.format = cfg_.format;
    o.frame = cfg_.frame;
    o.silence_timeout = std::chrono::milliseconds(static_cast<int>(cfg_.silence_timeout_s * 1000));
    o.reconnect = cfg_.reconnect;
    stream_ = std::make_unique<ImuStream>(o, [this] { return ctx_ ? ctx_->now() : Time(0); });
    wait_ = std::chrono::milliseconds(std::max(1, static_cast<int>(1000.0 / cfg_.poll_rate_hz)));
    init.set_rate(cfg_.poll_rate_hz);
  }

  void tick(Context& ctx) override {
    ctx_ = &ctx;
    for (auto& m : stream_->read(wait_)) ctx.publish(kImu, std::move(m));
  }

  void finish(Context& ctx) override {
    const ImuCounters& k = stream_->counters();
    ctx.set_report_section(
        ctx.id(), ReportSection()
                      .info("port", cfg_.port)
                      .info("format", cfg_.format)
                      .quantity("samples", k.samples)
                      .metric("bad_lines", k.bad_lines, "lines", Better::lower)
                      .info("last_bad_line", k.last_bad_line)
                      .quantity("replies", k.replies)
                      .metric("error_replies", k.error_replies, "", Better::lower)
                      .metric("hangups", k.hangups, "", Better::lower)
                      .metric("silences", k.silences, "", Better::lower)
                      .quantity("reconnects", k.reconnects)
                      .markdown(fmt::format("{} IMU samples from {}, {} bad line(s), {} reconnect(s).\n", k.samples,
                                            cfg_.port, k.bad_lines, k.reconnects)));
  }

 private:
  OcamsImuConfig cfg_;
  std::unique_ptr<ImuStream> stream_;
  std::chrono::milliseconds wait_{5};
  Context* ctx_ = nullptr;
};
KESTREL_REGISTER_NODE(OcamsImuNode)

}  // namespace kestrel::ocams
