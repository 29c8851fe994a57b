#pragma once
// A whole-request deadline for swingsim serve. cpp-httplib 0.11 (Debian's) times out each
// read after 5 s of silence but bounds no request as a whole: a client sending a byte every
// few seconds holds a connection thread for as long as it likes, and enough of them fill the
// pool. A watchdog thread lists the server's open connections (sockets of this process whose
// local port is the server's and that have a peer; serve/peer_watch.h finds them the same
// way) and shuts down one that has been outside a request handler for longer than the
// deadline: reading a request (or idling between keep-alive requests, which cpp-httplib ends
// after 2 s) takes milliseconds on the loopback, so only a slow sender reaches it.
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "serve/peer_watch.h"

namespace swingsim {

class RequestDeadline {
 public:
  /// Watches connections to local port `port`, every `period`; shuts down those outside a
  /// handler for longer than `deadline`.
  RequestDeadline(int port, std::chrono::milliseconds deadline, std::chrono::milliseconds period);
  ~RequestDeadline();
  RequestDeadline(const RequestDeadline&) = delete;
  RequestDeadline& operator=(const RequestDeadline&) = delete;

  /// A request from `peer` ("address:port") has been read and is being answered: its
  /// connection is exempt until finish(peer).
  void start(const std::string& peer);
  /// Its answer has been sent: the connection's clock starts again (keep-alive).
  void finish(const std::string& peer);
  /// Connections shut down so far.
  int getShutDowns() const;

 private:
  void watch();
  void check(std::chrono::steady_clock::time_point now, const std::vector<SocketPeer>& peers);

  struct Connection {
    int socket = -1;
    std::chrono::steady_clock::time_point since;  // outside a handler since
    bool answering = false;
  };
  const int port_;
  const std::chrono::milliseconds deadline_, period_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::map<std::string, Connection> connections_;  // by peer "address:port"
  int shutDowns_ = 0;
  std::thread thread_;
};

}  // namespace swingsim
