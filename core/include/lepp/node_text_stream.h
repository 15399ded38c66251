// SPDX-License-Identifier: GPL-3.0-or-later
// The .node's vertex lines made while the refinement runs (lepp refine with two
// threads; issue 40). The fast engine only appends vertices and never moves one, so
// vertex i's line is final once vertex i exists: a thread of its own formats the
// vertices the engine hands over (RefineOptions::on_vertices) into an unnamed
// temporary file in PREFIX's directory, never into PREFIX.node itself, which a run
// that fails must not have replaced. write_mesh then writes the .node's header (its
// count is known only at the end), copies these lines behind it, and formats the
// rest: the same bytes as a .node written whole.
#pragma once
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "lepp/pslg.h"

namespace lepp {

class NodeTextStream {
 public:
  // Starts the thread. The file is unnamed (O_TMPFILE; where the file system has none,
  // a file made and unlinked at once). nullptr when PREFIX's directory takes no file:
  // the .node is then written whole at the end, as without a stream.
  static std::unique_ptr<NodeTextStream> open(const std::string& prefix);
  ~NodeTextStream();  // stops the thread; the temporary file goes with it
  NodeTextStream(const NodeTextStream&) = delete;
  NodeTextStream& operator=(const NodeTextStream&) = delete;

  // Hands over vertices[k, size) for the k handed over before: copies them, since
  // the caller's array may move as it grows. `vertices` must begin with those handed
  // over before; the first `input_vertices` are the input's (marker 1), the same
  // number at every call.
  void add(const std::vector<Point>& vertices, std::size_t input_vertices);

  // Waits for the thread (once; later calls give the same answer). The lines of
  // vertices [0, lines) are then in fd() from offset 0, `bytes` of them. lines is 0
  // when anything went wrong (a failed write, input_vertices not the mesh's): the
  // .node is then formatted whole.
  struct Made {
    std::size_t lines = 0, bytes = 0;
  };
  Made finish(std::size_t input_vertices);
  int fd() const { return fd_; }

 private:
  explicit NodeTextStream(int fd);
  void run();  // the thread: formats each handed-over block into the file

  struct Block {
    std::size_t first = 0;  // the index of points[0]
    std::vector<Point> points;
  };
  int fd_ = -1;
  std::size_t handed_ = 0, input_vertices_ = 0;
  bool input_vertices_differ_ = false;  // add() saw two counts
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<Block> blocks_;   // under mutex_
  bool closing_ = false;       // under mutex_
  bool failed_ = false;        // the thread's alone until it is joined
  std::size_t written_ = 0;    // bytes; the thread's alone until it is joined
  bool finished_ = false;
  Made made_;
  std::thread thread_;
};

}  // namespace lepp
