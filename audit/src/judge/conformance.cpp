// SPDX-License-Identifier: GPL-3.0-or-later
// The conformance check: the trace replayed on lepp::audit::Replay.
#include "lepp/audit/judge/conformance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "judge/chain_summary.h"
#include "lepp/audit/judge/inexact.h"
#include "lepp/audit/judge/program_mesh.h"
#include "lepp/audit/replay.h"

namespace lepp::audit {

namespace {

ConformanceCandidate candidate(const ReplayChoice& c) {
  ConformanceCandidate out;
  out.bad = c.bad;
  out.lepp = c.lepp;
  out.terminal_edge = c.terminal_edge;
  out.rule = c.rule;
  out.point = c.point;
  out.distance = c.distance;
  out.tolerance = c.tolerance;
  out.euclidean = c.euclidean;
  out.t1 = c.t1;
  out.t2 = c.t2;
  out.split_edge = c.split_edge;
  return out;
}

ReplayRules rules_of(const ConformanceOptions& options) {
  ReplayRules rules;
  rules.method = options.method;
  rules.min_angle_deg = options.min_angle_deg;
  rules.angle_tolerance_deg = options.angle_tolerance_deg;
  rules.point_tolerance_ulps = options.point_tolerance_ulps;
  rules.max_area = options.max_area;
  rules.region_area_bounds = options.region_area_bounds;
  rules.follow_cocircular_flips = options.follow_cocircular_flips;
  rules.cocircular_search_budget = options.cocircular_search_budget;
  rules.centroid = options.area_centroid ? CentroidReading::Area : CentroidReading::Vertex;
  return rules;
}

// The rules on one of the program's meshes: a program that makes its own flips
// (or none) breaks no cocircular tie by CGAL's perturbation, so on those meshes the
// replay does not search other triangulations of cocircular cells.
ReplayRules rules_on(const ConformanceOptions& options, MeshReading reading) {
  ReplayRules rules = rules_of(options);
  rules.mesh = reading;
  // A program whose input or points are floats may still flip as CGAL does.
  if (reading != MeshReading::Exact && reading != MeshReading::FloatPoints && reading != MeshReading::FloatInput)
    rules.follow_cocircular_flips = false;
  return rules;
}

// A replay on `reading`'s mesh with the options' rules; under --arithmetic double
// it also accepts the paper's choices reached through double rounding. Every
// replay of the trace is made here, so each reads the trace the same way.
std::unique_ptr<Replay> replay_on(const Pslg& validated, const ConformanceOptions& options, MeshReading reading) {
  auto replay = std::make_unique<Replay>(validated, rules_on(options, reading));
  if (options.arithmetic_double)
    for (Deviation d : {Deviation::InexactLength, Deviation::InexactThreshold}) replay->allow(d);
  return replay;
}

// A step that took Remark 10's centroid inside the other triangle (the paper's rule, not a variant's).
bool remark10_centroid(const ReplayChoice& choice) {
  return choice.rule == Rule::CentroidInOther && choice.deviation == Deviation::Unknown;
}

// From the first named step on: the replay goes on with each named variant
// allowed (Replay::allow) and names the next deviation where a step fits none,
// until the trace ends or a step is no variant's point (unknown, a single
// point rule like circumcenter, a name it already allows) or cannot be inserted.
void follow_chain(Replay& replay, const std::vector<Point>& trace, std::size_t first, ConformanceFailure& f,
                  std::size_t& centroid_inside) {
  f.chain = {{f.deviation, first + 1, 0}};
  Deviation named = deviation_named(f.deviation);
  std::string named_what;  // the diagnosis of the step that named it (an unknown's nearest rules)
  std::size_t i = first;
  while (i < trace.size()) {
    if (!has_variant(named)) {
      // The first failing step's name is no rule set either: nothing to go on with,
      // and the chain stops there, with its reason as any other (its what is the failure's).
      if (f.chain.size() == 1) named_what = f.deviation_what;
      f.chain_end = named == Deviation::Unknown
                        ? fmt::format("step {} is {}", i + 1, named_what)
                        : fmt::format("step {} is {}'s point, not a rule set the replay can go on with", i + 1, to_string(named));
      f.chain_end_reason = named == Deviation::Unknown ? "no-rule" : "point-rule";
      f.chain_end_step = i + 1;
      return;
    }
    replay.allow(named);
    const Point& p = trace[i];
    ReplayChoice choice;
    if (!replay.match(p, choice)) {
      const DeviationMatch diagnosis = replay.diagnose(p);
      const Deviation next = diagnosis.deviation;
      named_what = diagnosis.what;
      const std::string name = to_string(next);
      for (const DeviationLink& l : f.chain)
        if (l.deviation == name) {
          f.chain_end = fmt::format("step {} is {}'s point at a configuration the replay cannot reach with it", i + 1, name);
          f.chain_end_reason = "unreachable";
          f.chain_end_step = i + 1;
          return;
        }
      f.chain.push_back({name, i + 1, 0});
      named = next;
      continue;  // the same step again, with the new name allowed
    }
    try {
      replay.insert(p, choice);
    } catch (const std::runtime_error& e) {
      f.chain_end = fmt::format("step {} cannot be inserted: {}", i + 1, e.what());
      f.chain_end_reason = "not-insertable";
      f.chain_end_step = i + 1;
      return;
    }
    if (choice.deviation != Deviation::Unknown)
      for (DeviationLink& l : f.chain) l.steps += l.deviation == to_string(choice.deviation);
    centroid_inside += remark10_centroid(choice);
    ++i;
  }
  f.chain_complete = true;
}

// remark10-ignored's points are remark10-reversed's too (a centroid outside
// the other triangle): a trace that also shows a point only the reversed rule
// has (the midpoint where the centroid is inside) is remark10-reversed from
// the ignored one's first step on.
void merge_remark10(ConformanceFailure& f) {
  const std::string ignored = to_string(Deviation::Remark10Ignored);
  const std::string reversed = to_string(Deviation::Remark10Reversed);
  auto find = [&](const std::string& n) {
    return std::find_if(f.chain.begin(), f.chain.end(), [&](const DeviationLink& l) { return l.deviation == n; });
  };
  auto ig = find(ignored), re = find(reversed);
  if (ig == f.chain.end() || re == f.chain.end()) return;
  ig->deviation = reversed;
  ig->steps += re->steps;
  f.chain.erase(re);
  if (f.deviation == ignored) {
    f.deviation = reversed;
    f.deviation_definition = definition(Deviation::Remark10Reversed);
  }
}

// The program's mesh in words, for a chain's end.
const char* mesh_words(MeshReading reading) {
  switch (reading) {
    case MeshReading::NoFlips: return "without flips";
    case MeshReading::NoFlipsButSplits: return "without flips but after a constrained edge's split";
    case MeshReading::DoubleIncircle: return "with its flips decided in double";
    case MeshReading::FloatPoints: return "with its points at float rounding";
    case MeshReading::TiesKept: return "with every exactly cocircular quad's diagonal kept as its insertion made it";
    case MeshReading::FloatInput: return "of its input vertices rounded to float";
    case MeshReading::Exact: break;
  }
  return "exactly";
}

// follow_chain on the program's mesh, from the trace's first step: f.chain[0] (the
// arithmetic name, at f.step) stays first; each step that is no allowed choice
// there is named by the catalogue and its rule allowed, as follow_chain does; a
// step no rule fits ends the chain with program-mesh-lost, not unknown: on the
// exact mesh such a step is expected, on the program's it says the replay lost it.
// Returns the steps it followed (the trace's length when complete).
// With f.deviation empty (the fallback of follow_program_mesh: a tie rule, not
// a name) the chain starts empty, and its first name becomes f.deviation.
std::size_t follow_on_program_mesh(Replay& replay, const std::vector<Point>& trace, MeshReading reading, ConformanceFailure& f,
                                   std::size_t& centroid_inside) {
  f.chain.clear();
  if (!f.deviation.empty()) {
    f.chain.push_back({f.deviation, f.step + 1, 0});
    replay.allow(deviation_named(f.deviation));  // a rule set's name first; no-op for the mesh's
  }
  f.chain_complete = false;
  f.chain_end.clear();
  f.chain_end_reason.clear();
  f.chain_end_step = 0;
  f.mesh_reading = to_string(reading);
  std::size_t i = 0;
  while (i < trace.size()) {
    const Point& p = trace[i];
    ReplayChoice choice;
    if (!replay.match(p, choice)) {
      const DeviationMatch diagnosis = replay.diagnose(p);
      const std::string name = to_string(diagnosis.deviation);
      if (diagnosis.deviation == Deviation::Unknown) {
        f.chain_end = fmt::format("step {} fits no rule of the catalogue on the program's mesh as the replay rebuilds it ({}): "
                                  "the program's mesh there is another, or its point is no rule; {}",
                                  i + 1, mesh_words(reading), diagnosis.what);
        f.chain_end_reason = "program-mesh-lost";
        f.chain_end_step = i + 1;
        return i;
      }
      for (const DeviationLink& l : f.chain)
        if (l.deviation == name) {
          f.chain_end = fmt::format("step {} is {}'s point at a configuration the replay cannot reach with it on the program's mesh ({})",
                                    i + 1, name, mesh_words(reading));
          f.chain_end_reason = "unreachable";
          f.chain_end_step = i + 1;
          return i;
        }
      if (f.chain.empty()) {
        f.deviation = name;
        f.deviation_what = fmt::format("step {} on the program's mesh as the replay rebuilds it ({}): {}", i + 1,
                                       mesh_words(reading), diagnosis.what);
        f.deviation_definition = definition(diagnosis.deviation);
        f.consistent_variant = false;
      }
      f.chain.push_back({name, i + 1, 0});
      if (!has_variant(diagnosis.deviation)) {
        f.chain_end = fmt::format("step {} is {}'s point, not a rule set the replay can go on with", i + 1, name);
        f.chain_end_reason = "point-rule";
        f.chain_end_step = i + 1;
        return i;
      }
      replay.allow(diagnosis.deviation);
      continue;  // the same step again, with the new name allowed
    }
    try {
      replay.insert(p, choice);
    } catch (const std::runtime_error& e) {
      f.chain_end = fmt::format("step {} cannot be inserted in the program's mesh as the replay rebuilds it ({}): {}", i + 1,
                                mesh_words(reading), e.what());
      f.chain_end_reason = "not-insertable";
      f.chain_end_step = i + 1;
      return i;
    }
    if (choice.deviation != Deviation::Unknown)
      for (DeviationLink& l : f.chain) l.steps += l.deviation == to_string(choice.deviation);
    centroid_inside += remark10_centroid(choice);
    ++i;
  }
  f.chain_complete = true;
  return i;
}

std::string tri(const Tri& t) { return fmt::format("({},{},{})", t[0], t[1], t[2]); }

// Which names of a chain a replay up to a step allows.
enum class Allowing {
  None,                  // the exact replay: only the paper's choices
  AllFromTheStart,       // every name of the chain, at every step
  EachFromItsFirstStep,  // each name from the step the chain named it at
};

// The trace's first `steps` points replayed on `reading`'s mesh, each matched to a
// choice and inserted: the mesh just before step `steps`. Null where a point is no
// choice there or an insertion throws (the replay would be broken).
std::unique_ptr<Replay> replay_trace_to(const Pslg& validated, const std::vector<Point>& trace, std::size_t steps,
                                        const ConformanceOptions& options, MeshReading reading,
                                        const std::vector<DeviationLink>& chain, Allowing allowing) {
  std::unique_ptr<Replay> replay = replay_on(validated, options, reading);
  if (allowing == Allowing::AllFromTheStart)
    for (const DeviationLink& l : chain) replay->allow(deviation_named(l.deviation));
  try {
    for (std::size_t i = 0; i < steps; ++i) {
      if (allowing == Allowing::EachFromItsFirstStep)
        for (const DeviationLink& l : chain)
          if (l.first_step <= i + 1) replay->allow(deviation_named(l.deviation));  // named at this step or before
      ReplayChoice choice;
      if (!replay->match(trace[i], choice)) return nullptr;
      replay->insert(trace[i], choice);
    }
  } catch (const std::runtime_error&) {
    return nullptr;
  }
  return replay;
}

// What a report shows of the failing step f.step at f.point on the replay `at`
// just before it: that mesh, the nearest choices, why the point is none of them
// (`reason` when the caller knows it already), and the catalogue's diagnosis.
void describe_step(Replay& at, std::string reason, ConformanceFailure& f) {
  const Point& p = f.point;
  f.mesh = at.mesh();
  f.candidates.clear();
  std::vector<ReplayChoice> all = at.all_choices(p, 20, f.candidates_total);
  for (const auto& c : all) f.candidates.push_back(candidate(c));
  f.nearest_distance = all.empty() ? -1 : all.front().distance;
  if (reason.empty()) {
    bool vertex = false;
    for (const Point& v : f.mesh.vertices) vertex = vertex || v == p;
    if (vertex)
      reason = "the point is already a vertex of the mesh";
    else if (all.empty())
      reason = "the mesh has no bad triangle: no point should be inserted";
    else
      // The same distance as the table of nearest choices (Euclidean); the tolerance
      // bounds the larger coordinate difference, given beside it.
      reason = fmt::format(
          "not the paper's choice for any bad triangle's Lepp (nearest choice {:.3g} away; its larger coordinate "
          "difference {:.3g}, tolerance {:.3g})",
          all.front().euclidean, all.front().distance, all.front().tolerance);
  }
  f.reason = reason;
  // The catalogue, on the same mesh with the same arithmetic and tolerance.
  const DeviationMatch dm = at.diagnose(p);
  f.deviation = to_string(dm.deviation);
  f.deviation_what = dm.what;
  f.deviation_definition = definition(dm.deviation);
  f.deviation_at.reset();
  f.deviation_paper.clear();
  if (dm.deviation != Deviation::Unknown) {
    f.deviation_at = candidate(dm.where);
    for (const auto& c : dm.paper) f.deviation_paper.push_back(candidate(c));
  }
}

// The failing step described again on `reading`'s mesh (describe_step), where it is
// no allowed choice there either: the trace replayed up to it on that mesh, each
// name of the chain allowed from its first step. The chain's names are kept.
// Unchanged where that replay does not get there or the point is a choice there.
void restate_step_on(const Pslg& validated, const std::vector<Point>& trace, const ConformanceOptions& options,
                     MeshReading reading, ConformanceFailure& f) {
  const std::unique_ptr<Replay> replay =
      replay_trace_to(validated, trace, f.step, options, reading, f.chain, Allowing::EachFromItsFirstStep);
  if (!replay) return;
  try {
    ReplayChoice choice;
    if (replay->match(trace[f.step], choice)) return;  // a choice on that mesh: nothing to show there
  } catch (const std::runtime_error&) {
    return;
  }
  ConformanceFailure g = f;
  describe_step(*replay, "", g);
  if (g.deviation != f.deviation) g.deviation_at.reset(), g.deviation_paper.clear();
  g.deviation = f.deviation;
  g.deviation_what = f.deviation_what;
  g.deviation_definition = f.deviation_definition;
  g.step_mesh_reading = to_string(reading);
  f = std::move(g);
}

}  // namespace

ConformanceReport check_conformance(const Pslg& validated, const std::vector<Point>& trace,
                                    const ConformanceOptions& options) {
  auto start = std::chrono::steady_clock::now();
  const std::unique_ptr<Replay> exact = replay_on(validated, options, MeshReading::Exact);
  Replay& replay = *exact;

  ConformanceReport report;
  report.steps = trace.size();
  report.area_centroid = options.area_centroid;
  report.arithmetic_double = options.arithmetic_double;
  std::unique_ptr<Replay> before;  // the mesh before a step whose insertion failed
  std::size_t centroid_inside = 0;             // ConformanceFailure::remark10_centroid_inside_steps
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const Point& p = trace[i];
    ReplayChoice choice;
    std::string reason;
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      reason = "not a finite point";
    } else if (replay.match(p, choice)) {
      if (options.theorem2_every_step && choice.t2[0] >= 0) {
        ++report.theorem2_pairs_checked;
        const Theorem2Check t2 = replay.theorem2(choice);
        if (!t2.holds && !report.theorem2_failure) {
          Theorem2StepFailure f;
          f.step = i;
          f.point = p;
          f.terminal_edge = choice.terminal_edge;
          f.t1 = choice.t1;
          f.t2 = choice.t2;
          f.apex = t2.apex;
          f.angle_deg = t2.angle_deg;
          f.mesh = replay.mesh();
          report.theorem2_failure = std::move(f);
        }
      }
      try {
        replay.insert(p, choice);
        ++report.steps_checked;
        centroid_inside += remark10_centroid(choice);
        if (choice.deviation == Deviation::InexactLength || choice.deviation == Deviation::InexactThreshold)
          ++report.inexact_steps[to_string(choice.deviation)];
        continue;
      } catch (const std::runtime_error& e) {
        reason = fmt::format("the point is a choice ({}) but cannot be inserted: {}", to_string(choice.rule), e.what());
        // The insertion may have stopped half way (the point in, a triangle not
        // counter-clockwise, even flat: issue 30), so the report's mesh, choices and
        // deviation come from the trace replayed again up to this step.
        before = replay_trace_to(validated, trace, i, options, MeshReading::Exact, {}, Allowing::None);
      }
    }
    Replay& at = before ? *before : replay;
    ConformanceFailure failure;
    failure.step = i;
    failure.point = p;
    describe_step(at, reason, failure);
    report.cocircular_search_exhausted = replay.cocircular_search_exhausted();
    report.conforms = false;
    report.failure = std::move(failure);
    break;
  }
  // Every deviation of the trace: the same replay goes on from the failing step
  // (not after a choice that could not be inserted: that replay is broken).
  if (report.failure && options.check_variant && !before) {
    ConformanceFailure& f = *report.failure;
    follow_chain(replay, trace, f.step, f, centroid_inside);
    merge_remark10(f);
    f.consistent_variant = fits_one_variant(f);
    if (f.consistent_variant) f.variant_steps = f.chain.front().steps;
  }
  if (report.failure) {
    ConformanceFailure& f = *report.failure;
    if (f.chain.empty()) f.chain = {{f.deviation, f.step + 1, 0}};
    f.remark10_centroid_inside_steps = centroid_inside;
  }
  report.cocircular_ties = replay.cocircular_ties();
  report.cocircular_flips = replay.cocircular_flips();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

