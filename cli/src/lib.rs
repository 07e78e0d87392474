//! The library behind the `nyquist` command: one module per subcommand (its clap arguments and
//! `run`), and the string parsers the command line uses (`render::parse_size`,
//! `render::parse_filter`, `compare::parse_filters`, `points::parse_grid`,
//! `points::parse_pixel`, `analyze::parse_csv`). The binary (`main.rs`) only dispatches; the
//! library exists so that the fuzz targets and tests can call the parsers, and the convergence
//! study's engine (`converge::Study`), directly.
//!
//! ```
//! assert_eq!(nyquist_cli::render::parse_size("32x16"), Ok([32, 16]));
//! assert!(nyquist_cli::render::parse_size("0x16").is_err());
//! ```
#![forbid(unsafe_code)]
// In WebAssembly the pictures are refused (`plot_unavailable.rs`), so their drawing code is unused.
#![cfg_attr(target_family = "wasm", allow(dead_code))]

pub mod analyze;
pub mod clock;
pub mod compare;
pub mod converge;
pub mod filter;
pub mod genz;
pub mod mask;
pub mod memory;
pub mod output;
#[cfg(not(target_family = "wasm"))]
pub mod plot;
#[cfg(target_family = "wasm")]
#[path = "plot_unavailable.rs"]
pub mod plot;
pub mod points;
pub mod progress;
pub mod raster;
pub mod render;
pub mod scene;
#[cfg(not(target_family = "wasm"))]
pub mod shaders;
pub mod svg;
pub mod web;
