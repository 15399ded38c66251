// SPDX-License-Identifier: GPL-3.0-or-later
// --shard K/N: which cases a shard runs, its report's shard data, and the shards merged into one report.
#include "lepp/audit/report/shard.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "lepp/audit/report/report.h"
#include "lepp/audit/run/subprocess.h"

namespace fs = std::filesystem;

namespace lepp::audit {
namespace {

std::uint64_t fnv1a(const std::string& s, std::uint64_t h) {
  for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

// The inputs' contents, bit for bit (not their names: the paper's problems are
// named by their path, which may differ between machines of one CI).
std::string inputs_hash(const std::vector<AuditInput>& inputs) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const AuditInput& in : inputs) {
    const Pslg& p = in.pslg;
    std::string k = fmt::format("{} {} {} {}\n", p.vertices.size(), p.segments.size(), p.holes.size(), p.regions.size());
    for (const Point& v : p.vertices) k += fmt::format("{:a} {:a}\n", v.x, v.y);
    for (const Segment& s : p.segments) k += fmt::format("{} {} {}\n", s.a, s.b, s.marker);
    for (const Point& v : p.holes) k += fmt::format("{:a} {:a}\n", v.x, v.y);
    for (const Region& r : p.regions) k += fmt::format("{:a} {:a} {:a} {:a}\n", r.at.x, r.at.y, r.attribute, r.max_area);
    h = fnv1a(k, h);
  }
  return fmt::format("{:016x}", h);
}

Row row_of(const std::string& key) {
  for (Row r : kAllRows)
    if (key == row_key(r)) return r;
  throw UsageError("unknown check " + key);
}

std::size_t row_index(Row r) { return static_cast<std::size_t>(r); }

Counterexample counterexample_of(const nlohmann::json& j, Row row) {
  Counterexample c;
  c.row = row;
  c.dir = j.at("dir").get<std::string>();
  c.input = j.at("input").get<std::string>();
  c.theta = j.at("theta").get<double>();
  c.vertices = j.at("vertices").get<std::size_t>();
  c.segments = j.at("segments").get<std::size_t>();
  c.holes = j.at("holes").get<std::size_t>();
  c.original_vertices = j.at("original_vertices").get<std::size_t>();
  c.original_segments = j.at("original_segments").get<std::size_t>();
  c.original_holes = j.at("original_holes").get<std::size_t>();
  c.shrink_steps = j.at("shrink_steps").get<std::size_t>();
  c.shrink_runs = j.at("shrink_runs").get<std::size_t>();
  c.shrink_timeout = j.at("shrink_timeout").get<double>();
  c.signature = j.at("signature").get<std::string>();
  c.detail = j.at("detail").get<std::string>();
  c.deviation = j.value("deviation", std::string());
  if (j.contains("deviations")) c.deviations = deviations_of(j.at("deviations"));
  c.chain_end_reason = j.value("chain_end_reason", std::string());
  c.mesh_reading = j.value("mesh_reading", std::string());
  c.original_detail = j.at("original_detail").get<std::string>();
  c.original_input = j.at("original_input").get<std::string>();
  c.deterministic = j.at("deterministic").get<bool>();
  c.nondeterminism = j.at("nondeterminism").get<std::string>();
  c.stderr_file = j.at("stderr_file").get<std::string>();
  c.reproduce = j.at("reproduce").get<std::string>();
  return c;
}

OrderTermination order_termination_of(const nlohmann::json& j) {
  OrderTermination t;
  t.input = j.at("input").get<std::string>();
  t.theta = j.at("theta").get<double>();
  t.engine_converged = j.at("engine_converged").get<bool>();
  t.fifo_converged = j.at("lepp_fifo_converged").get<bool>();
  t.converging = j.at("lepp_orders_converging").get<std::vector<std::string>>();
  t.random_converged = j.at("random_converged").get<int>();
  t.random_tried = j.at("random_tried").get<int>();
  return t;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) s.replace(at, from.size(), to);
}