MeshReading mesh_reading_for(const std::string& deviation) {
  if (deviation == kMissingFlips) return MeshReading::NoFlips;
  if (deviation == "inexact-incircle") return MeshReading::DoubleIncircle;
  if (deviation == "single-precision") return MeshReading::FloatPoints;
  if (deviation == "float-input") return MeshReading::FloatInput;
  return MeshReading::Exact;
}

void follow_program_mesh(const Pslg& validated, const std::vector<Point>& trace, const ConformanceOptions& options,
                         ConformanceFailure& f) {
  if (!options.check_variant) return;
  std::vector<MeshReading> readings{mesh_reading_for(f.deviation)};
  // A chain lost on the exact mesh at a step no rule fits, with nothing in the
  // final mesh to say why: the program's mesh may be another constrained Delaunay
  // one (an exactly cocircular quad's diagonal kept as its insertion made it, where
  // CGAL breaks the tie by its perturbation and the replay's search of cocircular
  // cells does not reach), or it decided flips in double and later insertions made
  // it Delaunay again. The chain is followed again from the first step on each,
  // and kept only when it goes past the step the exact chain lost.
  const bool fallback = readings.front() == MeshReading::Exact;
  std::size_t lost_at = 0;  // the exact chain's step no rule fits, 1-based
  if (fallback) {
    if (f.chain_end_reason == "no-rule") lost_at = f.chain_end_step;
    else return;
    readings = {MeshReading::TiesKept, MeshReading::DoubleIncircle, MeshReading::NoFlips, MeshReading::NoFlipsButSplits};
  }
  // Missing flips may be missing everywhere, only after a point put in a face (a
  // split made by a library's Delaunay insertion), or where a double in-circle
  // test overflows or underflows (huge or subnormal coordinates: beyond rounding,
  // so not inexact-incircle): each is tried.
  if (readings.front() == MeshReading::NoFlips)
    readings.insert(readings.end(), {MeshReading::NoFlipsButSplits, MeshReading::DoubleIncircle});
  // The one that follows the trace farthest is kept (the first on a tie).
  std::optional<ConformanceFailure> best;
  MeshReading best_reading = readings.front();
  std::size_t best_reached = 0;
  for (MeshReading r : readings) {
    std::unique_ptr<Replay> replay;
    try {
      replay = replay_on(validated, options, r);
    } catch (const std::invalid_argument&) {
      continue;  // no such mesh (two input vertices one at float rounding): the chain stays as it is
    }
    ConformanceFailure g = f;
    if (fallback) g.deviation.clear();  // the chain is named again, from the first step, on that mesh
    std::size_t centroid_inside = 0;
    const std::size_t reached = follow_on_program_mesh(*replay, trace, r, g, centroid_inside);
    merge_remark10(g);
    g.remark10_centroid_inside_steps = centroid_inside;
    if (!best || reached > best_reached) best = std::move(g), best_reading = r, best_reached = reached;
    if (best->chain_complete) break;
  }
  if (!best) return;  // no reading could be built
  if (fallback) {
    // The mesh's arithmetic (flips decided in double, or missing) is the
    // program's: named where the exact mesh lost the chain.
    const std::string name = best_reading == MeshReading::DoubleIncircle ? kInexactIncircle
                             : best_reading == MeshReading::TiesKept      ? ""
                                                                          : kMissingFlips;
    // Lost there (or sooner) on those meshes too: the exact chain stays. So it does
    // where every step is the paper's choice with cocircular ties kept (a program
    // the exact replay's search of cocircular cells did not follow; not met in the
    // measurements of docs/CONFORMANCE.md): no name says what the program did. With
    // every step the paper's choice on a program's mesh that has a name (flips
    // decided in double, none), that name alone is the chain.
    if (best_reached < lost_at || (best->chain.empty() && name.empty())) return;
    best->mesh_reading_fallback = true;
    auto& chain = best->chain;
    if (!name.empty() && std::none_of(chain.begin(), chain.end(), [&](const DeviationLink& l) { return l.deviation == name; })) {
      chain.insert(std::find_if(chain.begin(), chain.end(), [&](const DeviationLink& l) { return l.first_step >= lost_at; }),
                   {name, lost_at, 0});
      if (chain.front().deviation == name) {
        best->deviation = name;
        best->deviation_what = fmt::format(
            "step {} fits no rule on the exact mesh, and the paper's rules on the mesh {}: {} (its final mesh is Delaunay "
            "again: later insertions removed the difference)",
            lost_at, mesh_words(best_reading),
            name == kInexactIncircle ? "a quad cocircular within double rounding got the other diagonal"
                                     : "the program did not flip after its insertions");
        best->deviation_definition = name == kInexactIncircle ? inexact_definition(kInexactIncircle) : kMissingFlipsDefinition;
      }
    }
    // The step's picture and table on the mesh followed, where its chain starts at
    // the failing step: the choices the deviation's words speak of.
    if (best->chain.front().first_step == best->step + 1) restate_step_on(validated, trace, options, best_reading, *best);
  }
  f = std::move(*best);
}

