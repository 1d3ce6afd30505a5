#!/usr/bin/env bash
# The short form of the DNC load (issue 13 item 6), as a test: 20 libmodbus clients poll the
# status block at 100 Hz for 3 s against `trilho-cli serve` in real time; every request must be
# answered (none lost, no error, every client connected) and serve must report its servo
# timing and stop cleanly. No timing is asserted (a shared machine makes timed tests flaky):
# scripts/bench-dnc prints the figures. Usage: dnc_load_check.sh CLI BENCH [SECONDS=3].
# Exits 77 (skipped) when BENCH was not built (no libmodbus-dev).
set -euo pipefail
cli=$1 bench=${2:-} seconds=${3:-3}
[ -n "$bench" ] && [ -x "$bench" ] || { echo "trilho-bench-dnc not built (libmodbus-dev): skipped"; exit 77; }
tmp=$(mktemp -d)
serve=
cleanup() {
  [ -n "$serve" ] && kill "$serve" 2>/dev/null && wait "$serve" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
mkdir "$tmp/programs"
"$cli" serve --machine rail --modbus-tcp "127.0.0.1:$port" --programs "$tmp/programs" >"$tmp/serve.out" 2>&1 &
serve=$!
for _ in $(seq 200); do grep -q "remote writes" "$tmp/serve.out" && break; sleep 0.05; done
grep -q "remote writes" "$tmp/serve.out" || { echo "FAIL serve did not start"; cat "$tmp/serve.out"; exit 1; }
rc=0
"$bench" load "$port" 20 100 "$seconds" | tee "$tmp/load.out" || rc=$?
kill "$serve"
src=0
wait "$serve" || src=$?
serve=
cat "$tmp/serve.out"
result=$(grep '^result' "$tmp/load.out" || true)
fail=0
[ "$rc" -eq 0 ] || { echo "FAIL trilho-bench-dnc exit $rc (a request lost or a client not connected)"; fail=1; }
grep -q " lost=0 " <<<"$result" || { echo "FAIL requests lost: $result"; fail=1; }
grep -q " unconnected=0 " <<<"$result" || { echo "FAIL clients not connected: $result"; fail=1; }
grep -q "answered=$((20 * 100 * seconds)) " <<<"$result" || { echo "FAIL not every request answered: $result"; fail=1; }
grep -q "timing window_s=.*period_p99_us=.*rss_kib=" "$tmp/serve.out" || { echo "FAIL no timing line"; fail=1; }
[ "$src" -eq 0 ] || { echo "FAIL serve exit $src"; fail=1; }
[ "$fail" -eq 0 ] && echo "ok   20 clients x 100 Hz x ${seconds} s: every request answered"
exit "$fail"
