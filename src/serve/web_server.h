#pragma once
// swingsim serve's HTTP server (Debian's cpp-httplib: header only, a thread pool, a body
// size limit and a hook before routing for the Host/Origin checks): the page
// (serve/page_assets.h) and the JSON API (serve/serve_api.h). Every request passes the
// RequestGuard first; bodies above ServeLimits::maxBodyBytes are refused (413).
#include <chrono>
#include <memory>
#include <string>

#include "serve/leg_request.h"

namespace swingsim {

struct ServeOptions {
  std::string host = "127.0.0.1";  ///< address to bind; loopback unless the user says otherwise
  /// Port to bind; 0: any free port. With `firstFree`, the first free port from `port` up
  /// (`port` .. `port` + 99), for the default 8080.
  int port = 8080;
  bool firstFree = false;
  std::string dataDir = ".";  ///< holds participants/ and models/
  /// API calls computed at once (others wait for a slot); the server holds 4 connections
  /// per slot, at least 16, so idle or slow connections do not hold the compute.
  int threads = 4;
  /// A connection outside a request handler for longer than this (a request sent a byte at a
  /// time) is shut down (serve/request_deadline.h); keep-alive idling ends after 2 s anyway.
  std::chrono::milliseconds requestDeadline{10000};
  ServeLimits limits;
};

class WebServer {
 public:
  /// Lists the shipped files (ShippedFiles; throws InputError) and binds the port (throws
  /// RunError if it cannot).
  explicit WebServer(const ServeOptions& options);
  ~WebServer();
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  int getPort() const;
  /// http://HOST:PORT/
  std::string getOrigin() const;
  /// Answers requests until stop(); returns then.
  void run();
  /// Ends run() after the requests under way; safe from another thread once isRunning().
  void stop();
  /// run() is answering requests.
  bool isRunning() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swingsim
