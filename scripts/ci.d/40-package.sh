#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# lepp as Debian packages: cpack -G DEB from the existing build directory makes lepp,
# lepp-dev and python3-lepp (cmake/LeppDebian.cmake); check that every dependency they declare
# is installed here, unpack them into a throwaway root (dpkg -x: nothing touches the system),
# then run the installed command (--version, refine and certify on a paper problem, `lepp theorems
# --prove` on one row through its helper, `lepp audit`
# from an empty directory on the packaged corpus), build and run examples/outside_project with
# find_package(lepp) against that root only, and import the installed Python package from an
# empty directory (refine and certify through it).
# LEPP_BUILD_DIR overrides the build directory (default build/, made by scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${LEPP_BUILD_DIR:-build}
start=$(date +%s)
# A fixed folder inside the build directory (not mktemp): ccache hits on the example's compile.
work="$(cd "$build" && pwd)/package-check"
rm -rf "$work"
mkdir -p "$work/debs"

# 1. The packages. cpack installs the headers from the source tree and the libraries from the
# build: bring `lepp` (which links every packaged library) and the Python package up to date
# first, or a stale build pairs new headers with old libraries (a no-op after scripts/build.sh).
cmake --build "$build" --target lepp lepp_python > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
if ! (cd "$build" && cpack -G DEB -B "$work/debs") > "$work/cpack.log" 2>&1; then
  cat "$work/cpack.log"
  exit 1
fi
shopt -s nullglob
runtime=("$work"/debs/lepp_*.deb)
dev=("$work"/debs/lepp-dev_*.deb)
python=("$work"/debs/python3-lepp_*.deb)
if [ ${#runtime[@]} -ne 1 ] || [ ${#dev[@]} -ne 1 ] || [ ${#python[@]} -ne 1 ]; then
  echo "40-package: expected one lepp_*.deb, one lepp-dev_*.deb and one python3-lepp_*.deb in $work/debs" >&2
  ls -l "$work/debs" >&2
  exit 1
fi
debs=("${runtime[0]}" "${dev[0]}" "${python[0]}")
version=$(dpkg-deb -f "${runtime[0]}" Version)
for deb in "${debs[@]}"; do
  echo "$(basename "$deb"): $(du -k "$deb" | cut -f1) KiB, Installed-Size $(dpkg-deb -f "$deb" Installed-Size) KiB"
  echo "  Depends: $(dpkg-deb -f "$deb" Depends)"
done

# 2. Every declared dependency (name and version constraint) is satisfied on this machine.
missing=0
for deb in "${debs[@]}"; do
  IFS=',' read -ra deps <<< "$(dpkg-deb -f "$deb" Depends)"
  for dep in "${deps[@]}"; do
    dep=$(echo "$dep" | xargs)                      # trim
    name=${dep%% *}
    have=$(dpkg-query -W -f='${Status} ${Version}' "$name" 2>/dev/null | sed -n 's/^install ok installed //p')
    if [ -z "$have" ]; then
      echo "40-package: $(basename "$deb") depends on $dep: not installed" >&2; missing=1; continue
    fi
    if [[ "$dep" =~ \((\<\<|\<=|=|\>=|\>\>)\ ([^\)]+)\) ]]; then
      op=${BASH_REMATCH[1]}; want=${BASH_REMATCH[2]}
      case $op in '<<') op=lt;; '<=') op=le;; '=') op=eq;; '>=') op=ge;; '>>') op=gt;; esac
      if ! dpkg --compare-versions "$have" "$op" "$want"; then
        echo "40-package: $(basename "$deb") depends on $dep: installed $have" >&2; missing=1
      fi
    fi
  done
done
[ $missing -eq 0 ]

# Each find_dependency() of the installed leppConfig.cmake is a -dev package lepp-dev declares
# (a consumer's find_package(lepp) fails without it): the owner of NAMEConfig.cmake here.
dev_depends=$(dpkg-deb -f "${dev[0]}" Depends)
dpkg-deb --fsys-tarfile "${dev[0]}" | tar -xO --wildcards '*/cmake/lepp/leppConfig.cmake' > "$work/leppConfig.cmake"
for name in $(sed -n 's/^ *find_dependency(\([A-Za-z0-9_]*\).*/\1/p' "$work/leppConfig.cmake"); do
  # A module CMake itself ships (FindThreads.cmake) needs no package beyond cmake.
  compgen -G "/usr/share/cmake-*/Modules/Find${name}.cmake" >/dev/null && continue
  owner=$(dpkg -S "*/${name}Config.cmake" "*/${name}-config.cmake" 2>/dev/null | head -n1 | cut -d: -f1 || true)
  if [ -z "$owner" ] || ! echo ", $dev_depends" | grep -q ", $owner\b"; then
    echo "40-package: leppConfig.cmake calls find_dependency($name) (package ${owner:-unknown}), which lepp-dev does not declare" >&2
    missing=1
  fi
