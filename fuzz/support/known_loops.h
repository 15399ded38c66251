// SPDX-License-Identifier: GPL-3.0-or-later
// Loops the paper does not claim away, so a long fuzzing run records them and
// goes on instead of stopping: the midpoint method above alpha_limit (Section 3's
// special loop, Theorem 9 needs theta <= alpha_limit), the centroid method above
// 30 degrees (the paper's termination results are stated up to 30; above, only
// experiments), and the cascade at a small input angle (below 60 degrees; no
// termination claim for such inputs). A loop outside these (a centroid loop at
// theta <= 30, a midpoint loop at theta <= alpha_limit, with every input angle
// at the loop >= 60) contradicts the paper and still stops the run.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "lepp/refine.h"

namespace lepp::fuzz {

// Why a loop of class `loop_class` (classify_loop's names, without "loop-")
// with this method and theta is outside every termination claim of the paper,
// as one word: small-input-angle, midpoint-above-alpha-limit, centroid-above-30;
// "" when it is inside a proven band (a real finding).
std::string unclaimed_loop_reason(Method method, double theta_deg, const std::string& loop_class);

// An input whose smallest feature (two vertices, or a vertex and a segment it does
// not end) is below 2^-40 of its largest coordinate magnitude, or underflows: doubles
// do not resolve it at its place, and refinement there can cascade without end
// (docs/THEOREMS.md, "Termination in doubles"). "feature-below-resolution" for such
// an input, else "". Loops on such inputs are kept and gone past; every other
// finding on them (a crash, a mismatch, a certificate) still stops the run.
std::string below_resolution_reason(const Pslg& pslg);

// The theta band as it appears in file names: "10-20.7", "20.8-22.2",
// "22.3-30", "30.1-36" (the bands of theta_band()).
std::string band_label(double theta_deg);

// The key of a known finding: one example is kept per key.
// e.g. "fuzz_refine-loop-other-centroid-theta30.1-36".
std::string known_finding_key(const std::string& target, const std::string& finding_class, Method method,
                              double theta_deg);

// The directory known findings are kept in: $LEPP_FUZZ_KNOWN_DIR, else
// "known-findings" in the working directory (fuzz/run.sh sets
// WORK/TARGET/findings/known).
std::string known_findings_dir();

// Keeps `data` as DIR/KEY.bin and `message` as DIR/KEY.txt unless DIR/KEY.bin
// exists already (atomically: concurrent -fork jobs keep exactly one). Returns
// the path of the file kept, or "" when one was there already or the write
// failed.
std::string keep_known_example(const std::string& dir, const std::string& key, const std::uint8_t* data,
                               std::size_t size, const std::string& message);

// A finding of a known class outside the paper's claims: prints
// "LEPP-FINDING target=... class=... known=REASON kept=PATH : MESSAGE" (kept=
// only the first time per key), keeps the input once per key in
// known_findings_dir(), and returns, so libFuzzer goes on. In the replay
// driver's --expect-finding mode it throws FindingReported like report_finding,
// so known loops in corpus/regressions/*/open/ still count as reported.
void report_known_finding(const char* target, const std::string& finding_class, const std::string& reason,
                          const std::string& key, const std::string& message, const std::uint8_t* data,
                          std::size_t size);

}  // namespace lepp::fuzz
