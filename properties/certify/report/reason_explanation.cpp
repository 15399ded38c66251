// SPDX-License-Identifier: GPL-3.0-or-later
// The sentence under each kind of violation on a certificate's page: what its check tests.
#include "lepp/certify_html.h"

namespace lepp::certify {

const char* explanation(Reason reason) {
  switch (reason) {
    case Reason::BadTriangle: return "Every triangle names three distinct vertices that exist, with finite coordinates.";
    case Reason::NotCounterClockwise: return "Every triangle is counter-clockwise: its orientation is exactly positive.";
    case Reason::DuplicateMeshVertex: return "No two mesh vertices have identical coordinates.";
    case Reason::EdgeOverused: return "No edge belongs to more than two triangles (triangles do not overlap).";
    case Reason::EdgeSameDirection: return "Two triangles sharing an edge traverse it in opposite directions (no fold, no overlap).";
    case Reason::UnusedVertex: return "Every Steiner vertex, and every input vertex inside the domain, belongs to a triangle.";
    case Reason::BoundaryNotOnDomainBoundary: return "Every boundary edge of the mesh lies on the domain's boundary, facing the right way (no gap).";
    case Reason::MeshOutsideDomain: return "No triangle lies beyond a boundary segment of the domain (the exterior and the holes stay empty).";
    case Reason::DomainBoundaryUncovered: return "Every boundary segment of the domain has triangles along it.";
    case Reason::ChainEdgesMeet: return "The chains of mesh edges along the input segments cross nowhere, and no mesh vertex lies on one.";
    case Reason::EulerCharacteristic: return "V - E + F of the mesh equals the domain's Euler characteristic.";
    case Reason::InputVertexMissing: return "Every input vertex inside the domain is a mesh vertex.";
    case Reason::InputVertexMoved: return "Mesh vertex i equals input vertex i for the vertices the mesh says are the input's.";
    case Reason::SegmentMissing: return "Every input segment is a chain of mesh edges from one endpoint to the other.";
    case Reason::SteinerOffSegment: return "Every vertex of a segment's chain lies on the segment, within the rounding tolerance.";
    case Reason::ConstrainedEdgeNotOnSegment: return "Every edge the mesh lists as constrained lies on an input segment's chain.";
    case Reason::ConstrainedEdgeUnlisted: return "Every edge of a segment's chain is listed by the mesh as constrained.";
    case Reason::ConstrainedEdgeWrongSegment: return "A listed constrained edge is tagged with the segment whose chain it is on.";
    case Reason::NotLocallyDelaunay: return "No unconstrained edge has an opposite vertex strictly inside the other triangle's circumcircle (exact in-circle test).";
    case Reason::AngleBelowTheta: return "Every smallest angle is at least theta (sin^2 compared exactly against a bracket of sin^2 theta).";
    case Reason::AngleNotCertified: return "A smallest angle within one ulp of theta cannot be certified either way.";
    case Reason::UnimprovableNotInMesh: return "A triangle the mesher lists as unimprovable is a triangle of the mesh.";
    case Reason::UnimprovableRuleFails: return "A triangle listed as unimprovable satisfies the rule of ALGORITHM.md section 8.";
    case Reason::TerminalAngleOver120: return "Theorem 2: the triangles of every unconstrained terminal edge have no angle above 120 degrees.";
    case Reason::AreaAboveBound: return "Every triangle's area is at most the bound of its region and the global bound, exactly.";
  }
  return "";
}

}  // namespace lepp::certify
