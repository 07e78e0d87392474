//! Where output goes and how writing it fails: a closed stdout pipe, a full disk, a folder that
//! is missing or cannot be written, an extension that contradicts the format, and `compare
//! --json` without `--output`. Every failure is one line naming the flag, the path and the
//! operating system's reason once, exit status 2, and no file left behind.

mod common;

use common::{TempDir, assert_one_line_error, nyquist, temp_dir};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

fn spawn(args: &[&str], stdout: Stdio) -> Child {
    Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(args)
        .stdout(stdout)
        .stderr(Stdio::piped())
        .spawn()
        .expect("run nyquist")
}

/// Spawns `args`, reads the first `bytes` bytes of stdout (as `head -c` does), closes the pipe
/// and returns the exit status and stderr.
fn read_then_close(args: &[&str], bytes: usize) -> (Option<i32>, String) {
    let mut child = spawn(args, Stdio::piped());
    {
        let mut out = child.stdout.take().unwrap();
        let mut head = vec![0u8; bytes];
        out.read_exact(&mut head).unwrap();
    } // the read end closes here
    let status = child.wait().unwrap();
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    (status.code(), err)
}

#[test]
fn a_closed_stdout_pipe_exits_141_quietly() {
    for args in [
        &["points", "--count", "1000000"][..],
        &["points", "--count", "1000000", "--format", "json"],
        &["points", "--count", "1000000", "--format", "svg"],
        &["filter", "--filter", "box", "--grid", "2000"],
    ] {
        let (code, err) = read_then_close(args, 40);
        assert_eq!(code, Some(141), "{args:?}: stderr {err:?}");
        assert_eq!(err, "", "{args:?}");
    }
}

#[test]
fn the_help_documents_the_closed_pipe_status() {
    let o = nyquist(&["--help"]);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("141 (128 + SIGPIPE)"), "{text}");
}

/// A link in `dir` named `name` to `/dev/full`: writing through it fails with ENOSPC. (The
/// link, not the device, is what a writer that replaces its target would replace.)
fn full_disk(dir: &TempDir, name: &str) -> PathBuf {
    let link = dir.join(name);
    std::os::unix::fs::symlink("/dev/full", &link).unwrap();
    link
}

#[test]
fn a_full_disk_names_the_flag_and_the_path() {
    if !Path::new("/dev/full").exists() {
        eprintln!("no /dev/full here: skipped");
        return;
    }
    let dir = temp_dir("full-disk");
    for (args, name, flag) in [
        (&["points", "--count", "100000"][..], "p.csv", "--output"),
        (
            &["render", "--size", "16x16", "--spp", "1"],
            "r.pfm",
            "--output",
        ),
        (&["points", "--format", "png"], "p.png", "--output"),
        (&["filter", "--filter", "box"], "f.png", "--plot"),
    ] {
        let link = full_disk(&dir, name);
        let p = link.to_str().unwrap();
        let mut all = args.to_vec();
        all.extend([if flag == "--plot" { "--plot" } else { "-o" }, p]);
        let o = nyquist(&all);
        let err = String::from_utf8(o.stderr.clone()).unwrap();
        assert_eq!(
            err,
            format!("nyquist: {flag} {p}: cannot write: No space left on device (os error 28)\n"),
            "{all:?}"
        );
        assert_eq!(o.status.code(), Some(2));
        assert!(
            std::fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        std::fs::remove_file(&link).unwrap();
    }
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0, "stray files");
}

#[test]
fn a_full_disk_on_stdout_says_stdout() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        eprintln!("no /dev/full here: skipped");
        return;
    };
    let o = Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(["points", "--count", "100000"])
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(
        String::from_utf8(o.stderr).unwrap(),
        "nyquist: stdout: cannot write: No space left on device (os error 28)\n"
    );
    assert_eq!(o.status.code(), Some(2));
}

/// A folder nothing can be created in: a fresh folder without write permission, or, where
/// permissions do not bind (root), `/sys`. `None` if there is neither.
fn unwritable_folder(dir: &TempDir) -> Option<PathBuf> {
    use std::os::unix::fs::PermissionsExt;
    let ro = dir.join("ro");
    std::fs::create_dir(&ro).unwrap();
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
    if std::fs::File::create(ro.join("probe")).is_err() {
        return Some(ro);
    }
    let _ = std::fs::remove_file(ro.join("probe"));
    let sys = PathBuf::from("/sys");
    (sys.is_dir() && std::fs::File::create(sys.join("nyquist-probe")).is_err()).then_some(sys)
}

#[test]
fn an_unwritable_folder_names_the_path_and_the_reason_once() {
    let dir = temp_dir("unwritable");
    let Some(ro) = unwritable_folder(&dir) else {
        eprintln!("no unwritable folder here: skipped");
        return;
    };
    let cache = temp_dir("unwritable-cache");
    for (args, name, flag) in [
        (&["points"][..], "a.csv", "-o"),
        (&["points", "--format", "png"], "a.png", "-o"),
        (&["render", "--size", "8x8", "--spp", "1"], "a.png", "-o"),
        (&["filter", "--filter", "box"], "a.png", "--plot"),
        (&["analyze", "--sampler", "halton"], "a.png", "--spectrum"),
        (
            &[
                "converge",
                "--samplers",
                "random",
                "--max-spp",
                "32",
                "--runs",
                "2",
            ],
            "a.png",
            "--plot",
        ),
        (
            &[
                "compare",
                "--samplers",
                "random",
                "--spp",
                "1",
                "--size",
                "8x8",
            ],
            "a.png",
            "-o",
        ),
    ] {
        let path = ro.join(name);
        let p = path.to_str().unwrap();
        let mut all = args.to_vec();
        all.extend([flag, p]);
        let o = common::nyquist_cached(&all, &cache);
        let shown = if flag == "-o" { "--output" } else { flag };
        let err = String::from_utf8(o.stderr.clone()).unwrap();
        assert_eq!(
            err,
            format!("nyquist: {shown} {p}: cannot write: Permission denied (os error 13)\n"),
            "{all:?}"
        );
        assert_eq!(err.matches("Permission denied").count(), 1);
        assert_eq!(o.status.code(), Some(2));
        assert!(!path.exists());
    }
}

