#!/usr/bin/env bash
# tests/web/run.sh - the browser demo's real-browser test (tests/web/web_test.mjs) for
# tests/run_all.sh (section web). Needs node (Debian: nodejs), chromium and playwright-core
# (cd tests/web && npm ci); outside CI a missing one prints SKIP with what to install, with
# CI=true it is a FAIL. The fps figures go to build/web_test/web.csv (make bench-web writes
# bench/results/web.csv).
set -u
cd "$(dirname "$0")/../.."
if ! command -v node >/dev/null 2>&1; then
    if [ "${CI:-}" = true ]; then echo "FAIL web: node not found (apt-get install nodejs)"; echo "0 passed, 1 failed"; exit 1; fi
    echo "SKIP web: node not found (apt-get install nodejs)"; echo "0 passed, 0 failed"; exit 0
fi
# timeout: the last guard against a hang (the test has its own 600 s watchdog)
exec timeout 900 node tests/web/web_test.mjs --csv build/web_test/web.csv "$@"
