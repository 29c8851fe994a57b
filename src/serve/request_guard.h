#pragma once
// Which requests swingsim serve answers: only those addressed to the server itself (the
// Host header names the bound address and port, which a DNS-rebinding page cannot fake)
// and, when the browser says where the request comes from (Origin), only from the
// server's own page (another page open in the same browser is refused).
#include <string>
#include <vector>

namespace swingsim {

class RequestGuard {
 public:
  /// A server bound to `host` (an address such as 127.0.0.1, or a name) at `port`. The
  /// loopback names (127.0.0.1, localhost, [::1]) are accepted when `host` is a loopback
  /// address.
  RequestGuard(const std::string& host, int port);

  /// "" if a request with these Host and Origin headers ("" = absent) may be answered, else
  /// why not ("Host 'evil.example:8080' is not this server's (expected 127.0.0.1:8080)").
  std::string checkRequest(const std::string& hostHeader, const std::string& originHeader) const;

  /// The address the page is opened at: http://HOST:PORT/ ([::1] for an IPv6 host).
  std::string getOrigin() const;

 private:
  std::vector<std::string> hosts_;  // accepted Host values, "name:port"
};

/// True for 127.0.0.0/8, ::1 and "localhost".
bool isLoopbackHost(const std::string& host);

}  // namespace swingsim
