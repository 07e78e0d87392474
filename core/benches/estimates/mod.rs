//! Reading this run's criterion estimates back, for the ratio reports the benches print after
//! their run. Shared by the core and film benches (`#[path]`-included there).

use std::path::PathBuf;
use std::time::SystemTime;

/// Where criterion writes its estimates: `$CRITERION_HOME`, else `$CARGO_TARGET_DIR/criterion`,
/// else the workspace's `target/criterion` (benches run in the package directory).
fn criterion_dir() -> PathBuf {
    if let Some(home) = std::env::var_os("CRITERION_HOME") {
        return home.into();
    }
    match std::env::var_os("CARGO_TARGET_DIR") {
        Some(t) => PathBuf::from(t).join("criterion"),
        None => PathBuf::from("../target/criterion"),
    }
}

/// The median time per iteration (ns) of `group/function` if the run that started at `since`
/// measured it.
pub fn median_ns(group: &str, function: &str, since: SystemTime) -> Option<f64> {
    // Criterion stores a group or function `a/b` in the directory `a_b`.
    let dir = criterion_dir()
        .join(group.replace('/', "_"))
        .join(function.replace('/', "_"))
        .join("new");
    let path = dir.join("estimates.json");
    if std::fs::metadata(&path).ok()?.modified().ok()? < since {
        return None;
    }
    let text = std::fs::read_to_string(&path).ok()?;
    let rest = &text[text.find("\"median\"")?..];
    let rest = &rest[rest.find("\"point_estimate\":")? + "\"point_estimate\":".len()..];
    let end = rest.find([',', '}'])?;
    rest[..end].trim().parse().ok()
}

/// Prints a bench's closing report: `heading`, then one line per entry; nothing when the run
/// measured none of the report's cases.
pub fn print_report(heading: &str, lines: &[String]) {
    if lines.is_empty() {
        return;
    }
    println!("\n{heading}");
    for l in lines {
        println!("{l}");
    }
}
