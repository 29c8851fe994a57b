#include "cli/command.h"

#include "cli/option_checks.h"
#include "core/output_files.h"
#include "core/output_paths.h"
#include "core/special_files.h"

namespace swingsim::cli {

CLI::Option* addTextOption(CLI::App* sub, const std::string& flag, std::optional<std::string>& value,
                           const std::string& help, const std::string& typeName) {
  CLI::Option* option = sub->add_option_function<std::string>(
                               flag, [&value](const std::string& v) { value = v; }, help)
                            ->type_name(typeName);
  // Where output goes is checked while parsing: a directory given for a file, or a place we
  // cannot write, fails before any computation.
  if (typeName == "FILE") option->check(writableFilePath());
  if (typeName == "DIR") option->check(writableFolderPath());
  return option;
}

CLI::Option* addJsonOption(CLI::App* sub, std::optional<std::string>& json) {
  // `-`: the JSON alone on standard output (for a pipe into jq or a script); the text the
  // command prints goes to standard error instead.
  CLI::Option* option = sub->add_option_function<std::string>(
      "--json", [&json](const std::string& v) { json = v == "-" ? takeStandardOutputForData() : v; },
      "also write the machine-readable result to this JSON file (-: to standard output, the text then to standard "
      "error)");
  option->type_name("FILE");
  option->check(
      CLI::Validator([](std::string& text) { return text == "-" ? std::string() : writableFilePath()(text); }, ""));
  return option;
}

CLI::Option* addStudyOutOption(CLI::App* sub, std::optional<std::string>& out) {
  return addTextOption(sub, "--out", out, "output folder (default out/<study name>/)", "DIR");
}

std::string formatCommandLine(const CLI::App& command) {
  std::string positionals, options;
  for (const CLI::Option* o : command.get_options()) {
    if (o->count() == 0) continue;
    if (!o->nonpositional()) {
      for (const auto& value : o->results()) positionals += " " + value;
      continue;
    }
    if (o->get_type_size() == 0) {  // a switch
      options += " " + o->get_name();
      continue;
    }
    for (const auto& value : o->results()) options += " " + o->get_name() + " " + value;
  }
  return "swingsim " + command.get_name() + positionals + options;
}

std::vector<CommandFile> listRunOutputs(const std::string& folder, const std::vector<std::string>& names,
                                        const std::optional<std::string>& json) {
  std::vector<CommandFile> outputs =
      folder.empty() ? std::vector<CommandFile>{} : listFolderFiles("--out", folder, names);
  outputs.push_back({"--json", json.value_or("")});
  return outputs;
}

}  // namespace swingsim::cli