#[test]
fn compare_checks_an_unwritable_output_before_rendering() {
    let dir = temp_dir("compare-early");
    let Some(ro) = unwritable_folder(&dir) else {
        eprintln!("no unwritable folder here: skipped");
        return;
    };
    let path = ro.join("sheet.png");
    // Hours of rendering if it started: the answer must come at once.
    let mut child = spawn(
        &[
            "compare",
            "--samplers",
            "random",
            "--filters",
            "box",
            "--spp",
            "65536",
            "--size",
            "2048x2048",
            "-o",
            path.to_str().unwrap(),
        ],
        Stdio::piped(),
    );
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("compare rendered before checking its output");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    assert_eq!(status.code(), Some(2));
    assert!(err.contains("cannot write: Permission denied"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
}

#[test]
fn a_missing_folder_reads_the_same_for_every_writer() {
    let dir = temp_dir("missing-folder");
    let nodir = dir.join("nodir");
    for (args, name, flag) in [
        (&["points"][..], "a.csv", "-o"),
        (&["points", "--format", "json"], "a.json", "-o"),
        (&["render", "--size", "8x8", "--spp", "1"], "a.png", "-o"),
        (&["filter", "--filter", "box"], "a.png", "--plot"),
    ] {
        let path = nodir.join(name);
        let p = path.to_str().unwrap();
        let mut all = args.to_vec();
        all.extend([flag, p]);
        let o = nyquist(&all);
        let shown = if flag == "-o" { "--output" } else { flag };
        assert_eq!(
            String::from_utf8(o.stderr.clone()).unwrap(),
            format!(
                "nyquist: {shown} {p}: folder {} does not exist\n",
                nodir.display()
            ),
            "{all:?}"
        );
        assert_eq!(o.status.code(), Some(2));
    }
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
}

#[test]
fn an_extension_that_names_another_format_is_refused() {
    let dir = temp_dir("extension");
    let png = dir.join("a.png");
    let o = nyquist(&["points", "--format", "svg", "-o", png.to_str().unwrap()]);
    assert_eq!(
        String::from_utf8(o.stderr.clone()).unwrap(),
        format!(
            "nyquist: --output {}: .png names png output but --format is svg: give --format png \
             or another extension\n",
            png.display()
        )
    );
    assert_eq!(o.status.code(), Some(2));
    let json = dir.join("a.json");
    let o = nyquist(&["points", "-o", json.to_str().unwrap()]);
    assert_one_line_error(&o, "--output");
    assert!(
        String::from_utf8(o.stderr)
            .unwrap()
            .contains("but --format is csv")
    );
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "no partial file"
    );
}

#[test]
fn an_unknown_extension_gets_a_note() {
    let dir = temp_dir("unknown-extension");
    let xyz = dir.join("a.xyz");
    let o = nyquist(&["points", "--count", "2", "-o", xyz.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        String::from_utf8(o.stderr).unwrap(),
        format!(
            "nyquist: note: --output {}: unknown extension .xyz, writing csv (--format)\n",
            xyz.display()
        )
    );
    assert_eq!(
        std::fs::read_to_string(&xyz).unwrap(),
        "0,0\n0.5,0.33333334\n"
    );
}

/// Runs `args` with `dir` as the working folder (and the reference cache inside it).
fn in_folder(args: &[&str], dir: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(args)
        .current_dir(dir)
        .env("XDG_CACHE_HOME", dir.join("cache"))
        .output()
        .unwrap()
}

#[test]
fn compare_json_writes_no_sheet_unless_asked() {
    let dir = temp_dir("compare-json");
    let args = [
        "compare",
        "--samplers",
        "random",
        "--filters",
        "box",
        "--spp",
        "1",
        "--size",
        "8x8",
        "--json",
    ];
    let o = in_folder(&args, &dir);
    assert_eq!(o.status.code(), Some(0), "{:?}", o.stderr);
    assert!(!dir.join("compare.png").exists());
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("\"output\":null"), "{text}");
    let mut with_output = args.to_vec();
    with_output.extend(["-o", "sheet.png"]);
    let o = in_folder(&with_output, &dir);
    assert_eq!(o.status.code(), Some(0));
    assert!(dir.join("sheet.png").exists());
    // Without --json the sheet still defaults to compare.png.
    let o = in_folder(&args[..args.len() - 1], &dir);
    assert_eq!(o.status.code(), Some(0));
    assert!(dir.join("compare.png").exists());
    let help = String::from_utf8(nyquist(&["compare", "--help"]).stdout).unwrap();
    assert!(
        help.contains("with --json, no sheet is written unless"),
        "{help}"
    );
}
