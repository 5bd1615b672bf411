#!/usr/bin/env bash
# Records the bridge's message transcripts into RAW_OUT.jsonl (record_transcripts.py): starts
# rcssserver (synchronous, trainer mode with the referee on, no logs) in a private network
# namespace (unshare -rn: only loopback exists there), runs the recorder against it, then stops
# that server by its PID. Trim with make_transcripts.py.
# usage: run_transcripts.sh RAW_OUT.jsonl        (RCSS_HOME: where build.sh installed the server)
set -euo pipefail
out=$(realpath -m "$1")
here=$(cd "$(dirname "$0")" && pwd)
RCSS_HOME=${RCSS_HOME:-$HOME/.cache/rcss-reference}
PORT=${PORT:-6400}
exec unshare -rn bash -c '
  set -euo pipefail
  ip link set lo up
  mkdir -p "$0/probe-home"; cd "$0/probe-home"   # the server may write ./~/.rcssserver
  HOME="$0/probe-home" LD_LIBRARY_PATH="$0/install/lib" "$0/install/bin/rcssserver" \
    server::port=$1 server::coach_port=$(($1 + 1)) server::olcoach_port=$(($1 + 2)) \
    server::synch_mode=true server::coach=true server::coach_w_referee=true \
    server::game_logging=false server::text_logging=false >"$0/probe-home/server-transcripts.log" 2>&1 &
  pid=$!
  trap "kill $pid; wait $pid || true" EXIT
  sleep 1.5
  python3 "$2/record_transcripts.py" "$3" "$1"
' "$RCSS_HOME" "$PORT" "$here" "$out"
