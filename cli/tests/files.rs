//! Output files as users expect them: a symbolic link is written through to its target, an
//! existing file keeps its owner, group and permission bits (or is refused when the caller
//! could not have written it in place), long names work, `-` is stdout, devices and FIFOs are
//! written in place by name; and the reference cache creates nothing under a missing home and
//! says once what happened to it.

mod common;

use common::{assert_one_line_error, files, nyquist, stdout, temp_dir};
use std::io::Read;
use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// A quick 16 × 16 render: `render --size 16x16 --spp 1` with `more` flags.
fn render(more: &[&str]) -> Output {
    let mut args = vec!["render", "--size", "16x16", "--spp", "1"];
    args.extend_from_slice(more);
    nyquist(&args)
}

fn ok(o: &Output) {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

fn is_pfm_16(bytes: &[u8]) -> bool {
    bytes.starts_with(b"PF\n16 16\n-1.0\n") && bytes.len() == 14 + 16 * 16 * 12
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The user and group ids this test runs as (those of a file it creates).
fn my_ids(dir: &Path) -> (u32, u32) {
    let probe = dir.join("ids-probe");
    std::fs::write(&probe, b"").unwrap();
    let m = std::fs::metadata(&probe).unwrap();
    std::fs::remove_file(&probe).unwrap();
    (m.uid(), m.gid())
}

const NOBODY: u32 = 65534;

/// Runs nyquist as user and group 65534 (`nobody`) through `setpriv`, when this test runs as
/// root and `setpriv` exists; `None` otherwise.
fn nyquist_as_nobody(dir: &Path, args: &[&str]) -> Option<Output> {
    if my_ids(dir).0 != 0 {
        return None;
    }
    let o = Command::new("setpriv")
        .args([
            "--reuid=65534",
            "--regid=65534",
            "--clear-groups",
            env!("CARGO_BIN_EXE_nyquist"),
        ])
        .args(args)
        .output()
        .ok()?;
    Some(o)
}

#[test]
fn a_symbolic_link_is_written_through_to_its_target() {
    let dir = temp_dir("files-link");
    let elsewhere = temp_dir("files-link-target");
    let real = dir.join("real.pfm");
    std::fs::write(&real, b"old").unwrap();
    // A relative link, and a chain: an absolute link in another folder to the relative one.
    std::os::unix::fs::symlink("real.pfm", dir.join("link.pfm")).unwrap();
    let chain = elsewhere.join("chain.pfm");
    std::os::unix::fs::symlink(dir.join("link.pfm"), &chain).unwrap();
    for (path, name) in [(dir.join("link.pfm"), "link"), (chain.clone(), "chain")] {
        std::fs::write(&real, b"old").unwrap();
        ok(&render(&["-o", s(&path)]));
        assert!(
            std::fs::symlink_metadata(&path)
                .unwrap()
                .file_type()
                .is_symlink(),
            "{name}: the link was replaced"
        );
        assert!(is_pfm_16(&std::fs::read(&real).unwrap()), "{name}");
    }
    assert_eq!(files(&dir), ["link.pfm", "real.pfm"]);
    assert_eq!(
        files(&elsewhere),
        ["chain.pfm"],
        "a temporary file was left"
    );
    assert_eq!(
        std::fs::read_link(dir.join("link.pfm")).unwrap(),
        Path::new("real.pfm")
    );

    // A dangling link: its target is created, in the target's folder.
    std::fs::create_dir(dir.join("sub")).unwrap();
    let dangling = elsewhere.join("new.pfm");
    std::os::unix::fs::symlink(dir.join("sub/made.pfm"), &dangling).unwrap();
    ok(&render(&["-o", s(&dangling)]));
    assert!(is_pfm_16(&std::fs::read(dir.join("sub/made.pfm")).unwrap()));
    assert!(
        std::fs::symlink_metadata(&dangling)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    // Its target's folder missing: one line naming the folder, nothing created.
    let nowhere = elsewhere.join("nowhere.pfm");
    std::os::unix::fs::symlink(dir.join("missing/x.pfm"), &nowhere).unwrap();
    let o = render(&["-o", s(&nowhere)]);
    assert_one_line_error(
        &o,
        &format!("folder {} does not exist", dir.join("missing").display()),
    );
    // A loop: one line.
    std::os::unix::fs::symlink("loop-b.pfm", elsewhere.join("loop-a.pfm")).unwrap();
    std::os::unix::fs::symlink("loop-a.pfm", elsewhere.join("loop-b.pfm")).unwrap();
    let o = render(&["-o", s(&elsewhere.join("loop-a.pfm"))]);
    assert_one_line_error(&o, "symbolic links");
}

#[test]
fn an_existing_files_permission_bits_are_kept() {
    let dir = temp_dir("files-mode");
    let root = my_ids(&dir).0 == 0;
    for mode in [0o640, 0o600, 0o444, 0o755] {
        let p = dir.join(format!("m{mode:o}.pfm"));
        std::fs::write(&p, b"old").unwrap();
        std::fs::set_permissions(&p, std::fs::Permissions::from_mode(mode)).unwrap();
        let o = render(&["-o", s(&p)]);
        if mode & 0o200 == 0 && !root {
            // Not writable by its owner, who is not root: refused, untouched.
            assert_one_line_error(&o, "cannot be written by this user");
            assert_eq!(std::fs::read(&p).unwrap(), b"old");
        } else {
            ok(&o);
            assert!(is_pfm_16(&std::fs::read(&p).unwrap()), "{mode:o}");
        }
        let kept = std::fs::metadata(&p).unwrap().mode() & 0o7777;
        assert_eq!(kept, mode, "mode {mode:o} became {kept:o}");
    }
    // Through a link, the target's bits.
    let target = dir.join("m640.pfm");
    std::os::unix::fs::symlink(&target, dir.join("via.pfm")).unwrap();
    ok(&render(&["-o", s(&dir.join("via.pfm"))]));
    assert_eq!(std::fs::metadata(&target).unwrap().mode() & 0o7777, 0o640);
    // A new file gets the usual mode (0666 less the umask), not a copied one.
    let fresh = dir.join("fresh.pfm");
    ok(&render(&["-o", s(&fresh)]));
    assert_eq!(std::fs::metadata(&fresh).unwrap().mode() & 0o111, 0);
}

/// Root replacing another user's file keeps its owner and group.
#[test]
fn root_keeps_the_owner_of_a_file_it_replaces() {
    let dir = temp_dir("files-owner-root");
    if my_ids(&dir).0 != 0 {
        eprintln!("not root: skipped (changing a file's owner needs root)");
        return;
    }
    let p = dir.join("theirs.pfm");
    std::fs::write(&p, b"old").unwrap();
    std::os::unix::fs::chown(&p, Some(NOBODY), Some(NOBODY)).unwrap();
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o640)).unwrap();
    ok(&render(&["-o", s(&p)]));
    let m = std::fs::metadata(&p).unwrap();
    assert_eq!(
        (m.uid(), m.gid(), m.mode() & 0o7777),
        (NOBODY, NOBODY, 0o640)
    );
    assert!(is_pfm_16(&std::fs::read(&p).unwrap()));
}

/// In a world-writable folder, `nobody` may not replace root's read-only file (it could not
/// have written it in place), nor root's world-writable file (the new file could not keep
/// root as its owner); its own files it replaces.
#[test]
fn another_users_file_is_refused_where_it_could_not_be_written_or_kept() {
    let dir = temp_dir("files-owner");
    std::fs::set_permissions(&*dir, std::fs::Permissions::from_mode(0o777)).unwrap();
    let read_only = dir.join("root-ro.pfm");
    let writable = dir.join("root-rw.pfm");
    for (p, mode) in [(&read_only, 0o444), (&writable, 0o666)] {
        std::fs::write(p, b"root's").unwrap();
        std::fs::set_permissions(p, std::fs::Permissions::from_mode(mode)).unwrap();
    }
    let args = |p: &Path| -> Vec<String> {
        ["render", "--size", "8x8", "--spp", "1", "-o", s(p)]
            .map(str::to_owned)
            .to_vec()
    };
    let run = |p: &Path| {
        let a = args(p);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        nyquist_as_nobody(&dir, &a)
    };
    let Some(o) = run(&read_only) else {
        eprintln!("not root or no setpriv: skipped (the refusal is also unit-tested)");
        return;
    };
    assert_one_line_error(
        &o,
        &format!(
            "--output {}: the existing file cannot be written by this user (Permission denied",
            read_only.display()
        ),
    );
    let o = run(&writable).unwrap();
    assert_one_line_error(
        &o,
        &format!(
            "--output {}: belongs to user 0 and group 0, which this process cannot give",
            writable.display()
        ),
    );
    for p in [&read_only, &writable] {
        assert_eq!(std::fs::read(p).unwrap(), b"root's");
        assert_eq!(std::fs::metadata(p).unwrap().uid(), 0);
    }
    // Its own file: replaced, still its own; read-only: refused too (it could not write it).
    let own = dir.join("own.pfm");
    ok(&run(&own).unwrap());
    ok(&run(&own).unwrap());
    assert_eq!(std::fs::metadata(&own).unwrap().uid(), NOBODY);
    std::fs::set_permissions(&own, std::fs::Permissions::from_mode(0o444)).unwrap();
    let before = std::fs::read(&own).unwrap();
    assert_one_line_error(&run(&own).unwrap(), "cannot be written by this user");
    assert_eq!(std::fs::read(&own).unwrap(), before);
    assert_eq!(
        files(&dir),
        ["own.pfm", "root-ro.pfm", "root-rw.pfm"],
        "stray files"
    );
}

#[test]
fn names_up_to_255_bytes_work() {
    let dir = temp_dir("files-long");
    for len in [251, 255] {
        let name = format!("{}.pfm", "a".repeat(len - 4));
        let p = dir.join(&name);
        ok(&render(&["-o", s(&p)]));
        assert!(is_pfm_16(&std::fs::read(&p).unwrap()), "{len}");
        // And again, over the existing file.
        ok(&render(&["-o", s(&p)]));
        assert_eq!(files(&dir), std::slice::from_ref(&name));
        std::fs::remove_file(&p).unwrap();
    }
}

/// PNG's signature and the width and height of its IHDR chunk.
fn png_size(b: &[u8]) -> (u32, u32) {
    assert!(
        b.starts_with(b"\x89PNG\r\n\x1a\n"),
        "not a PNG: {:?}",
        &b[..b.len().min(8)]
    );
    (
        u32::from_be_bytes(b[16..20].try_into().unwrap()),
        u32::from_be_bytes(b[20..24].try_into().unwrap()),
    )
}

#[test]
fn a_dash_writes_to_stdout() {
    let o = render(&["-o", "-", "--format", "png"]);
    ok(&o);
    assert_eq!(png_size(&o.stdout), (16, 16));
    let o = render(&["-o", "-", "--format", "pfm"]);
    ok(&o);
    assert!(is_pfm_16(&o.stdout));
    // One format: no --format needed.
    let o = render(&["--error", "-"]);
    ok(&o);
    assert_eq!(png_size(&o.stdout), (16, 16));
    let o = nyquist(&["points", "--format", "png", "-o", "-"]);
    ok(&o);
    assert!(o.stdout.starts_with(b"\x89PNG"));
    let o = nyquist(&["mask", "--size", "8", "-o", "-", "--format", "exr"]);
    ok(&o);
    assert!(
        o.stdout.starts_with(&[0x76, 0x2f, 0x31, 0x01]),
        "not OpenEXR"
    );

    // Where the format cannot be known, or stdout carries something else: one line.
    assert_one_line_error(
        &render(&["-o", "-"]),
        "--output -: no extension to tell the format: give --format png|exr|pfm",
    );
    assert_one_line_error(
        &render(&["-o", "-", "--format", "png", "--metrics"]),
        "--output -: stdout carries the metrics",
    );
    assert_one_line_error(
        &render(&["-o", "-", "--format", "png", "--error", "-"]),
        "only one of them can go to stdout",
    );
    assert_one_line_error(
        &nyquist(&["compare", "-o", "-"]),
        "--output -: stdout carries the table",
    );
    assert_one_line_error(
        &nyquist(&["filter", "--filter", "box", "--plot", "-"]),
        "--plot -: stdout carries",
    );
    assert_one_line_error(&nyquist(&["mask", "-o", "-"]), "give --format png|exr");
    // An extension that names another format than --format.
    assert_one_line_error(
        &render(&["-o", "x.png", "--format", "exr"]),
        "--output x.png: .png names png output but --format is exr",
    );
}

#[test]
fn devices_are_written_in_place_by_name() {
    let o = render(&["-o", "/dev/null", "--format", "exr"]);
    ok(&o);
    assert!(o.stdout.is_empty() && o.stderr.is_empty());
    let o = render(&["-o", "/dev/stdout", "--format", "pfm"]);
    ok(&o);
    assert!(is_pfm_16(&o.stdout));
    let o = nyquist(&["points", "--count", "3", "-o", "/dev/stdout"]);
    ok(&o);
    assert_eq!(stdout(&o).lines().count(), 3);
    // Without --format where one is needed: one line naming the flag.
    assert_one_line_error(
        &render(&["-o", "/dev/null"]),
        "--output /dev/null: no extension to tell the format: give --format",
    );
    // /dev/stdout redirected to a file: the file gets the image (appended to what the shell
    // opened, as `>` and `>>` do), and the file is not replaced.
    let dir = temp_dir("files-stdout-file");
    let out = dir.join("out.pfm");
    let f = std::fs::File::create(&out).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args([
            "render",
            "--size",
            "16x16",
            "--spp",
            "1",
            "-o",
            "/dev/stdout",
            "--format",
            "pfm",
        ])
        .stdout(f)
        .output()
        .unwrap();
    ok(&o);
    assert!(is_pfm_16(&std::fs::read(&out).unwrap()));
    assert_eq!(files(&dir), ["out.pfm"]);
    assert!(Path::new("/dev/null").exists());
    assert!(!std::fs::metadata("/dev/null").unwrap().is_file());
}

fn mkfifo(p: &Path) -> bool {
    Command::new("mkfifo")
        .arg(p)
        .status()
        .is_ok_and(|s| s.success())
}

#[test]
fn a_fifo_is_written_in_place() {
    let dir = temp_dir("files-fifo");
    for (name, more) in [("pipe", &["--format", "pfm"][..]), ("pipe.pfm", &[][..])] {
        let fifo = dir.join(name);
        if !mkfifo(&fifo) {
            eprintln!("no mkfifo here: skipped");
            return;
        }
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || {
                let mut bytes = Vec::new();
                std::fs::File::open(&fifo)
                    .unwrap()
                    .read_to_end(&mut bytes)
                    .unwrap();
                bytes
            })
        };
        let mut args = vec!["-o", s(&fifo)];
        args.extend_from_slice(more);
        ok(&render(&args));
        let bytes = reader.join().unwrap();
        assert!(is_pfm_16(&bytes), "{name}: {} bytes", bytes.len());
        use std::os::unix::fs::FileTypeExt;
        assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
    }
    assert_eq!(files(&dir), ["pipe", "pipe.pfm"], "stray files");
}

