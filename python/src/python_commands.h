#pragma once
// The module's functions over file objects (load_study_dict, format_record) and the OpenSim
// commands (swings, import_osim, export_osim): python_commands.cpp.
#include <pybind11/pybind11.h>

namespace swingsim::python {

/// Defines them in the extension module `m`.
void addRecordFunctions(pybind11::module_& m);

}  // namespace swingsim::python
