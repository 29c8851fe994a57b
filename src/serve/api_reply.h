#pragma once
// The replies of swingsim serve's JSON API (serve/serve_api.h): a status and JSON text, with
// the library's exceptions turned into replies the page shows beside the field they name.
#include <functional>
#include <string>

#include "io/json_file.h"

namespace swingsim {

struct ApiReply {
  int status = 200;
  std::string body;  ///< JSON text
};

/// `answer()` as a 200 reply, or its exception as one: bad input (InputError, JSON that does
/// not parse) 400 {"error", "key", "message"} (the key the message names, for the page's
/// field), a failed run (RunError) 422 {"error"}, anything else 500 {"error"}.
ApiReply answerOrError(const std::function<Json()>& answer);

/// The deepest nesting of a request's JSON the server reads (the page's deepest is 3).
inline constexpr int kMaxRequestDepth = 64;

/// A request body as JSON (empty: {}). Throws Json::parse_error; InputError for nesting past
/// kMaxRequestDepth or a number a double cannot hold (1e400).
Json readRequestBody(const std::string& body);

}  // namespace swingsim
