// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's rows decided for one run: certificate, min-angle, Theorem 2, termination, conformance.
#include "lepp/audit/judge/checks.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "lepp/audit/judge/arithmetic.h"
#include "lepp/audit/judge/conformance.h"
#include "lepp/audit/judge/diagnosis.h"
#include "lepp/audit/judge/inexact.h"
#include "lepp/audit/judge/program_mesh.h"
#include "lepp/gen.h"

namespace lepp::audit {
namespace {

std::string first_violation(const certify::Report& report, certify::Check check, std::vector<certify::Violation>& out) {
  std::string first;
  std::size_t total = 0;
  for (std::size_t i = 0; i < report.count_by_reason.size(); ++i)
    if (certify::check_of(static_cast<certify::Reason>(i)) == check) total += report.count_by_reason[i];
  for (const certify::Violation& v : report.violations) {
    if (certify::check_of(v.reason) != check) continue;
    if (first.empty()) first = fmt::format("{}: {}", certify::to_string(v.reason), v.message);
    if (out.size() < 20) out.push_back(v);
  }
  if (total > 1) first += fmt::format(" (and {} more)", total - 1);
  return first;
}

// The rows whose verdict code stopped: undecided, an internal error of the audit.
void internal_error(CaseResult& c, std::initializer_list<Row> rows, const char* stage, const std::string& what) {
  for (Row r : rows) {
    RowResult e;
    e.verdict = Verdict::InternalError;
    e.detail = fmt::format("internal error of the audit: the {} stopped: {}", stage, what);
    e.internal_error = stage;
    c[r] = std::move(e);
  }
}

// A name the program's output gives a conformance failure before the catalogue's:
// the replay's meshes are not the program's, so the catalogue judged steps the
// program took on other meshes.
void name_first(ConformanceFailure& f, const std::string& name, const std::string& what, const char* definition) {
  f.deviation = name;
  f.deviation_what = what;
  f.deviation_definition = definition;
  f.consistent_variant = false;
  if (f.chain.empty()) f.chain.push_back({name, f.step + 1, 0});
  else f.chain.front().deviation = name;
}

// The program's arithmetic, named first in a conformance failure: from the
// final mesh, or, where the catalogue names no rule (unknown, precision), from
// the failing point against the paper's nearest choice.
void name_arithmetic(ConformanceFailure& f, const ArithmeticEvidence& from_mesh) {
  ArithmeticEvidence e = from_mesh;
  if (e.name.empty() && (f.deviation == "unknown" || f.deviation == "precision")) e = step_arithmetic(f);
  if (!e.name.empty()) name_first(f, e.name, e.what, arithmetic_definition(e.name));
}


}  // namespace

const char* row_key(Row row) {
  switch (row) {
    case Row::Certificate: return "certificate";
    case Row::MinAngle: return "min-angle";
    case Row::Theorem2: return "theorem-2";
    case Row::Termination: return "termination";
    case Row::Conformance: return "conformance";
  }
  return "?";
}

const char* row_statement(Row row) {
  switch (row) {
    case Row::Certificate:
      return "the output reads, covers the domain exactly, keeps every input vertex, keeps every segment as a chain "
             "of edges, and is a constrained Delaunay triangulation";
    case Row::MinAngle:
      return "every smallest angle >= theta, except triangles exempt by the small-input-angle rule (counted apart)";
    case Row::Theorem2: return "terminal triangles of every unconstrained terminal edge have largest angle <= 120 degrees";
    case Row::Termination:
      return "the run ends (within the timeout) where the paper claims it: centroid theta <= 30, midpoint theta <= 22, "
             "inputs without angles below 60 degrees";
    case Row::Conformance:
      return "every inserted point is the paper's choice for the Lepp of some bad triangle of the mesh at that moment";
  }
  return "?";
}

const char* row_passage(Row row) {
  switch (row) {
    case Row::Certificate:
      return "Sections 3 and 4, the algorithms: input a CDT, \"perform constrained Delaunay insertion of P into tau\"";
    case Row::MinAngle: return "Section 3: \"the algorithm finishes when the minimum angle in the mesh is >= theta_tol\"";
    case Row::Theorem2: return "Section 2, Theorem 2";
    case Row::Termination: return "Section 3.1, Theorem 9 (midpoint, theta <= alpha_limit); Section 4.1, Remark 15 (centroid, theta <= 30)";
    case Row::Conformance:
      return "Section 3, Select Point (constrained edge point insertion); Section 4, New Select Point with Remark 10";
  }
  return "?";
}

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::Held: return "held";
    case Verdict::Failed: return "failed";
    case Verdict::Finding: return "finding";
    case Verdict::NotApplicable: return "n/a";
    case Verdict::NotChecked: return "not checked";
    case Verdict::InternalError: return "internal-error";
  }
  return "?";
}

