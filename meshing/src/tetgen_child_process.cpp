#include "tetgen_child_process.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <stdio_ext.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <vector>

namespace tetblend {
namespace detail {
namespace {

// TetGen recurses in places; the child's thread gets a generous stack
// (address space only; pages are touched on demand).
constexpr std::size_t kChildStackBytes = std::size_t{256} << 20;
// Child report: header, then #P*3 doubles and #T*corners ints.
constexpr std::int32_t kReportOk = 0;
constexpr std::int32_t kReportTetGenError = 1;
// Longer limits are this one (a year: no overflow of the clock's ticks).
constexpr double kLongestLimitSeconds = 3.2e7;
// Code reported when TetGen threw something that is not its int code.
constexpr std::int32_t kUnknownThrow = -1;

struct ReportHeader {
  std::int32_t status;
  std::int32_t code;
  std::int32_t corners;
  std::int32_t padding;
  std::int64_t points;
  std::int64_t tets;
};

bool writeAll(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// State of the child process (one TetGen run per child, set before the
// thread starts).
struct ChildState {
  int writeFd = -1;
  bool flushStdout = false;
  std::vector<char> switches;
  tetgenio* in = nullptr;
};
ChildState gChild;

[[noreturn]] void leaveChild(int status) {
  if (gChild.flushStdout) {
    std::fflush(stdout);
    std::fflush(stderr);
  }
  ::_exit(status);
}

// Reached when TetGen's throw finds no handler on the child's thread: no
// destructor has run yet, so the double free of TetGen's error path is
// never reached.
[[noreturn]] void onUncaughtInChild() {
  std::int32_t code = kUnknownThrow;
  try {
    const std::exception_ptr e = std::current_exception();
    if (e) std::rethrow_exception(e);
  } catch (int tetgenCode) {
    code = tetgenCode;
  } catch (const std::bad_alloc&) {
    code = 1;  // TetGen's own code for out of memory
  } catch (...) {
  }
  const ReportHeader header{kReportTetGenError, code, 0, 0, 0, 0};
  writeAll(gChild.writeFd, &header, sizeof header);
  leaveChild(1);
}

// Thread body: deliberately without any try block, see onUncaughtInChild.
void* runOnChildThread(void*) {
  tetgenio out;
  ::tetrahedralize(gChild.switches.data(), gChild.in, &out);
  const std::int64_t nTets = out.tetrahedronlist != nullptr ? out.numberoftetrahedra : 0;
  const ReportHeader header{kReportOk, 0, out.numberofcorners, 0, out.numberofpoints, nTets};
  const bool ok =
      writeAll(gChild.writeFd, &header, sizeof header) &&
      writeAll(gChild.writeFd, out.pointlist, sizeof(double) * 3 * std::size_t(header.points)) &&
      writeAll(gChild.writeFd, out.tetrahedronlist,
               sizeof(int) * std::size_t(header.corners) * std::size_t(nTets));
  leaveChild(ok ? 0 : 2);
}

[[noreturn]] void childMain(int writeFd, const std::string& switches, tetgenio& in, bool silence) {
  // Bytes the parent had buffered but not yet written are its own: drop them.
  __fpurge(stdout);
  __fpurge(stderr);
  if (silence) {
    const int devNull = ::open("/dev/null", O_WRONLY);
    if (devNull >= 0) {
      ::dup2(devNull, STDOUT_FILENO);
      ::dup2(devNull, STDERR_FILENO);
    }
  }
  gChild.writeFd = writeFd;
  gChild.flushStdout = !silence;
  gChild.switches.assign(switches.begin(), switches.end());
  gChild.switches.push_back('\0');
  gChild.in = &in;
  std::set_terminate(onUncaughtInChild);
  pthread_attr_t attributes;
  pthread_t thread;
  if (pthread_attr_init(&attributes) != 0 ||
      pthread_attr_setstacksize(&attributes, kChildStackBytes) != 0 ||
      pthread_create(&thread, &attributes, runOnChildThread, nullptr) != 0) {
    ::_exit(3);
  }
  pthread_join(thread, nullptr);  // the thread leaves the process itself
  ::_exit(4);
}

using Clock = std::chrono::steady_clock;

// Milliseconds left until `deadline` for poll(): -1 (wait without limit) when
// there is no deadline, else at least 0.
int pollTimeout(const Clock::time_point* deadline) {
  if (deadline == nullptr) return -1;
  const auto left = std::chrono::ceil<std::chrono::milliseconds>(*deadline - Clock::now());
  return static_cast<int>(std::max<std::chrono::milliseconds::rep>(0, left.count()));
}

// Reads `fd` to its end; false when `deadline` (if any) passed first.
bool readAll(int fd, const Clock::time_point* deadline, std::vector<char>& bytes) {
  char chunk[1 << 16];
  for (;;) {
    pollfd ready{fd, POLLIN, 0};
    const int polled = ::poll(&ready, 1, pollTimeout(deadline));
    if (polled < 0 && errno == EINTR) continue;
    if (polled == 0) return false;
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    bytes.insert(bytes.end(), chunk, chunk + n);
  }
}

TetGenChildResult broken(const std::string& detail) {
  TetGenChildResult result;
  result.status = TetGenChildStatus::kBrokenChild;
  result.detail = detail;
  return result;
}

}  // namespace

TetGenChildResult runTetGenInChild(const std::string& switches, tetgenio& in, bool silence,
                                   double timeLimitSeconds) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    return broken(std::string("cannot create a pipe: ") + std::strerror(errno));
  }
  if (!silence) std::fflush(stdout);  // keep the parent's output before TetGen's
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    return broken(std::string("cannot fork: ") + std::strerror(error));
  }
  if (pid == 0) {
    ::close(fds[0]);
    childMain(fds[1], switches, in, silence);
  }
  ::close(fds[1]);
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                         std::min(timeLimitSeconds, kLongestLimitSeconds)));
  std::vector<char> bytes;
  const bool finished = readAll(fds[0], timeLimitSeconds > 0.0 ? &deadline : nullptr, bytes);
  ::close(fds[0]);
  if (!finished) ::kill(pid, SIGKILL);
  int waitStatus = 0;
  while (::waitpid(pid, &waitStatus, 0) < 0) {
    if (errno != EINTR) return broken(std::string("waitpid failed: ") + std::strerror(errno));
  }
  if (!finished) {
    TetGenChildResult result;
    result.status = TetGenChildStatus::kTimedOut;
    return result;
  }
  if (WIFSIGNALED(waitStatus)) {
    TetGenChildResult result;
    result.status = TetGenChildStatus::kSignal;
    result.code = WTERMSIG(waitStatus);
    result.detail = strsignal(result.code);
    return result;
  }
  ReportHeader header{};
  if (bytes.size() < sizeof header) {
    return broken("the TetGen process ended (exit status " +
                  std::to_string(WIFEXITED(waitStatus) ? WEXITSTATUS(waitStatus) : -1) +
                  ") without a report");
  }
  std::memcpy(&header, bytes.data(), sizeof header);
  TetGenChildResult result;
  result.code = header.code;
  if (header.status == kReportTetGenError) {
    result.status = TetGenChildStatus::kTetGenError;
    return result;
  }
  const std::size_t pointBytes = sizeof(double) * 3 * std::size_t(header.points);
  const std::size_t tetBytes = sizeof(int) * std::size_t(header.corners) * std::size_t(header.tets);
  if (header.status != kReportOk || header.points < 0 || header.tets < 0 || header.corners < 0 ||
      bytes.size() != sizeof header + pointBytes + tetBytes) {
    return broken("the TetGen process sent an incomplete report (" + std::to_string(bytes.size()) +
                  " bytes)");
  }
  result.status = TetGenChildStatus::kOk;
  result.corners = header.corners;
  result.points.resize(header.points, 3);
  std::memcpy(result.points.data(), bytes.data() + sizeof header, pointBytes);
  if (header.corners == 4) {
    result.tets.resize(header.tets, 4);
    std::memcpy(result.tets.data(), bytes.data() + sizeof header + pointBytes, tetBytes);
  }
  return result;
}

}  // namespace detail
}  // namespace tetblend