/// Runs a disk render with metrics (a reference without a closed form) with `env` set and
/// `XDG_CACHE_HOME` and `HOME` removed unless `env` sets them.
fn disk_metrics(env: &[(&str, &Path)], more: &[&str]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_nyquist"));
    c.args([
        "render",
        "--scene",
        "disk",
        "--size",
        "16x8",
        "--spp",
        "1",
        "--metrics",
    ])
    .args(more)
    .env_remove("XDG_CACHE_HOME")
    .env_remove("HOME")
    .stdin(Stdio::null());
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().unwrap()
}

fn reference_line(o: &Output) -> String {
    stdout(o)
        .lines()
        .find(|l| l.starts_with("reference "))
        .unwrap_or_default()
        .to_owned()
}

#[test]
fn a_missing_home_gets_no_cache_folder() {
    let dir = temp_dir("files-home");
    let home = dir.join("nonexistent");
    let o = disk_metrics(&[("HOME", &home)], &[]);
    ok(&o);
    assert!(!home.exists(), "created {}", home.display());
    assert!(files(&dir).is_empty());
    assert!(
        reference_line(&o).ends_with("rendered now (not cached)"),
        "{}",
        reference_line(&o)
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(
        err,
        format!(
            "nyquist: note: no reference cache: the home folder {} does not exist; references \
             are rendered every run\n",
            home.display()
        )
    );
    // A relative XDG_CACHE_HOME is ignored for the home, which exists: the cache goes there.
    std::fs::create_dir(&home).unwrap();
    let o = disk_metrics(
        &[("HOME", &home), ("XDG_CACHE_HOME", Path::new("rel"))],
        &[],
    );
    ok(&o);
    assert_eq!(files(&home.join(".cache/nyquist")).len(), 1);
    assert!(reference_line(&o).ends_with("rendered now and cached"));
    let o = disk_metrics(&[("HOME", &home)], &[]);
    assert!(
        reference_line(&o).ends_with("read from the cache"),
        "{}",
        reference_line(&o)
    );
    assert_eq!(String::from_utf8_lossy(&o.stderr), "");
}

#[test]
fn a_cache_folder_that_is_a_file_gets_one_note() {
    let dir = temp_dir("files-cache-file");
    let file = dir.join("cache");
    std::fs::write(&file, b"not a folder").unwrap();
    // Two references (the box means and the gaussian's converged image), one note.
    let o = disk_metrics(&[("XDG_CACHE_HOME", &file)], &["--filter", "gaussian"]);
    ok(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(
        err,
        format!(
            "nyquist: note: the reference cache {} cannot be used (Not a directory (os error \
             20)); references are rendered every run\n",
            file.join("nyquist").display()
        )
    );
    let line = reference_line(&o);
    assert!(
        line.ends_with("rendered now (not cached)") && !line.contains("cache)"),
        "{line}"
    );
    let o = disk_metrics(&[("XDG_CACHE_HOME", &file)], &["--json"]);
    assert!(
        stdout(&o).contains("rendered now (not cached)\""),
        "{}",
        stdout(&o)
    );
    assert_eq!(std::fs::read(&file).unwrap(), b"not a folder");
}

#[test]
fn a_damaged_cache_file_says_how() {
    let dir = temp_dir("files-cache-damage");
    let cache: PathBuf = dir.join("c");
    ok(&disk_metrics(&[("XDG_CACHE_HOME", &cache)], &[]));
    let folder = cache.join("nyquist");
    let name = files(&folder).pop().unwrap();
    let file = folder.join(&name);
    let good = std::fs::read(&file).unwrap();
    let mut garbage = good.clone();
    garbage[..7].copy_from_slice(b"GARBAGE");
    let checksum = good.windows(8).position(|w| w == b"fnv1a64 ").unwrap();
    for (damage, bytes, why) in [
        ("empty", Vec::new(), "is truncated (in its header)"),
        (
            "cut in its header",
            good[..30].to_vec(),
            "is truncated (in its header)",
        ),
        (
            "cut in its checksum line",
            good[..checksum + 10].to_vec(),
            "is truncated (in its checksum line)",
        ),
        (
            "cut in its pixels",
            good[..good.len() - 100].to_vec(),
            "is truncated (",
        ),
        ("padded", [&good[..], b"xx"].concat(), "is corrupt ("),
        (
            "a strange first line",
            garbage,
            "is corrupt (not a nyquist reference header)",
        ),
        (
            "other parameters",
            String::from_utf8_lossy(&good)
                .replacen("size 16x8", "size 8x16", 1)
                .into_bytes(),
            "was made from other parameters",
        ),
    ] {
        std::fs::write(&file, &bytes).unwrap();
        let o = disk_metrics(&[("XDG_CACHE_HOME", &cache)], &[]);
        ok(&o);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.starts_with(&format!(
                "nyquist: note: the cached reference {} {why}",
                file.display()
            )) && err.ends_with("; rendering it again\n")
                && err.lines().count() == 1,
            "{damage}: {err}"
        );
        assert!(
            reference_line(&o).ends_with("rendered now and cached"),
            "{damage}"
        );
        assert_eq!(
            std::fs::read(&file).unwrap(),
            good,
            "{damage}: not rewritten"
        );
    }
}
