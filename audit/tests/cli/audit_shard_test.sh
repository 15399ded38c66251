#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `lepp audit --shard K/N` and `lepp audit merge` (docs/AUDIT.md, "Over many
# machines"): an audit split in three shards and merged gives the single run's
# report (JSON, markdown, JUnit, exit status, the saved findings' files), apart
# from timings and the --out directory; on lepp's engine over the paper's
# problems and the hostile corpus, and on a --cmd program with failures on
# several rows (the independent test mesher with a seeded bug), so the merge
# must pick, number and copy the findings the single run saves. Then: merging
# refuses shards of different audits, missing or duplicate shards, and bad
# --shard values are exit 2.
# usage: audit_shard_test.sh LEPP_BINARY SOURCE_DIR TEST_MESHER
set -u
lepp=$1; src=$2; mesher=$3
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
# lepp with a watchdog: a command that hangs fails the test naming itself and
# the processes it left, instead of running into ctest's timeout with no output.
run_lepp() {
  timeout -k 5 120 "$lepp" "$@"; local s=$?
  if [ $s -eq 124 ] || [ $s -eq 137 ]; then
    # On stderr: stdout is the report's file here.
    ps -eo pid,ppid,stat,wchan:24,etime,args 2>/dev/null | grep -E "lepp|mesher" | grep -v grep >&2
    echo "FAIL: hung for 120 s: lepp $*" >&2
    exit 1
  fi
  return $s
}

# Runs the audit whole (NAME-single) and as shards 1/3, 2/3, 3/3 (NAME-K), merges
# them (NAME-merged), and compares. Arguments: NAME, then lepp audit's options.
split_and_compare() {
  local name=$1; shift
  run_lepp audit "$@" --out "$name-single" --json-file "$name-single.json" --junit "$name-single.xml" > "$name-single.md"
  local whole=$?
  [ $whole -le 1 ] || fail "$name: the single run exited $whole"
  for k in 1 2 3; do
    run_lepp audit "$@" --shard "$k/3" --out "$name-out-$k" --json > "$name-$k.json"; s=$?
    [ $s -le 1 ] || fail "$name: shard $k/3 exited $s"
  done
  # Shards in any order on the command line.
  run_lepp audit merge "$name-3.json" "$name-1.json" "$name-2.json" --out "$name-merged" --json "$name-merged.json" \
    --junit "$name-merged.xml" > "$name-merged.md"; s=$?
  [ $s -eq $whole ] || fail "$name: merge exited $s, the single run $whole"
  python3 - "$dir" "$name" <<'EOF' || fail "$name: the merged report differs from the single run's"
import json, os, re, sys
d, name = sys.argv[1], sys.argv[2]
timing = {"seconds", "engine_seconds", "comparison_seconds", "shrink_seconds", "overhead_per_run_ms"}

def paths(text, which):
    # The findings' directory, relative and absolute, is the only other difference.
    text = text.replace(os.path.join(d, f"{name}-{which}"), "OUT")
    return text.replace(f"{name}-{which}", "OUT")

def load(which):
    j = json.loads(paths(open(f"{d}/{name}-{which}.json").read(), which))
    for k in timing: j.pop(k)
    return j

single, merged = load("single"), load("merged")
assert "shard" not in merged, "the merged report still has shard data"
if single != merged:
    for k in single:
        if single[k] != merged.get(k): print("JSON differs at", k, ":", str(single[k])[:300], "|", str(merged.get(k))[:300])
    sys.exit(1)

def md(which):
    t = paths(open(f"{d}/{name}-{which}.md").read(), which)
    return re.sub(r"[0-9.]+ s with -j (\d+), of which the engine [0-9.]+ s", r"T s with -j \1, of which the engine T s", t)
if md("single") != md("merged"):
    import difflib; print("".join(difflib.unified_diff(md("single").splitlines(True), md("merged").splitlines(True)))); sys.exit(1)

def junit(which):
    return re.sub(r'time="[0-9.]+"', 'time="T"', paths(open(f"{d}/{name}-{which}.xml").read(), which))
assert junit("single") == junit("merged"), (junit("single"), junit("merged"))

# The findings on disk: the same directories, the same files, the same contents.
def tree(which):
    root = f"{d}/{name}-{which}"
    files = {}
    for base, _, names in os.walk(root):
        for f in names:
            p = os.path.join(base, f)
            files[os.path.relpath(p, root)] = paths(open(p, "rb").read().decode("utf-8", "replace"), which)
    return files
s, m = tree("single"), tree("merged")
assert sorted(s) == sorted(m), (sorted(s), sorted(m))
for f in s: assert s[f] == m[f], f
print(f"{name}: {single['runs']} runs, {sum(len(r['counterexamples']) for r in single['rows'])} findings, "
      f"{len(s)} files: merged = single")
EOF
}