const char* to_string(RunStatus status) {
  switch (status) {
    case RunStatus::Ok: return "ok";
    case RunStatus::ExitCode: return "exit-code";
    case RunStatus::Crashed: return "crashed";
    case RunStatus::TimedOut: return "timed-out";
    case RunStatus::Stopped: return "stopped";
    case RunStatus::UnreadableOutput: return "unreadable-output";
  }
  return "?";
}

bool termination_claimed(Method method, double theta) {
  return method == Method::Centroid ? theta <= 30 : theta <= 22;
}

CaseResult check_run(const Pslg& pslg, const EngineRequest& req, const EngineRun& run, const CheckOptions& options) {
  CaseResult c;
  // Termination first: it is decided by how the run ended.
  const bool ended = run.status != RunStatus::TimedOut && run.status != RunStatus::Stopped;
  if (ended) {
    c[Row::Termination] = {Verdict::Held, "", {}};
  } else {
    std::string what = run.status == RunStatus::TimedOut ? "did not end within the timeout" : "did not converge";
    if (!run.detail.empty()) what += ": " + run.detail;
    // The paper's termination results are for inputs without angles below 60 degrees
    // (lepp::gen::wellShapedPslg's class); a smaller input angle makes it a finding.
    const double input_angle = gen::min_input_angle_deg(pslg);
    const bool claimed = termination_claimed(req.method, req.theta) && input_angle >= 60;
    if (termination_claimed(req.method, req.theta) && !claimed)
      what += fmt::format(" (input angle {:.3g} degrees < 60: outside the class the paper's termination results cover)", input_angle);
    c[Row::Termination] = {claimed ? Verdict::Failed : Verdict::Finding, what, {}};
  }
  if (run.status != RunStatus::Ok) {
    // No final mesh to certify. A run that failed outright fails the certificate row (its output does not read).
    bool broken = run.status == RunStatus::ExitCode || run.status == RunStatus::Crashed ||
                  run.status == RunStatus::UnreadableOutput;
    std::string why = fmt::format("{}: {}", to_string(run.status), run.detail);
    c[Row::Certificate] = {broken ? Verdict::Failed : Verdict::NotApplicable, why, {}};
    for (Row r : {Row::MinAngle, Row::Theorem2, Row::Conformance}) c[r] = {Verdict::NotApplicable, "no mesh: " + why, {}};
    return c;
  }
  c.steiner_points = static_cast<std::int64_t>(run.mesh.vertices.size()) - static_cast<std::int64_t>(pslg.vertices.size());

  // The small-input-angle exemption rule for any mesher (docs/CERTIFIER.md): triangles
  // below theta under the influence of an input angle below 60 degrees are counted
  // apart, never as violations; the rule looks only at the input and the mesh.
  certify::Options o;
  o.min_angle_deg = req.theta;
  o.theorem2 = true;
  o.exempt_small_input_angles = true;
  // And the precision limit (section 5c): a program that stops where no point its
  // method allows can be inserted as rounded is not blamed.
  o.exempt_precision_limited = true;
  o.precision_method = req.method;
  o.tie_search_states = options.tie_search_states;
  o.max_listed_per_reason = 20;
  certify::Report report;
  bool certified = false;
  try {
    report = certify::certify(pslg, run.mesh, o);
    certified = true;
  } catch (const std::exception& e) {
    internal_error(c, {Row::Certificate, Row::MinAngle, Row::Theorem2}, "certifier", e.what());
  } catch (...) {
    internal_error(c, {Row::Certificate, Row::MinAngle, Row::Theorem2}, "certifier", "an unknown exception");
  }
  c.exempt_triangles = report.exempt_count;
  c.precision_exempt_triangles = report.precision_exempt_count;

  auto decide = [&](Row row, std::initializer_list<certify::Check> checks) {
    RowResult r;
    std::string detail;
    for (certify::Check ch : checks) {
      std::string d = first_violation(report, ch, r.violations);
      if (!d.empty() && detail.empty()) detail = d;
    }
    r.verdict = detail.empty() ? Verdict::Held : Verdict::Failed;
    r.detail = detail;
    c[row] = std::move(r);
  };
  if (certified) {
    decide(Row::Certificate, {certify::Check::Topology, certify::Check::InputVertices, certify::Check::Constraints,
                              certify::Check::Delaunay});
    decide(Row::MinAngle, {certify::Check::MinAngle});
    decide(Row::Theorem2, {certify::Check::Theorem2});
  }
  // A program whose output shows its arithmetic (coordinates at floats, too few
  // digits written): named first, the certificate's gaps are its consequence.
  // Read only for a failing row: it converts every coordinate to decimal.
  std::optional<ArithmeticEvidence> read_arithmetic;
  auto arithmetic_of_mesh = [&]() -> const ArithmeticEvidence& {
    if (!read_arithmetic) read_arithmetic = mesh_arithmetic(pslg, run.mesh);
    return *read_arithmetic;
  };
  // The smallest angles too: coordinates rounded after the program computed them
  // can flatten a small triangle below theta.
  for (Row row : {Row::Certificate, Row::MinAngle}) {
    RowResult& r = c[row];
    if (r.verdict != Verdict::Failed || arithmetic_of_mesh().name.empty()) continue;
    const ArithmeticEvidence& arithmetic = arithmetic_of_mesh();
    r.deviation = arithmetic.name;
    r.detail = fmt::format("{}: {}; what the certifier finds: {}", arithmetic.name, arithmetic.what, r.detail);
  }
  // A double program's rounding (inexact.h): a smallest angle below theta, or an
  // edge not locally Delaunay, by no more than double rounding, every violation
  // of the row. Named; accepted as notes under --arithmetic double.
  bool delaunay_within_rounding = false;
  if (certified) {
    // Every violation must be looked at: the first report lists 20 per reason,
    // so when those are all within rounding and there are more, certify again.
    std::optional<certify::Report> relisted;
    for (Row row : {Row::Certificate, Row::MinAngle}) {
      RowResult& r = c[row];
      if (r.verdict != Verdict::Failed || !r.deviation.empty()) continue;
      const bool cert = row == Row::Certificate;
      auto count = [&](const certify::Report& rep, bool* unlisted) {
        return cert ? inexact_incircle_edges(rep, unlisted) : inexact_threshold_triangles(rep, req.theta, unlisted);
      };
      bool unlisted = false;
      std::size_t n = count(relisted ? *relisted : report, &unlisted);
      if (unlisted && !relisted) {
        certify::Options all = o;
        all.max_listed_per_reason = static_cast<std::size_t>(-1);
        try {
          relisted = certify::certify(pslg, run.mesh, all);
          n = count(*relisted, nullptr);
        } catch (...) {
          n = 0;  // undecided: the row stays as the certifier says
        }
      }
      if (n == 0) continue;
      const char* name = cert ? kInexactIncircle : kInexactThreshold;
      delaunay_within_rounding = delaunay_within_rounding || cert;
      if (options.arithmetic_double) {
        r = RowResult{};
        r.verdict = Verdict::Held;
        r.inexact_steps[name] = n;
        continue;
      }
      r.deviation = name;
      r.detail = fmt::format("{}: {} {} {}; what the certifier finds: {}", name, n,
                             cert ? (n == 1 ? "edge is" : "edges are") : (n == 1 ? "triangle is" : "triangles are"),
                             cert ? "not locally Delaunay only within double rounding of the in-circle determinant"
                                  : "below theta only by double rounding of its smallest angle",
                             r.detail);
    }
  }
  // A program that exited non-zero but left a mesh: its mesh is judged, its status said.
  if (run.exit_code != 0)
    for (Row r : {Row::Certificate, Row::MinAngle, Row::Theorem2})
      if (c[r].verdict == Verdict::Failed) c[r].detail += fmt::format(" (the program exited with status {})", run.exit_code);

  if (!run.trace) {
    c[Row::Conformance] = {Verdict::NotChecked, "no trace", {}};
    return c;
  }
  std::vector<certify::Violation> scratch_violations;
  ConformanceOptions co;
  co.method = req.method;
  co.min_angle_deg = req.theta;
  co.angle_tolerance_deg = options.angle_tolerance_deg;
  co.point_tolerance_ulps = options.point_tolerance_ulps;
  co.area_centroid = options.area_centroid;
  co.arithmetic_double = options.arithmetic_double;
  // Under --arithmetic double a mesh Delaunay up to rounding is accepted: no missing flips.
  const bool not_delaunay = certified && !first_violation(report, certify::Check::Delaunay, scratch_violations).empty() &&
                            !(delaunay_within_rounding && options.arithmetic_double);
  try {
    ConformanceReport conf = check_conformance(pslg, *run.trace, co);
    if (conf.failure) name_arithmetic(*conf.failure, arithmetic_of_mesh());
    // The final mesh says the program misses flips (the certificate's Delaunay
    // check): named first, unless its arithmetic explains the mesh already.
    // When every edge it leaves is within rounding of cocircular, that is the name.
    if (conf.failure && not_delaunay && delaunay_within_rounding && arithmetic_definition(conf.failure->deviation)[0] == '\0')
      name_first(*conf.failure, kInexactIncircle,
                 fmt::format("the final mesh is not constrained Delaunay only within double rounding of the in-circle "
                             "determinant (certificate row): its flips were decided in double; the replay's catalogue "
                             "named this step {} on its own mesh",
                             conf.failure->deviation),
                 inexact_definition(kInexactIncircle));
    else if (conf.failure && not_delaunay && arithmetic_definition(conf.failure->deviation)[0] == '\0')
      name_first(*conf.failure, kMissingFlips,
                 fmt::format("the final mesh is not constrained Delaunay (certificate row); the replay's catalogue named "
                             "this step {} on its own mesh",
                             conf.failure->deviation),
                 kMissingFlipsDefinition);
    // The arithmetic of the mesh named: the chain again on the program's mesh (program_mesh.h).
    if (conf.failure) follow_program_mesh(pslg, *run.trace, co, *conf.failure);
    // Theorem 2 on the terminal pair of every replayed step, reported like a conformance finding.
    if (conf.theorem2_failure && c[Row::Theorem2].verdict == Verdict::Held) {
      const Theorem2StepFailure& f = *conf.theorem2_failure;
      RowResult r;
      r.verdict = Verdict::Failed;
      r.step = static_cast<long>(f.step) + 1;
      r.detail = fmt::format("step {} of {} ({:.17g}, {:.17g}): terminal edge ({},{}) of the replayed mesh: the angle at vertex {} "
                             "is over 120 degrees (about {:.6g})",
                             r.step, conf.steps, f.point.x, f.point.y, f.terminal_edge[0], f.terminal_edge[1], f.apex, f.angle_deg);
      r.diagnosis = std::make_shared<StepDiagnosis>(theorem2_diagnosis(conf, req.theta));
      certify::Violation v;
      v.message = r.detail;
      v.points.push_back(f.point);
      r.violations.push_back(std::move(v));
      c[Row::Theorem2] = std::move(r);
    }
    if (conf.conforms) {
      c[Row::Conformance] = {Verdict::Held, "", {}};
      c[Row::Conformance].inexact_steps = conf.inexact_steps;
    } else {
      RowResult r;
      r.verdict = Verdict::Failed;
      r.detail = conf.failure ? fmt::format("step {} of {} ({:.17g}, {:.17g}): {}", conf.failure->step + 1, conf.steps,
                                            conf.failure->point.x, conf.failure->point.y, conf.failure->reason)
                              : "does not conform";
      r.deviation = conf.failure ? conf.failure->deviation : "unknown";
      r.step = conf.failure ? static_cast<long>(conf.failure->step) + 1 : 0;
      if (conf.failure) {
        r.detail += fmt::format("; deviation {}: {}", conf.failure->deviation, conf.failure->deviation_what);
        r.consistent_variant = conf.failure->consistent_variant;
        r.deviations = conf.failure->chain;
        if (r.consistent_variant) r.detail += fmt::format(" (every step fits this one variant)");
        if (r.deviations.size() > 1) r.detail += "; every deviation: " + chain_text(r.deviations);
        if (!conf.failure->mesh_reading.empty())
          r.detail += fmt::format(" (on the program's mesh as the replay rebuilds it: {}{}; {})", conf.failure->mesh_reading,
                                  conf.failure->mesh_reading_fallback ? ", tried where the exact mesh lost the chain" : "",
                                  conf.failure->chain_complete ? "to the trace's end"
                                                               : conf.failure->chain_end_reason + ": " + conf.failure->chain_end);
        if (const std::string note = remark10_ignored_note(*conf.failure); !note.empty()) r.detail += "; " + note;
        if (not_delaunay)
          r.detail += "; the final mesh is not constrained Delaunay: the program's intermediate meshes probably differ "
                      "from the replay's (missing flips are the likely cause)";
        if (co.area_centroid) r.detail += " [reading: area centroid]";
        if (co.arithmetic_double) r.detail += " [reading: arithmetic of doubles]";
        auto diagnosis = std::make_shared<StepDiagnosis>(conformance_diagnosis(conf, req.theta, not_delaunay));
        // Where the chain stopped at no rule: that step's own picture (issue 42).
        if (std::optional<ConformanceFailure> end = chain_end_failure(pslg, *run.trace, co, *conf.failure)) {
          ConformanceReport at_end;
          at_end.steps = conf.steps;
          at_end.area_centroid = conf.area_centroid;
          at_end.failure = std::move(end);
          diagnosis->chain_end = std::make_shared<const StepDiagnosis>(conformance_diagnosis(at_end, req.theta, not_delaunay));
        }
        r.diagnosis = std::move(diagnosis);
        certify::Violation v;
        v.message = describe(conf, 3);
        v.points.push_back(conf.failure->point);
        for (const ConformanceCandidate& k : conf.failure->candidates) v.points.push_back(k.point);
        r.violations.push_back(std::move(v));
      }
      c[Row::Conformance] = std::move(r);
    }
    // Arithmetic the trace shows (not the mesh: that is named above) names the certifier's findings too.
    const std::string& conf_name = c[Row::Conformance].deviation;
    for (Row row : {Row::Certificate, Row::MinAngle}) {
      RowResult& r = c[row];
      if (r.verdict != Verdict::Failed || !r.deviation.empty() || arithmetic_definition(conf_name)[0] == '\0') continue;
      r.deviation = conf_name;
      r.detail = fmt::format("{} (the trace shows it: conformance row); what the certifier finds: {}", conf_name, r.detail);
    }
  } catch (const std::exception& e) {
    // Not the program's failure: the replay (or the step's diagnosis) could not decide.
    internal_error(c, {Row::Conformance}, "conformance replay", e.what());
  } catch (...) {
    internal_error(c, {Row::Conformance}, "conformance replay", "an unknown exception");
  }
  return c;
}

}  // namespace lepp::audit
