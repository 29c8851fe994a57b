#include "python_objects.h"

#include <filesystem>

#include "python_values.h"

namespace py = pybind11;

namespace swingsim::python {
namespace {

/// load(path) with the GIL released: a slow disk or a FIFO does not stop Python's threads.
template <class Load>
auto loadWithoutGil(Load load, const std::string& path) {
  py::gil_scoped_release release;
  return load(path);
}

}  // namespace

std::string folderOf(const std::string& path) {
  const std::string folder = std::filesystem::path(path).parent_path().string();
  return folder.empty() ? "." : folder;
}

bool isPackageObject(const py::handle& value, const char* name) {
  if (py::isinstance(value, py::module_::import("swingsim").attr(name))) return true;
  // An object made before importlib.reload(swingsim) (a notebook's autoreload) is an instance
  // of the class as it was: the same class by module and name anywhere in its MRO (it was
  // refused with "expected a swingsim.Participant, got swingsim.Participant").
  for (const py::handle cls : py::type::of(value).attr("__mro__")) {
    const py::object module = py::getattr(cls, "__module__", py::none());
    const py::object qualname = py::getattr(cls, "__qualname__", py::none());
    if (py::isinstance<py::str>(module) && py::isinstance<py::str>(qualname) &&
        module.cast<std::string>() == "swingsim" && qualname.cast<std::string>() == name)
      return true;
  }
  return false;
}

std::pair<std::string, std::string> objectAsYaml(const py::handle& object, const char* what) {
  const std::string origin = object.attr("origin").cast<std::string>();
  const std::string source = origin + " (edited in Python)";
  return {toYamlText(object.attr("to_dict")(), source + ": " + what), source};
}

Participant readParticipant(const py::handle& participant, const char* function) {
  const std::string where = std::string(function) + "(): participant";
  if (isPathArgument(participant)) return loadWithoutGil(loadParticipant, readPathArgument(participant, where));
  if (!isPackageObject(participant, "Participant"))
    throw py::type_error(
        formatArgumentProblem(where, "expected a path or a swingsim.Participant", describePython(participant)));
  const auto [text, source] = objectAsYaml(participant, "participant");
  return parseParticipant(text, source);
}

KneeModel readKnee(const py::handle& knee, const Participant& participant, const char* function) {
  const std::string where = std::string(function) + "(): knee";
  if (knee.is_none()) return loadWithoutGil(loadKneeModel, participant.kneeModelPath);
  if (isPathArgument(knee)) return loadWithoutGil(loadKneeModel, readPathArgument(knee, where));
  if (!isPackageObject(knee, "KneeModel"))
    throw py::type_error(formatArgumentProblem(
        where, "expected None (the participant's), a path or a swingsim.KneeModel", describePython(knee)));
  const auto [text, source] = objectAsYaml(knee, "knee model");
  return parseKneeModel(text, source);
}

}  // namespace swingsim::python
