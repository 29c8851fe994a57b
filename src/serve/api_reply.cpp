#include "serve/api_reply.h"

#include "core/input_error.h"
#include "serve/leg_request.h"

namespace swingsim {
namespace {

ApiReply replyError(int status, const std::string& message) {
  Json error = {{"error", message}};
  if (status == 400) {
    const std::string key = findErrorKey(message);
    error["key"] = key;
    const auto at = message.find(key + ": ");
    error["message"] = key.empty() || at == std::string::npos ? message : message.substr(at);
  }
  return {status,
          error.dump(-1, ' ', false, Json::error_handler_t::replace)};  // a message with bad UTF-8 still answers
}

}  // namespace

ApiReply answerOrError(const std::function<Json()>& answer) {
  try {
    return {200, answer().dump(-1, ' ', false, Json::error_handler_t::replace)};
  } catch (const Json::parse_error&) {
    return replyError(400, "request: expected a JSON object");
  } catch (const InputError& e) {
    return replyError(400, e.what());
  } catch (const RunError& e) {
    return replyError(422, e.what());
  } catch (const std::exception& e) {
    return replyError(500, e.what());
  }
}

Json readRequestBody(const std::string& body) {
  // Nesting is bounded before anything recurses over the document (dump, destruction).
  const auto depthGuard = [](int depth, Json::parse_event_t, Json&) {
    if (depth > kMaxRequestDepth)
      throw InputError("request: expected JSON nested at most " + std::to_string(kMaxRequestDepth) +
                       " deep (got deeper)");
    return true;
  };
  try {
    return Json::parse(body.empty() ? "{}" : body, depthGuard);
  } catch (const Json::out_of_range& e) {  // a number beyond a double (1e400): a 400, not a 500
    const std::string what = e.what();
    throw InputError("request: expected numbers a double holds (got " +
                     (what.size() > 160 ? what.substr(0, 160) + "..." : what) + ")");
  }
}

}  // namespace swingsim
