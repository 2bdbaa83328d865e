#!/usr/bin/env bash
# Installs the Debian packages tumble needs, skipping those already installed.
#   bash tools/install-deps.sh         everything: build and test all of it (tools/run-tests.sh, CI)
#   bash tools/install-deps.sh --cli   only what the tumble program needs with the viewer, tests,
#                                      benchmarks, peers and MPI off (tools/run-demo.sh)
set -euo pipefail

# The REQUIRED find_package calls of the CLI build: glm (top level), toml++ and Boost
# (libs/scenario), CLI11 (apps/cli); OpenMP comes with g++. pkg-config is only asked for by the
# viewer and the peers.
cli_packages=(
    cmake
    ninja-build
    g++
    libglm-dev
    libcli11-dev
    libtomlplusplus-dev
    libboost-dev
)

packages=(
    "${cli_packages[@]}"
    libgtest-dev
    libgmock-dev
    # bench/: Google Benchmark micro benchmarks, and the peer engines of tumble bench --peers
    # (each optional in CMake; installed here so CI builds and runs them)
    libbenchmark-dev
    libbullet-dev
    libode-dev
    libmujoco-dev
    pkg-config
    # the Python module (python/, docs/python.md): pybind11 over Debian's Python with NumPy;
    # pytest runs tests/python, Matplotlib draws the examples' PNG files; pip with setuptools and
    # wheel builds it for `python3 -m pip install --no-build-isolation .`
    pybind11-dev
    python3-dev
    python3-numpy
    python3-pytest
    python3-matplotlib
    python3-pip
    python3-setuptools
    python3-wheel
    # tumble plot and tumble validate --plot draw their PNG files with gnuplot
    gnuplot-nox
    # tumble throw: MPI (mpirun -n P tumble throw; its CLI test runs mpirun); Boost.Math's
    # distributions (libboost-dev) are in cli_packages
    libopenmpi-dev
    openmpi-bin
    # tools/ci-fuzz.sh: clang with libFuzzer and the sanitizer runtimes; llvm-symbolizer
    clang
    libclang-rt-dev
    llvm
    # the viewer (tumble view; -DTUMBLE_BUILD_VIEWER=OFF builds without these): GLFW, Dear ImGui
    # (with its backend sources), libepoxy for GL entry points, stb for PNG files; its capture
    # tests run under Xvfb with Mesa's software renderer (llvmpipe)
    libglfw3-dev
    libimgui-dev
    libepoxy-dev
    libstb-dev
    xvfb
    xauth
    libgl1-mesa-dri
    libglx-mesa0
    # the browser page (tools/build-web.sh, docs/web.md): Debian's emscripten (with its nodejs
    # and node-acorn) compiles the library to WebAssembly; its test (tests/web) drives headless
    # chromium with puppeteer-core, which npm installs from package-lock.json
    emscripten
    chromium
)
# npm for the page's packages: Debian's npm, unless a node with its own npm is installed (a
# NodeSource nodejs provides npm and conflicts with Debian's)
if [[ "${1:-}" != "--cli" ]] && ! command -v npm >/dev/null 2>&1; then
    packages+=(npm)
fi

if [[ "${1:-}" == "--cli" ]]; then
    packages=("${cli_packages[@]}")
elif [[ $# -gt 0 ]]; then
    echo "install-deps: unknown argument $1 (give --cli or nothing)" >&2
    exit 2
fi

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${db:Status-Status}' "$package" 2>/dev/null || true)
    if [[ "$status" != "installed" ]]; then
        missing+=("$package")
    fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
    echo "install-deps: all packages present"
    exit 0
fi

echo "install-deps: installing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
    run_as_root=()
elif command -v sudo >/dev/null 2>&1; then
    run_as_root=(sudo)
else
    echo "install-deps: missing packages (${missing[*]}) and not root; install them or run as root" >&2
    exit 1
fi

export DEBIAN_FRONTEND=noninteractive
"${run_as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
"${run_as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}"
