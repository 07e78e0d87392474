//! One progress bar on stderr for long work: created hidden, shown once the work has taken more
//! than a second, and only when stderr is a terminal (never in pipes, files or tests). On
//! WebAssembly, which has neither a terminal nor a clock, the bar does nothing.

#[cfg(not(target_family = "wasm"))]
pub use native::Progress;
#[cfg(target_family = "wasm")]
pub use silent::Progress;

#[cfg(not(target_family = "wasm"))]
mod native {
    use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
    use std::io::IsTerminal;
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::time::{Duration, Instant};

    /// Work shorter than this never shows a bar.
    const SHOW_AFTER: Duration = Duration::from_secs(1);

    /// A progress bar over `total` units that appears only when the work is slow.
    #[derive(Debug)]
    pub struct Progress {
        bar: ProgressBar,
        start: Instant,
        shown: AtomicBool,
    }

    impl Progress {
        /// A hidden bar over `total` tiles with a short message (e.g. "render").
        pub fn new(total: u64, message: &str) -> Progress {
            Progress::with_unit(total, message, "tiles")
        }

        /// A hidden bar over `total` units named `unit` (e.g. "realisations").
        pub fn with_unit(total: u64, message: &str, unit: &str) -> Progress {
            let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::hidden());
            let style = ProgressStyle::with_template(&format!(
                "{{msg}} [{{elapsed_precise}}] {{wide_bar}} {{pos}}/{{len}} {unit} (eta {{eta}})"
            ))
            .unwrap_or_else(|_| ProgressStyle::default_bar());
            bar.set_style(style);
            bar.set_message(message.to_owned());
            Progress {
                bar,
                start: Instant::now(),
                shown: AtomicBool::new(!std::io::stderr().is_terminal()),
            }
        }

        /// Adds `n` finished units; shows the bar once the work has taken more than a second.
        pub fn inc(&self, n: u64) {
            self.bar.inc(n);
            if !self.shown.load(Ordering::Relaxed)
                && self.start.elapsed() > SHOW_AFTER
                && !self.shown.swap(true, Ordering::Relaxed)
            {
                self.bar.set_draw_target(ProgressDrawTarget::stderr());
            }
        }

        /// Shows the bar at once (on a terminal), redrawn twice a second even while no unit
        /// finishes: for work known in advance to be long, where the first unit may take minutes.
        pub fn show_now(&self) {
            if !self.shown.swap(true, Ordering::Relaxed) {
                self.bar.set_draw_target(ProgressDrawTarget::stderr());
            }
            self.bar.enable_steady_tick(Duration::from_millis(500));
        }

        /// Removes the bar from the terminal.
        pub fn finish(&self) {
            self.bar.finish_and_clear();
        }
    }
}

#[cfg(target_family = "wasm")]
mod silent {
    /// The bar's interface, drawing nothing.
    #[derive(Debug)]
    pub struct Progress;

    impl Progress {
        /// A bar over `total` tiles.
        pub fn new(_total: u64, _message: &str) -> Progress {
            Progress
        }

        /// A bar over `total` units named `unit`.
        pub fn with_unit(_total: u64, _message: &str, _unit: &str) -> Progress {
            Progress
        }

        /// Adds `n` finished units.
        pub fn inc(&self, _n: u64) {}

        /// Shows the bar at once.
        pub fn show_now(&self) {}

        /// Removes the bar.
        pub fn finish(&self) {}
    }
}
