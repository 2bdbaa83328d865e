#!/usr/bin/env bash
# Builds the browser page (tools/build-web.sh) and serves build-web/site/ on
# http://localhost:8000 with Python's http.server (PORT=8080 for another port); Ctrl-C stops it.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/build-web.sh
port="${PORT:-8000}"
echo "tumble in the browser: open http://localhost:${port}/"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory build-web/site
