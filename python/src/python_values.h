#pragma once
// Conversions between the module's Python values and the documents swingsim reads and
// writes: JSON results become dicts/lists/numbers, YAML files become nested dicts (values in
// the file's units, keys as in the file) and go back to YAML text for the loaders, which
// check them as they check a file.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "io/json_file.h"
#include "io/yaml_tree.h"
#include "model/leg_parameters.h"
#include "study/run_arguments.h"

namespace swingsim::python {

/// A JSON document as Python objects: objects -> dict (key order kept), arrays -> list,
/// numbers -> int/float, null and
/// non-finite numbers -> None (as formatJson writes them).
pybind11::object toPython(const Json& json);

/// A YAML document as Python objects: maps -> dict, sequences -> list, scalars -> bool
/// (true/false), int, float or str, whichever reads the whole scalar; null -> None.
pybind11::object toPython(const YamlTree& node);
/// The YAML text swingsim wrote (a file format's writer) as Python objects, as toPython.
pybind11::object yamlTextToPython(const std::string& text);

/// The YAML text of a Python value built of dicts, lists/tuples, bools, numbers (numpy's
/// too) and strings; floats in their shortest form that reads back to the same double.
/// Throws InputError naming `where` for any other type.
std::string toYamlText(const pybind11::handle& value, const std::string& where);

/// A Python value for a message: its type and repr ("float 2.5", "numpy.ndarray of shape
/// (3,)"), cut at 80 characters.
std::string describePython(const pybind11::handle& value);

/// An argument (`where`: "sweep(): seed") as a whole number in `range`: a Python int or a
/// numpy integer scalar, not a bool or a float. Raises TypeError for another type, and
/// InputError (a ValueError) with range.expected outside the range, both naming `where`.
long long readWholeArgument(const pybind11::handle& value, const std::string& where, const WholeNumberRange& range);

/// An argument as a number: a Python int or float or a numpy number scalar, not a bool or an
/// array (TypeError naming `where`); `check` (as checkLowering) returns "" or what was
/// expected (InputError naming `where`).
double readNumberArgument(const pybind11::handle& value, const std::string& where, std::string (*check)(double));

/// An argument as text: a str (TypeError naming `where`).
std::string readTextArgument(const pybind11::handle& value, const std::string& where);
/// An argument as one of `choices` (the command line's oneOf): a str (TypeError), one of
/// them (InputError listing them, naming `where`).
std::string readChoiceArgument(const pybind11::handle& value, const std::string& where,
                               const std::vector<std::string>& choices);
/// An argument as a flag: a bool or numpy bool (TypeError naming `where`; 1 and 0 too).
bool readFlagArgument(const pybind11::handle& value, const std::string& where);

/// An added shank mass from its two arguments, added_mass_kg and added_mass_below_knee_m,
/// both >= 0 as the command line's --add-mass (InputError) or both None (TypeError for one
/// alone), `function` naming the call ("export_osim()").
std::optional<AddedMass> readAddedMassArguments(const pybind11::object& mass, const pybind11::object& below,
                                                const std::string& function);

/// An argument as a path: a str or an os.PathLike giving one (TypeError naming `where`).
bool isPathArgument(const pybind11::handle& value);
std::string readPathArgument(const pybind11::handle& value, const std::string& where);

}  // namespace swingsim::python