# lepp's fast engine on the paper's problems and the hostile corpus, the points
# compared with another engine (the ratio table). --timeout 0: a comparison gets at
# least a second otherwise, and on a loaded CI machine one cut short drops out of
# the ratio in one run and not in another (CI once counted 39 runs, not 40).
split_and_compare builtin --engine fast --sources paper,corpus --theta 20,25,30 --compare fast --no-cache --timeout 0 \
  --root "$src" -j 2
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert r["runs"]==60 and r["points_ratio"][0]["runs"]>=40, (r["runs"], r["points_ratio"])' \
  "$dir/builtin-single.json" || fail "builtin: not the 60 runs expected"

# merge's --json as lepp audit's (issue 41): bare, the JSON on stdout instead of the
# markdown; --json-file FILE writes the same JSON; --json FILE (above) still works;
# --json FILE with --json-file FILE is bad usage.
run_lepp audit merge builtin-1.json builtin-2.json builtin-3.json --out bare-out --json > bare.json || [ $? -eq 1 ] \
  || fail "merge --json: exit status"
run_lepp audit merge builtin-1.json builtin-2.json builtin-3.json --out bare-out --json-file file.json > file.md || [ $? -eq 1 ] \
  || fail "merge --json-file: exit status"
head -1 file.md | grep -q '^# lepp audit' || fail "merge --json-file: no markdown on stdout"
python3 -c 'import json,sys; a=json.load(open(sys.argv[1])); b=json.load(open(sys.argv[2])); assert a==b, "differ"' bare.json file.json \
  || fail "merge: bare --json on stdout and --json-file differ"
run_lepp audit merge builtin-1.json builtin-2.json builtin-3.json --out bare-out --json x.json --json-file y.json > /dev/null 2>&1
[ $? -eq 2 ] || fail "merge --json FILE --json-file FILE: not bad usage"

# A --cmd program failing two rows on some inputs (no-flips: certificate and
# conformance), each input in two shards (two angles, three shards), every case
# run twice, at most two findings per row: the merge must keep the single run's.
split_and_compare cmd --cmd "$mesher {in} {out} {theta} {method} --bug no-flips" --sources gen --seed 3 --theta 20,25 \
  --cases 16 --repeat 2 --max-findings 2 --compare fast --no-cache --timeout 0 -j 2
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); rows={x["check"]: x for x in r["rows"]}
assert rows["certificate"]["failed"] > 2 and len(rows["certificate"]["counterexamples"]) == 2, rows["certificate"]
assert rows["conformance"]["failed"] > 2 and len(rows["conformance"]["counterexamples"]) == 2, rows["conformance"]' \
  "$dir/cmd-single.json" || fail "cmd: the program does not fail as this test needs"

