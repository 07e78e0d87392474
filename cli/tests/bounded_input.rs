//! Reading is bounded: an endless or enormous input ends with one line naming the input and the
//! limit, in bounded time and memory, whatever the source (a pipe, `/dev/zero`, a file of one
//! long line). Each run is under an address-space limit (`ulimit -v`), so a reader that kept
//! everything would die on the allocator instead of printing the line; and under a watchdog,
//! so a reader that never stops fails the test instead of hanging it.

mod common;

use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// Runs `script` in `sh` with nyquist's path in `$N` and the address space limited to
/// `kib` KiB; kills it after `seconds` (the test then fails).
fn limited(script: &str, kib: u64, seconds: u64) -> Output {
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {kib} && {script}"))
        .env("N", env!("CARGO_BIN_EXE_nyquist"))
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run sh");
    let start = Instant::now();
    while child.try_wait().expect("wait").is_none() {
        if start.elapsed() > Duration::from_secs(seconds) {
            let _ = Command::new("pkill")
                .args(["-P", &child.id().to_string()])
                .status();
            let _ = child.kill();
            panic!("{script:?} still running after {seconds} s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().expect("output")
}

/// The last stderr line, which must be nyquist's one-line refusal (exit 2).
fn refusal(o: &Output) -> String {
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "stderr: {err}");
    assert_eq!(err.lines().count(), 1, "not one line: {err:?}");
    assert!(o.stdout.is_empty());
    err
}

/// 400 MB of address space: room for the program, far less than an endless input would take.
const ADDRESS_SPACE_KIB: u64 = 400_000;

#[test]
fn endless_stdin_ends_at_the_memory_limit() {
    let o = limited(
        r#"yes 0.5,0.25 | "$N" analyze - --max-memory 4M"#,
        ADDRESS_SPACE_KIB,
        5,
    );
    let err = refusal(&o);
    // 4 MB hold 500 000 coordinates: the refusal comes at the point that does not fit.
    assert!(
        err.starts_with(
            "nyquist: stdin: the points pass the 4.0 MB limit (--max-memory) after 500000 values \
             (250000 points)"
        ),
        "{err}"
    );
}

#[test]
fn endless_stdin_ends_at_the_default_limit_under_ulimit() {
    // Without --max-memory the limit is half the address space: 30 MB of 60 MB.
    let o = limited(r#"yes 0.5,0.25 | "$N" analyze"#, 60_000, 30);
    let err = refusal(&o);
    assert!(
        err.contains("limit (half the address-space limit (ulimit -v))"),
        "{err}"
    );
}

#[test]
fn dev_zero_ends_at_the_line_limit() {
    let o = limited(r#""$N" analyze /dev/zero"#, ADDRESS_SPACE_KIB, 5);
    let err = refusal(&o);
    assert!(
        err.starts_with("nyquist: /dev/zero line 1: longer than 1048576 bytes"),
        "{err}"
    );
}

#[test]
fn a_two_gigabyte_line_ends_after_one_mebibyte() {
    let dir = common::temp_dir("long-line");
    let path = dir.join("long.csv");
    // A sparse file: 2 GB of zero bytes, no line break, on no disk space.
    let file = std::fs::File::create(&path).unwrap();
    file.set_len(2_000_000_000).unwrap();
    drop(file);
    let script = format!(r#""$N" analyze '{}'"#, path.display());
    let o = limited(&script, ADDRESS_SPACE_KIB, 5);
    let err = refusal(&o);
    assert!(
        err.contains("long.csv line 1: longer than 1048576 bytes"),
        "{err}"
    );
}

#[test]
fn a_file_of_many_short_lines_ends_at_the_limit() {
    let dir = common::temp_dir("many-lines");
    let path = dir.join("many.csv");
    std::fs::write(&path, "0.5,0.25\n".repeat(200_000)).unwrap();
    let path = path.display().to_string();
    let o = common::nyquist(&["analyze", &path, "--max-memory", "1M"]);
    common::assert_one_line_error(
        &o,
        "many.csv: the points pass the 1.0 MB limit (--max-memory) after 125000 values",
    );
    // Under the limit the same file is read whole.
    let o = common::nyquist(&["analyze", &path, "--measures", "star", "--json"]);
    assert!(o.status.success());
    assert!(common::stdout(&o).starts_with("{\"points\":200000,\"dims\":2,"));
}

#[test]
fn only_a_first_line_without_numbers_is_a_header() {
    let run = |text: &str| {
        let mut child = Command::new(env!("CARGO_BIN_EXE_nyquist"))
            .args(["analyze", "--json", "--measures", "star"])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        use std::io::Write;
        child
            .stdin
            .take()
            .unwrap()
            .write_all(text.as_bytes())
            .unwrap();
        child.wait_with_output().unwrap()
    };
    // A malformed first line is an error, not a header.
    common::assert_one_line_error(
        &run("0.1;0.2\n0.5,0.5\n0.25,0.75\n"),
        "stdin line 1: '0.1;0.2' is not a number",
    );
    common::assert_one_line_error(&run(".5 0.5\n0.5,0.5\n"), "stdin line 1:");
    // Names with digits in them are a header.
    for header in ["x1,x2", "dim 0,dim 1", "u,v"] {
        let o = run(&format!("{header}\n0.5,0.5\n0.25,0.75\n"));
        assert!(o.status.success(), "{header}");
        assert!(common::stdout(&o).starts_with("{\"points\":2,"), "{header}");
    }
}
