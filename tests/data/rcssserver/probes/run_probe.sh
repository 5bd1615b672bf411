#!/usr/bin/env bash
# Records one probe MODE into RAW_OUT.json: starts rcssserver (synchronous, trainer mode, no logs) in a
# private network namespace (unshare -rn: no root needed; only loopback exists there, so it listens on 127.0.0.1 alone), runs
# record.py against it, then stops that server by its PID.
# usage: run_probe.sh MODE RAW_OUT.json        (RCSS_HOME: where build.sh installed the server)
set -euo pipefail
mode=$1; out=$(realpath -m "$2")
here=$(cd "$(dirname "$0")" && pwd)
RCSS_HOME=${RCSS_HOME:-$HOME/.cache/rcss-reference}
PORT=${PORT:-6400}
noise_off="server::player_rand=0 server::ball_rand=0 server::kick_rand=0"
case $mode in
  clean)     extra="$noise_off" ;;
  kicknoise) extra="server::player_rand=0 server::ball_rand=0" ;;
  noisy)     extra="" ;;
  referee|keeper|foulrule) extra="$noise_off server::coach_w_referee=true" ;;
  *) echo "unknown mode: $mode" >&2; exit 2 ;;
esac
exec unshare -rn bash -c '
  set -euo pipefail
  ip link set lo up
  mkdir -p "$0/probe-home"; cd "$0/probe-home"   # the server may write ./~/.rcssserver
  HOME="$0/probe-home" LD_LIBRARY_PATH="$0/install/lib" "$0/install/bin/rcssserver" \
    server::port=$1 server::coach_port=$(($1 + 1)) server::olcoach_port=$(($1 + 2)) \
    server::synch_mode=true server::coach=true server::game_logging=false server::text_logging=false \
    '"$extra"' >"$0/probe-home/server-$2.log" 2>&1 &
  pid=$!
  trap "kill $pid; wait $pid || true" EXIT
  sleep 1.5
  python3 "$3/record.py" "$2" "$4" "$1" $(($1 + 1))
' "$RCSS_HOME" "$PORT" "$mode" "$here" "$out"
