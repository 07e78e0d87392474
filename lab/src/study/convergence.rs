//! The convergence study as `nyquist converge` runs it: how fast each sampler's error falls with the sample count, on the five
//! test integrands of Christensen, Kensler and Kilpatrick, "Progressive Multi-Jittered Sample
//! Sequences" (EGSR 2018): disk, triangle, step, Gaussian and bilinear over the unit square.
//!
//! For every sampler and every power of two `N` from `--min-spp` to `--max-spp`, `--runs`
//! independent copies of the sampler (seeds hashed from `--seed` and the run, never 0) each give
//! the `N` image samples of pixel (0, 0) of a 1 × 1 image; the mean of an integrand over them is
//! one estimate, and `RMSE(N) = √(mean over runs of (estimate − exact)²)`. The slope of
//! `log RMSE` against `log N` (least squares) is the convergence order: −0.5 for independent
//! samples, about −0.75 for stratified samples on the discontinuous integrands, and down to
//! about −1.5 for scrambled nets on the smooth ones.
//!
//! The engine is [`super::Study`]; this module checks a [`ConvergeSpec`] and formats the
//! reports.
//!
//! ```
//! use nyquist_lab::study::{Study, unit_square::SquareIntegrand as Integrand};
//! let study = Study {
//!     samplers: vec!["random".into()],
//!     integrands: vec![Integrand::Bilinear],
//!     counts: vec![16, 64, 256],
//!     runs: 16,
//!     seed: 7,
//!     spp_hint: None,
//! };
//! let curves = study.run(1).unwrap().curves;
//! assert_eq!(curves.len(), 1);
//! let slope = curves[0].slope.unwrap();
//! assert!((-0.9..-0.2).contains(&slope), "{slope}");
//! ```

use super::genz::{Family, Genz};
use super::unit_square::SquareIntegrand as Integrand;
use super::{
    Curve, MAX_SAMPLES, MAX_SPP, Outcome, Study, StudyError, StudyFault, default_samplers,
    powers_of_two,
};
use crate::clock::Stopwatch;
use crate::json::{json_number, json_string};
use crate::words::count;
use anyhow::{Result, anyhow, bail};
use nyquist::sampler::NamedSamplerError;
use std::fmt::Write as _;
use std::path::PathBuf;

/// A study's error as the command words it: one line naming `--samplers` (and `--max-spp`
/// where a sampler's limit is passed).
pub fn study_error(e: StudyError) -> anyhow::Error {
    match e.error {
        StudyFault::Sampler(NamedSamplerError::SppAboveLimit { max, .. }) => anyhow!(
            "--samplers {} at {} spp: {} takes at most {max} samples per pixel (give --max-spp \
             {max} or less)",
            e.sampler,
            e.count,
            e.sampler
        ),
        _ => anyhow!("--samplers {e}"),
    }
}

