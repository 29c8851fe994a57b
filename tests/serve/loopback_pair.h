#pragma once
// For the serve tests that need a real TCP connection: a listener on 127.0.0.1 (a free
// port), a client connected to it and the accepted end, all closed at the end of the scope.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace swingsim {

// A listening socket on 127.0.0.1 (a free port), a client connected to it and the accepted end.
struct LoopbackPair {
  int listenPort = 0;
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
    listenPort = ntohs(at.sin_port);
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

}  // namespace swingsim
