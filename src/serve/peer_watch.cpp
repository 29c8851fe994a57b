#include "serve/peer_watch.h"

#include <dirent.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>

#include <cstdlib>

namespace swingsim {

namespace {

// The numeric address and port of `socket`'s peer; false if it is not a connected socket.
bool readPeer(int socket, std::string& address, int& port) {
  sockaddr_storage peer{};
  socklen_t length = sizeof peer;
  if (::getpeername(socket, reinterpret_cast<sockaddr*>(&peer), &length) != 0) return false;
  if (peer.ss_family != AF_INET && peer.ss_family != AF_INET6) return false;
  char host[NI_MAXHOST], service[NI_MAXSERV];
  if (::getnameinfo(reinterpret_cast<sockaddr*>(&peer), length, host, sizeof host, service, sizeof service,
                    NI_NUMERICHOST | NI_NUMERICSERV) != 0)
    return false;
  address = host;
  port = std::atoi(service);
  return true;
}

}  // namespace

std::optional<PeerWatch> PeerWatch::find(const std::string& peerAddress, int peerPort) {
  DIR* dir = ::opendir("/proc/self/fd");
  if (dir == nullptr) return std::nullopt;
  std::optional<PeerWatch> found;
  while (const dirent* entry = ::readdir(dir)) {
    char* end = nullptr;
    const long fd = std::strtol(entry->d_name, &end, 10);
    if (end == entry->d_name || *end != '\0' || fd == ::dirfd(dir)) continue;
    std::string address;
    int port = 0;
    if (readPeer(static_cast<int>(fd), address, port) && port == peerPort && address == peerAddress) {
      found = PeerWatch(static_cast<int>(fd));
      break;
    }
  }
  ::closedir(dir);
  return found;
}

bool PeerWatch::isGone() const {
  pollfd p{socket_, POLLRDHUP, 0};
  if (::poll(&p, 1, 0) <= 0) return false;
  return (p.revents & (POLLRDHUP | POLLHUP | POLLERR | POLLNVAL)) != 0;
}

}  // namespace swingsim