/// A convergence study as `nyquist converge` describes it: samplers, integrands (or Genz's
/// families in `dims` dimensions), the range of counts, runs and seed, and the outputs. With the
/// `clap` feature it is also the command's argument group (errors name its fields as flags).
#[derive(Clone, Debug)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
#[cfg_attr(
    feature = "clap",
    command(
        after_help = "Example: nyquist converge --samplers random,stratified,sobol \
    --integrands disk,triangle,step,gaussian,bilinear --max-spp 4096 --runs 64 --plot converge.png"
    )
)]
pub struct ConvergeSpec {
    /// Samplers, comma-separated (names as in `render --sampler`) [default: every sampler except
    /// uniform and adaptive]. `stratified` takes every power of two as a 2^⌈m/2⌉ × 2^⌊m/2⌋ grid.
    /// best-candidate takes at most 4096 spp and pmj02 at most 65536: above that, the default
    /// list leaves them out with a note, and naming them is an error.
    #[cfg_attr(
        feature = "clap",
        arg(long, value_delimiter = ',', value_name = "LIST")
    )]
    pub samplers: Vec<String>,
    /// Integrands, comma-separated [default: disk,triangle,step,gaussian,bilinear].
    #[cfg_attr(
        feature = "clap",
        arg(long, value_enum, value_delimiter = ',', value_name = "LIST")
    )]
    pub integrands: Vec<Integrand>,
    /// Smallest sample count N (a power of two).
    #[cfg_attr(feature = "clap", arg(long, value_name = "N", default_value_t = 16, value_parser = crate::flags::whole(1, MAX_SPP)))]
    pub min_spp: u32,
    /// Largest sample count N (a power of two, at most 2^20); the study takes every power of two
    /// from --min-spp to --max-spp.
    #[cfg_attr(feature = "clap", arg(long, value_name = "N", default_value_t = 4096, value_parser = crate::flags::whole(1, MAX_SPP)))]
    pub max_spp: u32,
    /// Independent runs (scrambles) per sampler and N.
    #[cfg_attr(feature = "clap", arg(long, default_value_t = 64, value_parser = crate::flags::whole(1u32, 1 << 20)))]
    pub runs: u32,
    /// Base seed: run r uses a hash of (seed, r).
    #[cfg_attr(feature = "clap", arg(long, default_value_t = 0, value_parser = crate::flags::whole(0, u64::MAX)))]
    pub seed: u64,
    /// Worker threads [default: the number of cores]; the numbers do not depend on it.
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(1u16, 1024)))]
    pub threads: Option<u16>,
    /// Also draw RMSE against N, log-log, one panel per integrand and one line per sampler,
    /// each panel with a legend of the samplers' slopes: SVG for FILE.svg, PNG for FILE.png.
    #[cfg_attr(feature = "clap", arg(long, value_name = "FILE.png|FILE.svg"))]
    pub plot: Option<PathBuf>,
    /// Print JSON (slopes and every RMSE) instead of the Markdown table.
    #[cfg_attr(feature = "clap", arg(long))]
    pub json: bool,
    /// Instead of the 2-D integrands, Genz's six test families in D dimensions (2 … 64; e.g.
    /// 4, 16, 64), with fixed parameters and exact integrals; the samplers also take
    /// halton-plain and sobol-plain (unscrambled). Prints a table of slopes and relative RMSE;
    /// --integrands, --plot and --json do not apply.
    #[cfg_attr(feature = "clap", arg(long, value_name = "D", value_parser = crate::flags::whole(2, crate::study::genz::MAX_DIMS)))]
    pub dims: Option<u32>,
    /// Make every sampler for H samples per pixel and draw each N from it, past H or short of
    /// it: how a progressive renderer that keeps sampling sees the sampler. Takes the samplers
    /// that continue past their spp (random, halton, sobol, owen-sobol, owen-sobol-bn, zsobol, pmj02, pmj02-bn, lattice-bn; the
    /// default list with this flag).
    #[cfg_attr(feature = "clap", arg(long, value_name = "H", value_parser = crate::flags::whole(1, MAX_SPP)))]
    pub spp_hint: Option<u32>,
}

impl Default for ConvergeSpec {
    /// The command's defaults: every default sampler, the five integrands (an empty list), N =
    /// 16 … 4096, 64 runs, seed 0, a table.
    fn default() -> ConvergeSpec {
        ConvergeSpec {
            samplers: Vec::new(),
            integrands: Vec::new(),
            min_spp: 16,
            max_spp: 4096,
            runs: 64,
            seed: 0,
            threads: None,
            plot: None,
            json: false,
            dims: None,
            spp_hint: None,
        }
    }
}

/// The spec's samplers: `--samplers`, trimmed, or the default list (with `--spp-hint`, the
/// samplers that continue past their spp).
fn samplers(args: &ConvergeSpec) -> Vec<String> {
    if !args.samplers.is_empty() {
        args.samplers.iter().map(|s| s.trim().to_owned()).collect()
    } else if args.spp_hint.is_some() {
        nyquist::sampler::CONTINUING_NAMES
            .iter()
            .map(|&n| n.to_owned())
            .collect()
    } else {
        default_samplers()
    }
}

