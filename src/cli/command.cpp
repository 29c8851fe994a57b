#include "cli/command.h"

namespace swingsim::cli {

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

}  // namespace swingsim::cli
