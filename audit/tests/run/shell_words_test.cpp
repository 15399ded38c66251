// SPDX-License-Identifier: GPL-3.0-or-later
// A command that is only words runs without /bin/sh (shell_words.h, subprocess.h):
// the split gives exactly sh's words, anything with more shell syntax than that
// goes to the shell, and a command behaves the same either way, down to the
// adapter's verdicts on programs that misbehave (programs/*.sh).
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lepp/audit/run/shell_words.h"
#include "lepp/audit/run/subprocess.h"
#include "lepp/engines/command_engine.h"
#include "lepp/validate.h"

#include "validated_square.h"

namespace fs = std::filesystem;
using namespace lepp;
using namespace lepp::audit;

namespace {

const std::string kPrograms = LEPP_AUDIT_PROGRAMS;
using Words = std::vector<std::string>;

TEST(ShellWords, PlaceholderValuesSplitAsTheShellQuotesThem) {
  // expand_command_template quotes each value: spaces and a quote inside one stay one word.
  const std::string c = expand_command_template("m {in} -o {out} --min-angle {theta} --method {method}",
                                                "/tmp/a b'c/in.poly", "/o", 22.5, Method::Midpoint);
  EXPECT_EQ(simple_command_words(c),
            (Words{"m", "/tmp/a b'c/in.poly", "-o", "/o", "--min-angle", "22.5", "--method", "midpoint"}));
}

TEST(ShellWords, QuotesAndBlanks) {
  EXPECT_EQ(simple_command_words("prog  a\tb "), (Words{"prog", "a", "b"}));
  EXPECT_EQ(simple_command_words("prog \"a  b\" 'c  d' e\\ f"), (Words{"prog", "a  b", "c  d", "e f"}));
  EXPECT_EQ(simple_command_words("prog '' \"\" x''y"), (Words{"prog", "", "", "xy"}));
  EXPECT_EQ(simple_command_words("prog 'a\"b' \"c'd\" '$HOME' '*'"), (Words{"prog", "a\"b", "c'd", "$HOME", "*"}));
  EXPECT_EQ(simple_command_words("./m --a=b x=y key:v,w@h%2+1^3 caf\xc3\xa9"),
            (Words{"./m", "--a=b", "x=y", "key:v,w@h%2+1^3", "caf\xc3\xa9"}));
}

TEST(ShellWords, ShellSyntaxGoesToTheShell) {
  for (const char* c : {"a | b", "a > f", "a < f", "a 2>&1", "a; b", "a && b", "a || b", "a &", "a $X", "a ${X}",
                        "a `b`", "a $(b)", "a *.poly", "a f?", "a [ab]", "~/m", "a ~", "a #c", "(a)", "{ a; }",
                        "a {b}", "a\nb", "a \\\nb", "a \\", "a 'b", "a \"b", "a \"$b\"", "a \"`b`\"",
                        "a \"b\\c\"", "X=1 prog", "PATH=/x prog", "echo hi", "'echo' hi", "ec\\ho hi", "exec prog",
                        "cd /", "test -f x", "[ -f x ]", "! prog", "time prog", "if", "true", "kill 1", "ulimit -v 1",
                        "", "   ", "'' x", "a !b" /* no syntax to sh, left to it all the same */}) {
    EXPECT_EQ(simple_command_words(c), std::nullopt) << "[" << c << "] would run without the shell";
  }
}

SubprocessLimits quick() {
  SubprocessLimits l;
  l.timeout_seconds = 10;
  return l;
}

TEST(ShellWords, WordsRunWithoutAShellAndGetSameArguments) {
  const std::string c = kPrograms + "/args.sh a 'b  c' \"d e\" f\\ g '' 'h'\\''i' 'x\ty'";
  ASSERT_TRUE(simple_command_words(c).has_value());
  const SubprocessResult direct = run_subprocess(c, quick());
  const SubprocessResult shell = run_shell_command(c, quick());
  ASSERT_EQ(direct.exit_code, 0) << direct.stderr_text;
  ASSERT_EQ(shell.exit_code, 0) << shell.stderr_text;
  const std::string args = "[a]\n[b  c]\n[d e]\n[f g]\n[]\n[h'i]\n[x\ty]\n";
  EXPECT_EQ(shell.stderr_text, args + "parent: sh\n");
  // The same arguments, and no shell between this process and the program.
  EXPECT_EQ(direct.stderr_text.substr(0, args.size()), args);
  EXPECT_EQ(direct.stderr_text.find("parent: sh\n"), std::string::npos) << direct.stderr_text;
  // With shell syntax, the shell runs it.
  const SubprocessResult via_shell = run_subprocess(c + " # a comment", quick());
  EXPECT_EQ(via_shell.stderr_text, args + "parent: sh\n");
}

// The program's whole environment is the one sh gives it: sh sets PWD to the working
// directory when the inherited one does not name it, and the program run without sh
// sees the same (a Python program prints its environment, then PWD).
TEST(ShellWords, TheProgramSeesTheEnvironmentAsUnderTheShell) {
  // Debian's python3 itself: a python3 earlier in PATH may be a shell script (pyenv's shims), which sets PWD.
  const std::string c =
      "/usr/bin/python3 -c 'import os, sys; sys.stderr.write(repr(sorted(os.environ.items())) + os.environ.get(\"PWD\", \"(unset)\"))'";
  ASSERT_TRUE(simple_command_words(c).has_value());
  const char* saved = std::getenv("PWD");
  const std::string kept = saved ? saved : "";
  const std::string here = fs::current_path().string();
  for (const char* pwd : {static_cast<const char*>(nullptr), "/", "relative/dir", here.c_str()}) {
    if (pwd) setenv("PWD", pwd, 1);
    else unsetenv("PWD");
    const SubprocessResult direct = run_subprocess(c, quick());
    const SubprocessResult shell = run_shell_command(c, quick());
    EXPECT_EQ(direct.stderr_text, shell.stderr_text) << "PWD " << (pwd ? pwd : "unset");
    const std::string physical = fs::canonical(".").string();
    EXPECT_EQ(direct.stderr_text.substr(direct.stderr_text.size() - std::min(direct.stderr_text.size(), physical.size())),
              physical)
        << "PWD " << (pwd ? pwd : "unset");
  }
  if (saved) setenv("PWD", kept.c_str(), 1);
  else unsetenv("PWD");
}

TEST(ShellWords, MissingProgramIsExit127EitherWay) {
  for (const std::string c : {"no-such-mesher-anywhere a b", "/no/such/mesher a"}) {
    const SubprocessResult direct = run_subprocess(c, quick());
    const SubprocessResult shell = run_shell_command(c, quick());
    EXPECT_EQ(direct.exit_code, 127) << c;
    EXPECT_EQ(shell.exit_code, 127) << c;
    const std::string program = c.substr(0, c.find(' '));
    EXPECT_NE(direct.stderr_text.find(program + ": not found"), std::string::npos) << direct.stderr_text;
  }
}

TEST(ShellWords, NotExecutableIsExit126EitherWay) {
  const fs::path dir = fs::temp_directory_path() / ("lepp-words-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "not-executable";
  std::ofstream(file) << "#!/bin/sh\nexit 0\n";
  ::chmod(file.c_str(), 0644);
  const std::string c = file.string() + " x";
  const SubprocessResult direct = run_subprocess(c, quick());
  const SubprocessResult shell = run_shell_command(c, quick());
  EXPECT_EQ(direct.exit_code, 126) << direct.stderr_text;
  EXPECT_EQ(shell.exit_code, 126) << shell.stderr_text;
  EXPECT_NE(direct.stderr_text.find("Permission denied"), std::string::npos) << direct.stderr_text;
  fs::remove_all(dir);
}

TEST(ShellWords, MemoryCapAppliesWithoutTheShell) {
  SubprocessLimits l = quick();
  l.memory_mb = 64;
  const std::string c = "python3 -c 'x = bytearray(256 * 1024 * 1024)'";
  ASSERT_TRUE(simple_command_words(c).has_value());
  const SubprocessResult r = run_subprocess(c, l);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.stderr_text.find("MemoryError"), std::string::npos) << r.stderr_text;
}

Pslg square() { return audit_test::validated_square(); }

EngineRun run_template(const std::string& templ, const fs::path& dir, double timeout) {
  EngineRequest r;
  r.theta = 25;
  r.timeout_seconds = timeout;
  r.work_dir = dir.string();
  return command_engine(templ)(square(), r);
}

// The command adapter's run of a template, then of the same template sent to the shell
// (a trailing comment): the same status, exit code, signal, detail and stderr.
TEST(ShellWords, AdapterVerdictsAreTheSameWithAndWithoutTheShell) {
  const fs::path dir = fs::temp_directory_path() / ("lepp-words-adapter-" + std::to_string(::getpid()));
  fs::create_directories(dir / "mesh");
  std::ofstream(dir / "mesh" / "m.node") << "4 2 0 0\n0 0 0\n1 4 0\n2 4 4\n3 0 4\n";
  std::ofstream(dir / "mesh" / "m.ele") << "2 3 0\n0 0 1 2\n1 0 2 3\n";
  struct Case {
    std::string templ;
    RunStatus status;
    double timeout;
  };
  const std::vector<Case> cases = {
      {kPrograms + "/garbage.sh {in} {out}", RunStatus::UnreadableOutput, 5},
      {kPrograms + "/missing.sh {in} {out}", RunStatus::UnreadableOutput, 5},
      {kPrograms + "/exit3.sh {in} {out}", RunStatus::ExitCode, 5},
      {kPrograms + "/crash.sh {in} {out}", RunStatus::Crashed, 5},
      {kPrograms + "/hang.sh {in} {out}", RunStatus::TimedOut, 0.5},
      {kPrograms + "/copy_mesh.sh {in} {out} " + (dir / "mesh" / "m").string(), RunStatus::Ok, 5},
  };
  for (const Case& c : cases) {
    ASSERT_TRUE(simple_command_words(expand_command_template(c.templ, "i", "o", 25, Method::Centroid)).has_value())
        << c.templ;
    fs::create_directories(dir / "a");
    fs::create_directories(dir / "b");
    const EngineRun direct = run_template(c.templ, dir / "a", c.timeout);
    const EngineRun shell = run_template(c.templ + " # by the shell", dir / "b", c.timeout);
    EXPECT_EQ(direct.status, c.status) << c.templ << ": " << direct.detail;
    EXPECT_EQ(shell.status, c.status) << c.templ << ": " << shell.detail;
    EXPECT_EQ(direct.exit_code, shell.exit_code) << c.templ;
    EXPECT_EQ(direct.signal, shell.signal) << c.templ;
    std::string shell_detail = shell.detail, direct_detail = direct.detail;
    for (std::string* d : {&shell_detail, &direct_detail}) {  // the work directories differ
      for (const fs::path& p : {dir / "a", dir / "b"})
        for (std::size_t at; (at = d->find(p.string())) != std::string::npos;) d->replace(at, p.string().size(), "W");
    }
    EXPECT_EQ(direct_detail, shell_detail) << c.templ;
    EXPECT_EQ(direct.mesh.triangles.size(), shell.mesh.triangles.size()) << c.templ;
    fs::remove_all(dir / "a");
    fs::remove_all(dir / "b");
  }
  EXPECT_EQ(run_template(cases[3].templ, dir, 5).signal, SIGSEGV);
  fs::remove_all(dir);
}

// A program gone between the template's check and a run: exit 127 naming it, either way.
TEST(ShellWords, AdapterProgramGoneIsExit127) {
  const fs::path dir = fs::temp_directory_path() / ("lepp-words-gone-" + std::to_string(::getpid()));
  fs::create_directories(dir / "work");
  const fs::path program = dir / "mesher";
  std::ofstream(program) << "#!/bin/sh\nexit 0\n";
  ::chmod(program.c_str(), 0755);
  EngineRequest r;
  r.timeout_seconds = 5;
  r.work_dir = (dir / "work").string();
  const Engine direct = command_engine(program.string() + " {in} {out}");
  const Engine shell = command_engine(program.string() + " {in} {out} # by the shell");
  fs::remove(program);
  for (const Engine* e : {&direct, &shell}) {
    const EngineRun run = (*e)(square(), r);
    EXPECT_EQ(run.status, RunStatus::ExitCode) << run.detail;
    EXPECT_EQ(run.exit_code, 127);
    EXPECT_NE(run.detail.find("exit status 127: "), std::string::npos) << run.detail;
    EXPECT_NE(run.detail.find(program.string() + ": not found"), std::string::npos) << run.detail;
  }
  fs::remove_all(dir);
}

}  // namespace
