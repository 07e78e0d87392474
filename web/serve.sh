#!/usr/bin/env bash
# Builds the explorer (web/build.sh) and serves it with `nyquist web` on 127.0.0.1 (port 8000
# unless --port says otherwise; --port 0 picks a free one). Extra arguments go to `nyquist web`.
set -euo pipefail
cd "$(dirname "$0")/.."
site=$(bash web/build.sh)
cargo build --quiet --release -p nyquist-cli
exec cargo run --quiet --release -p nyquist-cli -- web --root "$site" "$@"
