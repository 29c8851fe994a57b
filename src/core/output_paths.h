#pragma once
// Checks of where a command will write, run before any work (docs/robustness.md, "Where output
// goes"): a place that cannot be written, or a path too long for the file system, must fail
// at once, not after a run whose results then cannot be kept.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace swingsim {

/// Bytes a folder's path must leave free below PATH_MAX for the files written inside it
/// (the staging folder `.staging-HOST-PID/`, subfolders, a 64-byte file stem and its suffixes).
constexpr std::size_t kOutputNameReserve = 160;

/// "" if `path` can be written as an output file: not a directory; an existing FIFO, device
/// or /dev link we may write (written through, special_files.h); else inside a folder that
/// exists or can be made and that we may write in; no component longer than NAME_MAX once
/// the temporary suffix `.tmp-PID` is added, and the absolute path within PATH_MAX.
/// Otherwise what is wrong ("cannot write in the folder '/x' (permissions)").
std::string findOutputFileProblem(const std::string& path);

/// "" if `path` can be an output folder: not an existing file, a writable folder or one that
/// can be made, no component longer than NAME_MAX and the absolute path at least
/// kOutputNameReserve bytes shorter than PATH_MAX. Otherwise what is wrong.
std::string findOutputFolderProblem(const std::string& path);

/// Throws InputError "`where`: cannot write into 'PATH': PROBLEM" if findOutputFolderProblem
/// finds one; `where` names the source of the path ("study.yaml: output_dir", "--out").
void checkOutputFolder(const std::string& path, const std::string& where);

/// Throws InputError if two of `paths` are the same file (the same device and inode, so
/// `a.yaml`, `./a.yaml` and a link to it count as one): "SECOND: the same file as FIRST
/// (arguments I and J): `why`". Paths that do not exist are left to their reader. Linear time.
void checkDistinctFiles(const std::vector<std::string>& paths, const std::string& why);

/// A file a command reads or writes, and what named it ("--json", "MODEL.osim", "study.yaml:
/// measured"), for messages.
struct CommandFile {
  std::string source;
  std::string path;
};

/// The files `names` that a run writes into the folder `folder`, each named by `source`
/// ("--out"), for checkOutputsAreNotInputs.
std::vector<CommandFile> listFolderFiles(const std::string& source, const std::string& folder,
                                         const std::vector<std::string>& names);

/// Throws InputError "SOURCE 'PATH': would write over the input IN_SOURCE 'IN_PATH'; a
/// command never replaces one of its own inputs (write it elsewhere)" if an output resolves
/// to an input: the same file (device and inode, so a link or `./x` counts) or the same path
/// after std::filesystem::weakly_canonical. Outputs written through (a FIFO, /dev/stdout)
/// replace nothing and are left alone. Call it before any work.
void checkOutputsAreNotInputs(const std::vector<CommandFile>& inputs, const std::vector<CommandFile>& outputs);

/// The output folder of a study command: `out` (--out, checked while parsing), else
/// out/<safe study name>/, checked here (checkOutputFolder) so an unwritable or over-long
/// folder fails before any work. Throws InputError naming where the path came from.
std::string chooseStudyOutputFolder(const std::optional<std::string>& out, const std::string& studyName,
                                    const std::string& studyPath);

}  // namespace swingsim
