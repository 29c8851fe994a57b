#include "serve/web_server.h"

#include <httplib.h>

#include <algorithm>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>

#include "core/input_error.h"
#include "serve/page_assets.h"
#include "serve/peer_watch.h"
#include "serve/request_deadline.h"
#include "serve/request_guard.h"
#include "serve/serve_api.h"

namespace swingsim {
namespace {

constexpr int kFirstFreeTries = 100;  // ports tried from the default 8080 up
// cpp-httplib gives each connection a pool thread for as long as it is open: an idle keep-alive
// connection or a slow sender holds one. The pool therefore has this many connections per
// compute slot (at least kMinConnections), the compute itself is limited to ServeOptions::threads
// (ComputeSlots), and an idle keep-alive connection is closed after kKeepAliveS.
constexpr int kConnectionsPerSlot = 4;
constexpr int kMinConnections = 16;
constexpr int kKeepAliveS = 2;

// At most `n` API calls compute at once; the others wait for a slot (their connection stays).
class ComputeSlots {
 public:
  explicit ComputeSlots(int n) : free_(std::max(1, n)) {}
  void acquire() {
    std::unique_lock<std::mutex> lock(mutex_);
    freed_.wait(lock, [this] { return free_ > 0; });
    --free_;
  }
  void release() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++free_;
    }
    freed_.notify_one();
  }

 private:
  std::mutex mutex_;
  std::condition_variable freed_;
  int free_;
};

// The page may load its own files and talk to its own origin only; no other site may frame it.
constexpr const char* kContentSecurityPolicy =
    "default-src 'none'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data:; connect-src "
    "'self'; "
    "frame-ancestors 'none'; base-uri 'none'; form-action 'none'";

const char* contentTypeOf(const std::string& name) {
  if (name.size() > 3 && name.compare(name.size() - 3, 3, ".js") == 0) return "text/javascript; charset=utf-8";
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".css") == 0) return "text/css; charset=utf-8";
  return "text/html; charset=utf-8";
}

void sendJson(httplib::Response& res, int status, const std::string& body) {
  res.status = status;
  res.set_content(body, "application/json");
}

int bindPort(httplib::Server& server, const ServeOptions& o) {
  if (o.port == 0) return server.bind_to_any_port(o.host);
  for (int k = 0; k < (o.firstFree ? kFirstFreeTries : 1); ++k)
    if (server.bind_to_port(o.host, o.port + k)) return o.port + k;
  return -1;
}

}  // namespace

struct WebServer::Impl {
  ServeApi api;
  httplib::Server server;
  int port = -1;
  std::optional<RequestGuard> guard;
  ComputeSlots slots;
  std::optional<RequestDeadline> deadline;  // last: its watchdog stops first

  explicit Impl(const ServeOptions& o) : api(ShippedFiles(o.dataDir), o.limits), slots(o.threads) {}
  void addRoutes();
  void addGuard();
};

void WebServer::Impl::addGuard() {
  server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    const std::string problem = guard->checkRequest(req.get_header_value("Host"), req.get_header_value("Origin"));
    if (problem.empty()) return httplib::Server::HandlerResponse::Unhandled;
    sendJson(res, 403, Json{{"error", problem}}.dump());
    return httplib::Server::HandlerResponse::Handled;
  });
}

