#!/bin/bash
# A point whose worker dies (SIGKILL from outside, standing in for a crash) is a `failed` row
# saying so, and the sweep goes on with a fresh worker: the other points are `ok`.
# Usage: sweep_worker_crash_test.sh TRIBO WORK
set -u
tribo=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
printf '[rig]\ndrive_speed_m_per_s = 0.1\n[friction]\nlaw = "coulomb"\nmu_s = 0.3\nmu_k = 0.2\n[run]\nduration_s = 1.0\n' > rig.toml
# Point 0 runs ≈ 10 s of wall (30000 s of rig time); points 1 and 2 are cheap.
printf '[base]\ncommand = "rig"\nconfig = "rig.toml"\n[[axis]]\nkey = "run.duration_s"\nvalues = [30000.0, 1.0, 2.0]\n[sweep]\njobs = 1\n[outputs]\ncolumns = ["summary.json:regime"]\n' > spec.toml

"$tribo" sweep spec.toml --out out > sweep.log 2>&1 &
sweep=$!
# The worker: the sweep's child, forked to run point 0 (it runs in memory: no file to wait for).
worker=""
for _ in $(seq 100); do
  sleep 0.1
  for stat in /proc/[0-9]*/stat; do
    read -r pid _ _ ppid _ < "$stat" 2>/dev/null || continue
    [ "$ppid" = "$sweep" ] && worker=$pid
  done
  [ -n "$worker" ] && break
done
[ -n "$worker" ] || { echo "no worker process found under the sweep ($sweep)"; kill "$sweep"; exit 1; }
kill -9 "$worker"
wait "$sweep"
status=$?
rows=$(grep -v '^#' out/results.csv)
echo "$rows"
[ "$status" = 0 ] || { echo "the sweep exited with $status"; cat sweep.log; exit 1; }
echo "$rows" | grep -q '^0,30000,failed,"killed by signal 9 ' || { echo "point 0 is not a failed row naming signal 9"; exit 1; }
[ "$(echo "$rows" | grep -c ',ok,')" = 2 ] || { echo "points 1 and 2 must be ok"; exit 1; }
# The killed point keeps its config to rerun by hand; the points that succeeded leave no folder.
[ -f out/points/00000/config.toml ] && [ -f out/points/00000/log.txt ] && [ "$(ls out/points)" = 00000 ] ||
  { echo "expected out/points/00000/{config.toml,log.txt} and no other point folder"; ls -R out/points; exit 1; }
echo "worker crash: a failed row, and the sweep went on"
