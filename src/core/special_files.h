#pragma once
// Files that are not plain files: FIFOs (named pipes), devices and links to them, as a shell
// loop or a container hands them over (`--json /dev/stdout`, `<(...)`, `mkfifo`). Opening
// one never blocks for ever: a FIFO is opened non-blocking and waited on for at most
// kFifoWaitSeconds for its other end (docs/robustness.md, "Pipes, devices and links").
#include <cstddef>
#include <string>

namespace swingsim {

/// Longest wait for the other end of a FIFO, s: a writer for an input, a reader for an
/// output. A shell's `<(...)` or `mkfifo` partner starts within milliseconds; a FIFO
/// nobody serves is a mistake to report, not to wait on.
constexpr int kFifoWaitSeconds = 5;

/// Reads the whole of `path`, at most `maxBytes` (one byte more is read to tell that the
/// limit was passed; the caller words that error). Regular files and devices are read
/// directly; a FIFO is opened non-blocking and each wait for data is at most
/// kFifoWaitSeconds. Throws InputError naming the file if it cannot be opened, is a
/// directory, or its writer does not appear or stalls for kFifoWaitSeconds.
std::string readWithoutBlocking(const std::string& path, std::size_t maxBytes);

/// true if writing `path` must go through it, not replace it with a new file: it is (or a
/// link leads to) a FIFO, a device or a socket, or it is a link under /dev or /proc
/// (`/dev/stdout`, `/proc/self/fd/1`), which stands for an already open file. false for a
/// path that does not exist, a plain file, or a link to a plain file elsewhere (that file
/// is replaced atomically and the link kept: see resolveReplaceTarget).
bool isWriteThroughTarget(const std::string& path);

/// The file to replace atomically when writing `path`: the path itself, or for a link the
/// file it leads to, so the link stays a link.
std::string resolveReplaceTarget(const std::string& path);

/// Writes `contents` through `path` (a FIFO, a device or /dev/stdout; see
/// isWriteThroughTarget), appending, so an earlier output on the same stream is kept. A FIFO
/// is opened non-blocking and waited on for a reader for at most kFifoWaitSeconds. Throws
/// RunError naming the file if it cannot be opened or written (no reader, reader gone).
void writeThrough(const std::string& path, const std::string& contents);

/// `--json -`: standard output is kept for the data alone. From the first call on, what the
/// process prints to stdout goes to stderr, and the path returned (`/proc/self/fd/N`, a
/// duplicate of the original stdout, written through as isWriteThroughTarget says) reaches
/// the original stdout. The same path on every call. Throws RunError if the descriptors
/// cannot be duplicated.
std::string takeStandardOutputForData();

}  // namespace swingsim
