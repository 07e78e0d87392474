//! The `nyquist` command line: parse → configure → call the library → exit code.
//!
//! Every error is one line on stderr and exit status 2; output files are written to a temporary
//! file beside the target and renamed into place, so a failure leaves nothing behind.
#![forbid(unsafe_code)]

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use nyquist_cli::{analyze, compare, converge, filter, mask, points, render, shaders, web};
use std::process::ExitCode;

/// Sampling and reconstruction for image synthesis: point sets, filters, test renders,
/// sampler comparison sheets and convergence studies.
#[derive(Debug, Parser)]
#[command(
    name = "nyquist",
    version,
    about,
    max_term_width = 100,
    after_long_help = "Exit status: 0 on success; 2 for bad input or output that cannot be \
    written (one line on stderr, and no file left behind); 141 (128 + SIGPIPE), with nothing \
    printed, when the reader of stdout goes away, e.g. `nyquist points --count 100000 | head -3`, \
    as `seq` or `cat` do; 130 or 143 when SIGINT or SIGTERM ends the run (a file being written \
    is removed first)."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// The most memory a run may plan to use, e.g. 512M, 4G or 1.5GiB. A run whose estimate
    /// (films, references, images, points, spectra) passes it is refused before it allocates
    /// [default: half of the physical memory, or of the address-space limit (`ulimit -v`) when
    /// that is lower].
    #[arg(long, global = true, value_name = "SIZE", value_parser = nyquist_lab::memory::parse_size)]
    max_memory: Option<u64>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Print the points of a sequence or sampler.
    ///
    /// Example: nyquist points --sampler halton --count 16 --dims 2
    Points(points::PointsArgs),
    /// Print a reconstruction filter on a grid or as its lookup table; plot its spectrum.
    ///
    /// Example: nyquist filter --filter mitchell:b=0.5,c=0.25 --grid 5
    Filter(filter::FilterArgs),
    /// Render a built-in scene with a sampler and a filter; measure it against a reference.
    ///
    /// Example: nyquist render --scene zoneplate --sampler sobol --spp 16 --filter mitchell -o zp.png
    Render(render::RenderArgs),
    /// Render a scene with every sampler × filter × spp in parallel: one labelled contact sheet
    /// (PNG), an RMSE table (Markdown) or JSON.
    ///
    /// Example: nyquist compare --samplers uniform,stratified,sobol --spp 1,16 -o sheet.png
    Compare(compare::CompareArgs),
    /// Measure a point set: star and L2 discrepancies, minimum distance and rho; optionally its
    /// periodogram as a PNG.
    ///
    /// Example: nyquist analyze --sampler sobol --count 256 --spectrum sobol.png
    Analyze(analyze::AnalyzeArgs),
    /// Convergence study: RMSE against N over independent scrambles on five test integrands
    /// (disk, triangle, step, gaussian, bilinear), the log-log slope per sampler, and a plot.
    ///
    /// Example: nyquist converge --samplers random,stratified,sobol --runs 64 --plot conv.png
    Converge(converge::ConvergeArgs),
    /// Generate a blue-noise threshold mask (void-and-cluster): PNG (8 or 16 bits) and
    /// OpenEXR, 1 to 4 decorrelated channels, tileable.
    ///
    /// Example: nyquist mask --size 128 --channels 4 -o mask.png -o mask.exr
    Mask(mask::MaskArgs),
    /// Write the samplers as shader code: WGSL, and GLSL 450, HLSL, MSL and SPIR-V emitted from
    /// it (bit for bit the library's values; docs/gpu.md).
    ///
    /// Example: nyquist shaders --lang glsl,spirv -o shaders/
    Shaders(shaders::ShadersArgs),
    /// Serve the browser explorer (points, spectra, aliasing, filters and convergence computed
    /// in the page by the library compiled to WebAssembly) on a loopback address.
    ///
    /// Example: bash web/serve.sh (builds the site, then runs nyquist web --root SITE)
    Web(web::WebArgs),
}

