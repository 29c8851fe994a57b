#pragma once
// The package's file objects (swingsim/_records.py: Participant, KneeModel,
// DiagnosisStudy) as the C++ loaders' input: an argument that is a path is loaded, an object
// goes back to YAML text and through the same loader, so every check of a file applies.
#include <pybind11/pybind11.h>

#include <string>
#include <utility>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"

namespace swingsim::python {

/// The folder of `path` ("." for a bare file name).
std::string folderOf(const std::string& path);

/// An instance of the package's class `name` (Participant, KneeModel, ...)?
bool isPackageObject(const pybind11::handle& value, const char* name);

/// An object's YAML text (its to_dict()) and the name its messages carry: its origin with
/// " (edited in Python)" (relative paths resolve against the origin's folder).
std::pair<std::string, std::string> objectAsYaml(const pybind11::handle& object, const char* what);

/// `participant` (a path or a Participant) loaded; `function` names the call in messages.
Participant readParticipant(const pybind11::handle& participant, const char* function);

/// `knee`: None (the participant's knee_model), a path or a KneeModel, loaded.
KneeModel readKnee(const pybind11::handle& knee, const Participant& participant, const char* function);

}  // namespace swingsim::python
