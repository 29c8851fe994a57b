#pragma once
// YAML as a plain tree, for code above io/ that holds YAML text no format's archive describes:
// the page server's form edits and uploaded files (serve/leg_request.cpp, serve/serve_api.cpp)
// and the Python module's dicts (python/src). YamlTree reads and edits a document by key;
// YamlWriter writes one from nested calls. With io/yaml_reader.h and io/yaml_archive.h these
// are the only code that uses yaml-cpp (`YAML::` outside src/io/ fails the tree_check test).
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace swingsim {

/// A YAML document or one of its nodes. Copies share their nodes (as yaml-cpp's do): an
/// edit through one is seen through the others.
class YamlTree {
 public:
  enum class Kind { kNull, kScalar, kList, kMap };

  /// A null tree.
  YamlTree();
  /// Parses `text`. Throws InputError "`key`: expected `what` in YAML (got a YAML error:
  /// ...)" for text that is not YAML.
  static YamlTree parse(const std::string& text, const std::string& key, const std::string& what);

  Kind kind() const;
  bool isNull() const { return kind() == Kind::kNull; }
  bool isScalar() const { return kind() == Kind::kScalar; }
  bool isList() const { return kind() == Kind::kList; }
  bool isMap() const { return kind() == Kind::kMap; }
  /// A scalar's text ("" for another kind).
  std::string scalar() const;
  /// Whether a scalar was quoted in the text ("1" is text, 1 a number).
  bool isQuoted() const;
  /// A scalar that reads whole as a number (quoted or not); nullopt otherwise.
  std::optional<double> number() const;
  /// A map's entry `key`; a null tree if the tree is not a map or has no such key.
  YamlTree get(const std::string& key) const;
  /// The node at a dotted path of map keys ("segments.shank.mass_kg"); null if a part is absent.
  YamlTree find(const std::string& dottedKey) const;
  /// A map's entries in file order (empty for another kind).
  std::vector<std::pair<std::string, YamlTree>> entries() const;
  /// A list's items (empty for another kind).
  std::vector<YamlTree> items() const;
  /// Sets the scalar at a dotted path of map keys (the last one may be absent). Throws
  /// InputError "`dottedKey`: expected a map above 'PART' in `what`" when anything but a map
  /// lies on the path.
  void set(const std::string& dottedKey, const std::string& value, const std::string& what);
  /// The tree as YAML text.
  std::string emit() const;

 private:
  struct Node;
  explicit YamlTree(std::shared_ptr<Node> node);
  std::shared_ptr<Node> node_;
};

/// YAML text written from nested calls: maps in block style, lists in flow style.
class YamlWriter {
 public:
  YamlWriter();
  ~YamlWriter();
  YamlWriter(const YamlWriter&) = delete;
  YamlWriter& operator=(const YamlWriter&) = delete;

  void beginMap();
  /// The next entry's key (in a map).
  void key(const std::string& key);
  void endMap();
  void beginList();
  void endList();
  /// A scalar written as it is (a number, true, false).
  void plain(const std::string& text);
  /// A string, double-quoted so that it reads back as text.
  void quoted(const std::string& text);
  void null();
  /// The text written so far.
  std::string text() const;

 private:
  struct Emitter;
  std::unique_ptr<Emitter> out_;
};

}  // namespace swingsim
