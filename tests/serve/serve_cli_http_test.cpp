// `swingsim serve` on the command line: the printed address, a page answered there, Ctrl-C
// (SIGINT) stopping it cleanly, the loud warning off loopback, and a bad data folder.
#include <httplib.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <regex>
#include <thread>

#include "../test_build.h"
#include "run_swingsim.h"

namespace swingsim::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

struct Served {
  pid_t pid;
  fs::path log;
};

Served startServe(const std::vector<std::string>& args, const std::string& name) {
  const fs::path log = suiteTempDir("serve_cli") / (name + ".log");
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::FILE* f = std::freopen(log.c_str(), "w", stdout);
    if (f == nullptr || ::dup2(STDOUT_FILENO, STDERR_FILENO) < 0) ::_exit(127);
    std::vector<char*> argv{const_cast<char*>(SWINGSIM_BINARY), const_cast<char*>("serve")};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(SWINGSIM_BINARY, argv.data());
    ::_exit(127);
  }
  return {pid, log};
}

// The port of the printed "swingsim serve: http://HOST:PORT/" line, waiting up to a minute.
int waitForPort(const Served& s) {
  static const std::regex line(R"(swingsim serve: http://[^ ]+:(\d+)/)");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  std::smatch m;
  while (std::chrono::steady_clock::now() < deadline) {
    const std::string text = slurp(s.log);
    if (std::regex_search(text, m, line)) return std::stoi(m[1]);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return -1;
}

CliRun stop(const Served& s) {
  ::kill(s.pid, SIGINT);
  int status = 0;
  ::waitpid(s.pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(s.log)};
}

TEST(ServeCli, PrintsItsAddressAnswersThereAndStopsOnCtrlC) {
  const Served s = startServe({"--port", "0"}, "loopback");
  const int port = waitForPort(s);
  ASSERT_GT(port, 0) << slurp(s.log);
  httplib::Client client("127.0.0.1", port);
  const auto r = client.Get("/api/files");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_THAT(r->body, HasSubstr("\"p1\""));
  const CliRun end = stop(s);
  EXPECT_EQ(end.code, 0) << end.output;
  EXPECT_THAT(end.output, HasSubstr("swingsim serve: http://127.0.0.1:" + std::to_string(port) + "/\n"));
  EXPECT_THAT(end.output, HasSubstr("swingsim serve: stopped"));
  EXPECT_THAT(end.output, ::testing::Not(HasSubstr("WARNING")));
}

// 192.0.2.1 (TEST-NET-1, RFC 5737) is no address of this machine: the warning comes first,
// then the bind fails, so the test never opens a port to the network.
TEST(ServeCli, WarnsLoudlyOffLoopback) {
  const CliRun r = runSwingsim("serve --port 0 --host 192.0.2.1");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("swingsim serve: WARNING: listening on 192.0.2.1, not on loopback"));
  EXPECT_THAT(r.output, HasSubstr("cannot listen on 192.0.2.1"));
}

TEST(ServeCli, RefusesADataFolderWithoutShippedFiles) {
  const CliRun r = runSwingsim("serve --port 0 --data " + suiteTempDir("serve_cli").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("participants: expected a folder of shipped files"));
}

}  // namespace
}  // namespace swingsim::testing
