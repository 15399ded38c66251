// SPDX-License-Identifier: GPL-3.0-or-later
// The diagnosis of a step finding: words and a picture of the step.
#include "lepp/audit/judge/diagnosis.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "lepp/render.h"

namespace lepp::audit {
namespace {

std::string tri(const Tri& t) { return fmt::format("({},{},{})", t[0], t[1], t[2]); }
std::string pt(const Point& p) { return fmt::format("({:.17g}, {:.17g})", p.x, p.y); }

std::array<int, 3> sorted(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
}

// Triangles of the mesh by their vertex ids (any order).
std::map<std::array<int, 3>, int> index_of(const Mesh& mesh) {
  std::map<std::array<int, 3>, int> out;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) out[sorted(mesh.triangles[i])] = static_cast<int>(i);
  return out;
}

// One colour per rule of the paper, for the candidates' rings.
const char* rule_colour(Rule r) {
  switch (r) {
    case Rule::TerminalConstrainedMidpoint: return "#1f77b4";
    case Rule::TerminalMidpoint: return "#17becf";
    case Rule::SecondLongestMidpoint: return "#2ca02c";
    case Rule::QuadCentroid: return "#0b3d91";
    case Rule::CentroidInOther: return "#9467bd";
    case Rule::BothSecondLongestMidpoint: return "#8c564b";
  }
  return "blue";
}

}  // namespace

std::size_t StepDiagnosis::step() const {
  return std::visit([](const auto& f) { return f.step + 1; }, failure);
}

const Point& StepDiagnosis::point() const {
  return std::visit([](const auto& f) -> const Point& { return f.point; }, failure);
}

const Mesh& StepDiagnosis::mesh() const {
  return std::visit([](const auto& f) -> const Mesh& { return f.mesh; }, failure);
}

StepDiagnosis conformance_diagnosis(const ConformanceReport& r, double theta, bool final_not_delaunay) {
  if (!r.failure) throw std::invalid_argument("conformance_diagnosis: the report has no failure");
  return {*r.failure, r.steps, theta, r.area_centroid, final_not_delaunay};
}

StepDiagnosis theorem2_diagnosis(const ConformanceReport& r, double theta) {
  if (!r.theorem2_failure) throw std::invalid_argument("theorem2_diagnosis: the report has no Theorem 2 failure");
  return {*r.theorem2_failure, r.steps, theta, r.area_centroid, false};
}

std::string diagnosis_markdown(const StepDiagnosis& d) {
  std::string md = fmt::format("\n## The step (step.svg)\n\nStep {} of {}: the program inserted {}.\n", d.step(), d.steps, pt(d.point()));
  if (d.area_centroid) md += "The declared reading (`--centroid area`): the quad centroid is its area centroid.\n";
  if (const auto* t = std::get_if<Theorem2StepFailure>(&d.failure)) {
    md += fmt::format(
        "\nTheorem 2 fails on the terminal pair of this step, in the replay's mesh just before it: terminal edge ({},{}), "
        "triangles {} and {}; the angle at vertex {} is over 120 degrees (about {:.6g}; decided exactly: cos < -1/2).\n",
        t->terminal_edge[0], t->terminal_edge[1], tri(t->t1), tri(t->t2), t->apex, t->angle_deg);
    return md;
  }
  const ConformanceFailure& f = std::get<ConformanceFailure>(d.failure);
  md += fmt::format("\n{}\n\n**Deviation: `{}`**: {}.\n", f.reason, f.deviation, f.deviation_definition);
  if (f.deviation_at) {
    md += fmt::format("The program's point is {}: {} is {:.3g} away (tolerance {:.3g}).\n", f.deviation_what, pt(f.deviation_at->point),
                      f.deviation_at->euclidean, f.deviation_at->tolerance);
    for (const ConformanceCandidate& c : f.deviation_paper)
      md += fmt::format("- the paper's choice there: {} ({}), {:.3g} from the program's point\n", pt(c.point), to_string(c.rule), c.euclidean);
  } else if (f.deviation == "unknown") {
    md += fmt::format("The program's point is {}.\n", f.deviation_what);  // with the rules that came nearest
  } else if (!f.deviation_what.empty()) {
    md += fmt::format("What the program's output shows: {}.\n", f.deviation_what);  // its arithmetic (arithmetic.h)
  }
  if (f.consistent_variant)
    md += fmt::format(
        "\nEvery one of the {} traced steps is the paper's choice or `{}`'s ({} of them `{}`'s): the program follows one "
        "consistent variant.\n",
        d.steps, f.deviation, f.variant_steps, f.deviation);
  if (f.chain.size() > 1 || !f.chain_end.empty()) {
    md += "\n**Every deviation of the trace**, in the order it shows them (after each, the replay went on with that rule "
          "allowed):";
    for (std::size_t i = 0; i < f.chain.size(); ++i)
      md += fmt::format("{} `{}` from step {}{}", i ? "; then" : "", f.chain[i].deviation, f.chain[i].first_step,
                        f.chain[i].steps ? fmt::format(" ({} steps)", f.chain[i].steps) : "");
    md += f.chain_complete ? ", to the trace's end.\n" : fmt::format(". The replay stopped: {}.\n", f.chain_end);
  }
  // Which mesh the chain was judged on, even for a chain of one name.
  if (!f.mesh_reading.empty() && !f.mesh_reading_fallback)
    md += fmt::format("\nThe replay followed the program's mesh as it rebuilds it (`{}`, from the name `{}` of the final "
                      "mesh), not the exact one.\n",
                      f.mesh_reading, f.deviation);
  else if (!f.mesh_reading.empty())
    md += fmt::format("\nThe replay followed the program's mesh as it rebuilds it (`{}`), not the exact one: on the exact "
                      "mesh the chain lost a step no rule fits, and of the meshes a program whose final mesh is Delaunay "
                      "may have had, this one follows the trace farthest.\n",
                      f.mesh_reading);
  if (const std::string note = remark10_ignored_note(f); !note.empty()) md += "\n" + note + ".\n";
  if (d.final_not_delaunay)
    md += "\nThe final mesh is not constrained Delaunay (certificate row): the program's intermediate meshes probably "
          "differ from the replay's, and missing Delaunay flips after an insertion are the likely cause; the steps after "
          "the first such flip are judged on a mesh the program did not have.\n";
  if (!f.candidates.empty()) {
    // Which mesh the choices are of, where the chain was followed on another one.
    const std::string on = !f.step_mesh_reading.empty()
                               ? fmt::format(" on the program's mesh as the replay rebuilds it (`{}`)", f.step_mesh_reading)
                           : !f.mesh_reading.empty() ? std::string(" on the exact mesh") : std::string();
    md += fmt::format("\nThe nearest of the paper's {} choices at this step{} (Euclidean distances):\n\n", f.candidates_total, on);
    md += "| choice | rule | distance | bad triangle | Lepp | terminal edge |\n|---|---|---:|---|---|---|\n";
    for (std::size_t i = 0; i < f.candidates.size() && i < 8; ++i) {
      const ConformanceCandidate& c = f.candidates[i];
      std::string lepp;
      for (const Tri& t : c.lepp) lepp += (lepp.empty() ? "" : " ") + tri(t);
      md += fmt::format("| {} | {} | {:.3g} | {} | {} | ({},{}) |\n", pt(c.point), to_string(c.rule), c.euclidean, tri(c.bad), lepp,
                        c.terminal_edge[0], c.terminal_edge[1]);
    }
  }
  return md;
}

