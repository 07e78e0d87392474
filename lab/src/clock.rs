//! Wall-clock durations for the reports' `seconds` fields. Native builds use
//! [`std::time::Instant`]; `wasm32-unknown-unknown` has no clock (`Instant::now` panics there),
//! so in the browser every duration reads 0 and the page times the work itself.
//!
//! ```
//! let watch = nyquist_lab::clock::Stopwatch::start();
//! assert!(watch.seconds() >= 0.0);
//! ```

/// Started at creation; [`Stopwatch::seconds`] is the time since.
#[derive(Clone, Copy, Debug)]
pub struct Stopwatch {
    #[cfg(not(target_family = "wasm"))]
    start: std::time::Instant,
}

impl Stopwatch {
    /// Starts measuring.
    pub fn start() -> Stopwatch {
        Stopwatch {
            #[cfg(not(target_family = "wasm"))]
            start: std::time::Instant::now(),
        }
    }

    /// Seconds since [`Stopwatch::start`] (always 0 on WebAssembly).
    pub fn seconds(&self) -> f64 {
        #[cfg(not(target_family = "wasm"))]
        return self.start.elapsed().as_secs_f64();
        #[cfg(target_family = "wasm")]
        return 0.0;
    }
}
