//! Figures and pictures written to files: the extension and the folder are checked before any
//! drawing ([`kind_of`]), then the bytes are written atomically ([`crate::output::write_atomic`]).

use anyhow::Result;
use nyquist_lab::plot::{self, Kind};
use std::path::Path;

/// The format `path` asks for by its extension (`.png` or `.svg`); any other extension (also
/// none, as for `/dev/null`: name a link to it), `-` (the commands that draw figures print
/// their report on stdout), a missing folder or a folder in the way is one line naming `flag` (see
/// [`check_output`](crate::output::check_output)). In WebAssembly no figure is drawn: always
/// an error.
///
/// # Errors
/// As above.
pub fn kind_of(path: &Path, flag: &str) -> Result<Kind> {
    if cfg!(target_family = "wasm") {
        anyhow::bail!(
            "{flag} {}: pictures are drawn by the native nyquist command only",
            path.display()
        );
    }
    if crate::output::is_stdout(path) {
        anyhow::bail!(
            "{flag} -: stdout carries the command's report: give {flag} FILE.png|FILE.svg"
        );
    }
    crate::output::check_output(path, flag, &["png", "svg"])?;
    Ok(plot::kind(path))
}

/// Draws `fig` and writes it to `path` atomically, as PNG or SVG by the extension; `flag` names
/// the option in error messages.
///
/// # Errors
/// An extension other than `.png` or `.svg`, a drawing error, or a failed write; the file is
/// then left as it was.
pub fn save<F: plot::Figure>(fig: &F, path: &Path, flag: &str) -> Result<()> {
    let kind = kind_of(path, flag)?;
    let bytes = plot::render(fig, kind)?;
    write_bytes(path, flag, &bytes)
}

/// Writes `bytes` (an encoded picture) to `path` ([`crate::output::write_output`]: atomically,
/// or `-` for stdout); `flag` names the option in error messages.
///
/// # Errors
/// A failed write; the file is then left as it was.
pub fn write_bytes(path: &Path, flag: &str, bytes: &[u8]) -> Result<()> {
    crate::output::write_output(path, flag, |w| {
        w.write_all(bytes)?;
        Ok(())
    })
}
