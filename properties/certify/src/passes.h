// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's passes over one Certification, in the order certify() runs them (certify.cpp).
// Private to the certifier; lepp/certify/checks.h runs one group alone.
#pragma once
#include <future>
#include <optional>

#include "certification.h"
#include "lepp/stats.h"

namespace lepp::certify::pass {

// --- The mesh index (index/): each step builds a part and reports what it finds on the way.
void index_triangles(Certification& cert);           // tri_ok, ccw, longest, below_theta; bad and clockwise triangles (topology)
void index_half_edges(Certification& cert);          // twin, edges; overused and same-direction edges (topology)
void index_adjacency(Certification& cert);           // vertex adjacency, used, listed constrained edges (reports nothing)
void merge_duplicate_vertices(Certification& cert);  // merged; duplicate mesh vertices (topology)
void index_domain(Certification& cert);              // the expected domain and the input outside it
void index_input_vertices(Certification& cert);      // input <-> mesh vertex ids; moved and missing input vertices
void index_chains(Certification& cert);              // segment chains; missing segments, chain vertices off them
// Every index step above, in that order.
void build_index(Certification& cert);

// --- The checks (checks/), one file per group of Check; each group's steps in certify()'s order.
void check_unused_vertices(Certification& cert);
void check_coverage(Certification& cert);
void check_chains_cross_nowhere(Certification& cert);
void check_euler(Certification& cert);
void topology(Certification& cert);  // the four above

void check_outside_vertices_uncovered(Certification& cert);
void input_vertices(Certification& cert);  // the one above

void check_split_points(Certification& cert);
void check_listed_constrained_edges(Certification& cert);
void constraints(Certification& cert);  // the two above

void delaunay(Certification& cert);
void min_angle(Certification& cert);   // with the small-input-angle and precision-limit exemptions
void theorem2(Certification& cert);
void size_bound(Certification& cert);  // regions flooded, then areas against their bounds

// Not a check: the statistics the report shows; mesh_stats of the valid triangles
// (valid_triangle_stats, which needs only index_triangles) taken from `ahead` if given.
MeshStats valid_triangle_stats(const MeshIndex& ix);
void statistics(Certification& cert, std::future<MeshStats>* ahead = nullptr);

// One group alone on the full index: the report of lepp/certify/checks.h.
Report run_alone(Check group, void (*group_pass)(Certification&), const Pslg& pslg, const Mesh& mesh, const Options& options);

}  // namespace lepp::certify::pass
