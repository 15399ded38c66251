// SPDX-License-Identifier: GPL-3.0-or-later
// Writing time of each output format against Triangle's .node/.ele/.poly, on
// one mesh made by the fast engine (docs/BENCHMARKS.md, "Output formats").
// 10^6 triangles by default; LEPP_BENCH_HUGE=1 for 10^7. Files go to
// LEPP_BENCH_DIR (default: the system's temporary directory) and are removed.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include <benchmark/benchmark.h>

#include "bench_main.h"
#include "lepp/fast.h"
#include "lepp/mesh_formats.h"
#include "lepp/mesh_labels.h"
#include "problems.h"

namespace lepp::bench {
namespace {

struct Subject {
  Mesh mesh;
  MeshLabels labels;
  std::string prefix;
};

Subject& subject() {
  static Subject s = [] {
    const double triangles = std::getenv("LEPP_BENCH_HUGE") ? 1e7 : 1e6;
    Problem p = square_with_size_bound(triangles);
    Subject out;
    out.mesh = fast::refine(p.pslg, refine_options(p)).mesh;
    out.labels = mesh_labels(out.mesh, p.pslg);
    const char* dir = std::getenv("LEPP_BENCH_DIR");
    out.prefix = (std::filesystem::path(dir ? dir : std::filesystem::temp_directory_path().string()) /
                  ("lepp_write_bench_" + std::to_string(::getpid())))
                     .string();
    return out;
  }();
  return s;
}

double triangle_seconds = 0;  // the Triangle row's time per write, for the ratios

std::uintmax_t bytes_of(const std::string& prefix, MeshFormat f) {
  std::uintmax_t total = 0;
  const std::vector<std::string> exts =
      f == MeshFormat::Triangle ? std::vector<std::string>{".node", ".ele", ".poly"} : std::vector<std::string>{file_extension(f)};
  for (const std::string& e : exts) {
    total += std::filesystem::file_size(prefix + e);
    std::filesystem::remove(prefix + e);
  }
  return total;
}

void write(benchmark::State& state, MeshFormat format, bool binary) {
  Subject& s = subject();
  MeshWriteOptions options;
  options.binary = binary;
  double seconds = 0;
  std::uintmax_t bytes = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    write_mesh(s.prefix, s.mesh, format, s.labels, options);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.PauseTiming();
    bytes = bytes_of(s.prefix, format);
    state.ResumeTiming();
  }
  seconds /= static_cast<double>(state.iterations());
  if (format == MeshFormat::Triangle) triangle_seconds = seconds;
  state.counters["triangles"] = static_cast<double>(s.mesh.triangles.size());
  state.counters["MB"] = static_cast<double>(bytes) / 1e6;
  state.counters["MB_per_s"] = static_cast<double>(bytes) / 1e6 / seconds;
  if (triangle_seconds > 0) state.counters["vs_triangle"] = seconds / triangle_seconds;
}

void register_all() {
  struct Row {
    const char* name;
    MeshFormat format;
    bool binary;
  };
  // Triangle first: the other rows divide by its time.
  for (const Row& r : {Row{"triangle", MeshFormat::Triangle, false}, Row{"vtu", MeshFormat::Vtu, false},
                       Row{"msh2", MeshFormat::Msh2, false}, Row{"msh2_binary", MeshFormat::Msh2, true},
                       Row{"msh4", MeshFormat::Msh4, false}, Row{"msh4_binary", MeshFormat::Msh4, true}}) {
    benchmark::RegisterBenchmark((std::string("write/") + r.name).c_str(), write, r.format, r.binary)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
  }
}

}  // namespace
}  // namespace lepp::bench

int main(int argc, char** argv) {
  // The mesh is made before any clock starts.
  return lepp::bench::bench_main(argc, argv, lepp::bench::register_all, [] { lepp::bench::subject(); });
}
