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

/// The longest file name most file systems take (`NAME_MAX`), in bytes.
const NAME_MAX: usize = 255;

/// FNV-1a, 64 bits: the tag that keeps a shortened temporary name unique.
fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// The hidden temporary file beside `file` that a write goes to first: `.NAME.tmp-PID`. A
/// name too long for that within [`NAME_MAX`] bytes is cut and tagged with a hash of the whole
/// name: `.NAM~0123456789abcdef.tmp-PID`.
fn temporary(file: &Path) -> Result<PathBuf> {
    let name = file
        .file_name()
        .ok_or_else(|| anyhow!("--output {}: not a file name", file.display()))?
        .to_string_lossy();
    let suffix = format!(".tmp-{}", std::process::id());
    let stem = if 1 + name.len() + suffix.len() <= NAME_MAX {
        name.into_owned()
    } else {
        let tag = format!("~{:016x}", fnv1a64(name.as_bytes()));
        let mut keep = NAME_MAX - 1 - suffix.len() - tag.len();
        while !name.is_char_boundary(keep) {
            keep -= 1;
        }
        format!("{}{tag}", &name[..keep])
    };
    Ok(folder_of(file).join(format!(".{stem}{suffix}")))
}

/// Whether `path` names standard output (`-`).
pub fn is_stdout(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// Where an output goes, once `-` and symbolic links are resolved ([`target`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Target {
    /// `-`: standard output.
    Stdout,
    /// Opened by its name and written in place (appended to), never replaced: a device
    /// (`/dev/null`), a FIFO or socket, or a link to an open descriptor (`/dev/stdout`,
    /// `/dev/fd/N`, `/proc/self/fd/N`), which may also be a file the shell opened.
    InPlace,
    /// A regular file, existing or not: the end of any chain of symbolic links from the path,
    /// replaced through a temporary file in its own folder.
    File(PathBuf),
}

/// The most symbolic links followed from one path (Linux's own limit).
const MAX_LINKS: usize = 40;

/// Whether `path` is (a link under) the descriptor folders, whose links name open files
/// rather than paths (`pipe:[1234]`, or a file a shell opened with `>>`).
fn is_descriptor_link(path: &Path) -> bool {
    path.starts_with("/proc") || path.starts_with("/dev/fd")
}

/// Where `flag`'s `path` is written: see [`Target`]. A symbolic link is followed to its end,
/// a relative link read from the link's folder; a dangling link's target is the file created.
///
/// # Errors
/// A folder, a link that cannot be read, or more than 40 links in a chain; one line naming
/// `flag` and `path`.
pub fn target(path: &Path, flag: &str) -> Result<Target> {
    if is_stdout(path) {
        return Ok(Target::Stdout);
    }
    if let Ok(m) = std::fs::metadata(path) {
        if m.is_dir() {
            bail!("{flag} {}: is a folder", path.display());
        }
        if !m.is_file() {
            return Ok(Target::InPlace);
        }
    }
    let mut file = path.to_path_buf();
    for _ in 0..=MAX_LINKS {
        if is_descriptor_link(&file) {
            return Ok(Target::InPlace);
        }
        match std::fs::symlink_metadata(&file) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&file).map_err(|e| {
                    anyhow!(
                        "{flag} {}: cannot read the link {}: {e}",
                        path.display(),
                        file.display()
                    )
                })?;
                file = match file.parent() {
                    Some(dir) if !dir.as_os_str().is_empty() => dir.join(to),
                    _ => to,
                };
            }
            _ => {
                if file.file_name().is_none() {
                    bail!("{flag} {}: the link names no file", path.display());
                }
                return Ok(Target::File(file));
            }
        }
    }
    bail!(
        "{flag} {}: more than {MAX_LINKS} symbolic links in a chain (or a loop)",
        path.display()
    )
}

