#include "io/yaml_tree.h"

#include <yaml-cpp/yaml.h>

#include <sstream>

#include "core/input_error.h"

namespace swingsim {

struct YamlTree::Node {
  YAML::Node node;
};

YamlTree::YamlTree() : node_(std::make_shared<Node>()) {}
YamlTree::YamlTree(std::shared_ptr<Node> node) : node_(std::move(node)) {}

namespace {

YamlTree::Kind kindOf(const YAML::Node& n) {
  if (n.IsMap()) return YamlTree::Kind::kMap;
  if (n.IsSequence()) return YamlTree::Kind::kList;
  if (n.IsScalar()) return YamlTree::Kind::kScalar;
  return YamlTree::Kind::kNull;
}

}  // namespace

YamlTree YamlTree::parse(const std::string& text, const std::string& key, const std::string& what) {
  try {
    return YamlTree(std::make_shared<Node>(Node{YAML::Load(text)}));
  } catch (const YAML::Exception& e) {
    throw InputError(key + ": expected " + what + " in YAML (got a YAML error: " + e.msg + ")");
  }
}

YamlTree::Kind YamlTree::kind() const { return node_->node ? kindOf(node_->node) : Kind::kNull; }

std::string YamlTree::scalar() const { return isScalar() ? node_->node.Scalar() : std::string(); }

bool YamlTree::isQuoted() const { return isScalar() && node_->node.Tag() == "!"; }

std::optional<double> YamlTree::number() const {
  if (!isScalar()) return std::nullopt;
  try {
    return node_->node.as<double>();
  } catch (const YAML::Exception&) {
    return std::nullopt;
  }
}

YamlTree YamlTree::get(const std::string& key) const {
  if (!isMap()) return YamlTree();
  const YAML::Node& map = node_->node;
  const YAML::Node child = map[key];
  return child ? YamlTree(std::make_shared<Node>(Node{child})) : YamlTree();
}

YamlTree YamlTree::find(const std::string& dottedKey) const {
  YamlTree node = *this;
  std::stringstream parts(dottedKey);
  std::string part;
  while (!node.isNull() && std::getline(parts, part, '.')) node = node.get(part);
  return node;
}

std::vector<std::pair<std::string, YamlTree>> YamlTree::entries() const {
  std::vector<std::pair<std::string, YamlTree>> out;
  if (!isMap()) return out;
  for (const auto& item : node_->node)
    out.emplace_back(item.first.as<std::string>(), YamlTree(std::make_shared<Node>(Node{item.second})));
  return out;
}

std::vector<YamlTree> YamlTree::items() const {
  std::vector<YamlTree> out;
  if (!isList()) return out;
  for (const auto& item : node_->node) out.push_back(YamlTree(std::make_shared<Node>(Node{item})));
  return out;
}

void YamlTree::set(const std::string& dottedKey, const std::string& value, const std::string& what) {
  YAML::Node node = node_->node;
  std::stringstream parts(dottedKey);
  std::string part;
  while (std::getline(parts, part, '.')) {
    if (!node.IsDefined() || node.IsNull()) node = YAML::Node(YAML::NodeType::Map);  // a map not yet written
    if (!node.IsMap()) throw InputError(dottedKey + ": expected a map above '" + part + "' in " + what);
    YAML::Node next = node[part];
    node.reset(next);
  }
  node = value;
}

std::string YamlTree::emit() const {
  YAML::Emitter out;
  out << node_->node;
  return out.c_str();
}

struct YamlWriter::Emitter {
  YAML::Emitter out;
};

YamlWriter::YamlWriter() : out_(std::make_unique<Emitter>()) {}
YamlWriter::~YamlWriter() = default;
void YamlWriter::beginMap() { out_->out << YAML::BeginMap; }
void YamlWriter::key(const std::string& key) { out_->out << YAML::Key << key << YAML::Value; }
void YamlWriter::endMap() { out_->out << YAML::EndMap; }
void YamlWriter::beginList() { out_->out << YAML::Flow << YAML::BeginSeq; }
void YamlWriter::endList() { out_->out << YAML::EndSeq; }
void YamlWriter::plain(const std::string& text) { out_->out << text; }
void YamlWriter::quoted(const std::string& text) { out_->out << YAML::DoubleQuoted << text; }
void YamlWriter::null() { out_->out << YAML::Null; }
std::string YamlWriter::text() const { return out_->out.c_str(); }

}  // namespace swingsim
