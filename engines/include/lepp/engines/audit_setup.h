// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit` from its options: the engine under audit and the AuditOptions, the engines
// named by the registry. Part of lepp_peer_engines (Triangle and CGAL; not in the
// find_package package).
#pragma once
#include "lepp/audit/audit.h"
#include "lepp/audit/engine.h"
#include "lepp/audit/request.h"

namespace lepp::engines {

struct AuditSetup {
  audit::Engine engine;         // the program or built-in engine under audit
  audit::AuditOptions options;  // everything else run_audit needs; no progress callback (the caller's to print)
};

// The audit `lepp audit` runs for `request`: run_audit(setup.engine, setup.options).
// The reproduce command of findings names the running executable (audit::executable_path).
// Throws audit::UsageError, in this order: not exactly one of cmd and engine, a data root
// not found, the engine under audit unavailable (Triangle missing), an unknown or
// unavailable comparison (Triangle is left out quietly under "auto"), then the
// refusals of audit::apply_request.
AuditSetup audit_setup(const audit::AuditRequest& request);

}  // namespace lepp::engines