/// The one-line message for an I/O failure on `path` (written as `file`, the end of its
/// links): the flag, the path and the reason once.
fn io_message(flag: &str, path: &Path, file: &Path, e: &std::io::Error) -> anyhow::Error {
    let dir = folder_of(file);
    if e.kind() == ErrorKind::NotFound && !dir.is_dir() {
        return anyhow!(
            "{flag} {}: folder {} does not exist",
            path.display(),
            dir.display()
        );
    }
    anyhow!("{flag} {}: cannot write: {e}", path.display())
}

/// Refuses to replace the existing regular file `file` (`flag`'s `path`) unless the caller
/// could have written it in place (`faccessat(W_OK)` with the effective ids: its permission
/// bits, ACLs, a read-only file system). Replacing it needs only the folder's permission, which
/// would let anyone with a writable folder replace another user's read-only file.
#[cfg(unix)]
fn check_writable(flag: &str, path: &Path, file: &Path) -> Result<()> {
    use rustix::fs::{Access, AtFlags, CWD, accessat};
    accessat(CWD, file, Access::WRITE_OK, AtFlags::EACCESS).map_err(|e| {
        anyhow!(
            "{flag} {}: the existing file cannot be written by this user ({}); not replaced",
            path.display(),
            std::io::Error::from(e)
        )
    })
}

#[cfg(not(unix))]
fn check_writable(_: &str, _: &Path, _: &Path) -> Result<()> {
    Ok(())
}

/// Gives `new` (the temporary file about to replace `flag`'s `path`) the existing file's owner,
/// group and permission bits. The owner and group are changed only where they differ, and a
/// change the process may not make refuses the replacement: a file must not change hands by
/// being rewritten.
#[cfg(unix)]
fn adopt(flag: &str, path: &Path, new: &File, old: &std::fs::Metadata) -> Result<()> {
    use std::os::unix::fs::{MetadataExt, PermissionsExt};
    let mine = new.metadata()?;
    if (mine.uid(), mine.gid()) != (old.uid(), old.gid()) {
        std::os::unix::fs::fchown(new, Some(old.uid()), Some(old.gid())).map_err(|e| {
            anyhow!(
                "{flag} {}: belongs to user {} and group {}, which this process cannot give the \
                 new file ({e}); not replaced",
                path.display(),
                old.uid(),
                old.gid()
            )
        })?;
    }
    // After the owner: changing it clears the set-id bits.
    new.set_permissions(std::fs::Permissions::from_mode(old.mode() & 0o7777))
        .map_err(|e| io_message(flag, path, path, &e))
}

#[cfg(not(unix))]
fn adopt(flag: &str, path: &Path, new: &File, old: &std::fs::Metadata) -> Result<()> {
    new.set_permissions(old.permissions())
        .map_err(|e| io_message(flag, path, path, &e))
}

/// The metadata of the regular file `file` if it exists (`None` if not); a folder is an error.
fn existing(flag: &str, path: &Path, file: &Path) -> Result<Option<std::fs::Metadata>> {
    match std::fs::metadata(file) {
        Ok(m) if m.is_dir() => bail!("{flag} {}: is a folder", path.display()),
        Ok(m) => Ok(Some(m)),
        Err(e) if e.kind() == ErrorKind::NotFound => Ok(None),
        Err(e) => Err(io_message(flag, path, file, &e)),
    }
}

/// Creates the temporary file `tmp` anew (never through a link or an existing file: a stale one
/// of an earlier process with the same id is removed first) and registers it for removal on a
/// signal. The caller holds the lock of the writes in progress.
fn create_temporary(files: &mut Vec<PathBuf>, tmp: &Path) -> std::io::Result<File> {
    let create = || OpenOptions::new().write(true).create_new(true).open(tmp);
    let file = match create() {
        Err(e) if e.kind() == ErrorKind::AlreadyExists => {
            std::fs::remove_file(tmp)?;
            create()?
        }
        r => r?,
    };
    files.push(tmp.to_path_buf());
    Ok(file)
}

