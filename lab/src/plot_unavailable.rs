//! `plot` in a WebAssembly build: plotters needs the browser's canvas there (through
//! wasm-bindgen), which the browser explorer does not link, so `--plot` and `--spectrum` are
//! refused with one line; the explorer draws its own plots from the same numbers.

use anyhow::{Result, bail};
use std::path::Path;

/// A picture's format, chosen by the file name's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A PNG image.
    Png,
    /// An SVG document.
    Svg,
}

/// What can be drawn (nothing, here).
pub trait Figure {}

/// The format `path` names by its extension, as in native builds.
pub fn kind(path: &Path) -> Kind {
    let svg = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    if svg { Kind::Svg } else { Kind::Png }
}

/// Refuses: no picture is drawn in a WebAssembly build.
///
/// # Errors
/// Always.
pub fn render<F>(_figure: &F, _kind: Kind) -> Result<Vec<u8>> {
    bail!("pictures are drawn by the native nyquist command only")
}
