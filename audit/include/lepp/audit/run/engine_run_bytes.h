// SPDX-License-Identifier: GPL-3.0-or-later
// An EngineRun as bytes, to cross a process boundary (isolated_engine.h), and the
// call that asks for one (the PSLG and the request, sent to the fork server): every
// field, doubles bit for bit (-0.0, subnormals, NaN payloads), in the machine's
// own byte order (both ends are the same program). The bytes end with a mark and
// must be read whole: a prefix, a longer string or a changed count is refused,
// so a child that dies while writing never reads as a shorter mesh.
#pragma once
#include <string>

#include "lepp/audit/engine.h"

namespace lepp::audit {

std::string encode_engine_run(const EngineRun& run);

// Throws std::runtime_error (one line: what is wrong, at which byte) unless
// `bytes` is exactly one encoding.
EngineRun decode_engine_run(const std::string& bytes);

// One engine call: every field of the PSLG (line numbers and source included) and
// of the request, under the same rules.
std::string encode_engine_call(const Pslg& pslg, const EngineRequest& req);
void decode_engine_call(const std::string& bytes, Pslg& pslg, EngineRequest& req);

}  // namespace lepp::audit