fn main() -> ExitCode {
    let cli = match command()
        .try_get_matches()
        .and_then(|m| Cli::from_arg_matches(&m))
    {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    nyquist_lab::memory::set_limit(cli.max_memory);
    if let Err(e) = nyquist_cli::output::remove_temporaries_on_signals() {
        eprintln!("nyquist: {e:#}");
        return ExitCode::from(2);
    }
    let result = match &cli.command {
        Command::Points(args) => points::run(args),
        Command::Filter(args) => filter::run(args),
        Command::Render(args) => render::run(args),
        Command::Compare(args) => compare::run(args),
        Command::Analyze(args) => analyze::run(args),
        Command::Converge(args) => converge::run(args),
        Command::Mask(args) => mask::run(args),
        Command::Shaders(args) => shaders::run(args),
        Command::Web(args) => web::run(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader of stdout went away: stop quietly, as Unix tools do.
        Err(e) if nyquist_cli::output::is_broken_pipe(&e) => {
            ExitCode::from(nyquist_cli::output::BROKEN_PIPE_STATUS)
        }
        Err(e) => {
            eprintln!("nyquist: {}", one_line(&format!("{e:#}")));
            ExitCode::from(2)
        }
    }
}

/// The command line's parser: every flag that takes a value also takes one that starts with a
/// hyphen, so `--spp -1` and `--size -5x5` reach the flag's own parser, which names its range,
/// instead of reading as an unknown flag `-1`.
fn command() -> clap::Command {
    fn hyphen_values(cmd: clap::Command) -> clap::Command {
        let ids: Vec<clap::Id> = cmd
            .get_arguments()
            .filter(|a| a.get_long().is_some() && a.get_action().takes_values())
            .map(|a| a.get_id().clone())
            .collect();
        let cmd = ids
            .iter()
            .fold(cmd, |c, id| c.mut_arg(id, |a| a.allow_hyphen_values(true)));
        cmd.mut_subcommands(hyphen_values)
    }
    hyphen_values(Cli::command())
}

/// Help and version go to stdout with status 0; every parse error becomes one line, status 2.
fn clap_exit(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    match e.kind() {
        ErrorKind::DisplayHelp
        | ErrorKind::DisplayVersion
        | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = e.print();
            if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                ExitCode::from(2)
            } else {
                ExitCode::SUCCESS
            }
        }
        _ if empty_value(e).is_some() => {
            eprintln!("nyquist: {}", empty_value(e).unwrap_or_default());
            ExitCode::from(2)
        }
        ErrorKind::ValueValidation if rejected_value(e).is_some() => {
            eprintln!("nyquist: {}", rejected_value(e).unwrap_or_default());
            ExitCode::from(2)
        }
        _ => {
            let text = e.render().to_string();
            let text = text.strip_prefix("error: ").unwrap_or(&text);
            eprintln!("nyquist: {}", one_line(text));
            ExitCode::from(2)
        }
    }
}

/// The message for an empty value (`--samplers halton,,sobol`, `--spp 1,,4`, `--samplers=`):
/// the flag, the whole value as typed, and the values the flag takes where clap lists them.
/// Clap itself says "a value is required … but none was supplied" without naming the list.
fn empty_value(e: &clap::Error) -> Option<String> {
    use clap::error::{ContextKind, ContextValue};
    match e.get(ContextKind::InvalidValue) {
        Some(ContextValue::String(v)) if v.is_empty() => {}
        _ => return None,
    }
    let Some(ContextValue::String(arg)) = e.get(ContextKind::InvalidArg) else {
        return None;
    };
    let flag = arg.split([' ', '=']).next().unwrap_or(arg);
    // The value as typed: `--flag value` or `--flag=value`.
    let args: Vec<String> = std::env::args().collect();
    let typed = args.iter().enumerate().rev().find_map(|(i, a)| {
        if a == flag {
            args.get(i + 1).cloned()
        } else {
            a.strip_prefix(flag)?.strip_prefix('=').map(str::to_owned)
        }
    });
    let list = typed.as_deref().is_some_and(|t| t.contains(','));
    let mut msg = match typed {
        Some(t) if list => format!("{flag} '{t}': an empty item in the comma-separated list"),
        _ => format!("{flag}: a value is required"),
    };
    if let Some(ContextValue::Strings(valid)) = e.get(ContextKind::ValidValue)
        && !valid.is_empty()
    {
        msg.push_str(&format!(" (possible values: {})", valid.join(", ")));
    }
    Some(msg)
}

/// A value the flag's parser refused, as `FLAG VALUE: REASON` (`--spp -1: not in 1 ..= 1048576`),
/// where clap would say "invalid value '-1' for '--spp <SPP>': …". A value with spaces, or an
/// empty one, is quoted.
fn rejected_value(e: &clap::Error) -> Option<String> {
    use clap::error::{ContextKind, ContextValue};
    use std::error::Error as _;
    let Some(ContextValue::String(arg)) = e.get(ContextKind::InvalidArg) else {
        return None;
    };
    let Some(ContextValue::String(value)) = e.get(ContextKind::InvalidValue) else {
        return None;
    };
    let flag = arg.split([' ', '=']).next().unwrap_or(arg);
    let reason = e.source()?.to_string();
    let shown = if value.is_empty() || value.contains(char::is_whitespace) {
        format!("'{value}'")
    } else {
        value.clone()
    };
    Some(one_line(&format!("{flag} {shown}: {reason}")))
}

/// Folds a multi-line message into one line, dropping clap's usage and "--help" hints: lines
/// are joined with "; ", except after a line ending in ':' (a heading and its list), which is
/// followed by a space.
fn one_line(text: &str) -> String {
    let mut out = String::new();
    for l in text.lines().map(str::trim).filter(|l| {
        !l.is_empty() && !l.starts_with("Usage:") && !l.starts_with("For more information")
    }) {
        if !out.is_empty() {
            out.push_str(if out.ends_with(':') { " " } else { "; " });
        }
        out.push_str(l);
    }
    out
}
