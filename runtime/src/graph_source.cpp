#include "graph_source.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "yaml_checks.hpp"

namespace kestrel {

GraphSource::GraphSource(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GraphSource::~GraphSource() = default;
GraphSource::GraphSource(GraphSource&&) noexcept = default;
GraphSource& GraphSource::operator=(GraphSource&&) noexcept = default;

std::filesystem::path GraphSource::Impl::folder() const {
  return file.empty() ? std::filesystem::current_path() : std::filesystem::absolute(file).parent_path();
}

namespace {

// Includes deeper than this are taken for a runaway chain even without a repeated file.
constexpr std::size_t kMaxIncludeDepth = 16;

std::unique_ptr<GraphSource::Impl> parse(const std::string& text, std::string label, std::filesystem::path file) {
  auto impl = std::make_unique<GraphSource::Impl>();
  impl->label = std::move(label);
  impl->file = std::move(file);
  try {
    impl->root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    impl->read_errors.error(impl->at(e.mark), "YAML syntax error: " + e.msg);
  } catch (const YAML::Exception& e) {
    impl->read_errors.error(impl->at(e.mark), "cannot read YAML: " + e.msg);
  }
  return impl;
}

std::unique_ptr<GraphSource::Impl> read_file(const std::filesystem::path& file, const std::string& label) {
  std::ifstream in(file);
  if (!in) {
    auto impl = std::make_unique<GraphSource::Impl>();
    impl->label = label;
    impl->file = file;
    // The error_code forms: a name the file system refuses (too long, say) is a diagnostic too.
    std::error_code ec;
    const bool exists = std::filesystem::exists(file, ec);
    impl->read_errors.error(SourceLocation{label, 0, 0}, ec       ? "cannot read the graph file: " + ec.message()
                                                         : exists ? "cannot read the graph file"
                                                                  : "no such graph file");
    return impl;
  }
  std::stringstream text;
  text << in.rdbuf();
  return parse(text.str(), label, file);
}

// Reads the files `impl` includes, and theirs. `chain` holds the files being read, outermost
// first, to refuse a file that includes itself.
void read_includes(GraphSource::Impl& impl, std::vector<std::filesystem::path>& chain) {
  if (!impl.root.IsMap()) return;
  const YAML::Node& root = impl.root;  // const access: operator[] must not add the key
  const YAML::Node list = root["include"];
  if (!list) return;
  if (!list.IsSequence()) {
    impl.read_errors.error(impl.at(list), "'include' must be a list of graph files");
    return;
  }
  for (const auto& entry : list) {
    // Never assign to a YAML::Node: it would write through to the document. Fresh handles only.
    const bool is_part = entry.IsMap() && entry["part"];
    const YAML::Node file_node = !entry.IsMap() ? entry : is_part ? entry["part"] : entry["file"];
    const YAML::Node set = entry.IsMap() && !is_part ? entry["set"] : YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node args = is_part ? entry["args"] : YAML::Node(YAML::NodeType::Undefined);
    std::string as;
    if (entry.IsMap()) {
      const std::vector<std::string> keys =
          is_part ? std::vector<std::string>{"part", "as", "args"} : std::vector<std::string>{"file", "set"};
      for (auto it = entry.begin(); it != entry.end(); ++it)
        if (std::find(keys.begin(), keys.end(), it->first.Scalar()) == keys.end())
          impl.read_errors.error(impl.at(it->first),
                                 "unknown key '" + it->first.Scalar() +
                                     "' in an include; keys: " + (is_part ? "part, as, args" : "file, set") +
                                     " (a file's nodes join the graph's; a part's take a namespace)");
      if (!file_node) {
        impl.read_errors.error(impl.at(entry),
                               "an include needs 'file' (nodes that join the graph's) or 'part' (with 'as')");
        continue;
      }
      if (set && !set.IsMap()) {
        impl.read_errors.error(impl.at(set), "an include's 'set' must be a map of node.param: value");
        continue;
      }
      if (is_part) {
        const YAML::Node as_node = entry["as"];
        if (!as_node || !as_node.IsScalar() || !valid_node_id(as_node.Scalar())) {
          impl.read_errors.error(impl.at(as_node ? as_node : entry),
                                 "a part's include needs 'as': its namespace, a name that starts with a letter or '_' "
                                 "and holds only letters, digits, '_' and '-'");
          continue;
        }
        as = as_node.Scalar();
        if (args && !args.IsMap()) {
          impl.read_errors.error(impl.at(args), "a part's 'args' must be a map of name: value");
          continue;
        }
        // A part is found beside or below the file that includes it.
        if (file_node.IsScalar()) {
          const std::filesystem::path relative = file_node.Scalar();
          if (relative.is_absolute() ||
              std::any_of(relative.begin(), relative.end(), [](const auto& piece) { return piece == ".."; })) {
            impl.read_errors.error(impl.at(file_node),
                                   "a part is included from the includer's folder or below it, not '" +
                                       file_node.Scalar() + "' (no absolute path, no '..')");
            continue;
          }
        }
      }
    }
    if (!file_node.IsScalar() || file_node.Scalar().empty()) {
      impl.read_errors.error(
          impl.at(file_node),
          "an include is a graph file name, or a map with 'file' and 'set', or 'part', 'as' and 'args'");
      continue;
    }
    std::filesystem::path path = file_node.Scalar();
    if (path.is_relative()) path = (impl.folder() / path).lexically_normal();
    std::error_code ec;
    const auto canonical = std::filesystem::weakly_canonical(path, ec);
    if (ec) {
      impl.read_errors.error(impl.at(file_node),
                             "cannot read included graph file '" + path.string() + "': " + ec.message());
      continue;
    }
    if (std::find(chain.begin(), chain.end(), canonical) != chain.end() || chain.size() >= kMaxIncludeDepth) {
      impl.read_errors.error(impl.at(file_node),
                             "'" + file_node.Scalar() + "' is already being included: an include cycle");
      continue;
    }
    const auto status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) {
      impl.read_errors.error(impl.at(file_node), "included graph file '" + path.string() + "' does not exist");
      continue;
    }
    if (ec) {
      impl.read_errors.error(impl.at(file_node),
                             "cannot read included graph file '" + path.string() + "': " + ec.message());
      continue;
    }
    // A device, a pipe or a folder is no graph, and reading /dev/zero or a FIFO would never end.
    if (!std::filesystem::is_regular_file(status)) {
      impl.read_errors.error(impl.at(file_node), "included graph file '" + path.string() + "' is not a regular file");
      continue;
    }
    auto child = read_file(path, path.string());
    chain.push_back(canonical);
    read_includes(*child, chain);
    chain.pop_back();
    impl.read_errors.append(child->read_errors);  // the outermost file holds every reading error
    impl.includes.push_back({std::move(child), set, entry, as, args});
  }
}

void read_includes(GraphSource::Impl& impl) {
  std::vector<std::filesystem::path> chain;
  std::error_code ec;  // a file that cannot be resolved has already been reported by read_file()
  if (!impl.file.empty()) chain.push_back(std::filesystem::weakly_canonical(impl.file, ec));
  read_includes(impl, chain);
}

void collect_plugin_paths(const GraphSource::Impl& impl, std::vector<std::filesystem::path>& paths) {
  for (const auto& include : impl.includes) collect_plugin_paths(*include.source, paths);
  if (!impl.root.IsMap()) return;
  const YAML::Node& root = impl.root;
  const YAML::Node list = root["plugin_paths"];
  if (!list || !list.IsSequence()) return;
  for (const auto& entry : list) {
    if (!entry.IsScalar()) continue;
    std::filesystem::path p = entry.Scalar();
    p = p.is_absolute() ? p : (impl.folder() / p).lexically_normal();
    if (std::find(paths.begin(), paths.end(), p) == paths.end()) paths.push_back(p);
  }
}

}  // namespace

GraphSource GraphSource::from_file(const std::filesystem::path& file) {
  auto impl = read_file(file, file.string());
  read_includes(*impl);
  return GraphSource(std::move(impl));
}

GraphSource GraphSource::from_string(const std::string& yaml, const std::string& label) {
  auto impl = parse(yaml, label, {});
  read_includes(*impl);
  return GraphSource(std::move(impl));
}

std::vector<std::filesystem::path> GraphSource::plugin_paths() const {
  std::vector<std::filesystem::path> paths;
  collect_plugin_paths(*impl_, paths);
  return paths;
}

const Diagnostics& GraphSource::read_errors() const { return impl_->read_errors; }
const std::string& GraphSource::label() const { return impl_->label; }

}  // namespace kestrel
