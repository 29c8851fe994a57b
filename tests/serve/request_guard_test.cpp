// The Host/Origin checks of swingsim serve (serve/request_guard.h).
#include "serve/request_guard.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace swingsim {
namespace {

using ::testing::HasSubstr;

TEST(RequestGuard, AnswersItsOwnHostWithOrWithoutItsOwnOrigin) {
  const RequestGuard guard("127.0.0.1", 8123);
  EXPECT_EQ(guard.checkRequest("127.0.0.1:8123", ""), "");
  EXPECT_EQ(guard.checkRequest("localhost:8123", "http://localhost:8123"), "");
  EXPECT_EQ(guard.checkRequest("127.0.0.1:8123", "http://127.0.0.1:8123"), "");
  EXPECT_EQ(guard.getOrigin(), "http://127.0.0.1:8123/");
}

// DNS rebinding: a page at evil.example whose name now resolves to 127.0.0.1 sends its own
// name as Host.
TEST(RequestGuard, RefusesAnotherHostAsDnsRebindingWouldSendIt) {
  const RequestGuard guard("127.0.0.1", 8123);
  EXPECT_THAT(guard.checkRequest("evil.example:8123", ""), HasSubstr("Host 'evil.example:8123' is not this server's"));
  EXPECT_THAT(guard.checkRequest("127.0.0.1:8124", ""), HasSubstr("is not this server's"));
  EXPECT_THAT(guard.checkRequest("", ""), HasSubstr("is not this server's"));
}

// Another page open in the same browser posting to the server.
TEST(RequestGuard, RefusesAnotherOrigin) {
  const RequestGuard guard("127.0.0.1", 8123);
  EXPECT_THAT(guard.checkRequest("127.0.0.1:8123", "http://evil.example"),
              HasSubstr("Origin 'http://evil.example' is not"));
  EXPECT_THAT(guard.checkRequest("127.0.0.1:8123", "null"), HasSubstr("Origin 'null'"));
  EXPECT_THAT(guard.checkRequest("127.0.0.1:8123", "https://127.0.0.1:8123"), HasSubstr("is not this server's page"));
}

TEST(RequestGuard, ANonLoopbackHostAcceptsOnlyItsOwnName) {
  const RequestGuard guard("192.168.1.20", 9000);
  EXPECT_EQ(guard.checkRequest("192.168.1.20:9000", "http://192.168.1.20:9000"), "");
  EXPECT_THAT(guard.checkRequest("localhost:9000", ""), HasSubstr("is not this server's"));
  EXPECT_TRUE(isLoopbackHost("127.0.0.1"));
  EXPECT_TRUE(isLoopbackHost("::1"));
  EXPECT_FALSE(isLoopbackHost("0.0.0.0"));
}

}  // namespace
}  // namespace swingsim