done
[ $missing -eq 0 ]

# 3. The docs agree with the packages: each declared dependency is in docs/DEPENDENCIES.md,
# CHANGELOG.md has a section for this version, the packaged copyright is LICENSE.
for deb in "${debs[@]}"; do
  IFS=',' read -ra deps <<< "$(dpkg-deb -f "$deb" Depends)"
  for dep in "${deps[@]}"; do
    name=$(echo "$dep" | xargs | cut -d' ' -f1)
    if ! grep -q "\`$name\`" docs/DEPENDENCIES.md; then
      echo "40-package: $(basename "$deb") depends on $name, which docs/DEPENDENCIES.md does not list" >&2; missing=1
    fi
  done
done
grep -q "^## \[.*\] - $version\$\|^## \[$version\]" CHANGELOG.md || { echo "40-package: CHANGELOG.md has no section for $version" >&2; missing=1; }
[ $missing -eq 0 ]

# 4. Unpack into a throwaway root.
root="$work/root"
for deb in "${debs[@]}"; do dpkg -x "$deb" "$root"; done
lepp="$root/usr/bin/lepp"
cmp -s LICENSE "$root/usr/share/doc/lepp/copyright" || { echo "40-package: packaged copyright is not LICENSE" >&2; exit 1; }
if ldd "$lepp" | grep -q "not found"; then
  ldd "$lepp" >&2
  echo "40-package: the installed lepp misses a shared library" >&2
  exit 1
fi
# Z3 and MPFI are the helper's (lepp theorems, cli/helper.h), never lepp's own start.
helper="$root/usr/libexec/lepp/lepp-theorems"
if [ ! -x "$helper" ] || ldd "$helper" | grep -q "not found" || ldd "$lepp" | grep -q "libz3\|libmpfi"; then
  ldd "$lepp" "$helper" >&2
  echo "40-package: the installed lepp links Z3 or MPFI, or its helper $helper is missing or misses a library" >&2
  exit 1
fi

# 5. The installed command.
"$lepp" --version | tee "$work/version.txt"
if [ "$(head -n1 "$work/version.txt")" != "lepp $version" ]; then
  echo "40-package: lepp --version does not print the package version $version" >&2
  exit 1
fi
"$lepp" refine corpus/paper/A.poly -o "$work/A" --min-angle 30 --json -q > "$work/refine.json"
grep -q "\"lepp_version\": \"$version\"" "$work/refine.json" || { cat "$work/refine.json"; exit 1; }
"$lepp" certify corpus/paper/A.poly "$work/A" --min-angle 30 > "$work/certify.txt" || { cat "$work/certify.txt"; exit 1; }
echo "installed lepp refine + certify on corpus/paper/A.poly at 30 degrees: ok"
row=Lemma7.AcuteAlpha1AtLeast079Alpha0  # proved by MPFI and Z3 in 0.2 s
"$lepp" theorems --prove --only $row > "$work/theorems.txt" 2>&1 || { cat "$work/theorems.txt"; exit 1; }
grep -q "\`$row\`.*\*\*proved\*\*" "$work/theorems.txt" || { cat "$work/theorems.txt"; exit 1; }
echo "installed lepp theorems --prove (its helper in libexec/lepp) on $row: ok"

