#!/usr/bin/env bash
# Installs emit's build and test dependencies from Debian's packages, and three.js from npm for the
# live viewer's 3D view (viewer/package.json, pinned by viewer/package-lock.json: `npm ci` in
# viewer/, which CMake embeds into emit). Idempotent: it installs only what is missing, and does
# nothing (not even apt-get update or npm) when all is there.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  g++ cmake make pkg-config             # toolchain
  ccache                                # compiles reused across clones (CMakeLists.txt)
  libgmsh-dev                           # meshing (Gmsh's C++ API)
  libeigen3-dev                         # dense and sparse linear algebra
  libcli11-dev nlohmann-json3-dev       # command line, JSON
  libpng-dev                            # images
  libfreetype-dev fonts-dejavu-core     # their labels in a real font (DejaVu Sans)
  libceres-dev                          # nonlinear least squares (calibration)
  libsuitesparse-dev                    # CHOLMOD: the Jacobian's supernodal Cholesky
  libopenblas-dev                       # BLAS for the per-frame products
  libgtest-dev libbenchmark-dev         # tests, benchmarks
  zlib1g-dev                            # zlib's crc32: the tests' independent check of the packet CRC
  clang libclang-rt-14-dev              # libFuzzer (clang++ -fsanitize=fuzzer) for the decoder's fuzz test
  clang-format clang-tidy               # scripts/lint.sh: formatting and static analysis
  gcovr                                 # line coverage (scripts/coverage.sh)
  libboost-dev                          # the serial port and the live viewer's server (Boost.Asio, Beast)
  chromium                              # the live viewer's browser test (headless)
  cyclonedds-dev cyclonedds-tools       # DDS as ROS 2 speaks it (`emit live --dds`), idlc for its types
  pybind11-dev python3-dev python3-numpy  # the Python module (python/), against Debian's python3
  python3-pytest python3-matplotlib     # its tests, and examples/python/quickstart.py's picture
  dpkg-dev file lintian help2man        # the Debian package (scripts/package.sh): dpkg-shlibdeps, its
                                        # check, the manual page from the commands' help
)
# node and npm drive the browser test (playwright-core); any install of them will do.
command -v node >/dev/null || packages+=(nodejs)
command -v npm >/dev/null || packages+=(npm)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo=sudo
  fi
  echo "install-deps: installing ${missing[*]}"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# three.js, as the user running this (viewer/node_modules is the clone's, not the system's); only
# when viewer/node_modules does not already hold the pinned version.
pinned=$(node -p "require('./viewer/package-lock.json').packages['node_modules/three'].version")
installed=$(node -p "try { require('./viewer/node_modules/three/package.json').version } catch { '' }")
if [ "$installed" != "$pinned" ]; then
  echo "install-deps: installing three.js $pinned for the live viewer (npm ci in viewer/)"
  (cd viewer && npm ci --no-audit --no-fund)
fi
