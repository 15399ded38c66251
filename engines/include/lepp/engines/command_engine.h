// SPDX-License-Identifier: GPL-3.0-or-later
// The command adapter: any program, in any language, audited through a command
// template run once per case as /bin/sh runs it (directly, without the shell, when
// it is only words: lepp/audit/run/shell_words.h). Placeholders:
//   {in}      the input, a Triangle .poly file (1-based, %.17g coordinates)
//   {out}     an output prefix: the program writes {out}.node and {out}.ele
//             (Triangle's formats, 0- or 1-based), optionally {out}.poly (its
//             constrained edges) and {out}.trace (docs/AUDIT.md)
//   {theta}   the smallest angle asked for, degrees
//   {method}  centroid or midpoint
// Each value is substituted single-quoted for the shell. A run past the timeout
// is killed with its whole process group; --memory caps its address space.
#pragma once
#include <string>
#include <vector>

#include "lepp/audit/engine.h"
#include "lepp/audit/theta_text.h"  // {theta}

namespace lepp::audit {

// Checks a template: every {name} is a known placeholder, {in} and {out} appear,
// and the program (the first word) exists and is executable (searched in PATH
// when it has no '/'). Throws UsageError naming what is wrong.
void check_command_template(const std::string& command_template);

// The template with the placeholders replaced (quoted for the shell).
std::string expand_command_template(const std::string& command_template, const std::string& in, const std::string& out,
                                    double theta, Method method);

// The engine that runs the template. Writes REQUEST.work_dir/in.poly, runs the
// command with {out} = REQUEST.work_dir/out, reads out.node/.ele (and out.poly,
// out.trace when present). Throws UsageError at construction for a bad template.
Engine command_engine(const std::string& command_template);

// The steps of a command engine, for adapters that build their own command line
// (the Triangle engine): writes WORK_DIR/in.poly and names WORK_DIR/out (false and
// `failed` filled when the input cannot be written); runs a shell command and reads
// OUT.node/.ele/.poly/.trace into an EngineRun.
bool write_engine_input(const Pslg& pslg, const EngineRequest& request, std::string& in, std::string& out,
                        EngineRun& failed);
EngineRun run_command(const std::string& shell_command, const std::string& out, const EngineRequest& request);

}  // namespace lepp::audit
