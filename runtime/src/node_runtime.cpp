#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "graph_record.hpp"
#include "run_state.hpp"
#include "seeds.hpp"

namespace kestrel {

void Node::process(Context&) { throw Error("this node type has a triggering input but does not implement process()"); }
void Node::tick(Context&) {}
void Node::finish(Context&) {}

void NodeInit::set_rate(double hz) {
  if (!(hz > 0.0) || !std::isfinite(hz)) throw Error("node '" + id() + "': a timer rate must be positive");
  tick_interval_ns_ = 1e9 / hz;
}

void NodeInit::set_period(Duration period) {
  if (period <= Duration::zero()) throw Error("node '" + id() + "': a timer period must be positive");
  tick_interval_ns_ = static_cast<double>(period.count());
}

namespace detail {

std::uint64_t derive_seed(std::uint64_t seed, std::string_view name) { return component_seed(seed, name); }

std::shared_ptr<void> make_component(const Registry& registry, const std::string& owner, const ParamSet& owner_spec,
                                     const Params& owner_params, const std::string& param_name, std::string_view kind,
                                     std::uint64_t owner_seed, Logger& log) {
  const ParamSpec* spec = owner_spec.find(param_name);
  if (!spec || spec->type != ParamType::component)
    throw Error("'" + owner + "': '" + param_name + "' is not a component parameter in spec()");
  if (spec->component_kind != kind)
    throw Error("'" + owner + "': parameter '" + param_name + "' holds a " + spec->component_kind + ", not a " +
                std::string(kind));
  const auto config = owner_params.get<ComponentConfig>(param_name);
  const ComponentType* type = registry.find_component(kind, config.type);
  if (!type) throw Error("'" + owner + "': no " + std::string(kind) + " named '" + config.type + "'");
  static const Params kNoParams;
  const ComponentInit init(owner + "." + param_name, type->spec.param_set(), config.params ? *config.params : kNoParams,
                           registry, derive_seed(owner_seed, param_name), log);
  return type->factory(init);
}

}  // namespace detail

const Envelope& Context::envelope(std::string_view input) const {
  // A tap input has a slot per connection: the one that triggered this call comes first.
  if (rt_.current_trigger >= 0) {
    const detail::InputSlot& triggered = rt_.inputs[static_cast<std::size_t>(rt_.current_trigger)];
    if (triggered.spec->name == input) return triggered.current;
  }
  for (auto& slot : rt_.inputs)
    if (slot.spec->name == input) return slot.current;
  throw Error("node '" + rt_.id() + "' has no input named '" + std::string(input) + "'");
}

std::string_view Context::trigger() const {
  if (rt_.current_trigger < 0) return {};
  return rt_.inputs[static_cast<std::size_t>(rt_.current_trigger)].spec->name;
}

void Context::publish_erased(std::string_view output, std::shared_ptr<const void> payload, std::string_view type,
                             std::optional<Time> captured) {
  rt_.publish(output, std::move(payload), type, captured);
}

Time Context::now() const { return rt_.run->executor->now(); }
const std::string& Context::id() const { return rt_.id(); }
Logger& Context::log() { return *rt_.logger; }
std::mt19937_64& Context::rng() { return rt_.rng; }
namespace {
// The namespace of a node in a part ("front/" for "front/depth"; "" for a node of the graph's own):
// what it reports and the files it writes take it, so that a part included twice reports twice.
std::string node_namespace(const std::string& id) {
  const auto slash = id.rfind('/');
  return slash == std::string::npos ? std::string() : id.substr(0, slash + 1);
}
}  // namespace

void Context::set_report_section(const std::string& key, const ReportSection& section) {
  const std::string ns = node_namespace(rt_.id());
  // A node that reports under its own id (already namespaced) keeps it.
  rt_.run->report.set_section(rt_.id(), key.starts_with(ns) ? key : ns + key, section);
}
nlohmann::json Context::run_description() const { return detail::run_description(rt_.run->graph, rt_.run->options); }
bool Context::keeps_artifacts() const { return rt_.run->report.keeps_artifacts(); }
void Context::add_artifact(const std::string& file_name, std::string_view bytes, std::string caption) {
  std::string prefix = node_namespace(rt_.id());
  std::replace(prefix.begin(), prefix.end(), '/', '-');
  rt_.run->report.add_artifact(rt_.id(), prefix + file_name, bytes, std::move(caption));
}
void Context::end_of_stream() { rt_.source_ended = true; }
void Context::request_stop() { rt_.run->stop_requested = true; }
void Context::end_run(std::string_view why) { rt_.run->end_run(rt_.id(), why); }

namespace detail {

void Edge::count_delivery() {
  ++delivered;
  to->messages_in.fetch_add(1, std::memory_order_relaxed);
}

void Edge::push(const Envelope& envelope) {
  queue.push_back(envelope);
  high_water = std::max(high_water, queue.size());
  count_delivery();
}

void Edge::drop_queued() {
  dropped += queue.size();
  queue.clear();
}

bool NodeRuntime::has_triggering_input() const {
  for (const auto& slot : inputs)
    if (slot.edge && slot.triggers()) return true;
  return false;
}

bool NodeRuntime::call(Call what) {
  Context ctx(*this);
  const auto start = std::chrono::steady_clock::now();
  bool ok = true;
  try {
    switch (what) {
      case Call::process:
        node->process(ctx);
        break;
      case Call::tick:
        node->tick(ctx);
        break;
      case Call::finish:
        node->finish(ctx);
        break;
    }
  } catch (const std::exception& e) {
    ok = false;
    run->node_error(*this, e.what());
  } catch (...) {
    ok = false;
    run->node_error(*this, "unknown exception");
  }
  if (what != Call::finish) {
    processing.record(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count());
    calls.fetch_add(1, std::memory_order_relaxed);
  }
  return ok;
}

int NodeRuntime::oldest_waiting_input() const {
  int next = -1;
  std::uint64_t oldest = std::numeric_limits<std::uint64_t>::max();
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const Edge* e = inputs[i].edge;
    if (e && inputs[i].triggers() && !e->queue.empty() && e->queue.front().sequence < oldest) {
      oldest = e->queue.front().sequence;
      next = static_cast<int>(i);
    }
  }
  return next;
}

void NodeRuntime::take_message(int input) {
  InputSlot& slot = inputs[static_cast<std::size_t>(input)];
  slot.current = std::move(slot.edge->queue.front());
  slot.edge->queue.pop_front();
  current_trigger = input;
}

bool NodeRuntime::process_taken() {
  const bool ok = call(Call::process);
  current_trigger = -1;
  return ok;
}

void NodeRuntime::run_tick() {
  call(Call::tick);
  ++ticks;
}

void NodeRuntime::publish(std::string_view output, std::shared_ptr<const void> payload, std::string_view type,
                          std::optional<Time> captured) {
  const int index = config->type->spec.output_index(output);
  if (index < 0) throw Error("published on '" + std::string(output) + "', which is not an output of " + this->type());
  const PortSpec& port = config->type->spec.outputs()[static_cast<std::size_t>(index)];
  if (port.type() != type)
    throw Error("published a " + std::string(type) + " on output '" + port.name + "', declared as " + port.type());
  if (!payload) throw Error("published a null message on output '" + port.name + "'");
  const Envelope envelope{
      std::move(payload), type, run->executor->now(), run->next_sequence.fetch_add(1, std::memory_order_relaxed), id(),
      port.name};
  if (captured && *captured <= envelope.published_at) latency.record((envelope.published_at - *captured).count());
  messages_out.fetch_add(1, std::memory_order_relaxed);
  for (Edge* edge : outputs[static_cast<std::size_t>(index)]) run->executor->deliver(*edge, envelope);
}

RunState::RunState(const GraphConfig& g, const Registry& r, const RunOptions& o) : graph(g), registry(r), options(o) {}

bool RunState::instantiate() {
  const std::uint64_t seed = options.seed.value_or(graph.seed);
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const NodeConfig& config = graph.nodes[i];
    auto rt = std::make_unique<NodeRuntime>();
    rt->index = static_cast<int>(i);
    rt->config = &config;
    rt->run = this;
    rt->logger = std::make_unique<Logger>(config.id);
    rt->rng.seed(node_seed(seed, config.id));
    const NodeSpec& spec = config.type->spec;
    for (const auto& port : spec.inputs()) {
      InputSlot slot;
      slot.spec = &port;
      rt->inputs.push_back(std::move(slot));
    }
    rt->outputs.resize(spec.outputs().size());
    nodes.push_back(std::move(rt));
  }
  for (const auto& c : graph.connections) {
    auto edge = std::make_unique<Edge>();
    edge->config = &c;
    edge->from = nodes[static_cast<std::size_t>(c.from_node)].get();
    edge->to = nodes[static_cast<std::size_t>(c.to_node)].get();
    edge->to_port = c.to_port;
    // An input has one connection, except a tap, which gets a slot of its own per connection.
    edge->to_slot = c.to_port;
    if (edge->to->inputs[static_cast<std::size_t>(c.to_port)].edge) {
      InputSlot extra;
      extra.spec = edge->to->inputs[static_cast<std::size_t>(c.to_port)].spec;
      edge->to_slot = static_cast<int>(edge->to->inputs.size());
      edge->to->inputs.push_back(std::move(extra));
    }
    edge->to->inputs[static_cast<std::size_t>(edge->to_slot)].edge = edge.get();
    edge->from->outputs[static_cast<std::size_t>(c.from_port)].push_back(edge.get());
    edges.push_back(std::move(edge));
  }
  for (int i : graph.topological_order) order.push_back(nodes[static_cast<std::size_t>(i)].get());

