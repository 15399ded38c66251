// SPDX-License-Identifier: GPL-3.0-or-later
// A command that is only words, split as /bin/sh splits it (shell_words.h).
#include "lepp/audit/run/shell_words.h"

#include <cstring>

namespace lepp::audit {
namespace {

// Characters that mean nothing to the shell outside quotes (and bytes of UTF-8
// text); anything else unquoted is left to the shell. '=' is plain after the first word.
bool plain(char c) {
  const unsigned char u = static_cast<unsigned char>(c);
  return u >= 0x80 || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
         std::strchr("_-./,:@%+^=", c) != nullptr;
}

// The shell runs these itself, whether quoted or not (keywords only unquoted, but a
// quoted one is rare enough to leave to the shell too): dash's and bash's keywords and
// built-ins, which a program of the same name in PATH does not replace.
bool shell_word(const std::string& w) {
  static const char* const words[] = {
      "!", "{", "}", "[[", "]]", "case", "coproc", "do", "done", "elif", "else", "esac", "fi", "for", "function",
      "if", "in", "select", "then", "time", "until", "while", ".", ":", "[", "alias", "bg", "bind", "break",
      "builtin", "caller", "cd", "chdir", "command", "compgen", "complete", "compopt", "continue", "declare", "dirs",
      "disown", "echo", "enable", "eval", "exec", "exit", "export", "false", "fc", "fg", "getopts", "hash", "help",
      "history", "jobs", "kill", "let", "local", "logout", "mapfile", "popd", "printf", "pushd", "pwd", "read",
      "readarray", "readonly", "return", "set", "shift", "shopt", "source", "suspend", "test", "times", "trap",
      "true", "type", "typeset", "ulimit", "umask", "unalias", "unset", "wait"};
  for (const char* b : words)
    if (w == b) return true;
  return false;
}

}  // namespace

std::optional<std::vector<std::string>> simple_command_words(const std::string& command) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;         // a word has begun (an empty quoted '' is a word)
  bool first_has_equal = false;  // an unquoted '=' in the first word: an assignment, maybe
  const std::size_t n = command.size();
  for (std::size_t i = 0; i < n; ++i) {
    const char c = command[i];
    if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
      continue;
    }
    in_word = true;
    if (c == '\'') {
      const std::size_t close = command.find('\'', i + 1);
      if (close == std::string::npos) return std::nullopt;  // unterminated: the shell's error
      word.append(command, i + 1, close - i - 1);
      i = close;
    } else if (c == '"') {
      const std::size_t close = command.find_first_of("\"$`\\", i + 1);
      if (close == std::string::npos || command[close] != '"') return std::nullopt;
      word.append(command, i + 1, close - i - 1);
      i = close;
    } else if (c == '\\') {
      if (i + 1 >= n || command[i + 1] == '\n') return std::nullopt;  // a continuation, or nothing to quote
      word += command[++i];
    } else if (plain(c)) {
      if (c == '=' && words.empty()) first_has_equal = true;
      word += c;
    } else {
      return std::nullopt;  // $ ` * ? [ ~ # < > | & ; ( ) { } newline...: the shell's
    }
  }
  if (in_word) words.push_back(word);
  if (words.empty() || words[0].empty() || first_has_equal || shell_word(words[0])) return std::nullopt;
  return words;
}

}  // namespace lepp::audit