/// The format `flag`'s `path` is written in, one of `formats` (lower case, without the dot):
/// `given` (the value of `format_flag`, e.g. `--format`) or the path's extension, which must
/// agree when both name one. Standard output (`-`) and a device or FIFO without an extension
/// (`/dev/null`) take the one format of a flag that has only one; otherwise they need
/// `format_flag`, and where the command has none (`format_flag` is `None`) they are refused.
/// A file name without a known extension needs `format_flag` too.
///
/// # Errors
/// One line naming `flag`, the path and what would make it work.
pub fn choose_format(
    path: &Path,
    flag: &str,
    formats: &[&'static str],
    given: Option<&'static str>,
    format_flag: Option<&str>,
) -> Result<&'static str> {
    let ext = if is_stdout(path) {
        None
    } else {
        extension(path)
    };
    let named = ext
        .as_deref()
        .and_then(|e| formats.iter().copied().find(|f| *f == e));
    let list = || {
        formats
            .iter()
            .map(|f| format!(".{f}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    match (named, given) {
        (Some(e), Some(g)) if e != g => {
            let ff = format_flag.unwrap_or("--format");
            bail!(
                "{flag} {}: .{e} names {e} output but {ff} is {g}: give {ff} {e} or another name",
                path.display()
            )
        }
        (Some(e), _) => Ok(e),
        (None, Some(g)) => Ok(g),
        (None, None) => {
            let special = std::fs::metadata(path).is_ok_and(|m| !m.is_file());
            match format_flag {
                _ if formats.len() == 1 && (is_stdout(path) || special) => Ok(formats[0]),
                Some(ff) if is_stdout(path) || special || ext.is_none() => bail!(
                    "{flag} {}: no extension to tell the format: give {ff} {}",
                    path.display(),
                    formats.join("|")
                ),
                Some(ff) => bail!(
                    "{flag} {}: unknown image extension (expected {}, or give {ff})",
                    path.display(),
                    list()
                ),
                None if is_stdout(path) || special => bail!(
                    "{flag} {}: no extension to tell the format ({}): give a file name with \
                     one (a symbolic link to the device works)",
                    path.display(),
                    list()
                ),
                None => bail!(
                    "{flag} {}: unknown image extension (expected {})",
                    path.display(),
                    list()
                ),
            }
        }
    }
}

/// Checks, before any work, that `flag`'s `path` can take the output: its extension is one of
/// `formats` (lower case, without the dot; empty: any; see [`choose_format`], which callers with
/// a `--format` flag use instead), it names a file, its folder exists, and a file can be
/// created there (a temporary file is created and removed again). An existing file must be one
/// the caller could write, and its owner one the new file can keep. Standard output (`-`),
/// devices and FIFOs (`/dev/null`) are accepted as they are.
pub fn check_output(path: &Path, flag: &str, formats: &[&'static str]) -> Result<()> {
    if !formats.is_empty() {
        choose_format(path, flag, formats, None, None)?;
    }
    check_target(path, flag)
}

/// [`check_output`] without the extension.
///
/// # Errors
/// As [`check_output`].
pub fn check_target(path: &Path, flag: &str) -> Result<()> {
    if is_stdout(path) {
        return Ok(());
    }
    if path.file_name().is_none() {
        bail!("{flag} {}: not a file name", path.display());
    }
    let file = match target(path, flag)? {
        Target::Stdout | Target::InPlace => return Ok(()),
        Target::File(file) => file,
    };
    let dir = folder_of(&file);
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
    let old = existing(flag, path, &file)?;
    if old.is_some() {
        check_writable(flag, path, &file)?;
    }
    let probe = temporary(&file)?;
    // Created and removed under the lock of the writes in progress: a signal's handler takes
    // that lock before it exits, so it never exits between the two and leaves the probe behind.
    let mut files = in_progress();
    let created =
        create_temporary(&mut files, &probe).map_err(|e| io_message(flag, path, &file, &e));
    let result = created.and_then(|f| match &old {
        Some(m) => adopt(flag, path, &f, m),
        None => Ok(()),
    });
    let _ = std::fs::remove_file(&probe);
    files.retain(|f| f != &probe);
    result
}

/// The lower-case extension of `path`, if it has one.
pub fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
}

/// Writes `path` through `write`, errors naming `--output` ([`write_output`]).
pub fn write_atomic(path: &Path, write: impl FnOnce(&mut dyn Write) -> Result<()>) -> Result<()> {
    write_output(path, "--output", write)
}

/// Writes `flag`'s `path` through `write`, by its [`Target`]:
/// - `-`: standard output;
/// - a device, FIFO or descriptor link (`/dev/null`, `/dev/stdout`): opened by name and
///   written in place;
/// - a file, reached through any symbolic links: the bytes go to a temporary file in the
///   file's own folder, which is given the existing file's owner, group and permission bits and
///   renamed over it only when `write` and the flush succeeded (the links stay links). On any
///   error the temporary file is removed and the file is untouched. An existing file the caller
///   could not have written in place, or whose owner the process cannot keep, is refused.
///
/// Errors are one line naming `flag`, the path as given and the reason.
pub fn write_output(
    path: &Path,
    flag: &str,
    write: impl FnOnce(&mut dyn Write) -> Result<()>,
) -> Result<()> {
    let file = match target(path, flag)? {
        Target::Stdout => return write_stdout(write),
        Target::InPlace => {
            let fail = |e: anyhow::Error| match io_error(&e) {
                Some(io) if io.kind() != ErrorKind::BrokenPipe => io_message(flag, path, path, io),
                _ => e,
            };
            let file = OpenOptions::new()
                .append(true)
                .open(path)
                .map_err(|e| io_message(flag, path, path, &e))?;
            let mut w = BufWriter::new(file);
            write(&mut w).map_err(fail)?;
            return w.flush().map_err(|e| fail(e.into()));
        }
        Target::File(file) => file,
    };
    let fail = |e: anyhow::Error| match io_error(&e) {
        Some(io) if io.kind() != ErrorKind::BrokenPipe => io_message(flag, path, &file, io),
        _ => e,
    };
    let old = existing(flag, path, &file)?;
    if old.is_some() {
        check_writable(flag, path, &file)?;
    }
    let tmp = temporary(&file)?;
    let result = (|| -> Result<()> {
        let f = create_temporary(&mut in_progress(), &tmp)
            .map_err(|e| io_message(flag, path, &file, &e))?;
        if let Some(m) = &old {
            adopt(flag, path, &f, m)?;
        }
        let mut w = BufWriter::new(f);
        write(&mut w).map_err(fail)?;
        let f = w
            .into_inner()
            .map_err(|e| io_message(flag, path, &file, e.error()))?;
        f.sync_all()
            .map_err(|e| io_message(flag, path, &file, &e))?;
        let mut files = in_progress();
        std::fs::rename(&tmp, &file).map_err(|e| io_message(flag, path, &file, &e))?;
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

/// Runs `write` on stdout. A write error reads `stdout: cannot write: <reason>`; a closed pipe
/// stays recognisable to [`is_broken_pipe`].
fn write_stdout(write: impl FnOnce(&mut dyn Write) -> Result<()>) -> Result<()> {
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

/// Runs `write` on stdout, or on `path` ([`write_atomic`]; `-` is stdout too) when one is
/// given. A write error on stdout reads `stdout: cannot write: <reason>`; a closed pipe stays
/// recognisable to [`is_broken_pipe`].
pub fn to_stdout_or_file(
    path: Option<&Path>,
    write: impl FnOnce(&mut dyn Write) -> Result<()>,
) -> Result<()> {
    match path {
        Some(p) => write_atomic(p, write),
        None => write_stdout(write),
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

/// One warning on stderr, `nyquist: warning: <text>`: long work about to start, with its
/// estimate and how to make it smaller.
pub fn warn(text: &str) {
    eprintln!("nyquist: warning: {text}");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn io_messages_name_the_flag_path_and_reason_once() {
        let e = std::io::Error::from(ErrorKind::PermissionDenied);
        let m = io_message("--plot", Path::new("a.png"), Path::new("a.png"), &e).to_string();
        assert_eq!(m, format!("--plot a.png: cannot write: {e}"));
        let m = io_message(
            "--output",
            Path::new("no-such-folder-x/a.png"),
            Path::new("no-such-folder-x/a.png"),
            &ErrorKind::NotFound.into(),
        );
        assert_eq!(
            m.to_string(),
            "--output no-such-folder-x/a.png: folder no-such-folder-x does not exist"
        );
    }

    #[test]
    fn temporary_names_fit_name_max_and_stay_distinct() {
        let short = temporary(Path::new("dir/a.png")).unwrap();
        assert_eq!(
            short,
            Path::new(&format!("dir/.a.png.tmp-{}", std::process::id()))
        );
        let mut seen = Vec::new();
        for name in [
            format!("{}.png", "a".repeat(247)),
            format!("{}.png", "a".repeat(251)),
            format!("{}.exr", "a".repeat(251)),
            format!("{}.png", "é".repeat(125)),
        ] {
            let t = temporary(&Path::new("d").join(&name)).unwrap();
            let t = t.file_name().unwrap().to_str().unwrap().to_owned();
            assert!(t.len() <= NAME_MAX, "{} bytes", t.len());
            assert!(t.starts_with(".a") || t.starts_with(".é"), "{t}");
            assert!(t.ends_with(&format!(".tmp-{}", std::process::id())));
            assert!(!seen.contains(&t), "{t} twice");
            seen.push(t);
        }
    }

    #[test]
    fn formats_come_from_the_flag_or_the_extension() {
        let f = &["png", "exr", "pfm"][..];
        let pick =
            |p: &str, given| choose_format(Path::new(p), "--output", f, given, Some("--format"));
        assert_eq!(pick("a.PNG", None).unwrap(), "png");
        assert_eq!(pick("a.exr", Some("exr")).unwrap(), "exr");
        assert_eq!(pick("-", Some("pfm")).unwrap(), "pfm");
        assert_eq!(pick("a.dat", Some("pfm")).unwrap(), "pfm");
        for (p, given, message) in [
            (
                "a.png",
                Some("exr"),
                "--output a.png: .png names png output but --format is exr: give --format png or another name",
            ),
            (
                "-",
                None,
                "--output -: no extension to tell the format: give --format png|exr|pfm",
            ),
            (
                "a",
                None,
                "--output a: no extension to tell the format: give --format png|exr|pfm",
            ),
            (
                "a.tif",
                None,
                "--output a.tif: unknown image extension (expected .png, .exr, .pfm, or give --format)",
            ),
        ] {
            assert_eq!(pick(p, given).unwrap_err().to_string(), message);
        }
        // One format: stdout and devices take it; a file still needs its extension.
        let png = |p: &str| choose_format(Path::new(p), "--error", &["png"], None, None);
        assert_eq!(png("-").unwrap(), "png");
        assert_eq!(png("/dev/null").unwrap(), "png");
        assert_eq!(
            png("e.tif").unwrap_err().to_string(),
            "--error e.tif: unknown image extension (expected .png)"
        );
    }

    #[test]
    fn targets_resolve_links_and_devices() {
        assert_eq!(target(Path::new("-"), "--output").unwrap(), Target::Stdout);
        assert_eq!(
            target(Path::new("/dev/null"), "--output").unwrap(),
            Target::InPlace
        );
        assert_eq!(
            target(Path::new("/dev/stdout"), "--output").unwrap(),
            Target::InPlace
        );
        assert_eq!(
            target(Path::new("no-such-file.png"), "--output").unwrap(),
            Target::File("no-such-file.png".into())
        );
        assert_eq!(
            target(Path::new("/"), "--plot").unwrap_err().to_string(),
            "--plot /: is a folder"
        );
    }

    #[test]
    fn broken_pipes_are_found_through_context() {
        let e = anyhow::Error::from(std::io::Error::from(ErrorKind::BrokenPipe)).context("x");
        assert!(is_broken_pipe(&e));
        assert!(!is_broken_pipe(&anyhow!("x")));
    }
}
