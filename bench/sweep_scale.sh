#!/usr/bin/env bash
# Sweep at scale: wall time and peak memory of `ivv sweep` over an NV x NZ grid of
# the paper scene (v0 0.05-20 m/s log, zeta 0-2: rebounds, captures and the stiff corners, so
# point costs vary ~100x), on 1 and 2 threads and on 1 and 2 MPI ranks (1 thread each).
# A benchmark, not a test: timings depend on the machine and its load.
#
#   bench/sweep_scale.sh [NV] [NZ] [BUILD_DIR]     (default 1000 1000 build)
#
# Peak memory is the maximum resident set of one process (for MPI: the largest rank), and
# must not grow with the grid: rows are streamed to disk in index order.
set -euo pipefail
nv=${1:-1000}
nz=${2:-1000}
build=${3:-build}
ivv=$(realpath "$build/app/ivv")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none
grid=(--scene paper --v0 "0.05:20:$nv" --log --zeta "0:2:$nz" -q)

# run LABEL RANKS THREADS: prints wall seconds and peak RSS [MB]; checks the CSV equals the first.
run() {
  local label=$1 ranks=$2 threads=$3 csv="$work/$1.csv"
  local start end
  start=$(date +%s.%N)
  if [ "$ranks" = 0 ]; then
    /usr/bin/time -f "%M %U %S" -o "$work/$label.rss.0" "$ivv" sweep "${grid[@]}" --threads "$threads" \
      --out "$csv" || [ $? = 1 ]
  else
    # Exit status 1 (some points failed, named in the CSV) is not an error here; mpirun takes
    # ~2 s to tear a job down after a non-zero status, which would pollute the timing.
    mpirun --oversubscribe --bind-to none -np "$ranks" --mca btl self,vader sh -c \
      "/usr/bin/time -f \"%M %U %S\" -o $work/$label.rss.\$OMPI_COMM_WORLD_RANK $ivv sweep ${grid[*]} --threads $threads --out $csv; [ \$? -le 1 ]"
  fi
  end=$(date +%s.%N)
  local rss
  rss=$(cat "$work/$label".rss.* | awk '{print $1}' | sort -n | tail -1)
  local cpu
  cpu=$(cat "$work/$label".rss.* | awk '{s += $2 + $3} END {print s}')
  local same="reference"
  if [ -f "$work/ref.csv" ]; then cmp -s "$csv" "$work/ref.csv" && same="identical" || same="DIFFERS"; fi
  [ -f "$work/ref.csv" ] || cp "$csv" "$work/ref.csv"
  printf '%-12s wall %7.1f s  cpu %7.1f s  peak RSS %6.1f MB  csv %s\n' "$label" \
    "$(echo "$end - $start" | bc)" "$cpu" "$(echo "$rss / 1024" | bc -l)" "$same"
  echo "$end - $start" | bc > "$work/$label.wall"
}

echo "ivv sweep, $nv x $nz = $((nv * nz)) impacts, $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "(cpu: user + sys of every process; a wall speed-up needs idle cores, cpu shows the overhead)"
run threads-1 0 1
run threads-2 0 2
run ranks-1 1 1
run ranks-2 2 1
printf 'speed-up 1 -> 2 threads: %.2f\n' "$(echo "$(cat "$work/threads-1.wall") / $(cat "$work/threads-2.wall")" | bc -l)"
printf 'speed-up 1 -> 2 ranks:   %.2f\n' "$(echo "$(cat "$work/ranks-1.wall") / $(cat "$work/ranks-2.wall")" | bc -l)"
