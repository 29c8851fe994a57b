#pragma once
// Whether the client of a request being answered is still there. cpp-httplib 0.11 (Debian's)
// gives a handler neither its socket nor the connection's state, so the accepted socket is
// found by the request's peer address and port (Request::remote_addr, remote_port) among the
// process's open sockets, and asked with poll(2) whether the peer has closed or reset it.
// Linux only (POLLRDHUP, /proc/self/fd). Used by a long call (the page's tune) to stop when its
// client has gone, so an abandoned tuning does not hold a compute slot to its budget.
#include <optional>
#include <string>
#include <vector>

namespace swingsim {

/// A connected TCP socket of this process: its descriptor, its local port and its peer.
struct SocketPeer {
  int socket = -1;
  int localPort = 0;
  std::string address;  ///< the peer's, numeric
  int port = 0;         ///< the peer's
};

/// A peer's key, "ADDRESS:PORT": how the request deadline names a connection, from the
/// socket's side (SocketPeer) and from the request's (Request::remote_addr, remote_port).
inline std::string makePeerKey(const std::string& address, int port) { return address + ":" + std::to_string(port); }

/// Every connected TCP socket of this process (/proc/self/fd, getsockname, getpeername).
std::vector<SocketPeer> listSocketPeers();
/// The descriptor `socket` as a connected TCP socket; nullopt if it is not one (any more).
std::optional<SocketPeer> describeSocket(int socket);

class PeerWatch {
 public:
  /// The accepted socket whose peer is `peerAddress` (numeric, as getnameinfo gives it) port
  /// `peerPort`; nullopt if no open socket of this process has that peer.
  static std::optional<PeerWatch> find(const std::string& peerAddress, int peerPort);

  /// True once the peer has closed its side (or reset the connection): nothing it sends any
  /// more can be a request, and nobody reads the answer. A client that only half-closes
  /// after sending its request reads as gone too (browsers and curl do not do that).
  bool isGone() const;

  int getSocket() const { return socket_; }

 private:
  explicit PeerWatch(int socket) : socket_(socket) {}
  int socket_;  // not owned: cpp-httplib closes it
};

}  // namespace swingsim
