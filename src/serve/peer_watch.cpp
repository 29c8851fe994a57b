#include "serve/peer_watch.h"

#include <dirent.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>

#include <cstdlib>

namespace swingsim {

namespace {

// The numeric address and port of `a`; false for a family other than IPv4 and IPv6.
bool readAddress(const sockaddr_storage& a, socklen_t length, std::string& address, int& port) {
  if (a.ss_family != AF_INET && a.ss_family != AF_INET6) return false;
  char host[NI_MAXHOST], service[NI_MAXSERV];
  if (::getnameinfo(reinterpret_cast<const sockaddr*>(&a), length, host, sizeof host, service, sizeof service,
                    NI_NUMERICHOST | NI_NUMERICSERV) != 0)
    return false;
  address = host;
  port = std::atoi(service);
  return true;
}

// `socket`'s local port and peer; false if it is not a connected IP socket.
bool readSocketPeer(int socket, SocketPeer& out) {
  sockaddr_storage peer{}, local{};
  socklen_t peerLength = sizeof peer, localLength = sizeof local;
  if (::getpeername(socket, reinterpret_cast<sockaddr*>(&peer), &peerLength) != 0) return false;
  if (::getsockname(socket, reinterpret_cast<sockaddr*>(&local), &localLength) != 0) return false;
  std::string localAddress;
  out.socket = socket;
  return readAddress(peer, peerLength, out.address, out.port) &&
         readAddress(local, localLength, localAddress, out.localPort);
}

}  // namespace

std::vector<SocketPeer> listSocketPeers() {
  std::vector<SocketPeer> peers;
  DIR* dir = ::opendir("/proc/self/fd");
  if (dir == nullptr) return peers;
  while (const dirent* entry = ::readdir(dir)) {
    char* end = nullptr;
    const long fd = std::strtol(entry->d_name, &end, 10);
    if (end == entry->d_name || *end != '\0' || fd == ::dirfd(dir)) continue;
    SocketPeer p;
    if (readSocketPeer(static_cast<int>(fd), p)) peers.push_back(p);
  }
  ::closedir(dir);
  return peers;
}

std::optional<SocketPeer> describeSocket(int socket) {
  SocketPeer p;
  if (!readSocketPeer(socket, p)) return std::nullopt;
  return p;
}

std::optional<PeerWatch> PeerWatch::find(const std::string& peerAddress, int peerPort) {
  for (const SocketPeer& p : listSocketPeers())
    if (p.port == peerPort && p.address == peerAddress) return PeerWatch(p.socket);
  return std::nullopt;
}

bool PeerWatch::isGone() const {
  pollfd p{socket_, POLLRDHUP, 0};
  if (::poll(&p, 1, 0) <= 0) return false;
  return (p.revents & (POLLRDHUP | POLLHUP | POLLERR | POLLNVAL)) != 0;
}

}  // namespace swingsim
