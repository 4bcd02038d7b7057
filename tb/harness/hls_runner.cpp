#include "harness/hls_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <type_traits>

// Debian's libsystemc provides a main() that calls sc_main, so the library needs the symbol.
// Our programs have their own main and start SystemC only here, so it is never called.
extern "C" int sc_main(int, char**) { return 1; }

namespace tmu::tb {
namespace {

// RunResult through the pipe, its vectors' bytes written and read in place: a render's unit
// sends hundreds of megabytes of transactions (256 bytes each), and building the message in a
// string, reading it into another and decoding that copied them three more times (the copies
// and their page faults were most of an hls render's system time).
static_assert(std::is_trivially_copyable_v<Txn>);

class PipeWriter {
 public:
  explicit PipeWriter(int fd) : fd_(fd) {}
  bool ok() const { return ok_; }
  void bytes(const void* p, size_t n) {
    const auto* c = static_cast<const char*>(p);
    while (ok_ && n > 0) {
      const ssize_t k = ::write(fd_, c, n);
      if (k <= 0) {
        ok_ = false;
        return;
      }
      c += k;
      n -= static_cast<size_t>(k);
    }
  }
  void u64(uint64_t v) { bytes(&v, sizeof v); }
  void str(const std::string& s) {
    u64(s.size());
    bytes(s.data(), s.size());
  }
  template <typename T>
  void vec(const std::vector<T>& v) {
    u64(v.size());
    bytes(v.data(), v.size() * sizeof(T));
  }

 private:
  int fd_;
  bool ok_ = true;
};

class PipeReader {
 public:
  explicit PipeReader(int fd) : fd_(fd) {}
  void bytes(void* p, size_t n) {
    auto* c = static_cast<char*>(p);
    while (n > 0) {
      const ssize_t k = ::read(fd_, c, n);
      if (k <= 0) throw std::runtime_error("hls child: truncated result");
      c += k;
      n -= static_cast<size_t>(k);
    }
  }
  uint64_t u64() {
    uint64_t v = 0;
    bytes(&v, sizeof v);
    return v;
  }
  std::string str() {
    std::string s(u64(), '\0');
    bytes(s.data(), s.size());
    return s;
  }
  template <typename T>
  void vec(std::vector<T>& v) {
    v.resize(u64());
    bytes(v.data(), v.size() * sizeof(T));
  }

 private:
  int fd_;
};

bool send(int fd, const RunResult& r) {
  PipeWriter w(fd);
  w.vec(r.outputs);
  w.vec(r.output_cycles);
  w.u64(r.cycles);
  w.u64(r.counters.size());
  for (const auto& [name, value] : r.counters) {
    w.str(name);
    w.u64(value);
  }
  w.u64(r.requests.size());
  for (const std::vector<Txn>& channel : r.requests) w.vec(channel);
  w.bytes(&r.seconds, sizeof r.seconds);
  w.str(r.error);
  return w.ok();
}

RunResult receive(int fd) {
  PipeReader rd(fd);
  RunResult r;
  rd.vec(r.outputs);
  rd.vec(r.output_cycles);
  r.cycles = rd.u64();
  const uint64_t nc = rd.u64();
  for (uint64_t i = 0; i < nc; ++i) {
    std::string name = rd.str();
    r.counters.emplace_back(std::move(name), rd.u64());
  }
  r.requests.resize(rd.u64());
  for (std::vector<Txn>& channel : r.requests) rd.vec(channel);
  rd.bytes(&r.seconds, sizeof r.seconds);
  r.error = rd.str();
  return r;
}

}  // namespace

RunResult run_in_child(const std::function<RunResult()>& fn) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("hls: pipe failed");
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("hls: fork failed");
  if (pid == 0) {
    ::close(fds[0]);
    ::setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
    // The kernel's "simulation stopped by user" note is expected: every run ends by sc_stop.
    sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO,
                                            sc_core::SC_DO_NOTHING);
    RunResult r;
    try {
      r = fn();
    } catch (const std::exception& e) {
      r.error = std::string("hls: ") + e.what();
    }
    const bool ok = send(fds[1], r);
    ::close(fds[1]);
    std::fflush(nullptr);
    ::_exit(ok ? 0 : 3);
  }
  ::close(fds[1]);
  // Read before waiting: the child blocks on a full pipe until it is read. A child that dies
  // mid-way leaves a truncated result, reported by its exit status below.
  RunResult r;
  std::string truncated;
  try {
    r = receive(fds[0]);
  } catch (const std::exception& e) {  // a truncated result (or a size no vector can hold)
    truncated = e.what();
  }
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    RunResult failed;
    failed.error = WIFSIGNALED(status)
                       ? "hls child killed by signal " + std::to_string(WTERMSIG(status))
                       : "hls child exited with status " + std::to_string(WEXITSTATUS(status));
    return failed;
  }
  if (!truncated.empty()) throw std::runtime_error(truncated);
  return r;
}

}  // namespace tmu::tb
