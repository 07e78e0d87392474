#!/usr/bin/env bash
# Builds the explorer: the nyquist-web module for wasm32-unknown-unknown (profile `web`: small
# over fast) and the static page, assembled into one folder that any static server can serve.
# Prints that folder's path on its last line. Needs only Rust: the wasm32 target is added with
# rustup when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
    echo "adding the wasm32-unknown-unknown target (rustup target add)" >&2
    rustup target add wasm32-unknown-unknown >&2
fi
# lazy-tables: the samplers' speed tables (2.1 MiB) and Sobol matrices are built at first use in
# the browser instead of shipped in the module. small-code: the core's and the film's hot paths
# are not force-inlined (about 90 KB less after wasm-opt).
cargo build --quiet -p nyquist-web --profile web --target wasm32-unknown-unknown \
    --features nyquist/lazy-tables,nyquist-film/small-code >&2
target_dir=$(cargo metadata --format-version 1 --no-deps |
    sed -n 's/.*"target_directory":"\([^"]*\)".*/\1/p')
site="$target_dir/web-site"
rm -rf "$site"
mkdir -p "$site"
cp web/www/* "$site/"
module="$target_dir/wasm32-unknown-unknown/web/nyquist_web.wasm"
# Binaryen's optimiser, where it is installed (Debian: binaryen), takes about a seventh off; the
# page works the same without it.
if command -v wasm-opt >/dev/null; then
    wasm-opt -Oz --enable-bulk-memory --enable-sign-ext --enable-mutable-globals \
        --enable-nontrapping-float-to-int "$module" -o "$site/nyquist_web.wasm"
    echo "nyquist_web.wasm: $(wc -c <"$module") bytes, $(wc -c <"$site/nyquist_web.wasm") after wasm-opt -Oz" >&2
else
    cp "$module" "$site/"
    echo "nyquist_web.wasm: $(wc -c <"$site/nyquist_web.wasm") bytes (wasm-opt not found: not optimised further)" >&2
fi
echo "$site"
