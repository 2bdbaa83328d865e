#!/usr/bin/env bash
# ctest's web.page: builds the page, then checks it in headless Chromium against the CLI.
#   bash tests/web/run_web_test.sh CLI
# Exit 77 (skipped) with a message when emcc, Chromium or Node is missing.
set -euo pipefail
cli="$1"
cd "$(dirname "$0")/../.."

chromium="${CHROMIUM:-$(command -v chromium || true)}"
if [[ -z "$chromium" ]]; then
    echo "web.page skipped: chromium is not installed (bash tools/install-deps.sh installs it)"
    exit 77
fi
status=0
bash tools/build-web.sh || status=$?
if [[ $status -eq 77 ]]; then
    echo "web.page skipped: the page cannot be built here (see the line above)"
    exit 77
elif [[ $status -ne 0 ]]; then
    exit "$status"
fi
node tests/web/page_test.mjs build-web/site "$cli" "$chromium"
