// SPDX-License-Identifier: GPL-3.0-or-later
// The --cmd template adapter: any program, run as /bin/sh runs it once per case, as an audit engine.
#include "lepp/engines/command_engine.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "lepp/audit/run/subprocess.h"
#include "lepp/audit/theta_text.h"
#include "lepp/io.h"
#include "lepp/trace_io.h"

namespace fs = std::filesystem;

namespace lepp::audit {
namespace {

const char* const kPlaceholders[] = {"in", "out", "theta", "method"};

// Largest output file read: past this the output counts as unreadable (a runaway writer).
constexpr std::uintmax_t kMaxOutputBytes = 1ull << 30;

bool executable(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && access(path.c_str(), X_OK) == 0;
}

// Shell words that are not programs: the check is skipped for them.
bool shell_builtin(const std::string& w) {
  static const char* const words[] = {"exec", "env", "cd", "(", "{", "if", "for", "while", "!", "time", "nice", "timeout",
                                      "eval", ".", "set", "test", "[", "true", "false", "echo", "printf", ":", "exit",
                                      "sleep", "kill", "trap", "ulimit", "case", "until"};
  for (const char* b : words)
    if (w == b) return true;
  return false;
}

// The first word of the command that names a program (after VAR=value assignments).
std::string first_program(const std::string& t) {
  std::istringstream in(t);
  std::string w;
  while (in >> w) {
    if (w.find('=') != std::string::npos && w.find('=') > 0 && w[0] != '{' && w[0] != '/' && w[0] != '.') continue;
    // Strip simple quoting.
    if (w.size() >= 2 && (w.front() == '\'' || w.front() == '"') && w.back() == w.front()) w = w.substr(1, w.size() - 2);
    return w;
  }
  return "";
}

bool in_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string p = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= p.size()) {
    std::size_t end = p.find(':', start);
    if (end == std::string::npos) end = p.size();
    std::string dir = p.substr(start, end - start);
    if (dir.empty()) dir = ".";
    if (executable(dir + "/" + program)) return true;
    start = end + 1;
  }
  return false;
}

std::uintmax_t size_or_zero(const std::string& path) {
  std::error_code ec;
  auto s = fs::file_size(path, ec);
  return ec ? 0 : s;
}

// The last non-blank line of a text, trimmed.
std::string last_line(const std::string& text) {
  std::size_t end = text.find_last_not_of(" \t\r\n");
  if (end == std::string::npos) return "";
  std::size_t start = text.rfind('\n', end);
  start = start == std::string::npos ? 0 : start + 1;
  return text.substr(start, end - start + 1);
}

}  // namespace

void check_command_template(const std::string& t) {
  bool has_in = false, has_out = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] != '{') continue;
    std::size_t close = t.find('}', i);
    if (close == std::string::npos) break;  // a lone '{' is the shell's business
    std::string name = t.substr(i + 1, close - i - 1);
    bool looks_like_placeholder = !name.empty() && name.find_first_of(" \t;{$\"'") == std::string::npos;
    if (!looks_like_placeholder) continue;
    bool known = false;
    for (const char* p : kPlaceholders) known = known || name == p;
    if (!known)
      throw UsageError(fmt::format("unknown placeholder {{{}}} in --cmd (known: {{in}} {{out}} {{theta}} {{method}})", name));
    has_in = has_in || name == "in";
    has_out = has_out || name == "out";
    i = close;
  }
  if (!has_in || !has_out) throw UsageError("--cmd needs both {in} (the .poly file) and {out} (the output prefix)");
  std::string program = first_program(t);
  if (program.empty()) throw UsageError("--cmd is empty");
  if (shell_builtin(program) || program.find('{') != std::string::npos) return;
  bool found = program.find('/') != std::string::npos ? executable(program) : in_path(program);
  if (!found) throw UsageError(fmt::format("--cmd: program not found or not executable: {}", program));
}

