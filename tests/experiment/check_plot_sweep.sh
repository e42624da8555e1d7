#!/bin/sh
# scripts/plot-sweep on a hand-written runs.csv: a 640x420 PNG, and a
# missing column named with the ones there are. Exit 77 (skipped) without
# python3-matplotlib.
#   tests/experiment/check_plot_sweep.sh SOURCE_DIR WORK_DIR
set -u
plot=$1/scripts/plot-sweep
work=$2
/usr/bin/python3 -c 'import matplotlib' 2> /dev/null || { echo "skipped: no python3-matplotlib"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
cat > "$work/runs.csv" << 'CSV'
run,seed,rate,step,"growth, %"
1,1,0.5,1,10
1,1,0.5,2,20
2,2,0.5,1,12
3,1,1,1,30
4,2,1,1,
4,2,1,2,34
CSV
"$plot" "$work/runs.csv" --x rate --y "growth, %" --reference 25 --out "$work/p.png" > "$work/out.txt" || exit 1
[ "$(cat "$work/out.txt")" = "wrote $work/p.png" ] || { echo "said: $(cat "$work/out.txt")"; exit 1; }
# The PNG signature, then the IHDR chunk's width and height (bytes 16-23).
header=$(od -An -tx1 -N24 "$work/p.png" | tr -d ' \n')
[ "$header" = "89504e470d0a1a0a0000000d4948445200000280000001a4" ] || { echo "not a 640x420 PNG: $header"; exit 1; }
"$plot" "$work/runs.csv" --x speed --y "growth, %" --out "$work/q.png" 2> "$work/err.txt" && exit 1
[ "$(cat "$work/err.txt")" = "plot-sweep: $work/runs.csv has no column 'speed' (it has run, seed, rate, step, growth, %)" ] ||
  { echo "said: $(cat "$work/err.txt")"; exit 1; }
[ ! -e "$work/q.png" ] || exit 1
echo "plot-sweep: passed"