# The installed `lepp audit` finds its built-in inputs beside itself (share/lepp/corpus, no
# --root): from an empty directory, --engine fast runs the paper's problems and the hostile
# corpus (every file is run or listed as not validating); a built-in source that is not
# there is exit 2, never a silent skip.
share="$root/usr/share/lepp/corpus"
n_paper=$(ls "$share"/paper/*.poly | wc -l)
n_files=$(ls "$share"/paper/*.poly "$share"/hostile/*.poly | wc -l)
[ "$n_paper" -ge 4 ] || { echo "40-package: the package has $n_paper of the paper's problems under share/lepp" >&2; exit 1; }
mkdir -p "$work/empty"
s=0
(cd "$work/empty" && "$lepp" audit --engine fast --sources paper,corpus --theta 25 --compare none --no-shrink \
  --out "$work/audit-out" --json > "$work/audit.json") || s=$?
[ $s -eq 0 ] || { cat "$work/audit.json"; echo "40-package: installed lepp audit --engine fast: exit $s" >&2; exit 1; }
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); n=int(sys.argv[2]); p=int(sys.argv[3])
assert r["inputs"] >= p and r["inputs"] + len(r["skipped_inputs"]) == n, (r["inputs"], r["skipped_inputs"], n)
assert all("/usr/share/lepp/corpus/hostile/" in s for s in r["skipped_inputs"]), r["skipped_inputs"]' \
  "$work/audit.json" "$n_files" "$n_paper" || { echo "40-package: the installed audit did not run every packaged input" >&2; exit 1; }
s=0
(cd "$work/empty" && "$lepp" audit --engine fast --root "$work/empty" --compare none --out "$work/audit-out2" \
  > /dev/null 2> "$work/audit.err") || s=$?
[ $s -eq 2 ] && grep -q "paper" "$work/audit.err" ||
  { cat "$work/audit.err"; echo "40-package: a missing built-in source gave exit $s, not 2" >&2; exit 1; }
echo "installed lepp audit --engine fast from an empty directory: $(python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(r["inputs"], "inputs,", r["runs"], "runs")' "$work/audit.json"): ok"

# 6. find_package(lepp) against the unpacked root only; the package says the same version.
grep -q "^set(PACKAGE_VERSION \"$version\")" "$root/usr/lib/cmake/lepp/leppConfigVersion.cmake" ||
  { echo "40-package: leppConfigVersion.cmake does not say $version" >&2; exit 1; }
grep -q "^#define LEPP_VERSION_STRING \"$version\"" "$root/usr/include/lepp/version.h" ||
  { echo "40-package: lepp/version.h does not say $version" >&2; exit 1; }
cmake -S examples/outside_project -B "$work/example" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$root/usr" -DCMAKE_CXX_COMPILER_LAUNCHER="$(command -v ccache || true)" > "$work/example.log"
lepp_dir=$(sed -n 's/^lepp_DIR:PATH=//p' "$work/example/CMakeCache.txt")
case $lepp_dir in
  "$root"/*) ;;
  *) echo "40-package: find_package(lepp) found $lepp_dir, not the unpacked package" >&2; exit 1 ;;
esac
cmake --build "$work/example" >> "$work/example.log"
RC_PARAMS="${RC_PARAMS:-seed=20261122 max_success=100}" "$work/example/cdt_property"

# 7. The Python package where Debian's python3 looks (dist-packages), imported from an empty
# directory with only that directory on the path: the installed files alone make it work.
site="$root/usr/lib/python3/dist-packages"
cmp -s LICENSE "$root/usr/share/doc/python3-lepp/copyright" || { echo "40-package: python3-lepp copyright is not LICENSE" >&2; exit 1; }
for so in "$site"/lepp/_lepp*.so; do
  if ldd "$so" | grep -q "not found"; then ldd "$so" >&2; echo "40-package: $so misses a shared library" >&2; exit 1; fi
done
mkdir -p "$work/empty"  # step 6 made it: still empty (the audits wrote under --out)
paper_a="$PWD/corpus/paper/A.poly"
(cd "$work/empty" && PYTHONPATH="$site" /usr/bin/python3 -c "import lepp; print(lepp.__file__, lepp.__version__)") | tee "$work/import.txt"
case $(cut -d' ' -f1 "$work/import.txt") in
  "$site"/lepp/__init__.py) ;;
  *) echo "40-package: import lepp did not load the packaged lepp" >&2; exit 1 ;;
esac
[ "$(cut -d' ' -f2 "$work/import.txt")" = "$version" ] || { echo "40-package: lepp.__version__ is not $version" >&2; exit 1; }
(cd "$work/empty" && PYTHONPATH="$site" /usr/bin/python3 -c "
import lepp, sys
mesh = lepp.refine(sys.argv[1], min_angle=30)
assert mesh.converged and lepp.certify(sys.argv[1], mesh, min_angle=30).ok
import lepp.testing
print('installed python3-lepp: refine + certify of A.poly at 30 degrees: ok')" "$paper_a")
rm -rf "$work"
echo "40-package: ok in $(( $(date +%s) - start )) s"
