// SPDX-License-Identifier: GPL-3.0-or-later
// Theorem 1: iterated longest-edge bisection. A triangle's shape is its triple
// of squared side lengths up to scale, so the whole iteration runs on exact
// rational triples: bisecting the side of squared length c by the median gives
// the sons (a, c/4, m2) and (b, c/4, m2) with m2 = (2a + 2b - c)/4. Mirror
// images share a triple, so classes are similarity classes up to reflection.
#include <CGAL/Gmpq.h>

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <sstream>

#include "lepp/theorems/checks.h"

namespace lepp::theorems {
namespace {

using Q = CGAL::Gmpq;
using Triple = std::array<Q, 3>;  // sorted ascending, largest scaled to 1

Triple normalize(Triple t) {
  std::sort(t.begin(), t.end());
  Q top = t[2];
  for (auto& v : t) v /= top;
  return t;
}

Triple sides_of(const GridTriangle& g) {
  auto d2 = [](const GridPoint& a, const GridPoint& b) {
    Q dx(static_cast<double>(a.x - b.x)), dy(static_cast<double>(a.y - b.y));
    return dx * dx + dy * dy;
  };
  return normalize({d2(g.p[1], g.p[2]), d2(g.p[0], g.p[2]), d2(g.p[0], g.p[1])});
}

// Sons of bisecting side i of t by its median.
std::array<Triple, 2> bisect(const Triple& t, int i) {
  const Q& c = t[i];
  const Q& a = t[(i + 1) % 3];
  const Q& b = t[(i + 2) % 3];
  Q m2 = (Q(2) * a + Q(2) * b - c) / Q(4);
  return {normalize({a, c / Q(4), m2}), normalize({b, c / Q(4), m2})};
}

// Every bisection the rule allows (all tied longest edges, or the shortest edge).
std::vector<Triple> sons(const Triple& t, Bisection rule) {
  std::vector<Triple> out;
  if (rule == Bisection::ShortestEdge) {
    auto s = bisect(t, 0);
    return {s[0], s[1]};
  }
  for (int i = 2; i >= 0 && t[i] == t[2]; --i) {
    auto s = bisect(t, i);
    out.push_back(s[0]);
    out.push_back(s[1]);
  }
  return out;
}

// alpha(t) > alpha(t0)/2, exactly: with alpha opposite the smallest side,
// cos 2alpha = (b + c - a)^2 / (2bc) - 1 must be below cos alpha0 = d0 / sqrt(n0).
bool min_angle_above_half(const Triple& t, const Triple& t0) {
  Q r = (t[1] + t[2] - t[0]) * (t[1] + t[2] - t[0]) / (Q(2) * t[1] * t[2]) - Q(1);
  Q d0 = (t0[1] + t0[2] - t0[0]) / Q(2);
  Q n0 = t0[1] * t0[2];
  if (r < Q(0)) return true;
  return r * r * n0 < d0 * d0;
}

std::string show_triple(const Triple& t) {
  std::ostringstream s;
  s << "[" << t[0].to_double() << ", " << t[1].to_double() << ", 1]";
  return s.str();
}

}  // namespace

BisectionClasses bisection_classes(const GridTriangle& g, Bisection rule, std::size_t max_classes, int levels) {
  BisectionClasses r;
  Triple t0 = sides_of(g);
  std::map<Triple, int> id;
  std::vector<Triple> cls;
  std::vector<std::vector<int>> kids;  // all sons over all allowed bisections
  std::vector<std::array<int, 2>> first_kids;  // the sons of the first allowed bisection
  auto intern = [&](const Triple& t) {
    auto [it, fresh] = id.emplace(t, static_cast<int>(cls.size()));
    if (fresh) cls.push_back(t);
    return it->second;
  };
  intern(t0);
  // Breadth-first over classes; a level is the set of classes at that depth.
  std::vector<int> level{0};
  r.cumulative.push_back(1);
  std::size_t expanded = 0;
  int depth = 0;
  while (expanded < cls.size() && cls.size() <= max_classes) {
    // expand every class found so far, in order of discovery
    std::size_t end = cls.size();
    for (; expanded < end && cls.size() <= max_classes; ++expanded) {
      auto s = sons(cls[expanded], rule);
      std::vector<int> k;
      for (auto& t : s) k.push_back(intern(t));
      kids.push_back(k);
      first_kids.push_back({k[0], k[1]});
    }
    ++depth;
    if (depth <= levels) r.cumulative.push_back(cls.size());
  }
  r.closed = expanded == cls.size() && cls.size() <= max_classes;
  while (static_cast<int>(r.cumulative.size()) <= levels) r.cumulative.push_back(cls.size());
  r.classes = cls.size();

  for (std::size_t i = 0; i < cls.size(); ++i) {
    if (!min_angle_above_half(cls[i], t0)) {
      if (r.min_angle_bound) r.detail += "son class " + show_triple(cls[i]) + " has smallest angle <= alpha0/2; ";
      r.min_angle_bound = false;
    }
  }
  if (!r.closed) {
    r.detail += "no closure within " + std::to_string(max_classes) + " classes; ";
    r.all_reach_quasi_equilateral = false;
    return r;
  }
  // Quasi-equilateral: a class whose own closure has at most 4 classes.
  std::vector<char> quasi(cls.size(), 0);
  for (std::size_t i = 0; i < cls.size(); ++i) {
    std::vector<int> seen{static_cast<int>(i)};
    for (std::size_t j = 0; j < seen.size() && seen.size() <= 4; ++j)
      for (int k : kids[seen[j]])
        if (std::find(seen.begin(), seen.end(), k) == seen.end()) seen.push_back(k);
    quasi[i] = seen.size() <= 4;
    r.quasi_equilateral_classes += quasi[i];
  }
  // Every class reaches a quasi-equilateral one through the first-choice sons
  // (then the non-quasi area halves at least every |classes| levels: share -> 1).
  std::vector<char> reach = quasi;
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t i = 0; i < cls.size(); ++i)
      if (!reach[i] && (reach[first_kids[i][0]] || reach[first_kids[i][1]])) reach[i] = grew = true;
  }
  for (std::size_t i = 0; i < cls.size(); ++i)
    if (!reach[i]) {
      if (r.all_reach_quasi_equilateral) r.detail += "class " + show_triple(cls[i]) + " never reaches a quasi-equilateral class; ";
      r.all_reach_quasi_equilateral = false;
    }
  // Area share of quasi-equilateral triangles level by level (first-choice sons).
  std::vector<double> w(cls.size(), 0.0);
  w[0] = 1;
  for (int k = 0; k <= levels; ++k) {
    double share = 0;
    for (std::size_t i = 0; i < cls.size(); ++i) share += quasi[i] ? w[i] : 0;
    r.quasi_share.push_back(share);
    std::vector<double> next(cls.size(), 0.0);
    for (std::size_t i = 0; i < cls.size(); ++i) {
      next[first_kids[i][0]] += w[i] / 2;
      next[first_kids[i][1]] += w[i] / 2;
    }
    w = next;
  }
  return r;
}

