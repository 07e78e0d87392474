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

/// Refuses: no picture is drawn in a WebAssembly build.
///
/// # Errors
/// Always.
pub fn kind_of(path: &Path, flag: &str) -> Result<Kind> {
    bail!(
        "{flag} {}: pictures are drawn by the native nyquist command only",
        path.display()
    )
}

/// Refuses, as [`kind_of`].
///
/// # Errors
/// Always.
pub fn save<F>(_figure: &F, path: &Path, flag: &str) -> Result<()> {
    kind_of(path, flag).map(|_| ())
}
