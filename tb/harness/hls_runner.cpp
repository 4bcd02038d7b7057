#include "harness/hls_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

// Debian's libsystemc provides a main() that calls sc_main, so the library needs the symbol.
// Our programs have their own main and start SystemC only here, so it is never called.
extern "C" int sc_main(int, char**) { return 1; }

namespace tmu::tb {
namespace {

// A flat byte encoding of RunResult for the pipe.
void put(std::string& out, const void* p, size_t n) { out.append(static_cast<const char*>(p), n); }
void put_u64(std::string& out, uint64_t v) { put(out, &v, sizeof v); }
void put_str(std::string& out, const std::string& s) {
  put_u64(out, s.size());
  out += s;
}

struct Reader {
  const std::string& in;
  size_t at = 0;
  void get(void* p, size_t n) {
    if (at + n > in.size()) throw std::runtime_error("hls child: truncated result");
    std::memcpy(p, in.data() + at, n);
    at += n;
  }
  uint64_t u64() {
    uint64_t v = 0;
    get(&v, sizeof v);
    return v;
  }
  std::string str() {
    const uint64_t n = u64();
    if (at + n > in.size()) throw std::runtime_error("hls child: truncated result");
    std::string s = in.substr(at, n);
    at += n;
    return s;
  }
};

std::string encode(const RunResult& r) {
  std::string out;
  put_u64(out, r.outputs.size());
  for (size_t i = 0; i < r.outputs.size(); ++i) {
    put(out, r.outputs[i].f.data(), sizeof r.outputs[i].f);
    put_u64(out, r.output_cycles[i]);
  }
  put_u64(out, r.cycles);
  put_u64(out, r.counters.size());
  for (const auto& [name, value] : r.counters) {
    put_str(out, name);
    put_u64(out, value);
  }
  put_u64(out, r.requests.size());
  for (const std::vector<Txn>& channel : r.requests) {
    put_u64(out, channel.size());
    for (const Txn& t : channel) put(out, t.f.data(), sizeof t.f);
  }
  put(out, &r.seconds, sizeof r.seconds);
  put_str(out, r.error);
  return out;
}

RunResult decode(const std::string& in) {
  Reader rd{in};
  RunResult r;
  const uint64_t n = rd.u64();
  r.outputs.resize(n);
  r.output_cycles.resize(n);
  for (size_t i = 0; i < n; ++i) {
    rd.get(r.outputs[i].f.data(), sizeof r.outputs[i].f);
    r.output_cycles[i] = rd.u64();
  }
  r.cycles = rd.u64();
  const uint64_t nc = rd.u64();
  for (uint64_t i = 0; i < nc; ++i) {
    std::string name = rd.str();
    r.counters.emplace_back(std::move(name), rd.u64());
  }
  r.requests.resize(rd.u64());
  for (std::vector<Txn>& channel : r.requests) {
    channel.resize(rd.u64());
    for (Txn& t : channel) rd.get(t.f.data(), sizeof t.f);
  }
  rd.get(&r.seconds, sizeof r.seconds);
  r.error = rd.str();
  return r;
}

bool write_all(int fd, const std::string& data) {
  size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
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
    const bool ok = write_all(fds[1], encode(r));
    ::close(fds[1]);
    std::fflush(nullptr);
    ::_exit(ok ? 0 : 3);
  }
  ::close(fds[1]);
  std::string data;
  char buf[1 << 16];
  ssize_t n;
  while ((n = ::read(fds[0], buf, sizeof buf)) > 0) data.append(buf, static_cast<size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    RunResult r;
    r.error = WIFSIGNALED(status)
                  ? "hls child killed by signal " + std::to_string(WTERMSIG(status))
                  : "hls child exited with status " + std::to_string(WEXITSTATUS(status));
    return r;
  }
  return decode(data);
}

}  // namespace tmu::tb