/// Checks the spec and turns it into a study of the unit-square integrands; a default sampler
/// whose limit is below `max_spp` is left out with a note pushed to `notes`.
///
/// # Errors
/// One line naming the field at fault as a flag.
pub fn study(args: &ConvergeSpec, notes: &mut Vec<String>) -> Result<Study<Integrand>> {
    let mut samplers = samplers(args);
    for (i, s) in samplers.iter().enumerate() {
        if s.is_empty() {
            bail!("--samplers: empty sampler name (e.g. random,stratified)");
        }
        if samplers[..i].contains(s) {
            bail!("--samplers: {s} is given twice");
        }
    }
    for (i, f) in args.integrands.iter().enumerate() {
        if args.integrands[..i].contains(f) {
            bail!("--integrands: {} is given twice", f.name());
        }
    }
    for (flag, n) in [("--min-spp", args.min_spp), ("--max-spp", args.max_spp)] {
        if !n.is_power_of_two() {
            bail!("{flag} {n}: not a power of two (1, 2, 4, …, 16, …, 4096, …)");
        }
        if n > MAX_SPP {
            bail!("{flag} {n}: at most {MAX_SPP}");
        }
    }
    if args.min_spp >= args.max_spp {
        bail!(
            "--min-spp {} --max-spp {}: need at least two sample counts to fit a slope",
            args.min_spp,
            args.max_spp
        );
    }
    // A default sampler whose limit is below --max-spp is left out, with a note once every
    // flag is checked; named in --samplers it is an error. With --spp-hint the samplers are
    // made for the hint, which the study checks.
    let mut left_out = Vec::new();
    if args.samplers.is_empty() && args.spp_hint.is_none() {
        samplers.retain(|name| match nyquist::sampler::spp_limit(name) {
            Some(max) if args.max_spp > max => {
                left_out.push(format!(
                    "--max-spp {}: {name} takes at most {max} samples per pixel; left out of \
                     the study",
                    args.max_spp
                ));
                false
            }
            _ => true,
        });
    }
    let study = Study {
        samplers,
        integrands: if args.integrands.is_empty() {
            Integrand::ALL.to_vec()
        } else {
            args.integrands.clone()
        },
        counts: powers_of_two(args.min_spp, args.max_spp),
        runs: args.runs,
        seed: args.seed,
        spp_hint: args.spp_hint,
    };
    if study.work() > MAX_SAMPLES {
        bail!(
            "{} × {} × N = {}..{} is {} samples; at most {MAX_SAMPLES}",
            count(study.samplers.len() as u64, "sampler"),
            count(study.runs, "run"),
            args.min_spp,
            args.max_spp,
            study.work()
        );
    }
    notes.extend(left_out);
    Ok(study)
}

/// Refuses a study whose [`Study::memory`] on `threads` threads passes the memory limit
/// (`--max-memory`), naming the flags that size it.
///
/// # Errors
/// The one-line refusal of [`crate::memory::check`].
pub fn check_memory<I: super::Integrand + Clone>(study: &Study<I>, threads: usize) -> Result<()> {
    crate::memory::check(
        &format!(
            "{} × {} × --runs {} on {}",
            count(study.samplers.len() as u64, "sampler"),
            count(study.counts.len() as u64, "sample count"),
            study.runs,
            count(threads as u64, "thread")
        ),
        study.memory(threads),
    )
}

