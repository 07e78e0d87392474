//! The library behind the `nyquist` command: one module per subcommand (its clap arguments and
//! `run`), and the string parsers the command line uses (`render::parse_size`,
//! `render::parse_filter`, `compare::parse_filters`, `points::parse_grid`,
//! `points::parse_pixel`, `analyze::parse_csv`). The binary (`main.rs`) only dispatches; the
//! library exists so that the fuzz targets and tests can call the parsers directly. The work
//! itself (scenes, studies, figures) is `nyquist_lab`'s.
//!
//! ```
//! assert_eq!(nyquist_cli::render::parse_size("32x16"), Ok([32, 16]));
//! assert!(nyquist_cli::render::parse_size("0x16").is_err());
//! ```
#![forbid(unsafe_code)]
// In WebAssembly the figures are refused (`pictures::kind_of`), so their drawing code is unused.
#![cfg_attr(target_family = "wasm", allow(dead_code))]

pub mod analyze;
pub mod compare;
pub mod converge;
pub mod filter;
pub mod mask;
pub mod output;
pub mod pictures;
pub mod points;
pub mod progress;
pub mod render;
#[cfg(not(target_family = "wasm"))]
pub mod shaders;
pub mod web;