std::string expand_command_template(const std::string& t, const std::string& in, const std::string& out, double theta,
                                    Method method) {
  std::string r;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '{') {
      std::size_t close = t.find('}', i);
      if (close != std::string::npos) {
        std::string name = t.substr(i + 1, close - i - 1);
        std::string value;
        bool known = true;
        if (name == "in") value = in;
        else if (name == "out") value = out;
        else if (name == "theta") value = theta_text(theta);
        else if (name == "method") value = to_string(method);
        else known = false;
        if (known) {
          r += shell_quote(value);
          i = close;
          continue;
        }
      }
    }
    r += t[i];
  }
  return r;
}

EngineRun run_command(const std::string& shell_command, const std::string& out, const EngineRequest& req) {
  EngineRun run;
  SubprocessLimits limits;
  limits.timeout_seconds = req.timeout_seconds;
  limits.memory_mb = req.memory_mb;
  SubprocessResult sr = run_subprocess(shell_command, limits);
  run.seconds = sr.seconds;
  run.stderr_text = sr.stderr_text;
  for (const char* ext : {".node", ".ele", ".poly", ".trace"})
    if (fs::exists(out + ext)) run.output_files.push_back(out + ext);
  if (!sr.started) {
    run.status = RunStatus::Crashed;
    run.detail = sr.detail;
    return run;
  }
  if (sr.timed_out) {
    run.status = RunStatus::TimedOut;
    run.detail = fmt::format("killed after {:.3g} s", req.timeout_seconds);
    return run;
  }
  // The shell reports a signal of its last command as 128 + n.
  if (sr.signal == 0 && sr.exit_code > 128 && sr.exit_code < 128 + 65) sr.signal = sr.exit_code - 128;
  if (sr.signal != 0) {
    run.status = RunStatus::Crashed;
    run.signal = sr.signal;
    run.detail = fmt::format("killed by signal {} ({})", sr.signal, strsignal(sr.signal));
    return run;
  }
  // A non-zero exit with no readable output is a failed run; with readable output
  // (lepp refine exits 3 when it leaves unimprovable triangles) the mesh is what
  // counts: it is certified, and the status is kept in exit_code and detail.
  const bool nonzero = sr.exit_code != 0;
  if (nonzero) {
    run.exit_code = sr.exit_code;
    // Its last line, where an exception or an error message usually is (the first is
    // often debug noise); the whole stderr is kept with the finding.
    const std::string last = last_line(sr.stderr_text);
    run.detail = fmt::format("exit status {}{}{}", sr.exit_code, last.empty() ? "" : ": ", last.substr(0, 200));
    if (!fs::exists(out + ".node") || !fs::exists(out + ".ele")) {
      run.status = RunStatus::ExitCode;
      return run;
    }
  }
  try {
    for (const char* ext : {".node", ".ele", ".poly", ".trace"})
      if (size_or_zero(out + ext) > kMaxOutputBytes) throw InputError(out + ext, 0, "larger than 1 GiB: not read");
    run.mesh = read_mesh(out);
    if (fs::exists(out + ".trace")) run.trace = read_trace(out + ".trace");
  } catch (const std::exception& e) {
    run.status = nonzero ? RunStatus::ExitCode : RunStatus::UnreadableOutput;
    run.detail = nonzero ? run.detail + "; output unreadable: " + e.what() : e.what();
    run.mesh = Mesh{};
    return run;
  }
  run.status = RunStatus::Ok;
  return run;
}

bool write_engine_input(const Pslg& pslg, const EngineRequest& req, std::string& in, std::string& out, EngineRun& failed) {
  in = (fs::path(req.work_dir) / "in.poly").string();
  out = (fs::path(req.work_dir) / "out").string();
  try {
    write_poly(in, pslg);
    return true;
  } catch (const std::exception& e) {
    failed.status = RunStatus::Crashed;
    failed.detail = std::string("cannot write the input: ") + e.what();
    return false;
  }
}

Engine command_engine(const std::string& command_template) {
  check_command_template(command_template);
  return [command_template](const Pslg& pslg, const EngineRequest& req) {
    EngineRun run;
    std::string in, out;
    if (!write_engine_input(pslg, req, in, out, run)) return run;
    return run_command(expand_command_template(command_template, in, out, req.theta, req.method), out, req);
  };
}

}  // namespace lepp::audit
