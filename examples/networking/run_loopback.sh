#!/usr/bin/env bash
# Runs edyn-example-server in the background and edyn-example-client --check against it on
# loopback; fails when the client's check fails or the server does not stop cleanly.
#   run_loopback.sh SERVER CLIENT [PORT]
# The port defaults to one derived from this script's process id, so that runs in parallel
# rarely meet; a port that is taken is retried with the next.
set -uo pipefail
server_bin=$1
client_bin=$2
port=${3:-$((20000 + $$ % 20000))}
client_seconds=4

server_pid=""
stop_server() {
    [ -n "$server_pid" ] && kill "$server_pid" 2>/dev/null
}
trap stop_server EXIT

for attempt in 1 2 3; do
    # A safety limit, in case this script dies before stopping it.
    "$server_bin" --port "$port" --duration 60 > >(sed -u 's/^/server: /') 2>&1 &
    server_pid=$!
    sleep 0.3
    kill -0 "$server_pid" 2>/dev/null && break
    echo "loopback: the server could not start on port $port"
    server_pid=""
    port=$((port + 1))
done
[ -n "$server_pid" ] || exit 1

"$client_bin" --port "$port" --duration "$client_seconds" --check 2>&1 | sed -u 's/^/client: /'
client_status=${PIPESTATUS[0]}

kill -TERM "$server_pid"
wait "$server_pid"
server_status=$?
server_pid=""

if [ "$client_status" -ne 0 ]; then
    echo "loopback: the client failed (exit status $client_status)"
    exit 1
fi
if [ "$server_status" -ne 0 ]; then
    echo "loopback: the server exited with status $server_status"
    exit 1
fi
echo "loopback: passed on port $port"
