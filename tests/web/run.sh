#!/usr/bin/env bash
# Runs the web client's browser walkthrough against a real daemon:
#   bash tests/web/run.sh [BUILD_DIR]     (default: build/ in the repository)
# Starts BUILD_DIR/geodesic serve on a free loopback port, waits for /healthz, runs
# walkthrough.test.mjs with node's test runner in headless Chromium, stops the daemon and exits
# with the tests' status. Screenshots go to $SCREENSHOT_DIR (default BUILD_DIR/web-screenshots).
# Needs Debian's chromium and `npm ci` in tests/web (scripts/install-deps.sh does both).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
build=$(cd "${1:-$repo/build}" && pwd)
geodesic="$build/geodesic"

fail() { echo "web tests: $*" >&2; exit 1; }
[ -x "$geodesic" ] || fail "no $geodesic: build first"
"$geodesic" --help 2>&1 | grep -qw serve || fail "$geodesic has no 'serve' command"
command -v node >/dev/null || fail "node is missing: run scripts/install-deps.sh"
[ -x "${CHROMIUM:-/usr/bin/chromium}" ] || fail "no Chromium at ${CHROMIUM:-/usr/bin/chromium}: run scripts/install-deps.sh"
[ -d "$here/node_modules/playwright-core" ] || fail "playwright-core is missing: run 'npm ci' in tests/web (scripts/install-deps.sh does)"

# A free port: bind to port 0 and read what the kernel picked. Another process could take it
# before the daemon binds; that is rare on a test machine, and the daemon then fails loudly.
port=$(node -e 'const s = require("net").createServer().listen(0, "127.0.0.1", () => { console.log(s.address().port); s.close(); });')
url="http://127.0.0.1:$port"
log="$build/web-test-daemon.log"
data="$build/web-test-data"  # render jobs: a fresh data directory each run
rm -rf "$data"

# From the repository root, so the daemon finds web/ and scenes/.
cd "$repo"
# --max-depth differs from the default (16), so the page can only know it from `hello`.
max_depth=12
"$geodesic" serve --host 127.0.0.1 --port "$port" --data "$data" --max-depth "$max_depth" >"$log" 2>&1 &
daemon=$!
stop_daemon() {
  if kill -0 "$daemon" 2>/dev/null; then
    kill "$daemon" 2>/dev/null || true
    wait "$daemon" 2>/dev/null || true
  fi
}
trap stop_daemon EXIT

# 0 when GET $1 answers 2xx (node's fetch: curl is not among the project's packages).
http_ok() {
  node -e 'fetch(process.argv[1]).then((r) => process.exit(r.ok ? 0 : 1), () => process.exit(1))' "$1" 2>/dev/null
}

# Starting the Vulkan device (lavapipe) and compiling pipelines takes a while on two cores.
for _ in $(seq 1 240); do
  if http_ok "$url/healthz"; then break; fi
  if ! kill -0 "$daemon" 2>/dev/null; then
    cat "$log" >&2
    fail "the daemon exited before it answered /healthz"
  fi
  sleep 0.5
done
http_ok "$url/healthz" || { cat "$log" >&2; fail "no answer from $url/healthz after 120 s"; }
echo "web tests: daemon at $url (pid $daemon), log in $log"

status=0
GEODESIC_URL="$url" GEODESIC_PID="$daemon" GEODESIC_MAX_DEPTH="$max_depth" SCREENSHOT_DIR="${SCREENSHOT_DIR:-$build/web-screenshots}" \
  node --test --test-reporter=spec "$here/walkthrough.test.mjs" || status=$?
if [ "$status" -ne 0 ]; then
  echo "web tests: failed; the daemon's log ($log) ends:" >&2
  tail -n 40 "$log" >&2
fi
exit "$status"
