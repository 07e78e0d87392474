//! Writing output: files so that a failure never leaves a half-written file behind, stdout so
//! that a closed pipe ends the program quietly, and the checks every subcommand runs on its
//! output paths before any work.
//!
//! Every error about a file names the flag and the path, and gives the operating system's
//! reason once: `--output ro/a.png: cannot write in folder ro: Permission denied (os error 13)`.

use anyhow::{Result, anyhow, bail};
use std::fs::{File, OpenOptions};
use std::io::{BufWriter, ErrorKind, Write};
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// The exit status when stdout's reader has gone away (`nyquist points | head -3`): 128 + 13
/// (SIGPIPE), the status a shell reports for `seq`, `cat` or `yes` in the same place. Nothing
/// is printed.
pub const BROKEN_PIPE_STATUS: u8 = 141;

/// The temporary files of the writes in progress. A file is created and renamed into place while
/// this lock is held, so the signal handler sees every temporary file that exists, and removes
/// them before the process exits.
static IN_PROGRESS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn in_progress() -> MutexGuard<'static, Vec<PathBuf>> {
    IN_PROGRESS.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Installs the handler of SIGINT and SIGTERM: it removes the temporary files of writes in
/// progress ([`write_atomic`]) and exits with status 128 + the signal's number (130 for SIGINT,
/// 143 for SIGTERM), as a shell reports a process the signal killed. The handler runs on a
/// thread of its own, so no work is interrupted in an unsafe state.
///
/// # Errors
/// If the handler cannot be registered (the operating system refuses).
#[cfg(unix)]
pub fn remove_temporaries_on_signals() -> Result<()> {
    use signal_hook::consts::{SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM])
        .map_err(|e| anyhow!("cannot install the SIGINT/SIGTERM handler: {e}"))?;
    std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                // Held until exit: no new temporary file appears after the removal.
                let files = in_progress();
                for f in files.iter() {
                    let _ = std::fs::remove_file(f);
                }
                std::process::exit(128 + signal);
            }
        })
        .map_err(|e| anyhow!("cannot start the signal thread: {e}"))?;
    Ok(())
}

/// Where there are no POSIX signals (the browser, Windows), there is nothing to install.
///
/// # Errors
/// Never.
#[cfg(not(unix))]
pub fn remove_temporaries_on_signals() -> Result<()> {
    Ok(())
}

/// Whether `e` (or any error it wraps) is a write into a closed pipe.
pub fn is_broken_pipe(e: &anyhow::Error) -> bool {
    io_error(e).is_some_and(|io| io.kind() == ErrorKind::BrokenPipe)
}

/// The first I/O error `e` wraps, if any (the PNG writer reports its stream's failure as
/// `nyquist_film::Error::Io`, whose source is the I/O error).
fn io_error(e: &anyhow::Error) -> Option<&std::io::Error> {
    e.chain().find_map(|c| c.downcast_ref::<std::io::Error>())
}

/// The folder `path` goes into (`.` for a bare file name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// The temporary file beside `path` that [`write_atomic`] writes first.
fn temporary(path: &Path) -> Result<PathBuf> {
    let name = path
        .file_name()
        .ok_or_else(|| anyhow!("--output {}: not a file name", path.display()))?;
    Ok(folder_of(path).join(format!(
        ".{}.tmp-{}",
        name.to_string_lossy(),
        std::process::id()
    )))
}

/// Whether `path` exists and is neither a regular file nor a folder (a device such as
/// `/dev/null` or `/dev/full`, a FIFO): such a target is written in place, never replaced.
fn is_special(path: &Path) -> bool {
    std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir())
}

/// The one-line message for an I/O failure on `path`: the flag, the path and the reason once.
fn io_message(flag: &str, path: &Path, e: &std::io::Error) -> anyhow::Error {
    let dir = folder_of(path);
    if e.kind() == ErrorKind::NotFound && !dir.is_dir() {
        return anyhow!(
            "{flag} {}: folder {} does not exist",
            path.display(),
            dir.display()
        );
    }
    anyhow!("{flag} {}: cannot write: {e}", path.display())
}