  bool ok = true;
  for (auto& rt : nodes) {
    NodeInit init(rt->id(), rt->config->type->spec, rt->config->params, registry, node_seed(seed, rt->id()),
                  *rt->logger, graph.executor == ExecutorKind::realtime);
    const ExecutorNeed need = rt->config->type->spec.executor_need();
    if (need != ExecutorNeed::any && (need == ExecutorNeed::realtime) != (graph.executor == ExecutorKind::realtime)) {
      // build_graph() refuses such a graph; a host that changed the executor afterwards lands here.
      ok = false;
      node_error(*rt, fmt::format("could not start: it needs the {} executor ({})",
                                  need == ExecutorNeed::realtime ? "realtime" : "lockstep",
                                  rt->config->type->spec.executor_reason()));
      continue;
    }
    try {
      rt->node = rt->config->type->factory(init);
      rt->tick_interval_ns = init.tick_interval_ns();
    } catch (const std::exception& e) {
      ok = false;
      node_error(*rt, std::string("could not start: ") + e.what());
    }
  }
  return ok;
}

std::optional<double> RunState::duration_s() const {
  return options.duration_s ? options.duration_s : graph.duration_s;
}

bool RunState::all_sources_ended() const {
  for (const auto& node : nodes)
    if (node->has_timer() && !node->source_ended) return false;
  return true;
}

