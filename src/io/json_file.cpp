#include "io/json_file.h"

#include "core/output_files.h"

namespace swingsim {

std::string formatJson(const Json& document) {
  return document.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace) + "\n";
}

void writeJsonFile(const std::string& path, const Json& document) { writeFileAtomic(path, formatJson(document)); }

}  // namespace swingsim