std::optional<ConformanceFailure> chain_end_failure(const Pslg& validated, const std::vector<Point>& trace,
                                                    const ConformanceOptions& options, const ConformanceFailure& f) {
  if (f.chain_end_reason != "no-rule" && f.chain_end_reason != "program-mesh-lost") return std::nullopt;
  if (f.chain_end_step == 0 || f.chain_end_step > trace.size()) return std::nullopt;
  // The failing step itself (a chain of one name, on the mesh the failure was found
  // on): its picture is the finding's step.svg already.
  if (f.chain_end_step == f.step + 1 && f.mesh_reading.empty()) return std::nullopt;
  MeshReading reading = MeshReading::Exact;
  for (MeshReading r : {MeshReading::NoFlips, MeshReading::NoFlipsButSplits, MeshReading::DoubleIncircle, MeshReading::FloatPoints,
                        MeshReading::TiesKept, MeshReading::FloatInput})
    if (f.mesh_reading == to_string(r)) reading = r;
  const std::size_t end = f.chain_end_step - 1;
  const std::unique_ptr<Replay> at_end = replay_trace_to(validated, trace, end, options, reading, f.chain, Allowing::AllFromTheStart);
  if (!at_end) return std::nullopt;
  Replay& replay = *at_end;
  ConformanceFailure g;
  g.step = end;
  g.point = trace[end];
  g.reason = f.chain_end;
  g.mesh = replay.mesh();
  std::vector<ReplayChoice> all = replay.all_choices(g.point, 20, g.candidates_total);
  for (const auto& c : all) g.candidates.push_back(candidate(c));
  if (!all.empty()) g.nearest_distance = all.front().distance;
  const DeviationMatch dm = replay.diagnose(g.point);
  g.deviation = to_string(dm.deviation);
  g.deviation_what = dm.what;
  g.deviation_definition = definition(dm.deviation);
  g.mesh_reading = f.mesh_reading;
  return g;
}

