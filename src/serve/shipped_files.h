#pragma once
// The participant and knee model files swingsim serve offers: participants/*.yaml and
// models/*.yaml under its data folder, listed once when the server starts. A request names
// a file by its stem ("p1", "damping-table-default"), looked up in that list; a request's
// text is never joined into a path, so no request reaches a file outside the list.
#include <string>
#include <vector>

namespace swingsim {

class ShippedFiles {
 public:
  /// Lists `dataDir`/participants/*.yaml and `dataDir`/models/*.yaml, sorted by stem.
  /// Throws InputError if either folder is missing or holds no .yaml file.
  explicit ShippedFiles(const std::string& dataDir);

  const std::vector<std::string>& getParticipantNames() const { return participantNames_; }
  const std::vector<std::string>& getKneeNames() const { return kneeNames_; }
  /// The path of shipped participant `name`; throws InputError `key: a shipped participant,
  /// one of ... (got NAME)` for any name not in the list (`../../etc/passwd` included).
  std::string findParticipantPath(const std::string& name, const std::string& key = "participant") const;
  /// The same for a knee model.
  std::string findKneePath(const std::string& name, const std::string& key = "knee") const;
  /// The knee model folder (participants name models as ../models/NAME.yaml).
  const std::string& getModelsDir() const { return modelsDir_; }
  const std::string& getParticipantsDir() const { return participantsDir_; }
  /// The folder holding participants/ and models/ as absolute paths (as given when absolute,
  /// made absolute, and with links resolved; longest first; never "/"): the server's own
  /// location, which answers never show (ServeApi hides it).
  std::vector<std::string> getDataDirSpellings() const;

 private:
  std::string participantsDir_, modelsDir_;
  std::vector<std::string> participantNames_, kneeNames_;
};

}  // namespace swingsim
