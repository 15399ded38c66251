// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation catalogue's words: names, definitions, which are rule sets, and
// the line a match is reported with (lepp/audit/deviations.h).
#include "lepp/audit/deviations.h"

namespace lepp::audit {

const char* to_string(Deviation d) {
  switch (d) {
    case Deviation::AreaCentroid: return "area-centroid";
    case Deviation::VertexCentroid: return "vertex-centroid";
    case Deviation::TriangleCentroid: return "triangle-centroid";
    case Deviation::TerminalMidpoint: return "terminal-midpoint";
    case Deviation::CentroidNotMidpoint: return "centroid-not-midpoint";
    case Deviation::Remark10Ignored: return "remark10-ignored";
    case Deviation::Remark10Reversed: return "remark10-reversed";
    case Deviation::OtherSecondLongest: return "other-second-longest";
    case Deviation::Circumcenter: return "circumcenter";
    case Deviation::OffCenter: return "off-center";
    case Deviation::InexactThreshold: return "inexact-threshold";
    case Deviation::GoodTriangle: return "good-triangle";
    case Deviation::InexactLength: return "inexact-length";
    case Deviation::Precision: return "precision";
    case Deviation::Unknown: return "unknown";
  }
  return "unknown";
}

const char* definition(Deviation d) {
  switch (d) {
    case Deviation::AreaCentroid:
      return "the area centroid (centre of mass) of the terminal quad instead of the average of its four vertices (Lemma 11)";
    case Deviation::VertexCentroid:
      return "the average of the terminal quad's four vertices where the declared reading is the area centroid";
    case Deviation::TriangleCentroid: return "the centroid of one terminal triangle instead of the quad's";
    case Deviation::TerminalMidpoint: return "the terminal edge's midpoint where the paper chooses another point";
    case Deviation::CentroidNotMidpoint:
      return "the quad centroid where the paper asks for a midpoint (both second-longest edges constrained, or the midpoint method)";
    case Deviation::Remark10Ignored:
      return "no Remark 10: the quad centroid wherever exactly one second-longest edge is constrained, also where it is not "
             "inside the other triangle (the paper: the constrained edge's midpoint there)";
    case Deviation::Remark10Reversed:
      return "Remark 10 the wrong way round: the centroid where it is not inside the other triangle, or the constrained "
             "second-longest edge's midpoint where it is";
    case Deviation::OtherSecondLongest:
      return "the midpoint of another edge of a terminal triangle than the terminal edge and the paper's second-longest edge";
    case Deviation::Circumcenter: return "the circumcenter of a bad triangle (Ruppert, Chew)";
    case Deviation::OffCenter: return "the off-center of a bad triangle (Ungor)";
    case Deviation::InexactThreshold:
      return "the paper's choice for the Lepp of a triangle that is not bad, whose smallest angle is above theta by no more "
             "than a double computation of it may err (sin^2 within 16 DBL_EPSILON): the threshold compared in double";
    case Deviation::GoodTriangle: return "the paper's choice for the Lepp of a triangle that is not bad: a wrong threshold";
    case Deviation::InexactLength:
      return "the paper's choice for a Lepp reached by taking a length comparison the other way where the exact squared "
             "lengths differ by no more than a double computation of them may err (8 DBL_EPSILON relative)";
    case Deviation::Precision: return "within 1000 times the point tolerance of a paper choice: rounding beyond the tolerance";
    case Deviation::Unknown: return "no rule of the catalogue";
  }
  return "";
}

bool has_variant(Deviation d) {
  switch (d) {
    case Deviation::AreaCentroid: case Deviation::VertexCentroid: case Deviation::TriangleCentroid:
    case Deviation::TerminalMidpoint: case Deviation::CentroidNotMidpoint: case Deviation::Remark10Ignored:
    case Deviation::Remark10Reversed:
    case Deviation::OtherSecondLongest: case Deviation::InexactLength: case Deviation::InexactThreshold: return true;
    default: return false;
  }
}

namespace {

std::string tri_text(const Tri& t) { return "(" + std::to_string(t[0]) + "," + std::to_string(t[1]) + "," + std::to_string(t[2]) + ")"; }

}  // namespace

std::string match_text(Deviation deviation, const std::array<int, 2>& terminal_edge, const Tri& lepp_start) {
  const std::string edge = "(" + std::to_string(terminal_edge[0]) + "," + std::to_string(terminal_edge[1]) + ")";
  const bool good = deviation == Deviation::GoodTriangle || deviation == Deviation::InexactThreshold;
  const std::string lepp = "the Lepp of " + std::string(good ? "good" : "bad") + " triangle " + tri_text(lepp_start);
  switch (deviation) {
    case Deviation::AreaCentroid: return "the area centroid of the terminal quad of edge " + edge + " (" + lepp + ")";
    case Deviation::VertexCentroid: return "the vertex average of the terminal quad of edge " + edge + " (" + lepp + ")";
    case Deviation::TriangleCentroid: return "the centroid of one terminal triangle of edge " + edge + " (" + lepp + ")";
    case Deviation::TerminalMidpoint: return "the midpoint of terminal edge " + edge + " (" + lepp + ")";
    case Deviation::CentroidNotMidpoint: return "the quad centroid at terminal edge " + edge + ", where the paper asks for a midpoint (" + lepp + ")";
    case Deviation::Remark10Ignored:
      return "the quad centroid at terminal edge " + edge + ", outside the triangle across from the constrained second-longest "
             "edge, where Remark 10 asks for that edge's midpoint (" + lepp + ")";
    case Deviation::Remark10Reversed: return "Remark 10 the wrong way round at terminal edge " + edge + " (" + lepp + ")";
    case Deviation::OtherSecondLongest:
      return "the midpoint of another edge of a terminal triangle of edge " + edge +
             " than the terminal edge and the paper's second-longest edge (" + lepp + ")";
    case Deviation::Circumcenter: return "the circumcenter of bad triangle " + tri_text(lepp_start);
    case Deviation::OffCenter: return "the off-center of bad triangle " + tri_text(lepp_start);
    case Deviation::InexactThreshold:
      return "the paper's choice at terminal edge " + edge + " for " + lepp +
             ", whose smallest angle is above theta by no more than double rounding";
    case Deviation::GoodTriangle: return "the paper's choice at terminal edge " + edge + " for " + lepp;
    case Deviation::InexactLength:
      return "the paper's choice at terminal edge " + edge + " for " + lepp +
             ", reached by taking a comparison of two edge lengths within double rounding of each other the other way";
    case Deviation::Precision: return "near the paper's choice at terminal edge " + edge + " (" + lepp + "), beyond the tolerance";
    case Deviation::Unknown: break;
  }
  return "no rule of the catalogue";
}

}  // namespace lepp::audit
