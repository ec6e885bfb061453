// Fire orders at chosen times, for the tests of what carries them to the launcher.
#include <kestrel/messages/net_fire.hpp>
#include <kestrel/plugin.hpp>

namespace kestrel::test {

class FireOrders final : public Node {
 public:
  static constexpr Output<msg::NetFire> kFire{"fire"};
  static NodeSpec spec() {
    return NodeSpec("fire_orders", "Publishes a fire order at first_s and another at second_s")
        .output(kFire, "the orders")
        .param(param("first_s", 0.5).with_unit("s").at_least(0.0).describe("time of the first order"))
        .param(param("second_s", 4.0).with_unit("s").at_least(0.0).describe("time of the second order"));
  }
  explicit FireOrders(NodeInit& init) : times_{init.param<double>("first_s"), init.param<double>("second_s")} {
    init.set_rate(50.0);
  }
  void tick(Context& ctx) override {
    const double now = to_seconds(ctx.now());
    for (std::size_t i = 0; i < times_.size(); ++i) {
      if (sent_[i] || now < times_[i]) continue;
      sent_[i] = true;
      msg::NetFire fire;
      fire.stamp = ctx.now();
      fire.target_id = i + 1;
      ctx.publish(kFire, std::move(fire));
    }
  }

 private:
  std::array<double, 2> times_;
  std::array<bool, 2> sent_{false, false};
};
KESTREL_REGISTER_NODE(FireOrders)

}  // namespace kestrel::test