# A program with two deviations (issue 30): every deviation of each run is in the
# row's counts and each counterexample's list; the merge must carry both.
split_and_compare chain --cmd "$mesher {in} {out} {theta} {method} --bug area-centroid --bug other-second-longest" \
  --inputs "$src/corpus/paper" --theta 20,25,30 --max-findings 3 --no-shrink --compare none -j 2
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); conf=[x for x in r["rows"] if x["check"]=="conformance"][0]
assert set(conf["deviations"]) >= {"area-centroid", "other-second-longest"}, conf["deviations"]
assert any(len(c.get("deviations", [])) >= 2 for c in conf["counterexamples"]), conf["counterexamples"]' \
  "$dir/chain-single.json" || fail "chain: no counterexample with two deviations, as this test needs"

# The declared arithmetic of doubles (--arithmetic double): the notes it counts
# (steps accepted as inexact-length) summed like the other counts.
split_and_compare arithmetic --cmd "$mesher {in} {out} {theta} {method} --bug inexact-length" \
  --inputs "$src/audit/tests/mesher/arithmetic" --theta 20,25,30 --arithmetic double --compare none -j 2
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); conf=[x for x in r["rows"] if x["check"]=="conformance"][0]
assert r["arithmetic"] == "double" and conf["inexact_steps"].get("inexact-length", 0) >= 3, conf' \
  "$dir/arithmetic-single.json" || fail "arithmetic: no inexact-length notes, as this test needs"

# As a CI downloads them: each shard's JSON beside its findings directory, on a
# machine where the shards' own paths do not exist; merged from there the same.
for k in 1 2 3; do mkdir -p "ci/shard-$k" && cp "cmd-$k.json" "ci/shard-$k/report.json" && mv "cmd-out-$k" "ci/shard-$k/"; done
mv cmd-merged cmd-merged-first
"$lepp" audit merge ci/shard-*/report.json --out cmd-merged --json cmd-merged-ci.json > cmd-merged-ci.md 2> err; s=$?
[ $s -eq 1 ] && [ ! -s err ] || fail "merge of the downloaded shards: exit $s, $(cat err)"
diff -r cmd-merged-first cmd-merged > /dev/null || fail "merge of the downloaded shards: other findings"
diff cmd-merged.md cmd-merged-ci.md > /dev/null || fail "merge of the downloaded shards: another report"

# Refused, exit 2 with a message: shards of another audit (another seed), a shard
# missing, a shard twice, shards of another split, a report that is no shard's.
"$lepp" audit --cmd "$mesher {in} {out} {theta} {method} --bug no-flips" --sources gen --seed 4 --theta 20,25 --cases 16 \
  --repeat 2 --max-findings 2 --compare fast --no-cache -j 2 --shard 2/3 --out other-out --json > other-2.json
"$lepp" audit --cmd "$mesher {in} {out} {theta} {method} --bug no-flips" --sources gen --seed 3 --theta 20,25 --cases 16 \
  --repeat 2 --max-findings 2 --compare fast --no-cache -j 2 --shard 2/2 --out half-out --json > half-2.json
refused() {
  local why=$1 pattern=$2; shift 2
  "$lepp" audit merge "$@" --out refused > /dev/null 2> err; s=$?
  [ $s -eq 2 ] || fail "merge of $why: exit $s"
  grep -q "$pattern" err || fail "merge of $why: message $(cat err)"
}
refused "another seed's shard" "different audits: seed" cmd-1.json other-2.json cmd-3.json
refused "a missing shard" "shard 2/3 is missing" cmd-1.json cmd-3.json
refused "a shard twice" "shard 1/3 given twice" cmd-1.json cmd-1.json cmd-2.json cmd-3.json
refused "shards of another split" "different splits" cmd-1.json half-2.json
refused "a whole audit's report" "not a shard's report" cmd-single.json
[ -e refused ] && fail "a refused merge wrote findings"

for bad in 0/3 4/3 3/0 3 /3 1/ a/b 1/3/4 -1/3; do
  "$lepp" audit --engine fast --sources paper --compare none --shard "$bad" --out bad > /dev/null 2> err; s=$?
  [ $s -eq 2 ] || fail "--shard $bad: exit $s"
  grep -q "expected K/N" err || fail "--shard $bad: message $(cat err)"
done
echo "audit_shard: ok"
