// swingsim serve [--port N] [--host H] [--data DIR]: the page and JSON API of
// serve/web_server.h on this machine, until Ctrl-C (docs/serve.md).
#include <atomic>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>

#include "cli/command.h"
#include "cli/sweep_steps.h"
#include "serve/request_guard.h"
#include "serve/web_server.h"

namespace swingsim::cli {
namespace {

constexpr int kDefaultPort = 8080;
constexpr auto kStopPoll = std::chrono::milliseconds(100);  // how often Ctrl-C is looked for

struct ServeArguments {
  std::optional<int> port;
  std::optional<std::string> host;
  std::string data = ".";
};

int runServe(const ServeArguments& a) {
  ServeOptions options;
  options.host = a.host.value_or("127.0.0.1");
  options.port = a.port.value_or(kDefaultPort);
  options.firstFree = !a.port;
  options.dataDir = a.data;
  if (!isLoopbackHost(options.host))
    std::fprintf(stderr,
                 "swingsim serve: WARNING: listening on %s, not on loopback: anyone who can reach this address can run "
                 "simulations here (no login, no encryption). Stop with Ctrl-C unless you meant it.\n",
                 options.host.c_str());
  WebServer server(options);
  InterruptScope interrupt;  // Ctrl-C and SIGTERM set gInterrupted; the watcher below stops the server
  std::printf("swingsim serve: %s\n", server.getOrigin().c_str());
  std::fflush(stdout);
  std::atomic<bool> runEnded{false};
  std::thread watcher([&server, &runEnded] {
    while (!runEnded) {
      if (gInterrupted && server.isRunning()) return server.stop();
      std::this_thread::sleep_for(kStopPoll);
    }
  });
  server.run();
  runEnded = true;  // run() ended (stopped, or a socket error): the watcher ends too
  watcher.join();
  std::printf("swingsim serve: stopped\n");
  return 0;
}

}  // namespace

Command addServeCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "serve", "a local web page and JSON API: one swing as the knobs move, the sweep (docs/serve.md)");
  auto a = std::make_shared<ServeArguments>();
  sub->add_option_function<int>(
         "--port", [a](int v) { a->port = v; },
         "TCP port, 0 for any free one (default 8080, or the first free one above it)")
      ->type_name("N")
      ->check(CLI::Range(0, 65535));
  sub->add_option_function<std::string>(
         "--host", [a](const std::string& v) { a->host = v; },
         "address to listen on (default 127.0.0.1, this machine only; any other is "
         "reachable by others and is warned about)")
      ->type_name("H");
  sub->add_option("--data", a->data,
                  "folder holding the shipped participants/ and models/ (default: the current folder)")
      ->type_name("DIR");
  return {sub, [a] { return runServe(*a); }};
}

}  // namespace swingsim::cli
