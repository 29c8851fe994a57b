#pragma once
// A loaded knee model: its name and kind and the knee law it makes (the model's resisting
// law followed by its hyperextension stop).
#include <string>

#include "knee/knee_law.h"

namespace swingsim {

struct KneeModel {
  std::string path;
  std::string name;   ///< `name:` key, or the file stem
  std::string kind;   ///< `kind:` key: damping_table, mauch (more may follow)
  KneeLawSum law;     ///< the model's resisting law(s) followed by the hyperextension stop
};

}  // namespace swingsim
