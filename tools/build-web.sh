#!/usr/bin/env bash
# Builds the browser page (docs/web.md) into build-web/site/: the library, the scenario layer and
# the Embind glue compiled by Debian's emscripten, the page's files, three.js from node_modules
# (npm ci from package-lock.json) and every scenario file bundled as scenarios.js.
#   bash tools/build-web.sh        TUMBLE_WEB_JOBS (default 2) compile jobs
# Exit 77 (ctest's skip code for tests/web) when emcc or npm is not installed.
set -euo pipefail
cd "$(dirname "$0")/.."

for tool in emcmake emcc npm node; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "build-web: $tool is not installed (bash tools/install-deps.sh installs emscripten" \
             "and nodejs); the page is not built" >&2
        exit 77
    fi
done

# emcc's JavaScript optimiser needs Debian's node-acorn, in /usr/share/nodejs: Debian's node
# searches there, a node from elsewhere (NodeSource's) only when told
export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"

# npm packages as the lock file pins them; again only when the lock file changed
if [[ ! -f node_modules/.package-lock.json || package-lock.json -nt node_modules/.package-lock.json ]]
then
    npm ci --no-audit --no-fund
fi

emcmake cmake -S . -B build-web -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DTUMBLE_BUILD_WEB=ON -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_CLI=OFF \
    -DTUMBLE_BUILD_VIEWER=OFF -DTUMBLE_BUILD_PEERS=OFF -DTUMBLE_BUILD_BENCH=OFF \
    -DTUMBLE_BUILD_MPI=OFF -DTUMBLE_BUILD_PYTHON=OFF >/dev/null
cmake --build build-web --target tumble_web -j "${TUMBLE_WEB_JOBS:-2}"

site=build-web/site
mkdir -p "$site/vendor"
cp apps/web/site/index.html apps/web/site/style.css apps/web/site/*.js "$site/"
cp node_modules/three/build/three.module.min.js "$site/vendor/three.module.min.js"
cp node_modules/three/examples/jsm/controls/OrbitControls.js "$site/vendor/OrbitControls.js"
node apps/web/bundle-scenarios.mjs scenarios "$site/scenarios.js"
echo "build-web: page in $site/"
