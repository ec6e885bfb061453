#pragma once
// Private: a part's interface, as its file declares it. A part is a graph file with `part:` at its
// top: nodes and connections a graph includes under a namespace of its own (`include: [{part:
// FILE, as: NAME, args: {...}}]`), reached from outside only through the ports it declares and
// configured only through its args (and `--set NAME/NODE.param`), as a Drake diagram exports its
// subsystems' ports or a GStreamer bin its ghost pads.
//
//   part: hunter_camera
//   description: the simulated stereo camera on the hunter, and the detections it gives
//   inputs:
//     pose: {to: camera.pose, description: the hunter's pose}
//   outputs:
//     detections: {from: clusters.detections}
//   args:
//     num_disparities: {default: 128, unit: px, description: the matcher's range, to: depth.num_disparities}
//
// A port binds one of its nodes' ports (an input may feed several: `to: [a.in, b.in]`), or a port
// of a part it includes in turn; an arg binds parameters of its nodes, or args of its parts.
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

#include "graph_source.hpp"
#include "yaml_checks.hpp"

namespace kestrel {

/// "node.port" or "node.param" as written in a part's declaration, and where.
struct PartBinding {
  std::string node, name;
  YAML::Node yaml;
};

struct PartPort {
  std::string name, type, description;  // type: the message type it declares ("" if none)
  std::vector<PartBinding> bindings;    // an output has one
  YAML::Node yaml;
};

struct PartArg {
  std::string name, unit, description;
  YAML::Node default_value{YAML::NodeType::Undefined};  // undefined: the arg must be given
  std::vector<PartBinding> bindings;
  YAML::Node yaml;
};

struct PartInterface {
  std::string name, description;
  std::vector<PartPort> inputs, outputs;
  std::vector<PartArg> args;

  const PartPort* input(const std::string& name) const;
  const PartPort* output(const std::string& name) const;
  const PartArg* arg(const std::string& name) const;
  /// "inputs: a, b; outputs: c" (or "none").
  std::string ports() const;
  std::vector<std::string> arg_names() const;
};

/// The top-level keys a part's file may hold.
const std::vector<std::string>& part_file_keys();

/// Whether `file` is a part (it has `part:` at its top).
bool is_part_file(const GraphSource::Impl& file);

/// Reads the interface `file` declares; each malformed declaration is an error in `yaml`'s file.
PartInterface read_part_interface(const GraphSource::Impl& file, YamlChecks& yaml);

}  // namespace kestrel