namespace {
constexpr std::size_t kMaxClasses = 4000;
constexpr int kLevels = 10;
std::string counts(const BisectionClasses& r) {
  std::string s = "classes by level:";
  for (auto c : r.cumulative) s += " " + std::to_string(c);
  return s + (r.closed ? " (closed at " + std::to_string(r.classes) + ")" : " (open)");
}
std::string bucket(std::size_t n) {
  return n <= 4 ? "<=4 classes" : n <= 16 ? "5-16 classes" : n <= 64 ? "17-64 classes" : n <= 256 ? "65-256 classes" : ">256 classes";
}

// Parts (i) and (ii): one conclusion read off the classes, labelled by their number.
Verdict classes_verdict(Bisection rule, const BisectionClasses& r, bool conclusion) {
  Verdict v;
  v.hypothesis = rule == Bisection::LongestEdge;
  v.conclusion = conclusion;
  v.label = bucket(r.classes);
  v.detail = counts(r) + "; " + r.detail;
  return v;
}
}  // namespace

Verdict check_theorem1_min_angle(const GridTriangle& t0, Bisection rule) {
  const BisectionClasses r = bisection_classes(t0, rule, kMaxClasses, kLevels);
  return classes_verdict(rule, r, r.min_angle_bound);
}

Verdict check_theorem1_finite_classes(const GridTriangle& t0, Bisection rule) {
  const BisectionClasses r = bisection_classes(t0, rule, kMaxClasses, kLevels);
  return classes_verdict(rule, r, r.closed);
}

Verdict check_theorem1_quasi_equilateral(const GridTriangle& t0, Bisection rule) {
  auto r = bisection_classes(t0, rule, kMaxClasses, kLevels);
  Verdict v;
  v.hypothesis = rule == Bisection::LongestEdge;
  bool monotone = true;
  for (std::size_t k = 1; k < r.quasi_share.size(); ++k)
    if (r.quasi_share[k] + 1e-12 < r.quasi_share[k - 1]) monotone = false;
  v.conclusion = r.closed && r.all_reach_quasi_equilateral && monotone;
  double last = r.quasi_share.empty() ? 0 : r.quasi_share.back();
  v.label = last >= 0.999 ? "share 1 at level 10" : last >= 0.5 ? "share >= 0.5 at level 10" : "share < 0.5 at level 10";
  v.detail = counts(r) + "; quasi-equilateral classes " + std::to_string(r.quasi_equilateral_classes) +
             "; share at level 10 " + std::to_string(last) + (monotone ? "" : "; share decreased") + "; " + r.detail;
  return v;
}

}  // namespace lepp::theorems
