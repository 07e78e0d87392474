//! Helpers shared by the CLI end-to-end tests.
#![allow(dead_code)] // each test binary uses a subset

use std::process::{Command, Output};

pub fn nyquist(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(args)
        .output()
        .expect("run nyquist")
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

pub fn rows(o: &Output) -> Vec<Vec<f32>> {
    stdout(o)
        .lines()
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// One line on stderr, exit status 2, nothing on stdout.
pub fn assert_one_line_error(o: &Output, mentions: &str) {
    let err = String::from_utf8(o.stderr.clone()).unwrap();
    assert_eq!(o.status.code(), Some(2), "stderr: {err}");
    assert_eq!(err.lines().count(), 1, "not one line: {err:?}");
    assert!(
        err.contains(mentions),
        "{err:?} does not mention {mentions:?}"
    );
    assert!(o.stdout.is_empty());
}
