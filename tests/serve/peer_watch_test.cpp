// PeerWatch on real loopback sockets: the accepted socket is found by its peer's address and
// port, and it reads as gone once the client has closed, not before.
#include "serve/peer_watch.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

namespace swingsim {
namespace {

// A listening socket on 127.0.0.1 (a free port), a client connected to it and the accepted end.
struct LoopbackPair {
  int listener = -1, client = -1, accepted = -1;
  int clientPort = 0;
  LoopbackPair() {
    listener = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in at{};
    at.sin_family = AF_INET;
    at.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof at;
    if (::bind(listener, reinterpret_cast<sockaddr*>(&at), sizeof at) != 0 || ::listen(listener, 1) != 0 ||
        ::getsockname(listener, reinterpret_cast<sockaddr*>(&at), &length) != 0)
      return;
    client = ::socket(AF_INET, SOCK_STREAM, 0);
    if (::connect(client, reinterpret_cast<sockaddr*>(&at), sizeof at) != 0) return;
    accepted = ::accept(listener, nullptr, nullptr);
    sockaddr_in mine{};
    length = sizeof mine;
    ::getsockname(client, reinterpret_cast<sockaddr*>(&mine), &length);
    clientPort = ntohs(mine.sin_port);
  }
  ~LoopbackPair() {
    for (int fd : {listener, client, accepted})
      if (fd >= 0) ::close(fd);
  }
  void closeClient() {
    ::close(client);
    client = -1;
  }
};

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