// A finding one shard saved, with where it stands in the whole audit.
struct Candidate {
  std::size_t run = 0;
  bool internal = false;
  Row row = Row::Certificate;
  std::string input;
  Counterexample cx;
  fs::path source;  // its directory on this machine (empty: not found)
  std::string shard_abs_dir;
};

}  // namespace

ShardSpec parse_shard(const std::string& text) {
  const std::string usage = "--shard " + text + ": expected K/N, the K-th of N shards, 1 <= K <= N (e.g. --shard 2/8)";
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == text.size()) throw UsageError(usage);
  auto number = [&](const std::string& s) {
    if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
      throw UsageError(usage);
    return static_cast<std::size_t>(std::stoul(s));
  };
  ShardSpec spec{number(text.substr(0, slash)), number(text.substr(slash + 1))};
  if (spec.count < 1 || spec.index < 1 || spec.index > spec.count) throw UsageError(usage);
  return spec;
}

bool in_shard(std::size_t case_index, std::size_t shard_index, std::size_t shard_count) {
  return case_index % shard_count == shard_index - 1;
}

nlohmann::json shard_config(const AuditOptions& o, const std::vector<AuditInput>& inputs, std::size_t total_cases) {
  nlohmann::json compare = nlohmann::json::array();
  for (const NamedEngine& e : o.comparisons) compare.push_back(e.name);
  return {{"engine", o.engine_name},
          {"method", to_string(o.method)},
          {"thetas", o.thetas},
          {"seed", o.inputs.seed},
          {"cases", o.cases},
          {"total_cases", total_cases},
          {"inputs", inputs.size()},
          {"inputs_hash", inputs_hash(inputs)},
          {"repeat", o.repeat},
          {"timeout", o.timeout_seconds},
          {"memory_mb", o.memory_mb},
          {"angle_tolerance", o.checks.angle_tolerance_deg},
          {"point_tolerance", o.checks.point_tolerance_ulps},
          {"centroid", o.checks.area_centroid ? "area" : "vertex"},
          {"arithmetic", o.checks.arithmetic_double ? "double" : "exact"},
          {"tie_search_states", o.checks.tie_search_states},
          {"shrink", o.shrink},
          {"max_findings", o.max_findings_per_row},
          {"shrink_max_runs", o.shrink_max_runs},
          {"shrink_max_seconds", o.shrink_max_seconds},
          {"compare", compare},
          {"compare_orders", o.compare_orders},
          {"shards", o.shard_count}};
}

nlohmann::json shard_to_json(const AuditReport& rep) {
  const ShardData& d = *rep.shard;
  // deviation_first is in the markdown only ("first at ..."): the shard carries it with its run.
  nlohmann::json first = nlohmann::json::object(), deviation_first = nlohmann::json::object();
  for (Row r : kAllRows) {
    first[row_key(r)] = d.first_run[row_index(r)];
    for (const auto& [name, at] : d.deviation_first_run[row_index(r)])
      deviation_first[row_key(r)][name] = {{"run", at}, {"text", rep[r].deviation_first.at(name)}};
  }
  nlohmann::json points = nlohmann::json::array();
  for (const ShardData::Points& p : d.points) {
    nlohmann::json theirs = nlohmann::json::array();
    for (const auto& t : p.theirs) theirs.push_back(t ? nlohmann::json(*t) : nlohmann::json());
    points.push_back({{"case", p.case_index}, {"ours", p.ours}, {"theirs", theirs}});
  }
  nlohmann::json findings = nlohmann::json::array();
  for (const ShardData::Finding& f : d.findings)
    findings.push_back({{"dir", f.dir}, {"dir_absolute", f.dir_absolute}, {"run", f.run}, {"check", row_key(f.row)},
                        {"internal", f.internal}, {"input", f.input}});
  return {{"index", d.index},
          {"count", d.count},
          {"total_cases", d.total_cases},
          {"cases", d.cases},
          {"config", d.config},
          {"first_run", first},
          {"deviation_first", deviation_first},
          {"nondeterministic_cases", d.nondeterministic_cases},
          {"order_termination_cases", d.order_termination_cases},
          {"points", points},
          {"findings", findings}};
}

