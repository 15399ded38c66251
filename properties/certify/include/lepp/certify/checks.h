// SPDX-License-Identifier: GPL-3.0-or-later
// One group of checks alone (certify.h's Check): for a test or tool that asks one question
// of a mesh, e.g. "is it Delaunay?", without the rest of the certificate.
#pragma once
#include "lepp/certify.h"

namespace lepp::certify {

// Each builds the mesh index as certify() does (half-edges, input vertices, segment
// chains), then runs its group's checks with `options` as certify() reads them (e.g.
// check_theorem2 does nothing when options.theorem2 is false). The report lists and
// counts only that group's violations, in certify()'s order: violations the index finds
// on the way (a bad triangle, a missing segment) are kept when they belong to the group.
// Statistics and the exemption lists are filled only as far as the group fills them.
// pslg must be validated (lepp::validate), as for certify().
Report check_topology(const Pslg& pslg, const Mesh& mesh, const Options& options = {});
Report check_input_vertices(const Pslg& pslg, const Mesh& mesh, const Options& options = {});
Report check_constraints(const Pslg& pslg, const Mesh& mesh, const Options& options = {});
Report check_delaunay(const Pslg& pslg, const Mesh& mesh, const Options& options = {});
Report check_min_angle(const Pslg& pslg, const Mesh& mesh, const Options& options = {});
Report check_theorem2(const Pslg& pslg, const Mesh& mesh, const Options& options = {});
Report check_size_bound(const Pslg& pslg, const Mesh& mesh, const Options& options = {});

}  // namespace lepp::certify
