//! `nyquist converge`: how fast each sampler's error falls with the sample count
//! ([`nyquist_lab::study::convergence`]); this module runs the study on the command's threads,
//! draws `--plot` and prints the report.

use anyhow::Result;
use nyquist_lab::clock::Stopwatch;
use nyquist_lab::study::convergence::{command, genz_report, json, study, study_error, table};
use nyquist_lab::study::figure::Plot;

pub use nyquist_lab::study::convergence::{ConvergeSpec as ConvergeArgs, json_report};

/// Runs `nyquist converge`.
pub fn run(args: &ConvergeArgs) -> Result<()> {
    let threads = args
        .threads
        .map_or_else(nyquist_lab::render::default_threads, usize::from);
    if let Some(dims) = args.dims {
        let text = genz_report(args, dims, threads)?;
        return crate::output::print(&text);
    }
    if let Some(p) = &args.plot {
        crate::pictures::kind_of(p, "--plot")?;
    }
    let mut notes = Vec::new();
    let study = study(args, &mut notes)?;
    study.check().map_err(study_error)?;
    nyquist_lab::study::convergence::check_memory(&study, threads)?;
    notes.iter().for_each(|n| crate::output::note(n));
    let start = Stopwatch::start();
    let outcome = study.run(threads).map_err(study_error)?;
    let seconds = start.seconds();
    if let Some(p) = &args.plot {
        let title = command(&study);
        let figure = Plot {
            study: &study,
            curves: &outcome.curves,
            title: &title,
        };
        crate::pictures::save(&figure, p, "--plot")?;
    }
    let text = if args.json {
        json(&study, &outcome, args, threads, seconds)
    } else {
        table(&study, &outcome, args, threads, seconds)
    };
    crate::output::to_stdout_or_file(None, |w| {
        w.write_all(text.as_bytes())?;
        Ok(())
    })
}
