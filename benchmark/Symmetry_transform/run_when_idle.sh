#!/usr/bin/env bash
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Runs a benchmark command on a shared machine only when the machine is idle, and tells whether
# other programs disturbed it. Used for the figures of RESULTS.md.
#
#   run_when_idle.sh PREFIX TRIES command [args...]
#
# Each try waits until the CPUs are at least 85 % idle over two consecutive 5-second windows,
# runs the command (stdout to PREFIX.tT.out, stderr to PREFIX.tT.err; "@T@" in an argument is
# replaced by the try number T), and measures the CPU time that *other* processes used meanwhile:
# all busy time of /proc/stat minus the command's own user + system time, as a percentage of
# (number of CPUs x wall time). The first try where it is below 5 % is accepted ("CLEAN T" in
# PREFIX.log); otherwise the next try starts, and after TRIES tries PREFIX.log ends in DISTURBED.
set -uo pipefail
prefix=$1
tries=$2
shift 2
hz=$(getconf CLK_TCK)
cpus=$(nproc)

busy_and_idle() { # prints "busy idle" jiffies since boot, all CPUs
  read -r _ user nice system idle iowait irq softirq steal _ < /proc/stat
  echo "$((user + nice + system + irq + softirq + steal)) $((idle + iowait))"
}

wait_until_idle() {
  local quiet=0 b1 i1 b2 i2
  while [ "$quiet" -lt 2 ]; do
    read -r b1 i1 < <(busy_and_idle)
    sleep 5
    read -r b2 i2 < <(busy_and_idle)
    if [ $((100 * (i2 - i1) / (b2 - b1 + i2 - i1 + 1))) -ge 85 ]; then quiet=$((quiet + 1)); else quiet=0; fi
  done
}

for t in $(seq 1 "$tries"); do
  wait_until_idle
  args=()
  for a in "$@"; do args+=("${a//@T@/$t}"); done
  read -r b1 _ < <(busy_and_idle)
  start=$(date +%T)
  /usr/bin/time -f "%U %S %e" -o "$prefix.t$t.time" "${args[@]}" > "$prefix.t$t.out" 2> "$prefix.t$t.err"
  read -r b2 _ < <(busy_and_idle)
  read -r user system wall < "$prefix.t$t.time"
  foreign=$(awk -v b=$((b2 - b1)) -v hz="$hz" -v u="$user" -v s="$system" -v w="$wall" -v c="$cpus" \
                'BEGIN { printf "%.1f", (b / hz - u - s) / (c * w) * 100 }')
  echo "try $t start $start end $(date +%T) wall $wall own_cpu $(awk -v u="$user" -v s="$system" 'BEGIN { print u + s }') foreign_pct $foreign" >> "$prefix.log"
  if awk -v f="$foreign" 'BEGIN { exit !(f < 5) }'; then
    echo "CLEAN $t" >> "$prefix.log"
    exit 0
  fi
done
echo DISTURBED >> "$prefix.log"
exit 1
