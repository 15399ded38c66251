// SPDX-License-Identifier: GPL-3.0-or-later
// A command line that is only words, split as /bin/sh splits it, so that
// run_subprocess (subprocess.h) can execute the program directly instead of
// starting a shell that starts it (the shell and its own start cost more than the
// rest of a tiny mesher's run; the fuzzers and the audit run one command per input).
//
// The words are exactly the arguments sh -c would pass. Whatever needs the
// shell for more than splitting is left to it (nullopt): expansions ($, `, *, ?,
// [, ~), redirections, pipes, lists and groups (< > | & ; ( ) { }), comments (#),
// a newline, a line continuation, an unterminated quote, an assignment before the
// program (a '=' in the first word), a first word that is a shell keyword or
// built-in (the shell's own echo, test, exec, cd..., not a program), an empty
// command. What is split: words separated by blanks (space, tab), single-quoted
// text, double-quoted text with none of $ ` \ in it, and a backslash before any
// other character outside quotes (the adapter's placeholders, shell_quote'd,
// are 'value' with '\'' for a quote in it).
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace lepp::audit {

std::optional<std::vector<std::string>> simple_command_words(const std::string& command);

}  // namespace lepp::audit
