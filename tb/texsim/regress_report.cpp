#include "texsim/regress_report.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "common/atomic_file.hpp"

namespace tmu::texsim {
namespace {

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        // XML 1.0 has no control characters but tab, newline and return.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          out += '?';
        } else {
          out += c;
        }
    }
  }
  return out;
}

// The last `lines` lines of a log: where texsim says what failed.
std::string log_tail(const std::filesystem::path& log, size_t lines) {
  std::ifstream in(log);
  std::vector<std::string> all;
  for (std::string l; std::getline(in, l);) all.push_back(l);
  std::string out;
  for (size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i)
    out += all[i] + "\n";
  return out;
}

std::string verdict(const RegressResult& r) {
  if (r.timed_out) return "killed after the timeout";
  if (r.exit_code == 1) return "a model disagreed (exit 1)";
  if (r.exit_code == 2) return "bad input or argument (exit 2)";
  return fmt::format("exit {}", r.exit_code);
}

}  // namespace

std::string command_line(const std::vector<std::string>& command) {
  std::string out;
  for (const std::string& a : command) {
    const bool plain = a.find_first_of(" \t'\"\\$*?;&|<>()") == std::string::npos && !a.empty();
    std::string quoted = "'";
    for (char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += (out.empty() ? "" : " ") + (plain ? a : quoted + "'");
  }
  return out;
}

void write_junit(const std::filesystem::path& path, const std::string& suite,
                 const std::vector<RegressResult>& results) {
  size_t failures = 0;
  double seconds = 0;
  for (const RegressResult& r : results) {
    failures += !r.passed();
    seconds += r.seconds;
  }
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x << fmt::format("<testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" time=\"{:.3f}\">\n",
                   xml_escaped(suite), results.size(), failures, seconds);
  for (const RegressResult& r : results) {
    x << fmt::format("  <testcase classname=\"{}\" name=\"{}\" time=\"{:.3f}\">\n",
                     xml_escaped(r.test.kind), xml_escaped(r.test.name), r.seconds);
    if (!r.passed()) {
      std::string body = "reproduce: " + command_line(r.command) + "\n";
      for (const auto& w : r.waveforms) body += "waveform: " + w.string() + "\n";
      body += "log: " + r.log.string() + "\n" + log_tail(r.log, 20);
      x << fmt::format("    <failure message=\"{}\">{}</failure>\n", xml_escaped(verdict(r)),
                       xml_escaped(body));
    }
    x << fmt::format("    <system-out>{}</system-out>\n", xml_escaped(r.log.string()));
    x << "  </testcase>\n";
  }
  x << "</testsuite>\n";
  write_file_atomically(path, x.str());
}

std::string summary(const std::string& list, const std::vector<RegressResult>& results,
                    double seconds, int jobs) {
  size_t failures = 0;
  for (const RegressResult& r : results) failures += !r.passed();
  std::string out =
      fmt::format("regression {}: {} tests, {} passed, {} failed, {:.1f} s on {} jobs\n", list,
                  results.size(), results.size() - failures, failures, seconds, jobs);
  for (const RegressResult& r : results) {
    if (r.passed()) continue;
    out += fmt::format("\nFAIL {}: {} after {:.1f} s\n  reproduce: {}\n", r.test.name, verdict(r),
                       r.seconds, command_line(r.command));
    for (const auto& w : r.waveforms) out += fmt::format("  waveform: {}\n", w.string());
    out += fmt::format("  log: {}\n", r.log.string());
  }
  return out;
}

}  // namespace tmu::texsim
