#include "io/knee_model_knobs.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/input_error.h"
#include "io/knee_model_loader.h"

namespace swingsim {
namespace {

// One step of a key path: a map key, then list indices (`moment_Nm[3]` is moment_Nm, 3).
struct KeyStep {
  std::string key;
  std::vector<std::size_t> indices;
};

std::vector<KeyStep> parseKeyPath(const std::string& path) {
  std::vector<KeyStep> steps;
  std::stringstream s(path);
  std::string part;
  while (std::getline(s, part, '.')) {
    KeyStep step;
    const auto bracket = part.find('[');
    step.key = part.substr(0, bracket);
    for (auto at = bracket; at != std::string::npos; at = part.find('[', at + 1)) {
      const auto close = part.find(']', at);
      const std::string digits = close == std::string::npos ? "" : part.substr(at + 1, close - at - 1);
      if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 6)
        throw InputError("expected a key path such as damping_table.moment_Nm[3]");
      step.indices.push_back(static_cast<std::size_t>(std::stoul(digits)));
    }
    if (step.key.empty()) throw InputError("expected a key path such as damping_table.moment_Nm[3]");
    steps.push_back(step);
  }
  if (steps.empty()) throw InputError("expected a key path such as damping_table.moment_Nm[3]");
  return steps;
}

// The node at `path` in `root`; with `create`, missing map keys on the way are added (maps
// inside, a null at the end). Throws InputError saying which step is not there.
YAML::Node findNode(YAML::Node root, const std::string& path, bool create) {
  YAML::Node node = root;
  const std::vector<KeyStep> steps = parseKeyPath(path);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const KeyStep& step = steps[i];
    if (!node.IsMap()) throw InputError("'" + step.key + "' is not inside a map of the knee model");
    YAML::Node next = node[step.key];
    if (!next.IsDefined() || next.IsNull()) {
      if (!create) throw InputError("the knee model has no key '" + step.key + "'");
      if (!step.indices.empty()) throw InputError("the knee model has no list '" + step.key + "'");
      if (i + 1 < steps.size()) {
        node[step.key] = YAML::Node(YAML::NodeType::Map);
        next.reset(node[step.key]);  // reset: a Node's operator= would write into the tree
      }
    }
    for (std::size_t index : step.indices) {
      if (!next.IsSequence() || index >= next.size())
        throw InputError("'" + step.key + "' has no item " + std::to_string(index) + " (lists count from 0)");
      next.reset(next[index]);
    }
    node.reset(next);
  }
  return node;
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

KneeModelKnobs::KneeModelKnobs(const std::string& path) : path_(path) {
  loadKneeModel(path);  // the file itself must load: its own messages come first
  text_ = readText(path);
}

KneeModelKnobs KneeModelKnobs::fromText(const std::string& text, const std::string& path) {
  parseKneeModel(text, path);  // the text itself must load: its own messages come first
  return KneeModelKnobs(path, text);
}

KneeModel KneeModelKnobs::load() const { return parseKneeModel(text_, path_); }

std::string KneeModelKnobs::checkKey(const std::string& key) const {
  YAML::Node root = YAML::Load(text_);
  YAML::Node node;
  try {
    node = findNode(root, key, true);
  } catch (const InputError& e) {
    return e.what();
  }
  if (!node.IsDefined() || node.IsNull()) return "";
  if (node.IsSequence())
    return "holds a list of " + std::to_string(node.size()) + " values: name one item, e.g. " + key + "[0]";
  if (node.IsMap()) return "holds a map, not a number: name a key inside it";
  try {
    node.as<double>();
  } catch (const YAML::Exception&) {
    return "holds '" + node.Scalar() + "', not a number";
  }
  return "";
}

double KneeModelKnobs::fileValue(const std::string& key) const {
  YAML::Node node = findNode(YAML::Load(text_), key, true);
  return node.IsDefined() && node.IsScalar() ? node.as<double>() : std::numeric_limits<double>::quiet_NaN();
}

KneeModel KneeModelKnobs::make(const std::vector<std::string>& keys, const std::vector<double>& values) const {
  YAML::Node root = YAML::Load(text_);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    YAML::Node node = findNode(root, keys[i], true);
    std::ostringstream v;
    v.precision(17);
    v << values[i];
    node = v.str();
  }
  YAML::Emitter out;
  out << root;
  KneeModel model = parseKneeModel(out.c_str(), path_);
  return model;
}

}  // namespace swingsim
