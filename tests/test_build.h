#pragma once
// What differs between build directories, for the tests: defined in the build's generated
// test_build.cpp (CMakeLists.txt), so every test file compiles to the same object in the plain
// and the sanitized build (and the compiler cache serves one to the other).

namespace swingsim::testing {
/// The command line built beside these tests (absolute path).
extern const char* const kSwingsimBinary;
/// Whether this build's libraries and command line carry the sanitizers (scripts/test.sh's
/// second pass).
extern const bool kSanitized;
}  // namespace swingsim::testing

/// The command line built beside these tests, as a C string.
#define SWINGSIM_BINARY (::swingsim::testing::kSwingsimBinary)
