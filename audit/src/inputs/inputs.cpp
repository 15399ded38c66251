// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's inputs: RapidCheck's generated PSLGs, the corpus, the user's .poly files.
#include "lepp/audit/inputs/inputs.h"

#include <algorithm>
#include <filesystem>
#include <tuple>

#include <fmt/format.h>

#include "lepp/audit/engine.h"
#include "lepp/gen.h"
#include "lepp/io.h"
#include "lepp/validate.h"
#include "inputs/shrink_tree.h"

namespace fs = std::filesystem;

namespace lepp::audit {
namespace {

std::vector<std::string> poly_files(const fs::path& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return files;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ".poly") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::optional<Pslg> read_validated(const std::string& path, std::string& why) {
  try {
    std::vector<std::string> warnings;
    return validate(read_poly(path), warnings);
  } catch (const std::exception& e) {
    why = e.what();
    return std::nullopt;
  }
}

std::optional<AuditInput> generated_input(std::uint64_t seed, std::size_t index, int size) {
  // One random stream per (seed, index): inputs do not depend on how many came before.
  rc::Random random(seed * 0x9E3779B97F4A7C15ull + index);
  rc::Gen<Pslg> gen = index % 2 == 0 ? gen::anyPslg() : gen::wellShapedPslg();
  try {
    rc::Shrinkable<Pslg> s = gen(random, size);
    std::vector<std::string> warnings;
    AuditInput in;
    Pslg raw = s.value();
    in.pslg = validate(raw, warnings);
    in.name = fmt::format("{} (seed {}, input {}, size {})", raw.source, seed, index, size);
    in.shrink_tree = std::make_shared<const ShrinkTree>(ShrinkTree{std::move(s)});
    return in;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::vector<AuditInput> collect_inputs(const InputSources& src, std::vector<std::string>& skipped) {
  std::vector<std::string> files;
  if (!src.dirs.empty()) {
    for (const std::string& d : src.dirs) {
      std::error_code ec;
      if (fs::is_regular_file(d, ec)) {
        files.push_back(d);
        continue;
      }
      if (!fs::is_directory(d, ec)) throw UsageError(fmt::format("--inputs: no such directory: {}", d));
      auto f = poly_files(d);
      files.insert(files.end(), f.begin(), f.end());
    }
  } else {
    // A built-in source asked for and not there is bad usage, never a silent skip: an
    // audit that quietly lost the paper's problems would report on what is left.
    for (auto [wanted, dir, name] : {std::tuple{src.paper, "paper", "paper"}, std::tuple{src.corpus, "hostile", "corpus"}}) {
      if (!wanted) continue;
      const fs::path d = fs::path(src.source_root) / "corpus" / dir;
      auto f = poly_files(d);
      if (f.empty()) {
        std::string others = name == std::string("paper") ? "gen,corpus" : "gen,paper";
        throw UsageError(fmt::format(
            "the built-in source {} (corpus/{}/*.poly) is not under {}: give the directory that holds corpus/ with --root, "
            "or leave it out with --sources {}",
            name, dir, fs::absolute(src.source_root).lexically_normal().string(), others));
      }
      files.insert(files.end(), f.begin(), f.end());
    }
  }
  std::vector<AuditInput> inputs;
  for (const std::string& f : files) {
    if (inputs.size() >= src.count) break;
    std::string why;
    auto p = read_validated(f, why);
    if (!p) {
      skipped.push_back(fmt::format("{}: {}", f, why));
      continue;
    }
    AuditInput in;
    in.name = f;
    in.path = f;
    in.pslg = std::move(*p);
    inputs.push_back(std::move(in));
  }
  if (src.dirs.empty() && src.generated) {
    const std::size_t want = src.count > inputs.size() ? src.count - inputs.size() : 0;
    for (std::size_t i = 0, made = 0; made < want && i < want * 4 + 16; ++i) {
      int size = want > 1 ? static_cast<int>(static_cast<double>(made) * src.max_size / static_cast<double>(want - 1)) : src.max_size / 2;
      auto in = generated_input(src.seed, i, size);
      if (!in) {
        skipped.push_back(fmt::format("generated input {} (seed {}) does not validate", i, src.seed));
        continue;
      }
      inputs.push_back(std::move(*in));
      ++made;
    }
  }
  return inputs;
}

}  // namespace lepp::audit
