// libFuzzer target: a request body of swingsim serve's JSON API (serve/serve_api.h), read as
// the server reads it: the body's size and depth bounds, the leg request (serve/leg_request.cpp),
// its key check, the participant and knee loaded from the shipped files, and for a tune the
// knobs and targets (serve/tune_call.cpp). The first byte picks the call: 0 describe the
// participant, 1 simulate, 2 tune (budgets cut to a few swings, so an input costs
// milliseconds). Every input must get a reply: an exception escaping, a 500 (an error the
// server did not foresee) or a reply that is not JSON aborts, so libFuzzer reports it.
#include <nlohmann/json.hpp>

#include <string>

#include "fuzz_common.h"
#include "serve/serve_api.h"

namespace {

const swingsim::ServeApi& api() {
  static const swingsim::ServeApi instance = [] {
    swingsim::ServeLimits limits;
    limits.maxSwingWallSeconds = 0.5;
    limits.maxTuneWallSeconds = 0.5;
    limits.maxTuneSwings = 4;
    limits.maxSweepPoints = 2;
    return swingsim::ServeApi(swingsim::ShippedFiles(swingsim::fuzz::sourcePath("")), limits);
  }();
  return instance;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  if (size == 0) return 0;
  const std::string body = fuzz::asText(data + 1, size - 1);
  ApiReply reply;
  switch (data[0] % 3) {
    case 0:
      reply = api().describeParticipant(body);
      break;
    case 1:
      reply = api().simulate(body);
      break;
    default:
      reply = api().tune(body);
      break;
  }
  if (reply.status == 500 || !nlohmann::json::accept(reply.body)) __builtin_trap();
  return 0;
}
