#include <fstream>
#include <sstream>

#include "graph_source.hpp"

namespace kestrel {

GraphSource::GraphSource(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GraphSource::~GraphSource() = default;
GraphSource::GraphSource(GraphSource&&) noexcept = default;
GraphSource& GraphSource::operator=(GraphSource&&) noexcept = default;

namespace {
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
}  // namespace

GraphSource GraphSource::from_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) {
    auto impl = std::make_unique<Impl>();
    impl->label = file.string();
    impl->file = file;
    impl->read_errors.error(SourceLocation{file.string(), 0, 0},
                            std::filesystem::exists(file) ? "cannot read the graph file" : "no such graph file");
    return GraphSource(std::move(impl));
  }
  std::stringstream text;
  text << in.rdbuf();
  return GraphSource(parse(text.str(), file.string(), file));
}

GraphSource GraphSource::from_string(const std::string& yaml, const std::string& label) {
  return GraphSource(parse(yaml, label, {}));
}

std::vector<std::filesystem::path> GraphSource::plugin_paths() const {
  std::vector<std::filesystem::path> paths;
  if (!impl_->root.IsMap()) return paths;
  const YAML::Node& root = impl_->root;  // const access: operator[] must not add the key
  const YAML::Node list = root["plugin_paths"];
  if (!list || !list.IsSequence()) return paths;
  const std::filesystem::path base = impl_->file.empty() ? std::filesystem::current_path()
                                                         : std::filesystem::absolute(impl_->file).parent_path();
  for (const auto& entry : list) {
    if (!entry.IsScalar()) continue;
    std::filesystem::path p = entry.Scalar();
    paths.push_back(p.is_absolute() ? p : (base / p).lexically_normal());
  }
  return paths;
}

const Diagnostics& GraphSource::read_errors() const { return impl_->read_errors; }
const std::string& GraphSource::label() const { return impl_->label; }

}  // namespace kestrel
