#include "serve/request_deadline.h"

#include <sys/socket.h>

#include <set>

#include "serve/peer_watch.h"

namespace swingsim {

RequestDeadline::RequestDeadline(int port, std::chrono::milliseconds deadline, std::chrono::milliseconds period)
    : port_(port), deadline_(deadline), period_(period), thread_([this] { watch(); }) {}

RequestDeadline::~RequestDeadline() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void RequestDeadline::start(const std::string& peer) {
  std::lock_guard<std::mutex> lock(mutex_);
  connections_[peer].answering = true;
}

void RequestDeadline::finish(const std::string& peer) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = connections_.find(peer);
  if (it == connections_.end()) return;
  it->second.answering = false;
  it->second.since = std::chrono::steady_clock::now();
}

int RequestDeadline::getShutDowns() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return shutDowns_;
}

void RequestDeadline::watch() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, period_, [this] { return stopping_; });
    if (stopping_) break;
    lock.unlock();
    const auto peers = listSocketPeers();
    lock.lock();
    check(std::chrono::steady_clock::now(), peers);
  }
}

void RequestDeadline::check(std::chrono::steady_clock::time_point now, const std::vector<SocketPeer>& peers) {
  std::set<std::string> open;
  for (const SocketPeer& p : peers) {
    if (p.localPort != port_) continue;
    const std::string key = makePeerKey(p.address, p.port);
    open.insert(key);
    auto [it, added] = connections_.try_emplace(key);
    Connection& c = it->second;
    if (added || c.socket != p.socket) {  // new (or the descriptor now serves another connection)
      c.socket = p.socket;
      c.since = now;  // a new connection is not answering (Connection's default)
    }
    if (!c.answering && now - c.since > deadline_) {
      // The descriptor is checked again just before: it may have been closed and reused since.
      const std::optional<SocketPeer> still = describeSocket(c.socket);
      if (!still || still->address != p.address || still->port != p.port) continue;
      ::shutdown(c.socket, SHUT_RDWR);  // cpp-httplib's read fails and it closes the connection
      c.since = now;
      ++shutDowns_;
    }
  }
  // Connections that have closed, unless a handler still has them.
  for (auto it = connections_.begin(); it != connections_.end();)
    it = open.count(it->first) || it->second.answering ? std::next(it) : connections_.erase(it);
}

}  // namespace swingsim
