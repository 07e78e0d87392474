//! Every subcommand's `--help` succeeds and shows an example.

mod common;

use common::{nyquist, stdout};

#[test]
fn every_subcommand_help_has_an_example() {
    for sub in ["points", "filter", "render", "compare", "converge"] {
        let o = nyquist(&[sub, "--help"]);
        assert!(o.status.success(), "{sub}");
        let s = stdout(&o);
        assert!(s.contains(&format!("Example: nyquist {sub}")), "{sub}: {s}");
    }
    let o = nyquist(&["--help"]);
    assert!(o.status.success());
    for sub in ["points", "filter", "render", "compare", "converge"] {
        assert!(stdout(&o).contains(sub));
    }
}

#[test]
fn unknown_subcommand_is_one_line_exit_2() {
    let o = nyquist(&["paint"]);
    common::assert_one_line_error(&o, "paint");
}