/// Checks, before any work, that `flag`'s `path` can take the output: its extension is one of
/// `formats` (lower case, without the dot; empty: any), it names a file, its folder exists, and
/// a file can be created there (a temporary file is created and removed again). Devices and
/// FIFOs (`/dev/null`) are accepted as they are.
pub fn check_output(path: &Path, flag: &str, formats: &[&str]) -> Result<()> {
    if !formats.is_empty() {
        let ext = extension(path);
        if !ext.as_deref().is_some_and(|e| formats.contains(&e)) {
            bail!(
                "{flag} {}: unknown image extension (expected {})",
                path.display(),
                formats
                    .iter()
                    .map(|f| format!(".{f}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            );
        }
    }
    if path.file_name().is_none() {
        bail!("{flag} {}: not a file name", path.display());
    }
    if path.is_dir() {
        bail!("{flag} {}: is a folder", path.display());
    }
    if is_special(path) {
        return Ok(());
    }
    let dir = folder_of(path);
    if !dir.is_dir() {
        if dir.exists() {
            bail!(
                "{flag} {}: {} is not a folder",
                path.display(),
                dir.display()
            );
        }
        bail!(
            "{flag} {}: folder {} does not exist",
            path.display(),
            dir.display()
        );
    }
    let probe = temporary(path)?;
    // Created and removed under the lock of the writes in progress: a signal's handler takes
    // that lock before it exits, so it never exits between the two and leaves the probe behind.
    let _files = in_progress();
    match File::create(&probe) {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(())
        }
        Err(e) => Err(io_message(flag, path, &e)),
    }
}

/// The lower-case extension of `path`, if it has one.
pub fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
}

/// Writes `path` through `write`: the bytes go to a temporary file in the same folder, which is
/// renamed over `path` only when `write` and the flush succeeded. On any error the temporary file
/// is removed and `path` is untouched. A device or FIFO (`/dev/null`, `/dev/full`) is written in
/// place instead of being replaced. Errors name `--output` (callers for other flags replace it).
pub fn write_atomic(path: &Path, write: impl FnOnce(&mut dyn Write) -> Result<()>) -> Result<()> {
    const FLAG: &str = "--output";
    let fail = |e: anyhow::Error| match io_error(&e) {
        Some(io) if io.kind() != ErrorKind::BrokenPipe => io_message(FLAG, path, io),
        _ => e,
    };
    if is_special(path) {
        let file = OpenOptions::new()
            .write(true)
            .open(path)
            .map_err(|e| io_message(FLAG, path, &e))?;
        let mut w = BufWriter::new(file);
        write(&mut w).map_err(fail)?;
        return w.flush().map_err(|e| io_message(FLAG, path, &e));
    }
    let tmp = temporary(path)?;
    let result = (|| -> Result<()> {
        let file = {
            let mut files = in_progress();
            let file = File::create(&tmp).map_err(|e| io_message(FLAG, path, &e))?;
            files.push(tmp.clone());
            file
        };
        let mut w = BufWriter::new(file);
        write(&mut w).map_err(fail)?;
        let file = w
            .into_inner()
            .map_err(|e| io_message(FLAG, path, e.error()))?;
        file.sync_all().map_err(|e| io_message(FLAG, path, &e))?;
        let mut files = in_progress();
        std::fs::rename(&tmp, path).map_err(|e| io_message(FLAG, path, &e))?;
        files.retain(|f| f != &tmp);
        Ok(())
    })();
    if result.is_err() {
        let mut files = in_progress();
        let _ = std::fs::remove_file(&tmp);
        files.retain(|f| f != &tmp);
    }
    result
}

/// Runs `write` on stdout, or on `path` atomically when one is given. A write error on stdout
/// reads `stdout: cannot write: <reason>`; a closed pipe stays recognisable to
/// [`is_broken_pipe`].
pub fn to_stdout_or_file(
    path: Option<&Path>,
    write: impl FnOnce(&mut dyn Write) -> Result<()>,
) -> Result<()> {
    match path {
        Some(p) => write_atomic(p, write),
        None => {
            let stdout = std::io::stdout();
            let mut lock = BufWriter::new(stdout.lock());
            let result = write(&mut lock).and_then(|()| Ok(lock.flush()?));
            result.map_err(|e| match io_error(&e) {
                Some(io) => {
                    let kind = io.kind();
                    anyhow!(std::io::Error::new(
                        kind,
                        format!("stdout: cannot write: {io}")
                    ))
                }
                None => e,
            })
        }
    }
}

/// Prints `text` on stdout as it is (the caller ends it with a newline), with the errors of
/// [`to_stdout_or_file`] instead of `println!`'s panic on a closed pipe.
pub fn print(text: &str) -> Result<()> {
    to_stdout_or_file(None, |w| {
        w.write_all(text.as_bytes())?;
        Ok(())
    })
}

/// One note on stderr, `nyquist: note: <text>`: a flag that changes nothing, a default chosen.
pub fn note(text: &str) {
    eprintln!("nyquist: note: {text}");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn io_messages_name_the_flag_path_and_reason_once() {
        let e = std::io::Error::from(ErrorKind::PermissionDenied);
        let m = io_message("--plot", Path::new("a.png"), &e).to_string();
        assert_eq!(m, format!("--plot a.png: cannot write: {e}"));
        let m = io_message(
            "--output",
            Path::new("no-such-folder-x/a.png"),
            &ErrorKind::NotFound.into(),
        );
        assert_eq!(
            m.to_string(),
            "--output no-such-folder-x/a.png: folder no-such-folder-x does not exist"
        );
    }

    #[test]
    fn broken_pipes_are_found_through_context() {
        let e = anyhow::Error::from(std::io::Error::from(ErrorKind::BrokenPipe)).context("x");
        assert!(is_broken_pipe(&e));
        assert!(!is_broken_pipe(&anyhow!("x")));
    }
}