AuditReport merge_shards(const std::vector<MergeInput>& shards, const std::string& out_dir, std::vector<std::string>& warnings) {
  if (shards.empty()) throw UsageError("merge: no shard reports given");
  // 1. Shards of one audit, each once, every case in exactly one.
  for (const MergeInput& s : shards)
    if (!s.report.is_object() || !s.report.contains("shard"))
      throw UsageError(s.path + " is not a shard's report (from lepp audit --shard K/N --json)");
  const nlohmann::json& first = shards.front().report;
  const nlohmann::json& config = first["shard"]["config"];
  const std::size_t n = first["shard"]["count"].get<std::size_t>();
  std::map<std::size_t, std::string> by_index;
  for (const MergeInput& s : shards) {
    const nlohmann::json& d = s.report["shard"];
    if (d["count"].get<std::size_t>() != n)
      throw UsageError(fmt::format("{} is shard {}/{}, {} is shard {}/{}: shards of different splits", shards.front().path,
                                   first["shard"]["index"].get<std::size_t>(), n, s.path, d["index"].get<std::size_t>(),
                                   d["count"].get<std::size_t>()));
    // The likeliest mix-ups named first (the object's own order is alphabetical).
    std::vector<std::string> keys = {"engine", "method", "thetas", "seed", "cases", "inputs", "inputs_hash"};
    for (const auto& [key, value] : config.items()) keys.push_back(key);
    for (const auto& [key, value] : d["config"].items()) keys.push_back(key);
    for (const std::string& key : keys)
      if (config.value(key, nlohmann::json()) != d["config"].value(key, nlohmann::json()))
        throw UsageError(fmt::format("{} and {} are shards of different audits: {} is {} in one, {} in the other", shards.front().path,
                                     s.path, key, config.value(key, nlohmann::json()).dump(),
                                     d["config"].value(key, nlohmann::json()).dump()));
    if (first.value("lepp_version", std::string()) != s.report.value("lepp_version", std::string()))
      throw UsageError(fmt::format("{} and {} were written by different lepp versions ({} and {})", shards.front().path, s.path,
                                   first.value("lepp_version", std::string("?")), s.report.value("lepp_version", std::string("?"))));
    const std::size_t k = d["index"].get<std::size_t>();
    if (!by_index.emplace(k, s.path).second)
      throw UsageError(fmt::format("shard {}/{} given twice: {} and {}", k, n, by_index[k], s.path));
  }
  for (std::size_t k = 1; k <= n; ++k)
    if (!by_index.count(k)) throw UsageError(fmt::format("shard {}/{} is missing: every shard of the audit is needed", k, n));
  const std::size_t total_cases = config["total_cases"].get<std::size_t>();
  std::vector<std::size_t> owner(total_cases, 0);
  for (const MergeInput& s : shards) {
    const std::size_t k = s.report["shard"]["index"].get<std::size_t>();
    for (std::size_t c : s.report["shard"]["cases"].get<std::vector<std::size_t>>()) {
      if (c >= total_cases) throw UsageError(fmt::format("{}: case {} beyond the audit's {} cases", s.path, c, total_cases));
      if (owner[c]) throw UsageError(fmt::format("case {} was run by shards {} and {}: the shards overlap", c, owner[c], k));
      owner[c] = k;
    }
  }
  for (std::size_t c = 0; c < total_cases; ++c)
    if (!owner[c]) throw UsageError(fmt::format("case {} was run by no shard", c));

  // 2. What every shard says alike, then the sums.
  AuditReport rep;
  rep.engine = first["engine"].get<std::string>();
  rep.method = Method::Centroid;  // unless the shard names another
  parse_method(first["method"].get<std::string>(), rep.method);
  rep.thetas = first["thetas"].get<std::vector<double>>();
  rep.seed = first["seed"].get<std::uint64_t>();
  rep.inputs = first["inputs"].get<std::size_t>();
  rep.skipped_inputs = first["skipped_inputs"].get<std::vector<std::string>>();
  rep.area_centroid = first["centroid"].get<std::string>() == "area";
  rep.arithmetic_double = first.value("arithmetic", "exact") == "double";
  rep.tie_search_states = first.value("tie_search_states", kTieSearchStates);
  rep.jobs = first["jobs"].get<std::size_t>();
  rep.repeat = first["repeat"].get<std::size_t>();
  rep.points_cache_dir = first["points_cache_dir"].get<std::string>();
  rep.out_dir = out_dir;
  for (std::size_t i = 0; i < kRows; ++i) rep.rows[i].row = kAllRows[i];
  const std::size_t max_findings = config["max_findings"].get<std::size_t>();
  const std::vector<std::string> compare = config["compare"].get<std::vector<std::string>>();

  std::array<std::size_t, kRows> first_run{};
  std::array<std::map<std::string, std::size_t>, kRows> deviation_run;
  std::vector<std::pair<std::size_t, std::string>> nondeterministic;
  std::vector<std::pair<std::size_t, OrderTermination>> order_terminations;
  std::vector<std::pair<std::size_t, nlohmann::json>> points;
  std::vector<Candidate> candidates;
  for (const MergeInput& s : shards) {
    const nlohmann::json& j = s.report;
    const nlohmann::json& d = j["shard"];
    rep.cases += j["runs"].get<std::size_t>();
    rep.internal_error_runs += j["internal_error_runs"].get<std::size_t>();
    rep.exempt_triangles += j["exempt_triangles"].get<std::size_t>();
    rep.runs_with_exempt += j["runs_with_exempt_triangles"].get<std::size_t>();
    rep.precision_exempt_triangles += j["precision_exempt_triangles"].get<std::size_t>();
    rep.runs_with_precision_exempt += j["runs_with_precision_exempt_triangles"].get<std::size_t>();
    rep.nondeterministic_cases += j["nondeterministic_cases"].get<std::size_t>();
    rep.comparison_runs += j["comparison_runs"].get<std::size_t>();
    rep.comparison_cache_hits += j["comparison_cache_hits"].get<std::size_t>();
    rep.seconds += j["seconds"].get<double>();
    rep.engine_seconds += j["engine_seconds"].get<double>();
    rep.comparison_seconds += j["comparison_seconds"].get<double>();
    rep.shrink_seconds += j["shrink_seconds"].get<double>();
    for (int st = 0; st < 6; ++st) rep.status_counts[st] += j["run_status"][to_string(static_cast<RunStatus>(st))].get<std::size_t>();
    for (const nlohmann::json& r : j["rows"]) {
      const Row row = row_of(r["check"].get<std::string>());
      RowSummary& sum = rep[row];
      sum.run += r["runs"].get<std::size_t>();
      sum.held += r["held"].get<std::size_t>();
      sum.failed += r["failed"].get<std::size_t>();
      sum.findings += r["findings"].get<std::size_t>();
      sum.not_applicable += r["not_applicable"].get<std::size_t>();
      sum.not_checked += r["not_checked"].get<std::size_t>();
      sum.internal_errors += r["internal_errors"].get<std::size_t>();
      for (const auto& [name, runs] : r["deviations"].items()) sum.deviations[name] += runs.get<std::size_t>();
      for (const auto& [name, runs] : r["deviations_consistent"].items()) sum.deviation_consistent[name] += runs.get<std::size_t>();
      // Named copies: a range-for over items() of a temporary would read a destroyed object.
      const nlohmann::json inexact_runs = r.value("inexact_runs", nlohmann::json::object());
      const nlohmann::json inexact_steps = r.value("inexact_steps", nlohmann::json::object());
      for (const auto& [name, runs] : inexact_runs.items()) sum.inexact_runs[name] += runs.get<std::size_t>();
      for (const auto& [name, steps] : inexact_steps.items()) sum.inexact_steps[name] += steps.get<std::size_t>();
      // Each first is the one of the earliest run in the whole audit's order.
      const std::string f = r["first"].get<std::string>();
      const std::size_t at = d["first_run"][row_key(row)].get<std::size_t>();
      if (!f.empty() && (sum.first_detail.empty() || at < first_run[row_index(row)])) {
        sum.first_detail = f;
        first_run[row_index(row)] = at;
      }
    }
    for (const auto& [key, names] : d["deviation_first"].items())
      for (const auto& [name, first_at] : names.items()) {
        const std::size_t i = row_index(row_of(key)), at = first_at["run"].get<std::size_t>();
        auto it = deviation_run[i].find(name);
        if (it != deviation_run[i].end() && it->second < at) continue;
        deviation_run[i][name] = at;
        rep.rows[i].deviation_first[name] = first_at["text"].get<std::string>();
      }
    const auto nd = d["nondeterministic_cases"].get<std::vector<std::size_t>>();
    for (std::size_t i = 0; i < nd.size(); ++i) nondeterministic.push_back({nd[i], j["nondeterministic_first"][i].get<std::string>()});
    const auto ot = d["order_termination_cases"].get<std::vector<std::size_t>>();
    for (std::size_t i = 0; i < ot.size(); ++i) order_terminations.push_back({ot[i], order_termination_of(j["order_termination"][i])});
    for (const nlohmann::json& p : d["points"]) points.push_back({p["case"].get<std::size_t>(), p});
    // The shard's saved findings, found by their directory among its counterexamples.
    std::map<std::string, std::pair<Row, const nlohmann::json*>> by_dir;
    for (const nlohmann::json& r : j["rows"])
      for (const nlohmann::json& c : r["counterexamples"]) by_dir[c["dir"].get<std::string>()] = {row_of(r["check"].get<std::string>()), &c};
    for (const nlohmann::json& c : j["internal_errors"]) by_dir[c["dir"].get<std::string>()] = {row_of(c["check"].get<std::string>()), &c};
    const fs::path beside = fs::path(s.path).parent_path();
    for (const nlohmann::json& f : d["findings"]) {
      Candidate cand;
      cand.run = f["run"].get<std::size_t>();
      cand.internal = f["internal"].get<bool>();
      cand.row = row_of(f["check"].get<std::string>());
      cand.input = f["input"].get<std::string>();
      cand.shard_abs_dir = f["dir_absolute"].get<std::string>();
      const std::string dir = f["dir"].get<std::string>();
      auto it = by_dir.find(dir);
      if (it == by_dir.end()) throw UsageError(fmt::format("{}: finding {} is not among its counterexamples", s.path, dir));
      cand.cx = counterexample_of(*it->second.second, it->second.first);
      // Beside the JSON (a CI's downloaded artifacts), in the directory named like the shard's --out;
      // else where the shard wrote it (one machine).
      const fs::path rel = fs::path(dir).lexically_normal();
      std::error_code ec;
      for (const fs::path& p : {beside / rel.parent_path().filename() / rel.filename(), fs::path(cand.shard_abs_dir)})
        if (fs::is_directory(p, ec)) {
          cand.source = p;
          break;
        }
      candidates.push_back(std::move(cand));
    }
  }

  std::sort(nondeterministic.begin(), nondeterministic.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < nondeterministic.size() && i < 5; ++i) rep.nondeterministic_first.push_back(nondeterministic[i].second);
  std::stable_sort(order_terminations.begin(), order_terminations.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [c, t] : order_terminations) rep.order_terminations.push_back(std::move(t));
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t e = 0; e < compare.size(); ++e) {
    std::vector<std::pair<double, double>> ours_theirs;
    for (const auto& [c, p] : points)
      if (!p["theirs"][e].is_null()) ours_theirs.push_back({p["ours"].get<double>(), p["theirs"][e].get<double>()});
    rep.ratios.push_back(points_ratio(compare[e], ours_theirs));
  }

  // 3. The findings the whole audit saves: run_audit's choice (per row at most
  // max_findings, one per input, internal errors apart), in its order (run, then
  // an internal error before the rows, the rows in order). Each shard saved the
  // first of its own: the whole audit's are among them.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return std::make_tuple(a.run, !a.internal, row_index(a.row)) < std::make_tuple(b.run, !b.internal, row_index(b.row));
  });
  std::set<std::pair<int, std::string>> chosen;
  std::array<std::size_t, kRows> planned{};
  std::size_t internal_planned = 0, finding_number = 0, internal_number = 0;
  std::vector<std::pair<Candidate*, fs::path>> kept;
  for (Candidate& c : candidates) {
    std::size_t number;
    if (c.internal) {
      if (internal_planned >= max_findings || !chosen.insert({-1, c.input}).second) continue;
      ++internal_planned;
      number = ++internal_number;
    } else {
      if (planned[row_index(c.row)] >= max_findings || !chosen.insert({static_cast<int>(c.row), c.input}).second) continue;
      ++planned[row_index(c.row)];
      number = ++finding_number;
    }
    kept.push_back({&c, fs::path(out_dir) / fmt::format("{}-{}", c.internal ? "internal-error" : row_key(c.row), number)});
  }
  std::error_code ec;
  for (const auto& [c, to] : kept)
    if (!c->source.empty() && fs::exists(to, ec) && fs::equivalent(c->source, to, ec))
      throw UsageError(fmt::format("merge --out {}: that is where a shard's findings are ({}); give another directory", out_dir,
                                   c->source.string()));
  for (auto& [c, to] : kept) {
    Counterexample cx = c->cx;
    const fs::path abs_to = fs::absolute(to).lexically_normal();
    const std::string old_input = shell_quote((fs::path(c->shard_abs_dir) / "input.poly").string());
    const std::string new_input = shell_quote((abs_to / "input.poly").string());
    cx.dir = to.string();
    replace_all(cx.reproduce, old_input, new_input);
    if (!cx.original_input.empty()) cx.original_input = (to / "original.poly").string();
    if (!cx.stderr_file.empty()) cx.stderr_file = (to / "stderr.txt").string();
    if (c->source.empty()) {
      warnings.push_back(fmt::format("the files of {} (shard finding {}) were not found beside its report nor at {}: {} has none",
                                     c->cx.dir, c->input, c->shard_abs_dir, to.string()));
    } else {
      fs::remove_all(to, ec);
      fs::create_directories(to.parent_path(), ec);
      fs::copy(c->source, to, fs::copy_options::recursive, ec);
      if (ec) throw UsageError(fmt::format("cannot copy {} to {}: {}", c->source.string(), to.string(), ec.message()));
      // The reproduce line names the input by its absolute path: now the merged copy's.
      for (const char* name : {"reproduce.sh", "finding.md"}) {
        const fs::path f = to / name;
        if (!fs::exists(f, ec)) continue;
        std::string text = text_of(f);
        replace_all(text, old_input, new_input);
        std::ofstream(f) << text;
      }
    }
    (c->internal ? rep.internal_errors : rep[c->row].counterexamples).push_back(std::move(cx));
  }
  for (RowSummary& s : rep.rows)
    std::stable_sort(s.counterexamples.begin(), s.counterexamples.end(),
                     [](const Counterexample& a, const Counterexample& b) { return a.vertices < b.vertices; });
  const double overhead = rep.seconds - rep.engine_seconds - rep.comparison_seconds - rep.shrink_seconds;
  rep.overhead_per_case_ms = rep.cases ? 1000 * std::max(0.0, overhead) / static_cast<double>(rep.cases) : 0;
  return rep;
}

}  // namespace lepp::audit
