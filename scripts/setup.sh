#!/usr/bin/env bash
# Installs what emit needs (Debian packages, and three.js from npm for the live viewer's 3D view) and
# builds it in build/ (Release).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEMIT_BUILD_TESTS=OFF >/dev/null
cmake --build build -j"$(nproc)" --target emit emit_python
echo "setup: built build/emit and the Python module in build/python (PYTHONPATH=build/python python3 -c 'import emit')"
