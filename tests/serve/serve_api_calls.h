#pragma once
// swingsim serve's API called as the web server calls it, without HTTP, for the serve tests:
// one ServeApi over the repository's shipped files with the default limits.
#include <gtest/gtest.h>

#include <string>

#include "serve/serve_api.h"

namespace swingsim::serve_test {

inline const ServeApi& shippedServeApi() {
  static const ServeApi api(ShippedFiles(SWINGSIM_SOURCE_DIR), ServeLimits{});
  return api;
}

/// The JSON answer of `call` on `body`, checked to come with `expectedStatus`.
inline Json callServeApi(ApiReply (ServeApi::*call)(const std::string&) const, const Json& body,
                         int expectedStatus = 200) {
  const ApiReply r = (shippedServeApi().*call)(body.dump());
  EXPECT_EQ(r.status, expectedStatus) << r.body;
  return Json::parse(r.body);
}

}  // namespace swingsim::serve_test
