#!/usr/bin/env bash
# Section 11 of docs/tutorial.md, run as written: its commands, in a copy of
# the checkout, and their outputs compared with the outputs the tutorial
# shows. The test breaks when the tutorial and what the commands do part.
#
#   check_tutorial.sh SOURCE BUILD WORK INTERPRETER CHECK -- CMAKE_ARGS...
#
# The tutorial assumes a built checkout. The copy (at WORK, a path of more
# than 40 characters) is configured with CMAKE_ARGS, and takes its
# interpreter, vvm_check and model cache from BUILD as links: nothing is
# compiled but the model. Files the tutorial has the reader save ("Save
# this as `tutorial/draw.vvp`:" before a code block) are written; from the
# section's heading on, each ```sh block is run with sh from the top of the
# copy, and a ```text block right after it is the output it must print.
# Outputs are compared after what differs from run to run is made alike:
# the checkout's folder (the tutorial's is /tmp/tut_repo), times, test
# numbers, the padding ctest lines up columns with, and the line of the
# runner script that reports a failure (the tutorial shows it as "…").
set -euo pipefail

source_dir=$1 build_dir=$2 work=$3 interpreter=$4 checker=$5
shift 5
[ "${1:-}" = "--" ] && shift
section='## 11. '
tutorial_root=/tmp/tut_repo

rm -rf "$work"
mkdir -p "$work"
for entry in CMakeLists.txt cmake docs examples models tests vvc vvinterpreter vvlib; do
  cp -R "$source_dir/$entry" "$work/"
done
cd "$work"
cmake -S . -B build "$@" >/dev/null
link_from_build() {  # the program at $1 of BUILD, at the same place in the copy's build
  local rel=${1#"$build_dir"/}
  mkdir -p "build/$(dirname "$rel")"
  ln -sf "$1" "build/$rel"
}
link_from_build "$interpreter"
link_from_build "$checker"
# The cache may not exist yet when this is the first test ctest starts.
mkdir -p "$build_dir/test-model-cache"
ln -sfn "$build_dir/test-model-cache" build/test-model-cache

# The tutorial as steps: NNN.file (with its path), NNN.sh, NNN.out.
plan=$(mktemp -d)
trap 'rm -rf "$plan"' EXIT
awk -v plan="$plan" -v section="$section" '
  function start_block(kind, path) {
    n++
    body = sprintf("%s/%03d", plan, n)
    printf "" > body
    printf "%03d %s %s\n", n, kind, path > (plan "/steps")
  }
  index($0, section) == 1 { in_section = 1 }
  /^## / && index($0, section) != 1 { in_section = 0 }
  in_block && /^```[ \t]*$/ { in_block = 0; if (body != "") close(body); after_sh = (kind == "sh"); next }
  in_block { if (body != "") print > body; next }
  /^```/ {
    lang = substr($0, 4)
    in_block = 1
    body = ""
    if (target != "") { kind = "file"; start_block("file", target) }
    else if (in_section && lang == "sh") { kind = "sh"; start_block("sh", "") }
    else if (in_section && lang == "text" && after_sh) { kind = "out"; start_block("out", "") }
    else kind = "none"
    target = ""
    after_sh = 0
    next
  }
  /^[ \t]*$/ { next }
  { after_sh = 0; target = "" }
  match($0, /`[^`]+`:[ \t]*$/) { target = substr($0, RSTART + 1, RLENGTH - 1); sub(/`:[ \t]*$/, "", target) }
' "$work/docs/tutorial.md"
[ -s "$plan/steps" ] || { echo "no steps found in docs/tutorial.md ($section)"; exit 1; }

normalise() {
  local text=${1//"$work"/$tutorial_root}
  printf '%s\n' "$text" | sed -E \
    -e 's/[0-9]+\.[0-9]+ sec/T sec/g' \
    -e 's/#[0-9]+:/#N:/g' -e 's/Start +[0-9]+:/Start N:/' -e 's/^([ \t]*)[0-9]+ - /\1N - /' \
    -e 's/run_example\.cmake:[0-9]+/run_example.cmake:…/' \
    -e 's/\.{3,}/.../g' -e 's/[ \t]+/ /g' -e 's/ +$//' |
    sed -e :a -e '/^\n*$/{$d;N;ba' -e '}'  # no trailing blank lines
}

output=""
ran=0 compared=0
while read -r number kind path; do
  case $kind in
    file)
      mkdir -p "$(dirname "$path")"
      cp "$plan/$number" "$path"
      ;;
    sh)
      command=$(cat "$plan/$number")
      echo "\$ $command"
      output=$(sh -c "$command" 2>&1 </dev/null) || true
      ran=$((ran + 1))
      ;;
    out)
      expected=$(normalise "$(cat "$plan/$number")")
      got=$(normalise "$output")
      if [ "$got" != "$expected" ]; then
        echo "the output differs from what docs/tutorial.md shows (- tutorial, + now):"
        diff <(printf '%s\n' "$expected") <(printf '%s\n' "$got") || true
        exit 1
      fi
      compared=$((compared + 1))
      ;;
  esac
done <"$plan/steps"
echo "ran $ran commands of the tutorial's section 11; $compared outputs as shown"
[ "$ran" -gt 0 ] && [ "$compared" -gt 0 ]
