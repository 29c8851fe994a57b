#include "serve/request_guard.h"

#include <algorithm>
#include <cctype>

namespace swingsim {
namespace {

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string hostWithPort(const std::string& host, int port) {
  const bool ipv6 = host.find(':') != std::string::npos && host.front() != '[';
  return (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

}  // namespace

bool isLoopbackHost(const std::string& host) {
  const std::string h = lowercase(host);
  return h == "localhost" || h == "::1" || h == "[::1]" || h.rfind("127.", 0) == 0;
}

RequestGuard::RequestGuard(const std::string& host, int port) {
  hosts_.push_back(lowercase(hostWithPort(host, port)));
  if (isLoopbackHost(host))
    for (const char* name : {"127.0.0.1", "localhost", "::1"}) {
      const std::string h = hostWithPort(name, port);
      if (std::find(hosts_.begin(), hosts_.end(), h) == hosts_.end()) hosts_.push_back(h);
    }
}

std::string RequestGuard::getOrigin() const { return "http://" + hosts_.front() + "/"; }

std::string RequestGuard::checkRequest(const std::string& hostHeader, const std::string& originHeader) const {
  const std::string host = lowercase(hostHeader);
  if (std::find(hosts_.begin(), hosts_.end(), host) == hosts_.end())
    return "Host '" + hostHeader + "' is not this server's (expected " + hosts_.front() + ")";
  if (originHeader.empty()) return "";  // a navigation or a command-line client: no other page involved
  const std::string origin = lowercase(originHeader);
  for (const std::string& h : hosts_)
    if (origin == "http://" + h) return "";
  return "Origin '" + originHeader + "' is not this server's page (expected http://" + hosts_.front() + ")";
}

}  // namespace swingsim
