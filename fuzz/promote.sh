#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Turns a fuzz finding into a ctest regression in one command.
#   fuzz/promote.sh [--target T] [--open | --fixed] [--note WORDS] FILE
# Replays FILE once with the replay driver of the default build
# (${LEPP_BUILD:-build}/fuzz/<target>_replay, built if missing) and copies it to
#   corpus/regressions/<target>/open/<class>-<what>-<sha>.<ext>  when it still reports a finding
#   corpus/regressions/<target>/<class>-<what>-<sha>.<ext>       when it runs clean (fixed) or crashes
# (an input already there, byte for byte, is not copied again)
# where <class> is the LEPP-FINDING class (or crash / clean), <what> the method
# and theta for the structured targets. The fuzz-replay ctest tests replay both
# directories (fuzz/CMakeLists.txt), so nothing else needs registering; a new
# directory makes the next build re-run cmake. --open / --fixed force the place;
# --note adds words to the name. The target comes from --target, else from a
# path component or file-name prefix naming one (out/fuzz/fuzz_refine/...,
# fuzz_refine-loop-...bin). Run it with the LEPP_FUZZ_METHOD / LEPP_FUZZ_THETA of
# the fuzzing run: they are baked into the copy. LEPP_BUILD picks the build, LEPP_REGRESSIONS the
# destination (default corpus/regressions).
set -euo pipefail
usage() { echo "usage: fuzz/promote.sh [--target T] [--open | --fixed] [--note WORDS] FILE" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
build=${LEPP_BUILD:-$root/build}
targets="fuzz_parse fuzz_refine fuzz_differential fuzz_cdt fuzz_engine"
target="" place="" note="" file=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --target) target=${2:-}; shift 2 || usage ;;
    --open) place=open; shift ;;
    --fixed) place=fixed; shift ;;
    --note) note=${2:-}; shift 2 || usage ;;
    -h|--help) usage ;;
    -*) echo "promote.sh: unknown option $1" >&2; usage ;;
    *) [[ -z $file ]] || usage; file=$1; shift ;;
  esac
done
[[ -n $file ]] || usage
[[ -f $file ]] || { echo "promote.sh: $file: no such file" >&2; exit 2; }

if [[ -z $target ]]; then
  abs=$(readlink -f "$file")
  for t in $targets; do
    if [[ $abs == */$t/* || $(basename "$abs") == "$t"-* ]]; then target=$t; break; fi
  done
  [[ -n $target ]] || { echo "promote.sh: cannot tell the target of $file: use --target" >&2; exit 2; }
fi
[[ " $targets " == *" $target "* ]] || { echo "promote.sh: unknown target $target" >&2; exit 2; }

replay=$build/fuzz/${target}_replay
if [[ ! -x $replay ]]; then
  [[ -f $build/build.ninja ]] || { echo "promote.sh: no build in $build (configure it, or set LEPP_BUILD)" >&2; exit 2; }
  ninja -C "$build" "${target}_replay" >/dev/null
fi

# An input found with LEPP_FUZZ_METHOD / LEPP_FUZZ_THETA pinned decodes to
# another method or theta without them: bake them into the file first (run
# promote.sh with the same environment as the fuzzing run).
src=$file
if [[ $target != fuzz_parse && ( -n ${LEPP_FUZZ_METHOD:-} || -n ${LEPP_FUZZ_THETA:-} ) ]]; then
  [[ -x $build/fuzz/fuzz_make_seeds ]] || ninja -C "$build" fuzz_make_seeds >/dev/null
  baked=$(mktemp)
  "$build/fuzz/fuzz_make_seeds" --bake "$file" "$baked" >&2
  file=$baked
fi

# Replay once, expecting a finding: exit 0 = reported, 1 = ran clean, >128 = crashed.
log=$(mktemp)
trap 'rm -f "$log" ${baked:-}' EXIT
status=0
env -u LEPP_FUZZ_METHOD -u LEPP_FUZZ_THETA -u LEPP_FUZZ_MIN_INPUT_ANGLE "$replay" --expect-finding "$file" >/dev/null 2>"$log" || status=$?
line=$(grep -m1 '^LEPP-FINDING' "$log" || true)
if [[ $status -eq 0 && -n $line ]]; then
  cls=$(sed -n 's/.* class=\([^ ]*\).*/\1/p' <<<"$line")
  default_place=open
elif [[ $status -gt 128 || $status -eq 134 ]]; then
  cls=crash
  default_place=fixed
  echo "promote.sh: the replay driver crashed on it (status $status): it goes with the fixed regressions, so" \
       "fuzz_replay.$target fails until the crash is fixed" >&2
  tail -5 "$log" >&2
else
  # Runs clean now: name it after libFuzzer's artifact kind when it has one.
  kind=$(basename "$file" | sed -n 's/^\(crash\|timeout\|oom\|leak\|slow-unit\)-.*/\1/p')
  cls=${kind:+$kind-}clean
  default_place=fixed
fi
place=${place:-$default_place}

# What the input was: method and theta for the structured targets.
what=""
if [[ -n $line ]]; then
  method=$(sed -n 's/.* method=\([a-z]*\).*/\1/p' <<<"$line")
  theta=$(sed -n 's/.* theta=\([0-9.]*\).*/\1/p' <<<"$line")
  [[ -n $method ]] && what=-$method
  [[ -n $theta ]] && what=$what-theta$theta
fi
[[ -n $note ]] && what=$what-$(tr -cs 'A-Za-z0-9.' '-' <<<"$note" | sed 's/-$//')
sha=$(sha1sum "$file" | cut -c1-8)
base=$(basename "$src")
ext=bin
[[ $base == *.* ]] && ext=${base##*.}
[[ $ext == txt || $ext == md ]] && { echo "promote.sh: $file looks like a note, not an input" >&2; exit 2; }

dir=${LEPP_REGRESSIONS:-$root/corpus/regressions}/$target
[[ $place == open ]] && dir=$dir/open
mkdir -p "$dir"
dest=$dir/$cls$what-$sha.$ext
for old in "$dir"/*; do
  if [[ -f $old ]] && cmp -s "$old" "$file"; then
    echo "promote.sh: already there: $old" >&2
    exit 0
  fi
done
cp "$file" "$dest"
echo "$dest"
[[ -n $line ]] && echo "  finding: ${line:0:300}" >&2
echo "  ctest: ctest --test-dir $build -R 'fuzz_replay\.$target' (git add the file)" >&2
