// RequestDeadline on real loopback sockets: a connection left outside a handler past the
// deadline is shut down (the client reads the end of the stream); one being answered is left
// alone until its answer, and its clock starts again then.
#include "serve/request_deadline.h"

#include <poll.h>
#include <sys/socket.h>

#include <chrono>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "loopback_pair.h"

namespace swingsim {
namespace {

using std::chrono::milliseconds;

// True once the client reads the end of the stream (the server shut its side), waiting at
// most `limit`; the wait ends at the first sign.
bool clientSeesEnd(int client, milliseconds limit) {
  pollfd p{client, POLLIN, 0};
  if (::poll(&p, 1, static_cast<int>(limit.count())) <= 0) return false;
  char byte;
  return ::recv(client, &byte, 1, MSG_DONTWAIT) == 0;
}

TEST(RequestDeadline, ShutsDownAConnectionOutsideAHandlerPastTheDeadline) {
  LoopbackPair pair;
  ASSERT_GE(pair.accepted, 0);
  RequestDeadline deadline(pair.listenPort, milliseconds(200), milliseconds(20));
  EXPECT_TRUE(clientSeesEnd(pair.client, milliseconds(10000)));
  EXPECT_EQ(deadline.getShutDowns(), 1);
}

TEST(RequestDeadline, LeavesAConnectionBeingAnsweredAlone) {
  LoopbackPair pair;
  ASSERT_GE(pair.accepted, 0);
  const std::string peer = "127.0.0.1:" + std::to_string(pair.clientPort);
  RequestDeadline deadline(pair.listenPort, milliseconds(200), milliseconds(20));
  deadline.start(peer);
  std::this_thread::sleep_for(milliseconds(1000));  // five deadlines
  EXPECT_FALSE(clientSeesEnd(pair.client, milliseconds(0)));
  EXPECT_EQ(deadline.getShutDowns(), 0);
  deadline.finish(peer);  // answered: the next request has the deadline again
  EXPECT_TRUE(clientSeesEnd(pair.client, milliseconds(10000)));
  EXPECT_EQ(deadline.getShutDowns(), 1);
}

TEST(RequestDeadline, WatchesOnlyItsOwnPort) {
  LoopbackPair pair;
  ASSERT_GE(pair.accepted, 0);
  RequestDeadline deadline(pair.listenPort + 1 == 65536 ? 1 : pair.listenPort + 1, milliseconds(100), milliseconds(20));
  std::this_thread::sleep_for(milliseconds(500));
  EXPECT_FALSE(clientSeesEnd(pair.client, milliseconds(0)));
  EXPECT_EQ(deadline.getShutDowns(), 0);
}

}  // namespace
}  // namespace swingsim
