//! `nyquist converge`: how fast each sampler's error falls with the sample count
//! ([`nyquist_lab::study::convergence`]); this module runs the study on the command's threads,
//! draws `--plot` and prints the report.

use anyhow::Result;
use nyquist_lab::clock::Stopwatch;
use nyquist_lab::study::convergence::{command, genz_report, json, study, study_error, table};
use nyquist_lab::study::figure::Plot;

pub use nyquist_lab::study::convergence::{ConvergeSpec as ConvergeArgs, json_report};

/// Samples above which a study is announced before it starts (several seconds of work or more).
const LARGE_STUDY: u64 = 1 << 28;

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
    // Long studies say so first, and show their progress over the (sampler, N, run) tasks.
    let samples = study.work();
    let tasks = study.samplers.len() * study.counts.len() * study.runs as usize;
    let bar = crate::progress::Progress::with_unit(tasks as u64, "converge", "tasks");
    if samples > LARGE_STUDY {
        crate::output::warn(&format!(
            "{} × {} N × --runs {}: about {:.1e} samples; this may take a while; fewer --runs or \
             --samplers, or a lower --max-spp, make it shorter",
            nyquist_lab::words::count(study.samplers.len() as u64, "sampler"),
            study.counts.len(),
            study.runs,
            samples as f64
        ));
        bar.show_now();
    }
    let start = Stopwatch::start();
    let outcome = study
        .run_with_progress(threads, &|_, _| bar.inc(1))
        .map_err(study_error);
    bar.finish();
    let outcome = outcome?;
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
