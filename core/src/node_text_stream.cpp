// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind node_text_stream.h: the .node's lines made beside the refinement.
#include "lepp/node_text_stream.h"

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

#include "node_line.h"

namespace lepp {
namespace {

// The directory a file PREFIX.node goes to: its temporary file must lie on the same
// file system, so that copying it into the .node stays in the kernel.
std::string directory_of(const std::string& prefix) {
  const std::filesystem::path parent = std::filesystem::path(prefix).parent_path();
  return parent.empty() ? "." : parent.string();
}

bool write_all(int fd, const char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    data += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

}  // namespace

std::unique_ptr<NodeTextStream> NodeTextStream::open(const std::string& prefix) {
  const std::string directory = directory_of(prefix);
  int fd = ::open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd < 0) {  // a file system without O_TMPFILE (an overlay, NFS): a named file, unlinked at once
    std::string name = directory + "/.lepp-node-XXXXXX";
    fd = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd >= 0) ::unlink(name.c_str());
  }
  if (fd < 0) return nullptr;
  return std::unique_ptr<NodeTextStream>(new NodeTextStream(fd));
}

NodeTextStream::NodeTextStream(int fd) : fd_(fd), thread_([this] { run(); }) {}

NodeTextStream::~NodeTextStream() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
    blocks_.clear();  // a run that ended early: its lines are not needed
  }
  ready_.notify_one();
  if (thread_.joinable()) thread_.join();
  ::close(fd_);
}

void NodeTextStream::add(const std::vector<Point>& vertices, std::size_t input_vertices) {
  if (handed_ == 0) input_vertices_ = input_vertices;
  input_vertices_differ_ = input_vertices_differ_ || input_vertices != input_vertices_;
  if (vertices.size() <= handed_ || finished_) return;
  Block block{handed_, std::vector<Point>(vertices.begin() + static_cast<std::ptrdiff_t>(handed_), vertices.end())};
  handed_ = vertices.size();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    blocks_.push_back(std::move(block));
  }
  ready_.notify_one();
}

void NodeTextStream::run() {
  // 1 MiB a write, as write_mesh's own files (block_file.h); room for one more line.
  constexpr std::size_t kBlock = std::size_t{1} << 20;
  std::vector<char> text(kBlock + detail::kNodeLine);
  std::size_t used = 0;
  auto flush = [&] {
    failed_ = failed_ || !write_all(fd_, text.data(), used);
    if (!failed_) written_ += used;
    used = 0;
  };
  for (;;) {
    Block block;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      ready_.wait(lock, [&] { return closing_ || !blocks_.empty(); });
      if (blocks_.empty()) break;  // closing, and every block formatted
      block = std::move(blocks_.front());
      blocks_.pop_front();
    }
    if (failed_) continue;
    for (std::size_t k = 0; k < block.points.size(); ++k) {
      const std::size_t i = block.first + k;
      used = static_cast<std::size_t>(
          detail::write_node_line(text.data() + used, i, block.points[k], i < input_vertices_) - text.data());
      if (used >= kBlock) flush();
    }
  }
  if (used > 0 && !failed_) flush();
}

NodeTextStream::Made NodeTextStream::finish(std::size_t input_vertices) {
  if (finished_) return made_;
  finished_ = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  ready_.notify_one();
  thread_.join();
  if (!failed_ && !input_vertices_differ_ && (handed_ == 0 || input_vertices == input_vertices_))
    made_ = {handed_, written_};
  return made_;
}

}  // namespace lepp
