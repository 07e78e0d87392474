//! `nyquist analyze`: quality measures of a point set and its periodogram as a picture
//! ([`nyquist_lab::analysis`]); this module gives the analysis the command's notes, progress
//! bar and figure files, and prints the report.

use anyhow::Result;
use nyquist_lab::analysis::{Host, SpectrumPlot};
use std::path::Path;

pub use nyquist_lab::analysis::{
    AnalyzeSpec as AnalyzeArgs, Measure, SPECTRUM_HEIGHT, SPECTRUM_WIDTH, StarMethod, load,
    parse_csv, periodogram,
};

/// The command line as an analysis host: notes and warnings on stderr, a progress bar that
/// appears when the work is slow, figures through [`crate::pictures`].
#[derive(Debug, Default)]
struct Command {
    bar: Option<crate::progress::Progress>,
}

impl Host for Command {
    fn note(&mut self, text: &str) {
        crate::output::note(text);
    }

    fn warn(&mut self, text: &str) {
        crate::output::warn(text);
    }

    fn check_figure(&mut self, path: &Path, flag: &str) -> Result<()> {
        crate::pictures::kind_of(path, flag).map(|_| ())
    }

    fn save_spectrum(&mut self, figure: &SpectrumPlot<'_>, path: &Path, flag: &str) -> Result<()> {
        crate::pictures::save(figure, path, flag)
    }

    fn progress_start(&mut self, total: u64, what: &str, unit: &str, now: bool) {
        let bar = crate::progress::Progress::with_unit(total, what, unit);
        if now {
            bar.show_now();
        }
        self.bar = Some(bar);
    }

    fn progress_inc(&mut self) {
        if let Some(b) = &self.bar {
            b.inc(1);
        }
    }

    fn progress_finish(&mut self) {
        if let Some(b) = self.bar.take() {
            b.finish();
        }
    }
}

/// Everything `nyquist analyze` does but print: the report, after writing the `--spectrum`
/// picture if one is asked for.
///
/// # Errors
/// One line naming the flag at fault, as the command prints it.
pub fn report(args: &AnalyzeArgs) -> Result<String> {
    nyquist_lab::analysis::report(args, &mut Command::default())
}

/// Runs `nyquist analyze`.
pub fn run(args: &AnalyzeArgs) -> Result<()> {
    let text = report(args)?;
    crate::output::to_stdout_or_file(None, |w| {
        w.write_all(text.as_bytes())?;
        Ok(())
    })
}