std::string diagnosis_svg(const StepDiagnosis& d, const std::string& title) {
  const Mesh& mesh = d.mesh();
  if (mesh.triangles.empty()) throw std::invalid_argument("diagnosis_svg: no mesh");
  const auto index = index_of(mesh);
  auto ids = [&](const std::vector<Tri>& tris) {
    std::vector<int> out;
    for (const Tri& t : tris) {
      auto it = index.find(sorted(t));
      if (it != index.end()) out.push_back(it->second);
    }
    return out;
  };
  render::RenderOptions ro;
  ro.color = render::ColorBy::Angle;
  ro.highlight_bad = true;  // the bad triangles near the point, outlined in red
  ro.min_angle_deg = d.theta;
  ro.title = title;
  std::vector<int> focus;
  std::vector<Point> focus_points{d.point()};
  if (const auto* t = std::get_if<Theorem2StepFailure>(&d.failure)) {
    render::Highlight pair{ids({t->t1, t->t2}), {t->terminal_edge}, {}, "#ff7f0e",
                           fmt::format("terminal pair of step {}, terminal edge ({},{}); angle at {} about {:.4g} degrees", d.step(),
                                       t->terminal_edge[0], t->terminal_edge[1], t->apex, t->angle_deg)};
    focus = pair.triangles;
    ro.highlights.push_back(pair);
  } else {
    const ConformanceFailure& f = std::get<ConformanceFailure>(d.failure);
    // The nearest choice's Lepp, then its terminal pair and edge.
    const ConformanceCandidate* near = f.candidates.empty() ? nullptr : &f.candidates.front();
    if (f.deviation_at && f.deviation_at->bad[0] >= 0) near = &*f.deviation_at;
    if (near) {
      std::vector<Tri> lepp = near->lepp;
      std::vector<Tri> pair;
      for (const Tri& t : {near->t1, near->t2})
        if (t[0] >= 0) pair.push_back(t);
      render::Highlight path{ids(lepp), {}, {}, "#ffbf00", fmt::format("Lepp of bad triangle {}", tri(near->bad))};
      render::Highlight term{ids(pair), {}, {}, "#ff7f0e", fmt::format("terminal pair, terminal edge ({},{})", near->terminal_edge[0], near->terminal_edge[1])};
      if (near->terminal_edge[0] >= 0) term.edges.push_back(near->terminal_edge);
      focus = path.triangles;
      focus.insert(focus.end(), term.triangles.begin(), term.triangles.end());
      focus_points.push_back(near->point);
      ro.highlights.push_back(path);
      ro.highlights.push_back(term);
    }
    // Every choice, one ring colour per rule.
    std::map<Rule, render::Highlight> by_rule;
    for (const std::vector<ConformanceCandidate>* choices : {&f.candidates, &f.deviation_paper})
      for (const ConformanceCandidate& c : *choices) {
        render::Highlight& h = by_rule[c.rule];
        h.colour = rule_colour(c.rule);
        h.label = fmt::format("the paper's choices: {}", to_string(c.rule));
        h.points.push_back(c.point);
      }
    for (auto& [rule, h] : by_rule) ro.highlights.push_back(h);
    if (f.deviation_at)
      ro.highlights.push_back({{}, {}, {f.deviation_at->point}, "#e377c2", fmt::format("{}: {}", f.deviation, f.deviation_what)});
  }
  ro.highlights.push_back({{}, {}, {d.point()}, "red", fmt::format("the program's point, step {}", d.step())});
  ro.window = render::window_around(mesh, focus, focus_points, 0.5);
  return render::render_svg(mesh, ro);
}

}  // namespace lepp::audit