std::string chain_text(const std::vector<DeviationLink>& chain) {
  std::string s;
  for (const DeviationLink& l : chain) s += fmt::format("{}{} from step {}", s.empty() ? "" : "; then ", l.deviation, l.first_step);
  return s;
}

std::string remark10_ignored_note(const ConformanceFailure& f) {
  const std::string ignored = to_string(Deviation::Remark10Ignored);
  bool named = false;
  for (const DeviationLink& l : f.chain) named = named || l.deviation == ignored;
  if (!named) return "";
  if (f.remark10_centroid_inside_steps > 0)
    return fmt::format("remark10-ignored, not remark10-reversed: {} steps took the quad centroid inside the other triangle "
                       "(the paper's Remark 10, which a reversed program never does)",
                       f.remark10_centroid_inside_steps);
  return "remark10-reversed fits the trace as well: no step had the quad centroid inside the other triangle with one "
         "second-longest edge constrained, where the two tell apart";
}

std::string describe(const ConformanceReport& r, std::size_t max_candidates) {
  if (r.conforms) {
    std::string s = fmt::format("conforms: {} of {} steps are the paper's choices\n", r.steps_checked, r.steps);
    for (const auto& [name, steps] : r.inexact_steps)
      s += fmt::format("  {} of them only under the double reading (--arithmetic double): {}\n", steps, name);
    return s;
  }
  const ConformanceFailure& f = *r.failure;
  std::string s = fmt::format("step {} of {}: point ({:.17g}, {:.17g}): {}\n", f.step, r.steps, f.point.x, f.point.y, f.reason);
  s += fmt::format("deviation: {}: {}", f.deviation, f.deviation_what);
  if (f.deviation_at) s += fmt::format(", at ({:.17g}, {:.17g}), {:.3g} away", f.deviation_at->point.x, f.deviation_at->point.y, f.deviation_at->euclidean);
  s += "\n";
  for (const ConformanceCandidate& c : f.deviation_paper)
    s += fmt::format("  the paper's choice there: ({:.17g}, {:.17g}) {}, {:.3g} away\n", c.point.x, c.point.y, to_string(c.rule), c.euclidean);
  if (f.consistent_variant)
    s += fmt::format("every one of the {} steps is the paper's choice or {}'s ({} of them {}'s): one consistent variant\n", r.steps,
                     f.deviation, f.variant_steps, f.deviation);
  if (f.chain.size() > 1 || !f.chain_end.empty())
    s += fmt::format("every deviation of the trace: {}{}{}\n", chain_text(f.chain),
                     f.chain_complete ? " (to the trace's end)" : "; the replay stopped: " + f.chain_end,
                     f.mesh_reading.empty() ? "" : fmt::format(" [followed on the program's mesh: {}]", f.mesh_reading));
  if (const std::string note = remark10_ignored_note(f); !note.empty()) s += note + "\n";
  std::size_t n = std::min(max_candidates, f.candidates.size());
  if (n) s += fmt::format("nearest of {} choices at this step:\n", f.candidates_total);
  for (std::size_t i = 0; i < n; ++i) {
    const ConformanceCandidate& c = f.candidates[i];
    std::string lepp;
    for (const Tri& t : c.lepp) lepp += " " + tri(t);
    s += fmt::format("  ({:.17g}, {:.17g}) {} distance {:.3g}: bad {}, Lepp{}, terminal edge ({},{})\n", c.point.x, c.point.y,
                     to_string(c.rule), c.euclidean, tri(c.bad), lepp, c.terminal_edge[0], c.terminal_edge[1]);
  }
  if (r.theorem2_failure)
    s += fmt::format("Theorem 2 fails at step {}: the angle at vertex {} of terminal edge ({},{}) is over 120 degrees (about {:.6g})\n",
                     r.theorem2_failure->step, r.theorem2_failure->apex, r.theorem2_failure->terminal_edge[0],
                     r.theorem2_failure->terminal_edge[1], r.theorem2_failure->angle_deg);
  if (r.area_centroid) s += "reading declared: the quad centroid is its area centroid (--centroid area)\n";
  if (r.arithmetic_double) s += "reading declared: the arithmetic of doubles (--arithmetic double)\n";
  if (r.cocircular_search_exhausted)
    s += "note: the search of the cocircular cells' other triangulations gave up (cocircular_search_budget): "
         "the point may be a choice of a constrained Delaunay mesh it did not reach\n";
  else if (r.cocircular_ties > 0)
    s += fmt::format("note: the mesh had {} cocircular ties and the replay flipped {} cocircular edges to follow the trace; "
                     "unless follow_cocircular_flips is off, every triangulation of the cocircular cells was searched\n",
                     r.cocircular_ties, r.cocircular_flips);
  return s;
}

}  // namespace lepp::audit
