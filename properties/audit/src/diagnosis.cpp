// SPDX-License-Identifier: GPL-3.0-or-later
// The diagnosis of a step finding: words and a picture of the step.
#include "lepp/audit/diagnosis.h"

#include <algorithm>
#include <map>
#include <stdexcept>

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

StepDiagnosis conformance_diagnosis(const ConformanceReport& r, double theta, bool final_not_delaunay) {
  StepDiagnosis d;
  if (!r.failure) throw std::invalid_argument("conformance_diagnosis: the report has no failure");
  const ConformanceFailure& f = *r.failure;
  d.step = f.step + 1;
  d.steps = r.steps;
  d.point = f.point;
  d.mesh = f.mesh;
  d.theta = theta;
  d.area_centroid = r.area_centroid;
  d.reason = f.reason;
  d.candidates = f.candidates;
  d.candidates_total = f.candidates_total;
  d.deviation = f.deviation;
  d.deviation_what = f.deviation_what;
  d.deviation_definition = f.deviation_definition;
  d.deviation_at = f.deviation_at;
  d.deviation_paper = f.deviation_paper;
  d.consistent_variant = f.consistent_variant;
  d.variant_steps = f.variant_steps;
  d.final_not_delaunay = final_not_delaunay;
  return d;
}

StepDiagnosis theorem2_diagnosis(const ConformanceReport& r, double theta) {
  StepDiagnosis d;
  if (!r.theorem2_failure) throw std::invalid_argument("theorem2_diagnosis: the report has no Theorem 2 failure");
  const Theorem2StepFailure& f = *r.theorem2_failure;
  d.theorem2 = true;
  d.step = f.step + 1;
  d.steps = r.steps;
  d.point = f.point;
  d.mesh = f.mesh;
  d.theta = theta;
  d.area_centroid = r.area_centroid;
  d.terminal_edge = f.terminal_edge;
  d.t1 = f.t1;
  d.t2 = f.t2;
  d.apex = f.apex;
  d.angle_deg = f.angle_deg;
  return d;
}

std::string diagnosis_markdown(const StepDiagnosis& d) {
  std::string md = fmt::format("\n## The step (step.svg)\n\nStep {} of {}: the program inserted {}.\n", d.step, d.steps, pt(d.point));
  if (d.area_centroid) md += "The declared reading (`--centroid area`): the quad centroid is its area centroid.\n";
  if (d.theorem2) {
    md += fmt::format(
        "\nTheorem 2 fails on the terminal pair of this step, in the replay's mesh just before it: terminal edge ({},{}), "
        "triangles {} and {}; the angle at vertex {} is over 120 degrees (about {:.6g}; decided exactly: cos < -1/2).\n",
        d.terminal_edge[0], d.terminal_edge[1], tri(d.t1), tri(d.t2), d.apex, d.angle_deg);
    return md;
  }
  md += fmt::format("\n{}\n\n**Deviation: `{}`**: {}.\n", d.reason, d.deviation, d.deviation_definition);
  if (d.deviation_at) {
    md += fmt::format("The program's point is {}: {} is {:.3g} away (tolerance {:.3g}).\n", d.deviation_what, pt(d.deviation_at->point),
                      d.deviation_at->euclidean, d.deviation_at->tolerance);
    for (const ConformanceCandidate& c : d.deviation_paper)
      md += fmt::format("- the paper's choice there: {} ({}), {:.3g} from the program's point\n", pt(c.point), to_string(c.rule), c.euclidean);
  }
  if (d.consistent_variant)
    md += fmt::format(
        "\nEvery one of the {} traced steps is the paper's choice or `{}`'s ({} of them `{}`'s): the program follows one "
        "consistent variant.\n",
        d.steps, d.deviation, d.variant_steps, d.deviation);
  if (d.final_not_delaunay)
    md += "\nThe final mesh is not constrained Delaunay (certificate row): the program's intermediate meshes probably "
          "differ from the replay's, and missing Delaunay flips after an insertion are the likely cause; the steps after "
          "the first such flip are judged on a mesh the program did not have.\n";
  if (!d.candidates.empty()) {
    md += fmt::format("\nThe nearest of the paper's {} choices at this step (Euclidean distances):\n\n", d.candidates_total);
    md += "| choice | rule | distance | bad triangle | Lepp | terminal edge |\n|---|---|---:|---|---|---|\n";
    for (std::size_t i = 0; i < d.candidates.size() && i < 8; ++i) {
      const ConformanceCandidate& c = d.candidates[i];
      std::string lepp;
      for (const Tri& t : c.lepp) lepp += (lepp.empty() ? "" : " ") + tri(t);
      md += fmt::format("| {} | {} | {:.3g} | {} | {} | ({},{}) |\n", pt(c.point), to_string(c.rule), c.euclidean, tri(c.bad), lepp,
                        c.terminal_edge[0], c.terminal_edge[1]);
    }
  }
  return md;
}

std::string diagnosis_svg(const StepDiagnosis& d, const std::string& title) {
  const Mesh& mesh = d.mesh;
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
  std::vector<Point> focus_points{d.point};
  if (d.theorem2) {
    render::Highlight pair{ids({d.t1, d.t2}), {d.terminal_edge}, {}, "#ff7f0e",
                           fmt::format("terminal pair of step {}, terminal edge ({},{}); angle at {} about {:.4g} degrees", d.step,
                                       d.terminal_edge[0], d.terminal_edge[1], d.apex, d.angle_deg)};
    focus = pair.triangles;
    ro.highlights.push_back(pair);
  } else {
    // The nearest choice's Lepp, then its terminal pair and edge.
    const ConformanceCandidate* near = d.candidates.empty() ? nullptr : &d.candidates.front();
    if (d.deviation_at && d.deviation_at->bad[0] >= 0) near = &*d.deviation_at;
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
    for (const ConformanceCandidate& c : d.candidates) {
      render::Highlight& h = by_rule[c.rule];
      h.colour = rule_colour(c.rule);
      h.label = fmt::format("the paper's choices: {}", to_string(c.rule));
      h.points.push_back(c.point);
    }
    for (const ConformanceCandidate& c : d.deviation_paper) {
      render::Highlight& h = by_rule[c.rule];
      h.colour = rule_colour(c.rule);
      h.label = fmt::format("the paper's choices: {}", to_string(c.rule));
      h.points.push_back(c.point);
    }
    for (auto& [rule, h] : by_rule) ro.highlights.push_back(h);
    if (d.deviation_at)
      ro.highlights.push_back({{}, {}, {d.deviation_at->point}, "#e377c2", fmt::format("{}: {}", d.deviation, d.deviation_what)});
  }
  ro.highlights.push_back({{}, {}, {d.point}, "red", fmt::format("the program's point, step {}", d.step)});
  ro.window = render::window_around(mesh, focus, focus_points, 0.5);
  return render::render_svg(mesh, ro);
}

}  // namespace lepp::audit
