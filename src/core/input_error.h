#pragma once
// The one error type for anything a user can get wrong in a file or on the command line.
// Messages follow `file:line: key: what is wrong (got VALUE)`.
#include <stdexcept>
#include <string>

namespace swingsim {

/// Thrown for bad user input (files, keys, values, arguments). The CLI prints the
/// message and exits with code 1.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

/// Thrown when a run fails for a physical or numerical reason (integrator failure,
/// a swing that never ends). The message says when, in what state, and the likely cause.
class RunError : public std::runtime_error {
 public:
  explicit RunError(const std::string& message) : std::runtime_error(message) {}
};

/// Formats a double for messages: shortest representation that round-trips.
std::string formatNumber(double value);
/// A time for a message, s, to 0.1 ms (formatNumber of the rounded value): a time computed
/// from events or samples would otherwise print 16 digits.
std::string formatSeconds(double seconds);

}  // namespace swingsim
