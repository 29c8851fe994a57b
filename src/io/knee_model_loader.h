#pragma once
// The knee model file (models/*.yaml: a damping table or a Mauch cylinder, with optional
// added effects and a hyperextension stop), read and written through one description of
// its fields (io/yaml_archive.h). Knee friction belongs to the participant's knee unit
// (Burkett Table 2, Tc) and is added by swing/knee_setup.
#include <string>

#include "knee/mauch_cylinder.h"
#include "model/knee_model.h"

namespace swingsim {

class YamlMap;
class YamlReadArchive;
class YamlWriteArchive;

/// Reads a knee model. Throws InputError (`file:line: key: ...`) on any bad input.
KneeModel loadKneeModel(const std::string& path);
/// Same, from YAML text (tests, fuzzers).
KneeModel parseKneeModel(const std::string& text, const std::string& path);

/// The Mauch cylinder of a `kind: mauch` model file (at its dial setting). Throws InputError.
MauchCylinderParams loadMauchCylinder(const std::string& path);

/// Added cylinder effects from an `effects:`-style map (also a bench study's hidden
/// effects). `phases`: the model's phases (0: not known yet).
MauchAddedEffects readMauchAddedEffects(YamlMap& effects, int phases);
/// The fields of an `effects:`-style map, for the archives of io/yaml_archive.h (a bench
/// study's hidden effects are written and read through them).
void serialize(YamlReadArchive& a, MauchAddedEffects& e, int phases);
void serialize(YamlWriteArchive& a, MauchAddedEffects& e, int phases);

/// The YAML text of a knee model spec, with `header` lines as leading comments.
std::string formatKneeModelYaml(const KneeModelSpec& spec, const std::string& header = "");

}  // namespace swingsim
