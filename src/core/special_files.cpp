#include "core/special_files.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <thread>

#include "core/input_error.h"

namespace swingsim {

namespace {

/// Closes a descriptor when it goes out of scope.
struct FdCloser {
  int fd;
  ~FdCloser() {
    if (fd >= 0) ::close(fd);
  }
};

std::string fifoWaitText() { return std::to_string(kFifoWaitSeconds) + " s"; }

// Waits for `fd` to have data or to be closed by its writer; false after kFifoWaitSeconds.
bool waitReadable(int fd) {
  pollfd p{fd, POLLIN, 0};
  for (;;) {
    const int ready = ::poll(&p, 1, kFifoWaitSeconds * 1000);
    if (ready > 0) return true;
    if (ready == 0) return false;
    if (errno != EINTR) return false;
  }
}

bool isUnder(const std::filesystem::path& path, const char* root) {
  std::error_code ec;
  const std::string text = std::filesystem::absolute(path, ec).lexically_normal().string();
  const std::string prefix = std::string(root) + "/";
  return text.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

std::string readWithoutBlocking(const std::string& path, std::size_t maxBytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(path + ": cannot open file (" + std::strerror(errno) + ")");
  const FdCloser closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) throw InputError(path + ": is a directory (expected a file)");
  const bool fifo = S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode);
  // A FIFO opened without a writer reads as empty (0 bytes) until one connects: only after
  // some data or a writer's close (POLLHUP) is a 0 the end of the file.
  bool writerSeen = !fifo;
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= maxBytes) {
    const ssize_t n = ::read(fd, chunk, std::min(sizeof chunk, maxBytes + 1 - text.size()));
    if (n > 0) {
      text.append(chunk, static_cast<std::size_t>(n));
      writerSeen = true;
      continue;
    }
    if (n == 0 && writerSeen) break;
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)
      throw InputError(path + ": read error (" + std::strerror(errno) + ")");
    if (!waitReadable(fd))
      throw InputError(path +
                       (fifo ? (writerSeen ? ": a FIFO (named pipe) whose writer sent nothing for "
                                           : ": a FIFO (named pipe) that nobody writes: waited ")
                             : ": no data for ") +
                       fifoWaitText() + " (the limit; start the program that writes it first, or give a plain file)");
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 0) > 0 && (p.revents & POLLHUP)) writerSeen = true;
  }
  return text;
}

bool isWriteThroughTarget(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(path, ec);
  if (ec || !fs::exists(link)) return false;
  const fs::file_status target = fs::status(path, ec);
  if (ec) return false;  // a dangling link: replaced like a missing file's target
  if (fs::is_character_file(target) || fs::is_block_file(target) || fs::is_fifo(target) || fs::is_socket(target))
    return true;
  // /dev/stdout -> /proc/self/fd/1 -> the file the shell redirected to: writing a new file
  // there would replace the link, or a file the shell still writes through.
  return fs::is_symlink(link) && (isUnder(path, "/dev") || isUnder(path, "/proc"));
}

std::string resolveReplaceTarget(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_symlink(fs::symlink_status(path, ec))) return path;
  const fs::path target = fs::weakly_canonical(path, ec);
  return ec ? path : target.string();
}

void writeThrough(const std::string& path, const std::string& contents) {
  // Text printed to stdout before must come out before this file's (when it is /dev/stdout).
  std::fflush(stdout);
  std::fflush(stderr);
  int fd = -1;
  // The process's own stdout or stderr (/dev/stdout while stdout goes to a file): written
  // through a duplicate of that descriptor, which shares its offset, so the text printed
  // after follows this file's contents instead of overwriting them (`--json
  // /dev/stdout > file` opened the file a second time at its own offset).
  struct stat target {};
  if (::stat(path.c_str(), &target) == 0)
    for (const int own : {STDOUT_FILENO, STDERR_FILENO}) {
      struct stat open {};
      if (fd < 0 && ::fstat(own, &open) == 0 && open.st_dev == target.st_dev && open.st_ino == target.st_ino)
        fd = ::dup(own);
    }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kFifoWaitSeconds);
  while (fd < 0) {
    fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd >= 0) break;
    // ENXIO: a FIFO without a reader yet.
    if (errno != ENXIO && errno != EINTR) throw RunError(path + ": cannot write (" + std::strerror(errno) + ")");
    if (std::chrono::steady_clock::now() >= deadline)
      throw RunError(path + ": a FIFO (named pipe) that nobody reads: waited " + fifoWaitText() +
                     " (the limit) for a reader; start the reader first, or give a plain file");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const FdCloser closer{fd};
  // Blocking writes from here: a reader that reads slowly is waited for.
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  // A reader that goes away must give an error, not kill the process with SIGPIPE.
  struct sigaction ignore {
  }, before{};
  ignore.sa_handler = SIG_IGN;
  ::sigaction(SIGPIPE, &ignore, &before);
  std::size_t done = 0;
  int error = 0;
  while (done < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + done, contents.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n < 0 && errno != EINTR) {
      error = errno;
      break;
    }
  }
  ::sigaction(SIGPIPE, &before, nullptr);
  if (error)
    throw RunError(path + ": write failed after " + std::to_string(done) + " of " + std::to_string(contents.size()) +
                   " bytes (" + std::strerror(error) + ")");
}

std::string takeStandardOutputForData() {
  static std::mutex mutex;
  static std::string path;
  std::lock_guard<std::mutex> lock(mutex);
  if (!path.empty()) return path;
  std::cout.flush();
  std::fflush(stdout);
  const int saved = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  if (saved < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0)
    throw RunError(std::string("--json -: cannot keep standard output for the JSON (") + std::strerror(errno) + ")");
  path = "/proc/self/fd/" + std::to_string(saved);
  return path;
}

}  // namespace swingsim
