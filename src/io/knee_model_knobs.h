#pragma once
// A knee model file whose numeric keys can be set: the tuning's knobs on the knee. Each
// setting edits the file's YAML tree (a key path such as `damping_table.extension_factor`,
// `damping_table.moment_Nm[3]` or `settings[0].coefficients[1].c_Ns_per_m`) and reloads it
// through the knee model loader, so a knob gets every check the file's own value gets and
// works for every knee kind without knowing it.
#include <string>
#include <utility>
#include <vector>

#include "model/knee_model.h"

namespace swingsim {

class KneeModelKnobs {
 public:
  /// Reads the model file (checked by loading it once). Throws InputError.
  explicit KneeModelKnobs(const std::string& path);
  /// A knee model from its YAML text (an upload), `path` naming it in messages and as the
  /// model's path (knee model files name no other file, so nothing is read there). Throws
  /// InputError.
  static KneeModelKnobs fromText(const std::string& text, const std::string& path);

  /// The model as the file gives it, no key set.
  KneeModel load() const;

  /// "" if `key` can be a knob: it names a number in the file, or an absent key inside the
  /// file's maps (the loader decides whether it knows it, when a value is set); else what
  /// is wrong ("holds a list of 8 numbers: name one, e.g. moment_Nm[0]").
  std::string checkKey(const std::string& key) const;
  /// The value `key` holds in the file, or NaN if it is absent (checkKey passed).
  double fileValue(const std::string& key) const;
  /// The model with keys[i] set to values[i], reloaded through the loader (model.path stays
  /// the file's). Throws InputError with the loader's message (its line numbers refer to
  /// the edited tree, so callers name the knob instead). Safe to call from several threads.
  KneeModel make(const std::vector<std::string>& keys, const std::vector<double>& values) const;

  const std::string& path() const { return path_; }

 private:
  KneeModelKnobs(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {}
  std::string path_, text_;
};

}  // namespace swingsim
