#!/bin/sh
# Regenerates docs/stability.md: builds the stability suite (and the vct binary its CLI
# cases run) in $BUILD (default build-stability), runs it, and writes the table of
# cases x methods. VCT_STABILITY_SLOW=1 adds the 512^3 grid (about a minute, GBs of RAM on
# llvmpipe). Exit status is the suite's: a failing case still writes the report.
#   scripts/make_stability_doc.sh [BUILD_DIR]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-stability}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
make -C "$build" -j"$(nproc)" vct vct_tests_stability >/dev/null
VCT_STABILITY_SLOW=1 VCT_STABILITY_REPORT="$root/docs/stability.md" "$build/vct_tests_stability"
