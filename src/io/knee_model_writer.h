#pragma once
// Writes a Mauch cylinder model as knee model YAML (`kind: mauch`, docs/mauch.md), with the
// `effects:` block of an augmented model (docs/diagnosis.md), so `loadKneeModel`, `fit`,
// `compare` and the swing simulator read it back.
#include <string>

#include "knee/joint_stop.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {

struct MauchModelText {
  std::string name;
  std::string description;
  std::string header;           ///< comment lines written first (without '#')
  double flexionDial = 90;      ///< deg
  double extensionDial = 90;    ///< deg
  JointStopParams stop;         ///< the base model's hyperextension stop
};

/// YAML text of `params`; numbers written to round-trip exactly.
std::string formatMauchModelYaml(const MauchCylinderParams& params, const MauchModelText& text);

}  // namespace swingsim