void RunState::announce_when_running() {
  if (announced_) return;
  for (const auto& node : nodes)
    if (node->has_timer() && node->calls.load() == 0 && !node->source_ended) return;
  announced_ = true;
  if (options.on_running) options.on_running();
}

bool RunState::stopping() const {
  return stop_requested.load() || end_requested.load() || failed.load() ||
         (options.stop_flag != nullptr && options.stop_flag->load());
}

void RunState::end_run(const std::string& node, std::string_view why) {
  std::lock_guard lock(ended_by_mutex_);
  if (!ended_by_.is_null()) return;
  ended_by_ = {{"node", node}, {"why", std::string(why)}};
  end_requested = true;
}

nlohmann::json RunState::ended_by() const {
  std::lock_guard lock(ended_by_mutex_);
  return ended_by_;
}

void RunState::node_error(NodeRuntime& node, const std::string& what) {
  node.errors.fetch_add(1, std::memory_order_relaxed);
  const std::string message = "node '" + node.id() + "' (" + node.type() + "): " + what;
  {
    std::lock_guard lock(errors_mutex_);
    // Keep the first errors whole; a node failing on every message must not grow memory.
    if (errors_.size() < 100) errors_.push_back(message);
  }
  if (graph.on_error == ErrorPolicy::stop || !node.node) {
    failed = true;
    node.logger->error("{}", what);
  } else if (node.errors.load() <= 10) {
    node.logger->warn("{} (message dropped; on_error: skip){}", what,
                      node.errors.load() == 10 ? " - further errors of this node are counted, not logged" : "");
  }
}

std::vector<std::string> RunState::errors() const {
  std::lock_guard lock(errors_mutex_);
  return errors_;
}

}  // namespace detail
}  // namespace kestrel
