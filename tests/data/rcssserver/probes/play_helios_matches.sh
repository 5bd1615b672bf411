#!/usr/bin/env bash
# Plays helios-base v helios-base full matches with the reference kit
# (../shared/reference/rcssserver/run-helios-match.sh), one at a time, each inside a private
# network namespace whose only interface is the loopback (so the server is reachable on
# 127.0.0.1 only). The game logs go to $RCSS_HOME/logs/helios_NN.rcg (outside the work tree);
# helios_figures.py then turns them into ../helios_matches.json.
# usage: play_helios_matches.sh FIRST LAST [STOP_AFTER_EPOCH_SECONDS]
set -uo pipefail
KIT=${KIT:-/work/shared/reference/rcssserver}
first=$1; last=$2; stop=${3:-0}
for i in $(seq "$first" "$last"); do
  if [ "$stop" -gt 0 ] && [ "$(date +%s)" -gt "$stop" ]; then echo "stopping before match $i (time)"; break; fi
  name=$(printf "helios_%02d" "$i")
  nice -n 5 unshare -n bash -c "ip link set lo up && '$KIT/run-helios-match.sh' '$name'" > "/tmp/$name.stats" 2>&1
  head -2 "/tmp/$name.stats"
done
