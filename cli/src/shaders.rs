//! `nyquist shaders`: the samplers as shader code (nyquist-gpu): the WGSL source and GLSL 450,
//! HLSL, MSL and SPIR-V emitted from it, one file per language in a folder, or a check that a
//! folder holds exactly what this build would write.

use crate::output::write_atomic;
use anyhow::{Result, bail};
use clap::Args;
use nyquist_gpu::{Language, emit};
use std::path::PathBuf;

/// Arguments of `nyquist shaders`.
#[derive(Debug, Args)]
#[command(after_help = "Example: nyquist shaders --lang glsl,spirv -o shaders/")]
pub struct ShadersArgs {
    /// Languages, comma-separated: wgsl, glsl, hlsl, msl, spirv, or all.
    #[arg(long, default_value = "all", value_parser = parse_languages)]
    pub lang: Languages,
    /// Folder to write nyquist.wgsl, nyquist.comp.glsl, nyquist.hlsl, nyquist.metal and
    /// nyquist.spv into (it must exist).
    #[arg(
        short,
        long,
        value_name = "DIR",
        required_unless_present_any = ["check", "costs"]
    )]
    pub output: Option<PathBuf>,
    /// Compare the files in DIR with what would be written, write nothing, and fail (one
    /// line, status 2) naming every file that differs or is missing.
    #[arg(long, value_name = "DIR", conflicts_with = "output")]
    pub check: Option<PathBuf>,
    /// Print each pixel sampler's size in SPIR-V instructions (camera sample, get_1d, get_2d,
    /// each with everything it calls) as a Markdown table, and write nothing.
    #[arg(long, conflicts_with_all = ["output", "check"])]
    pub costs: bool,
}

/// A set of languages, in [`Language::ALL`]'s order, without repeats.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Languages(pub Vec<Language>);

/// Parses `--lang`: language names separated by commas (ASCII case ignored), or `all`.
///
/// ```
/// use nyquist_cli::shaders::parse_languages;
/// use nyquist_gpu::Language;
/// assert_eq!(parse_languages("spirv,GLSL").unwrap().0, [Language::Glsl, Language::SpirV]);
/// assert_eq!(parse_languages("all").unwrap().0.len(), 5);
/// assert!(parse_languages("cuda").is_err());
/// ```
pub fn parse_languages(s: &str) -> Result<Languages, String> {
    let names = || {
        Language::ALL
            .iter()
            .map(|l| l.name())
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut picked = [false; Language::ALL.len()];
    for part in s.split(',') {
        let part = part.trim();
        if part.eq_ignore_ascii_case("all") {
            picked = [true; Language::ALL.len()];
            continue;
        }
        match Language::ALL
            .iter()
            .position(|l| l.name().eq_ignore_ascii_case(part))
        {
            Some(i) => picked[i] = true,
            None => {
                return Err(format!(
                    "'{part}' is not a shader language (expected {}, or all)",
                    names()
                ));
            }
        }
    }
    Ok(Languages(
        Language::ALL
            .into_iter()
            .zip(picked)
            .filter_map(|(l, p)| p.then_some(l))
            .collect(),
    ))
}

/// Runs `nyquist shaders`.
pub fn run(args: &ShadersArgs) -> Result<()> {
    if args.costs {
        return crate::output::print(&nyquist_gpu::costs::sampler_table()?);
    }
    let (dir, flag) = match (&args.output, &args.check) {
        (Some(dir), _) => (dir, "--output"),
        (None, Some(dir)) => (dir, "--check"),
        (None, None) => bail!("--output: a folder is required (or --check DIR, or --costs)"),
    };
    if !dir.is_dir() {
        bail!("{flag} {}: not an existing folder", dir.display());
    }
    // Every language is emitted before anything is written: a failure leaves no file.
    let mut files = Vec::new();
    for &language in &args.lang.0 {
        files.push((language, emit(language)?));
    }
    if args.check.is_some() {
        let stale: Vec<&str> = files
            .iter()
            .filter(|(l, bytes)| {
                std::fs::read(dir.join(l.file_name())).ok().as_ref() != Some(bytes)
            })
            .map(|(l, _)| l.file_name())
            .collect();
        if !stale.is_empty() {
            bail!(
                "--check {}: stale or missing: {} (regenerate with nyquist shaders -o {})",
                dir.display(),
                stale.join(", "),
                dir.display()
            );
        }
        return Ok(());
    }
    for (language, bytes) in &files {
        let path = dir.join(language.file_name());
        write_atomic(&path, |w| Ok(w.write_all(bytes)?))?;
    }
    Ok(())
}
