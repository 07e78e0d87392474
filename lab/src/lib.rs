//! The nyquist laboratory: what the command line, the browser explorer and the examples share
//! above the library. Point sets and samplers by name come from the core
//! ([`nyquist::sampler::NamedSampler`]); here are the test scenes and their references
//! ([`scene`]), convergence studies over any integrand family ([`study`]), one work queue
//! ([`parallel`]), memory limits ([`memory`]), the numeric flags' ranges ([`flags`]), a clock that also works in WebAssembly
//! ([`clock`]) and the figures ([`plot`], [`raster`], [`svg`]).
//!
//! Errors here are messages for people ([`anyhow::Error`]) where a front end only shows them,
//! and typed values ([`study::StudyError`]) where a front end words them itself.
//!
//! ```
//! use nyquist_lab::study::{Study, unit_square::SquareIntegrand};
//! let study = Study { samplers: vec!["stratified".into()], integrands: vec![SquareIntegrand::Disk],
//!                     counts: vec![16, 64], runs: 4, seed: 1, spp_hint: None };
//! assert_eq!(study.run(1).unwrap().curves[0].spp, [16, 64]);
//! ```
#![forbid(unsafe_code)]
// In WebAssembly the figures are refused (`plot_unavailable.rs`), so their drawing code is unused.
#![cfg_attr(target_family = "wasm", allow(dead_code))]

pub mod analysis;
pub mod blue_tile;
pub mod clock;
pub mod error_spectrum;
pub mod filter;
pub mod flags;
pub mod json;
pub mod memory;
pub mod parallel;
#[cfg(not(target_family = "wasm"))]
pub mod plot;
#[cfg(target_family = "wasm")]
#[path = "plot_unavailable.rs"]
pub mod plot;
pub mod pmj02_seed;
pub mod points;
pub mod raster;
pub mod render;
pub mod scene;
pub mod study;
pub mod svg;
pub mod url;
pub mod words;