void WebServer::Impl::addRoutes() {
  // The page's files by fixed name: a request path never becomes a file path.
  server.Get(R"(/(|index\.html|page\.js|page\.css))", [](const httplib::Request& req, httplib::Response& res) {
    const std::string name = req.matches[1].str().empty() ? "index.html" : req.matches[1].str();
    const auto asset = findPageAsset(name);
    if (!asset) return sendJson(res, 404, R"({"error":"no such page file"})");
    res.set_content(std::string(*asset), contentTypeOf(name));
  });
  server.Get("/api/files", [this](const httplib::Request&, httplib::Response& res) {
    const ApiReply r = api.listFiles();
    sendJson(res, r.status, r.body);
  });
  // Each call's own body limit (an .osim upload's is larger than the others'), and a compute
  // slot while it answers.
  const auto answer = [this](const char* path, std::size_t maxBytes,
                             std::function<ApiReply(const httplib::Request&)> call) {
    server.Post(path, [this, maxBytes, call](const httplib::Request& req, httplib::Response& res) {
      if (req.body.size() > maxBytes)
        return sendJson(res, 413,
                        Json{{"error", "request body: expected at most " + std::to_string(maxBytes) + " bytes (got " +
                                           std::to_string(req.body.size()) + ")"}}
                            .dump());
      // Exempt from the request deadline while it is answered (a tuning takes up to 30 s).
      struct Answering {
        RequestDeadline& d;
        std::string peer;
        ~Answering() { d.finish(peer); }
      } answering{*deadline, makePeerKey(req.remote_addr, req.remote_port)};
      deadline->start(answering.peer);
      slots.acquire();
      struct Release {
        ComputeSlots& s;
        ~Release() { s.release(); }
      } release{slots};
      const ApiReply r = call(req);
      sendJson(res, r.status, r.body);
    });
  };
  const auto post = [this, &answer](const char* path, ApiReply (ServeApi::*call)(const std::string&) const,
                                    std::size_t maxBytes) {
    answer(path, maxBytes, [this, call](const httplib::Request& req) { return (api.*call)(req.body); });
  };
  const ServeLimits& limits = api.getLimits();
  post("/api/participant", &ServeApi::describeParticipant, limits.maxBodyBytes);
  post("/api/simulate", &ServeApi::simulate, limits.maxBodyBytes);
  post("/api/sweep", &ServeApi::sweep, limits.maxBodyBytes);
  post("/api/report", &ServeApi::report, limits.maxBodyBytes);
  post("/api/export_osim", &ServeApi::exportOsim, limits.maxBodyBytes);
  post("/api/import_osim", &ServeApi::importOsim, limits.maxOsimBytes);
  // A tuning runs for up to its budget (30 s): it stops when its client has gone (a closed
  // page, a cancelled fetch), found by its socket's peer (cpp-httplib 0.11 gives a handler
  // no connection state; serve/peer_watch.h).
  answer("/api/tune", limits.maxBodyBytes, [this](const httplib::Request& req) {
    const std::optional<PeerWatch> peer = PeerWatch::find(req.remote_addr, req.remote_port);
    return api.tune(req.body, [&peer] { return peer && peer->isGone(); });
  });
  server.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (res.body.empty()) sendJson(res, res.status, Json{{"error", "HTTP " + std::to_string(res.status)}}.dump());
  });
}

WebServer::WebServer(const ServeOptions& options) : impl_(std::make_unique<Impl>(options)) {
  Impl& s = *impl_;
  const int connections = std::max(kMinConnections, kConnectionsPerSlot * options.threads);
  s.server.new_task_queue = [connections] { return new httplib::ThreadPool(static_cast<std::size_t>(connections)); };
  s.server.set_keep_alive_timeout(kKeepAliveS);
  s.server.set_payload_max_length(std::max(options.limits.maxBodyBytes, options.limits.maxOsimBytes));
  s.server.set_default_headers({{"Content-Security-Policy", kContentSecurityPolicy},
                                {"X-Content-Type-Options", "nosniff"},
                                {"Referrer-Policy", "no-referrer"},
                                {"Cache-Control", "no-store"}});
  // SO_REUSEADDR only: cpp-httplib's default adds SO_REUSEPORT, which would let a second
  // server (the user's own, or another program of the same user) share the port and take
  // part of the requests; the first free port is then not found either.
  s.server.set_socket_options([](int sock) {  // httplib's socket_t is int on POSIX
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
  });
  s.port = bindPort(s.server, options);
  if (s.port <= 0)
    throw RunError("swingsim serve: cannot listen on " + options.host + " port " + std::to_string(options.port) +
                   (options.firstFree ? " or the next " + std::to_string(kFirstFreeTries - 1) : std::string()) +
                   " (in use, or not an address of this machine)");
  s.guard.emplace(options.host, s.port);
  // Checked four times a deadline, at most every 250 ms.
  s.deadline.emplace(
      s.port, options.requestDeadline,
      std::min(std::chrono::milliseconds(250), std::max(std::chrono::milliseconds(1), options.requestDeadline / 4)));
  s.addGuard();
  s.addRoutes();
}

WebServer::~WebServer() = default;

int WebServer::getPort() const { return impl_->port; }
std::string WebServer::getOrigin() const { return impl_->guard->getOrigin(); }
void WebServer::run() { impl_->server.listen_after_bind(); }
void WebServer::stop() {
  impl_->api.requestStop();  // a tuning under way ends at its next swing (SIGTERM waited for all of it)
  impl_->server.stop();
}
bool WebServer::isRunning() const { return impl_->server.is_running(); }

}  // namespace swingsim
