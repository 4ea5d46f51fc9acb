#!/usr/bin/env bash
# Training throughput: moves per second and learner updates per second of `psxrl train` for the
# tabular agent (q, simple observation) and the seed's agent-local DQN (dqn, local), with one and
# two environments, on Tumble level 1. Each row is one real run of EPISODES episodes (default 40,
# nine training to one greedy test, moves capped at 50) with seed 1; the figures are the run's
# own summary line, and the run's CPU time (user + system) per move, which depends far less on
# what else the machine runs than the rates do. Prints a Markdown table. PSXRL names another
# psxrl executable (with its libpsxrl_dqn.so beside it), to compare two builds.
#
#   [PSXRL=path/psxrl] bench/train_throughput.sh [EPISODES]
set -euo pipefail
cd "$(dirname "$0")/.."
episodes=${1:-40}
psxrl=${PSXRL:-./build/psxrl}
[ -x "$psxrl" ] || { echo "train_throughput: build first ($psxrl missing)" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) threads, load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "Tumble level 1, $episodes episodes per row, --max-moves 50, --seed 1"
echo
echo "| agent | observation | envs | moves/s | learner updates/s | wall-clock | CPU ms per move |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for spec in "q simple" "dqn local"; do
  set -- $spec
  for envs in 1 2; do
    summary=$(/usr/bin/time -f "cpu %U %S" -o "$out/time" "$psxrl" train --agent "$1" --obs "$2" --envs "$envs" \
              --episodes "$episodes" --max-moves 50 --seed 1 --quiet --out "$out/$1-$envs")
    read -r _ user system < "$out/time"
    all_moves=$(awk -F, 'NR > 1 { n += $5 } END { print n }' "$out/$1-$envs/metrics.csv")
    per_move=$(awk -v u="$user" -v s="$system" -v n="$all_moves" 'BEGIN { printf "%.2f", 1000 * (u + s) / n }')
    seconds=$(sed -nE 's/.* in ([0-9.]+) s;.*/\1/p' <<<"$summary")
    line=$(grep '^throughput:' <<<"$summary")
    moves=$(sed -E 's/throughput: ([0-9.]+) moves.*/\1/' <<<"$line")
    updates=$(sed -E 's/.*, ([0-9.]+) learner updates.*/\1/' <<<"$line")
    printf '| %s | %s | %d | %s | %s | %s s | %s |\n' "$1" "$2" "$envs" "$moves" "$updates" "$seconds" "$per_move"
  done
done
