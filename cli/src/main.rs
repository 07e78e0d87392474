//! The `nyquist` command line (filled in by the foundation work).
fn main() {}
