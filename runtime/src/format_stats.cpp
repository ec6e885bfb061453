#include <fmt/format.h>

#include "kestrel/runtime/run.hpp"

namespace kestrel {

std::string format_stats(const RunResult& result) {
  std::size_t id_width = 4, type_width = 4, label_width = 10;
  for (const auto& n : result.nodes) {
    id_width = std::max(id_width, n.id.size());
    type_width = std::max(type_width, n.type.size());
  }
  for (const auto& c : result.connections) label_width = std::max(label_width, c.label.size() + (c.delayed ? 10 : 0));

  // Latency: from the capture stamp of what a node publishes to its publication (docs/architecture.md).
  std::string out = fmt::format("{:<{}}  {:<{}}  {:>9}  {:>9}  {:>7}  {:>6}  {:>10}  {:>10}  {:>10}  {:>11}  {:>11}\n",
                                "node", id_width, "type", type_width, "in", "out", "drops", "errors", "p50 µs",
                                "p99 µs", "max µs", "age p50 ms", "age p99 ms");
  const auto latency = [](const DurationHistogram& h, double q) {
    return h.count() ? fmt::format("{:.1f}", static_cast<double>(h.quantile(q)) / 1e6) : std::string("-");
  };
  for (const auto& n : result.nodes) {
    out += fmt::format("{:<{}}  {:<{}}  {:>9}  {:>9}  {:>7}  {:>6}  {:>10.1f}  {:>10.1f}  {:>10.1f}  {:>11}  {:>11}\n",
                       n.id, id_width, n.type, type_width, n.messages_in, n.messages_out, n.drops, n.errors,
                       n.processing.quantile(0.5) / 1e3, n.processing.quantile(0.99) / 1e3, n.processing.max() / 1e3,
                       latency(n.latency, 0.5), latency(n.latency, 0.99));
  }
  out += fmt::format("\n{:<{}}  {:<9}  {:>9}  {:>7}  {:>10}\n", "connection", label_width, "policy", "delivered",
                     "drops", "high-water");
  for (const auto& c : result.connections) {
    out += fmt::format("{:<{}}  {:<9}  {:>9}  {:>7}  {:>10}\n", c.label + (c.delayed ? " (delayed)" : ""), label_width,
                       c.policy, c.delivered, c.drops, c.high_water);
  }
  return out;
}

}  // namespace kestrel