/// The study `nyquist converge ARGS --json` prints (without `--dims`), run on `threads` threads
/// with `progress(done, total)` after each task; the same numbers whatever the thread count.
///
/// ```
/// use nyquist_lab::study::{convergence::{ConvergeSpec, json_report}, unit_square::SquareIntegrand};
/// let spec = ConvergeSpec { samplers: vec!["stratified".into()],
///                           integrands: vec![SquareIntegrand::Disk], min_spp: 16, max_spp: 256,
///                           runs: 8, ..ConvergeSpec::default() };
/// let json = json_report(&spec, 1, &|_, _| {}).unwrap();
/// assert!(json.starts_with("{\"runs\":8,") && json.contains("\"sampler\":\"stratified\""));
/// ```
///
/// # Errors
/// As `nyquist converge` reports them (one line naming the flag).
pub fn json_report(
    args: &ConvergeSpec,
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<String> {
    if args.dims.is_some() {
        bail!("--dims: Genz's study prints a table only");
    }
    let study = study(args, &mut Vec::new())?;
    check_memory(&study, threads)?;
    let start = Stopwatch::start();
    let outcome = study
        .run_with_progress(threads, progress)
        .map_err(study_error)?;
    Ok(json(&study, &outcome, args, threads, start.seconds()))
}

/// A slope for the table: two decimals, or `-` where there is none.
fn slope_text(s: Option<f64>) -> String {
    s.map_or_else(|| "-".to_owned(), |s| format!("{s:.2}"))
}

/// The Markdown table: one row per sampler, per integrand the slope and the RMSE at the
/// largest N.
pub fn table(
    study: &Study<Integrand>,
    o: &Outcome<Integrand>,
    args: &ConvergeSpec,
    threads: usize,
    seconds: f64,
) -> String {
    let mut s = format!(
        "Slope of log RMSE against log N (least squares over N = {}, {}, …, {}; {} per N, seeds \
         hashed from --seed {}{}), with the RMSE at N = {} in brackets{}\n\n",
        args.min_spp,
        2 * args.min_spp,
        args.max_spp,
        count(study.runs, "independent run"),
        study.seed,
        study.spp_hint.map_or_else(String::new, |h| format!(
            "; every sampler made for --spp-hint {h} and drawing N"
        )),
        args.max_spp,
        args.plot
            .as_ref()
            .map_or_else(String::new, |p| format!("; plot: {}", p.display()))
    );
    s.push_str("| sampler |");
    let mut rule = String::from("|---|");
    for f in &study.integrands {
        s.push_str(&format!(" {} |", f.name()));
        rule.push_str("---:|");
    }
    s.push('\n');
    s.push_str(&rule);
    s.push('\n');
    let ni = study.integrands.len();
    for row in o.curves.chunks(ni.max(1)) {
        let Some(first) = row.first() else { continue };
        s.push_str(&format!("| {} |", first.sampler));
        for c in row {
            let last = c.rmse.last().copied().unwrap_or(f64::NAN);
            s.push_str(&format!(" {} ({last:.1e}) |", slope_text(c.slope)));
        }
        s.push('\n');
    }
    let rounded: Vec<String> = o
        .curves
        .chunks(ni.max(1))
        .filter_map(|row| row.first())
        .filter(|c| c.spp != study.counts)
        .map(|c| {
            format!(
                "{} uses {} spp",
                c.sampler,
                c.spp
                    .iter()
                    .map(u32::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        })
        .collect();
    s.push('\n');
    if let Some(line) = super::missing_slopes(&o.curves, |f| f.name().to_owned()) {
        s.push_str(&line);
        s.push('\n');
    }
    if !rounded.is_empty() {
        s.push_str(&format!(
            "Rounded sample counts (slopes fit the counts used): {}\n",
            rounded.join("; ")
        ));
    }
    s.push_str(&format!(
        "Exact integrals: {}\n",
        study
            .integrands
            .iter()
            .map(|f| format!("{} {:.6}", f.name(), f.integral()))
            .collect::<Vec<_>>()
            .join(", ")
    ));
    s.push_str(&format!(
        "{} × {} N × {}: {:.1} M samples in {seconds:.2} s on {threads} thread{}\n",
        count(study.samplers.len() as u64, "sampler"),
        study.counts.len(),
        count(study.runs, "run"),
        o.samples as f64 / 1e6,
        if threads == 1 { "" } else { "s" }
    ));
    s
}

/// One JSON object: the study, the exact integrals and every curve.
pub fn json(
    study: &Study<Integrand>,
    o: &Outcome<Integrand>,
    args: &ConvergeSpec,
    threads: usize,
    seconds: f64,
) -> String {
    let list = |v: Vec<String>| v.join(",");
    let integrands = list(
        study
            .integrands
            .iter()
            .map(|f| {
                format!(
                    "{{\"name\":{},\"reference\":{}}}",
                    json_string(f.name()),
                    json_number(f.integral())
                )
            })
            .collect(),
    );
    let curves = list(
        o.curves
            .iter()
            .map(|c| {
                format!(
                    "{{\"sampler\":{},\"integrand\":{},\"slope\":{},\"spp\":[{}],\"rmse\":[{}]}}",
                    json_string(&c.sampler),
                    json_string(c.integrand.name()),
                    c.slope.map_or_else(|| "null".to_owned(), json_number),
                    list(c.spp.iter().map(u32::to_string).collect()),
                    list(c.rmse.iter().map(|&e| json_number(e)).collect()),
                )
            })
            .collect(),
    );
    format!(
        "{{\"runs\":{},\"seed\":{},\"min_spp\":{},\"max_spp\":{},\"spp_hint\":{},\"counts\":[{}],\"plot\":{},\"threads\":{threads},\"seconds\":{},\"samples\":{},\"integrands\":[{integrands}],\"curves\":[{curves}]}}\n",
        study.runs,
        study.seed,
        args.min_spp,
        args.max_spp,
        study
            .spp_hint
            .map_or_else(|| "null".to_owned(), |h| h.to_string()),
        list(study.counts.iter().map(u32::to_string).collect()),
        args.plot
            .as_ref()
            .map_or_else(|| "null".to_owned(), |p| json_string(&p.to_string_lossy())),
        json_number(seconds),
        o.samples,
    )
}

/// The command line that reproduces a study (every flag written out), the plot's title.
///
/// ```
/// use nyquist_lab::study::convergence::command;
/// use nyquist_lab::study::{Study, unit_square::SquareIntegrand as Integrand};
/// let s = Study { samplers: vec!["random".into()], integrands: vec![Integrand::Disk],
///                 counts: vec![16, 32], runs: 8, seed: 1, spp_hint: None };
/// assert_eq!(command(&s), "nyquist converge --samplers random --integrands disk \
///     --min-spp 16 --max-spp 32 --runs 8 --seed 1");
/// ```
pub fn command(study: &Study<Integrand>) -> String {
    format!(
        "nyquist converge --samplers {} --integrands {} --min-spp {} --max-spp {} --runs {} --seed {}{}",
        study.samplers.join(","),
        study
            .integrands
            .iter()
            .map(|f| f.name())
            .collect::<Vec<_>>()
            .join(","),
        study.counts.first().copied().unwrap_or(1),
        study.counts.last().copied().unwrap_or(1),
        study.runs,
        study.seed,
        study
            .spp_hint
            .map_or_else(String::new, |h| format!(" --spp-hint {h}"))
    )
}

/// Genz's Markdown table: per sampler, each family's slope and relative RMSE at the largest count.
fn genz_table(curves: &[Curve<Genz>], dims: u32, runs: u32) -> String {
    let mut s = format!(
        "Genz families in {dims} dimensions, {}: slope of log relative RMSE against log N, \
         and relative RMSE at the largest N.\n\n| sampler |",
        count(runs, "run")
    );
    for f in Family::ALL {
        let _ = write!(s, " {} |", f.name());
    }
    s += "\n|---|";
    s += &"---|".repeat(Family::ALL.len());
    s.push('\n');
    for row in curves.chunks(Family::ALL.len()) {
        let _ = write!(s, "| {} |", row[0].sampler);
        for c in row {
            let slope = c
                .slope
                .map_or_else(|| "-".to_owned(), |v| format!("{v:.2}"));
            let last = c.rmse.last().copied().unwrap_or(f64::NAN);
            let _ = write!(s, " {slope} ({last:.1e}) |");
        }
        s.push('\n');
    }
    if let Some(line) = super::missing_slopes(curves, |f| f.family.name().to_owned()) {
        s.push('\n');
        s.push_str(&line);
        s.push('\n');
    }
    s
}

/// The table `nyquist converge --dims D` prints: Genz's families ([`super::genz`]) in `dims`
/// dimensions, run on `threads` threads.
///
/// # Errors
/// Flags that do not apply, bad sample counts, unknown samplers.
pub fn genz_report(args: &ConvergeSpec, dims: u32, threads: usize) -> Result<String> {
    if args.plot.is_some() || args.json {
        bail!("--dims {dims}: --plot and --json apply to the 2-D study only");
    }
    if !args.integrands.is_empty() {
        bail!(
            "--dims {dims} --integrands: Genz's six families replace the 2-D integrands (give \
             one or the other)"
        );
    }
    for (flag, n) in [("--min-spp", args.min_spp), ("--max-spp", args.max_spp)] {
        if !n.is_power_of_two() || n > MAX_SPP {
            bail!("{flag} {n}: a power of two up to {}", MAX_SPP);
        }
    }
    if args.min_spp >= args.max_spp {
        bail!(
            "--min-spp {} --max-spp {}: need at least two sample counts",
            args.min_spp,
            args.max_spp
        );
    }
    let samplers = samplers(args);
    for name in &samplers {
        let base = name.strip_suffix("-plain").unwrap_or(name);
        if let Some(max) = nyquist::sampler::spp_limit(base)
            && args.spp_hint.unwrap_or(args.max_spp) > max
        {
            bail!(
                "--samplers {name}: takes at most {max} samples per pixel (give {} {max} or less)",
                if args.spp_hint.is_some() {
                    "--spp-hint"
                } else {
                    "--max-spp"
                }
            );
        }
    }
    let counts = powers_of_two(args.min_spp, args.max_spp);
    let study = Study {
        samplers,
        integrands: Genz::all(dims as usize),
        counts,
        runs: args.runs,
        seed: args.seed,
        spp_hint: args.spp_hint,
    };
    check_memory(&study, threads)?;
    let curves = study.run(threads).map_err(study_error)?.curves;
    Ok(genz_table(&curves, dims, args.runs))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_samplers_fail_before_any_work() {
        let s = Study {
            samplers: vec!["random".into(), "nope".into()],
            integrands: vec![Integrand::Disk],
            counts: vec![16],
            runs: 2,
            seed: 0,
            spp_hint: None,
        };
        let e = study_error(s.run(1).unwrap_err()).to_string();
        assert!(e.starts_with("--samplers nope: unknown sampler"), "{e}");
        let s = Study {
            samplers: vec!["best-candidate".into()],
            counts: vec![4096, 8192],
            ..s
        };
        let e = study_error(s.run(1).unwrap_err()).to_string();
        assert!(e.contains("best-candidate at 8192 spp"), "{e}");
    }
}
