// Nodes that need one executor: a stand-in for a real device (realtime) and for a node whose
// results only mean something step by step (lockstep). They count what they receive.
#include <kestrel/plugin.hpp>

#include "test_messages.hpp"

namespace kestrel::test {

template <ExecutorNeed kNeed>
class NeedsExecutor final : public Node {
 public:
  static constexpr Input<Number> kIn{"in"};
  static NodeSpec spec() {
    const bool realtime = kNeed == ExecutorNeed::realtime;
    return NodeSpec(realtime ? "realtime_only" : "lockstep_only",
                    realtime ? "Counts numbers; needs the realtime executor, as a device would"
                             : "Counts numbers; needs the lockstep executor")
        .needs_executor(kNeed, realtime ? "it stands for a real device" : "it checks a step-by-step result")
        .input(kIn, "numbers", {.trigger = Trigger::on_message, .optional = true});
  }
  explicit NeedsExecutor(NodeInit&) {}
  void process(Context&) override { ++count_; }
  void finish(Context& ctx) override { ctx.set_report_section(ctx.id(), ReportSection().quantity("count", count_)); }

 private:
  std::int64_t count_ = 0;
};

using RealtimeOnly = NeedsExecutor<ExecutorNeed::realtime>;
using LockstepOnly = NeedsExecutor<ExecutorNeed::lockstep>;
KESTREL_REGISTER_NODE(RealtimeOnly)
KESTREL_REGISTER_NODE(LockstepOnly)

}  // namespace kestrel::test
