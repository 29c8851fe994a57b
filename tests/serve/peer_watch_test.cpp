// PeerWatch on real loopback sockets: the accepted socket is found by its peer's address and
// port, and it reads as gone once the client has closed, not before.
#include "serve/peer_watch.h"

#include <sys/socket.h>

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "loopback_pair.h"

namespace swingsim {
namespace {

TEST(PeerWatch, FindsTheAcceptedSocketByItsPeer) {
  LoopbackPair pair;
  ASSERT_GE(pair.accepted, 0);
  const auto watch = PeerWatch::find("127.0.0.1", pair.clientPort);
  ASSERT_TRUE(watch.has_value());
  EXPECT_EQ(watch->getSocket(), pair.accepted);  // not the client's own socket, whose peer is the listener
  EXPECT_FALSE(PeerWatch::find("127.0.0.2", pair.clientPort).has_value());
}

TEST(PeerWatch, TheClientIsGoneOnceItHasClosedNotBefore) {
  LoopbackPair pair;
  ASSERT_GE(pair.accepted, 0);
  const auto watch = PeerWatch::find("127.0.0.1", pair.clientPort);
  ASSERT_TRUE(watch.has_value());
  EXPECT_FALSE(watch->isGone());
  // Data from the client is not a close.
  ASSERT_EQ(::send(pair.client, "GET", 3, 0), 3);
  EXPECT_FALSE(watch->isGone());
  pair.closeClient();
  // On loopback the close reaches the other end within close(2); the wait only guards a
  // slow kernel and ends at the first true.
  bool gone = watch->isGone();
  for (int i = 0; i < 5000 && !gone; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    gone = watch->isGone();
  }
  EXPECT_TRUE(gone);
}

}  // namespace
}  // namespace swingsim
