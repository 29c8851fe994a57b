#pragma once
// Checks of option values, run by CLI11 while parsing: a value that fails one is a usage
// error (exit 2) with the message `--flag: expected ... (got 'VALUE')`.
#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/leg_parameters.h"
#include "study/run_arguments.h"

namespace swingsim::cli {

/// A finite number; `check(value)` returns "" if it is usable, else what was expected
/// ("expected a relative accuracy in [1e-14, 0.01]").
CLI::Validator finiteNumber(std::function<std::string(double)> check = {});
/// A whole number in `range` (study/run_arguments.h, the ranges Python checks too); a
/// refusal says range.expected.
CLI::Validator wholeNumberIn(const WholeNumberRange& range);
/// One of `keys`.
CLI::Validator oneOf(const std::vector<std::string>& keys);

/// A file the command will write (--json, --save-model): not a directory, and inside a
/// folder that exists or can be made (the nearest existing one is a folder we may write
/// in), or a FIFO or device we may write; a path within NAME_MAX and PATH_MAX
/// (findOutputFileProblem). Checked while parsing, so a bad place fails before any
/// computation or output.
CLI::Validator writableFilePath();
/// A folder the command will write into (--out): not an existing file, and either a
/// writable folder or one that can be made, with room below PATH_MAX for its files
/// (findOutputFolderProblem).
CLI::Validator writableFolderPath();

/// "0.5@0.2": 0.5 kg at 0.2 m below the knee (both finite, >= 0); nullopt if malformed.
std::optional<AddedMass> readAddedMass(const std::string& text);
/// An added mass as readAddedMass reads it.
CLI::Validator addedMassSpec();

}  // namespace swingsim::cli
