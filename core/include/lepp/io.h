// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle's file formats: .poly/.node in, PREFIX.node/.ele/.poly out.
// docs/FORMATS.md describes what is accepted and what is written.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp {

class NodeTextStream;

// Bad input: names the file and line and what is wrong. CLI exit status 2.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, const std::string& what);
  const std::string& file() const { return file_; }
  int line() const { return line_; }  // 0 when the problem has no single line
 private:
  std::string file_;
  int line_;
};

// Reads a .poly file (and the .node beside it when the .poly lists no vertices).
// Syntax only: geometry (duplicates, crossings, ...) is checked by validate().
Pslg read_poly(const std::string& path);
// Reads a .node file alone (a point set, no segments).
Pslg read_node(const std::string& path);

// Reads PREFIX.node, PREFIX.ele and, if present, PREFIX.poly (its segments are
// the constrained edges; the marker, if >= 1, is read as input segment id + 1).
Mesh read_mesh(const std::string& prefix);
// Writes PREFIX.node, PREFIX.ele, PREFIX.poly with 1-based numbering, as Triangle does.
// threads > 1: the .node (its coordinates cost the most to format) on a second
// thread beside the .ele and .poly; the same files. `node_text`: the .node's lines
// made beside the refinement (node_text_stream.h), used where they are whole and the
// mesh's; the same files with it or without.
void write_mesh(const std::string& prefix, const Mesh& mesh, int threads = 1, NodeTextStream* node_text = nullptr);
// Writes a .poly file of a PSLG (used by tests, fuzzers and generators).
void write_poly(const std::string& path, const Pslg& pslg);

// PREFIX.unimprovable: the triangles left bad by the small-input-angle rule.
void write_unimprovable(const std::string& prefix, const std::vector<UnimprovableTriangle>& list);
// Empty when the file does not exist.
std::vector<UnimprovableTriangle> read_unimprovable(const std::string& prefix);

}  // namespace lepp
