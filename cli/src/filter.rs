//! `nyquist filter`: print a reconstruction filter on a grid, its precomputed table, its
//! integral, and plot its profile and frequency response.

use crate::output::{to_stdout_or_file, write_atomic};
use anyhow::{Context, Result};
use clap::{Args, ValueEnum};
use nyquist::filter::{Axis, Filter, FilterKind, FilterTable, Interpolation};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Output formats of `filter`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// One `x,y,value` row per line, no header.
    Csv,
    /// One JSON array of `{"x": …, "y": …, "value": …}` objects.
    Json,
}

/// Arguments of `nyquist filter`.
#[derive(Debug, Args)]
#[command(
    after_help = "Example: nyquist filter --filter mitchell:b=0.5,c=0.25 --grid 9 --plot m.png"
)]
pub struct FilterArgs {
    /// Filter spec `name[:key=value,…]`: box, triangle, gaussian, mitchell, lanczos; keys
    /// radius, rx, ry, alpha, sigma (gaussian), b, c (mitchell), tau (lanczos).
    #[arg(long, value_name = "SPEC", value_parser = parse_spec)]
    pub filter: FilterKind,
    /// Grid points per axis over [−rx, rx] × [−ry, ry], ends included.
    #[arg(long, value_name = "N", default_value_t = 9,
          value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub grid: u32,
    /// Print the precomputed 16 × 16 lookup table (the quadrant [0, rx] × [0, ry]) instead of
    /// the grid.
    #[arg(long)]
    pub table: bool,
    /// Output format.
    #[arg(long, value_enum, default_value = "csv")]
    pub format: Format,
    /// Also draw the 1D profile and its frequency response (|Fourier transform|) to a PNG.
    #[arg(long, value_name = "FILE.png")]
    pub plot: Option<PathBuf>,
}

fn parse_spec(s: &str) -> std::result::Result<FilterKind, String> {
    FilterKind::parse(s).map_err(|e| e.to_string())
}

/// Runs the subcommand: rows on stdout, `radius` and `integral` lines on stderr.
pub fn run(args: &FilterArgs) -> Result<()> {
    if let Some(path) = &args.plot {
        crate::output::check_output(path, "--plot", &["png"])?;
    }
    let f = &args.filter;
    let [rx, ry] = f.radius();
    let rows = if args.table {
        let table: FilterTable =
            FilterTable::new(f, Interpolation::Linear).context("--filter: cannot tabulate")?;
        let v = table.view();
        let mut rows = Vec::with_capacity(v.len() * v.len());
        for j in 0..v.len() {
            for i in 0..v.len() {
                let (x, y) = (v.sample_point(Axis::X, i), v.sample_point(Axis::Y, j));
                rows.push([x, y, v.entry(i, j)]);
            }
        }
        rows
    } else {
        let n = args.grid;
        let at = |k: u32, r: f32| {
            if n == 1 {
                0.0
            } else {
                (-f64::from(r) + 2.0 * f64::from(r) * f64::from(k) / f64::from(n - 1)) as f32
            }
        };
        let mut rows = Vec::with_capacity((n as usize) * (n as usize));
        for j in 0..n {
            for i in 0..n {
                let (x, y) = (at(i, rx), at(j, ry));
                rows.push([x, y, f.eval(x, y)]);
            }
        }
        rows
    };
    if let Some(path) = &args.plot {
        plot(f, path)?;
    }
    to_stdout_or_file(None, |w| write_rows(w, &rows, args.format))?;
    eprintln!("radius {rx} {ry}");
    eprintln!("integral {}", f.integral());
    Ok(())
}

/// Writes the rows; `-0` (a negative lobe's zero, or a grid point at the centre) prints as `0`.
fn write_rows(w: &mut dyn Write, rows: &[[f32; 3]], format: Format) -> Result<()> {
    let rows = rows.iter().map(|r| r.map(|v| v + 0.0));
    match format {
        Format::Csv => {
            for [x, y, v] in rows {
                writeln!(w, "{x},{y},{v}")?;
            }
        }
        Format::Json => {
            write!(w, "[")?;
            for (k, [x, y, v]) in rows.enumerate() {
                let sep = if k == 0 { "" } else { "," };
                write!(w, "{sep}{{\"x\":{x},\"y\":{y},\"value\":{v}}}")?;
            }
            writeln!(w, "]")?;
        }
    }
    Ok(())
}

/// The 1D profile along x: the separable factor, or `f(x, 0)` for a non-separable filter.
fn profile(f: &dyn Filter, x: f32) -> f64 {
    f64::from(f.eval_1d(Axis::X, x).unwrap_or_else(|| f.eval(x, 0.0)))
}

/// `|F(ν)| = |∫ f(x) e^(−2πiνx) dx|` by the midpoint rule on 4096 cells over [−r, r].
fn spectrum(f: &dyn Filter, nu: f64) -> f64 {
    const CELLS: u32 = 4096;
    let r = f64::from(f.radius()[0]);
    let h = 2.0 * r / f64::from(CELLS);
    let (mut re, mut im) = (0.0f64, 0.0f64);
    for k in 0..CELLS {
        let x = -r + (f64::from(k) + 0.5) * h;
        let v = profile(f, x as f32);
        let phase = 2.0 * std::f64::consts::PI * nu * x;
        re += v * phase.cos();
        im -= v * phase.sin();
    }
    (re * h).hypot(im * h)
}

/// Two panels, 480 × 320 each: the profile over [−r, r] (scaled to its peak), and |F(ν)| for
/// ν ∈ [0, 2] cycles per pixel scaled to |F(0)|, with a grey line at the Nyquist limit ν = ½.
fn plot(f: &FilterKind, path: &Path) -> Result<()> {
    const W: usize = 480;
    const H: usize = 320;
    const M: usize = 24; // margin
    let f: &dyn Filter = f.as_dyn();
    let mut img = vec![255u8; 2 * W * H * 3];
    let mut put = |x: usize, y: usize, c: [u8; 3]| {
        if x < 2 * W && y < H {
            img[(y * 2 * W + x) * 3..][..3].copy_from_slice(&c);
        }
    };
    let r = f64::from(f.radius()[0]);
    let xs: Vec<f64> = (0..W - 2 * M)
        .map(|i| -r + 2.0 * r * i as f64 / (W - 2 * M - 1) as f64)
        .collect();
    let prof: Vec<f64> = xs.iter().map(|&x| profile(f, x as f32)).collect();
    let nus: Vec<f64> = (0..W - 2 * M)
        .map(|i| 2.0 * i as f64 / (W - 2 * M - 1) as f64)
        .collect();
    let spec: Vec<f64> = nus.iter().map(|&nu| spectrum(f, nu)).collect();
    for (panel, values, nyquist) in [(0usize, &prof, None), (1, &spec, Some(0.5 / 2.0))] {
        let x0 = panel * W + M;
        let lo = values.iter().cloned().fold(0.0f64, f64::min);
        let hi = values.iter().cloned().fold(0.0f64, f64::max).max(1e-30);
        let to_y = |v: f64| {
            let t = (v - lo) / (hi - lo);
            (M as f64 + (1.0 - t) * (H - 2 * M) as f64).round() as usize
        };
        // Axes: the zero line and the left edge.
        for i in 0..W - 2 * M {
            put(x0 + i, to_y(0.0), [160, 160, 160]);
        }
        for y in M..H - M {
            put(x0, y, [0, 0, 0]);
            if let Some(t) = nyquist {
                put(
                    x0 + ((W - 2 * M - 1) as f64 * t) as usize,
                    y,
                    [200, 200, 200],
                );
            }
        }
        // The curve, joined vertically between neighbouring columns.
        let mut prev = to_y(values[0]);
        for (i, &v) in values.iter().enumerate() {
            let y = to_y(v);
            for yy in prev.min(y)..=prev.max(y) {
                put(x0 + i, yy, [20, 60, 200]);
            }
            prev = y;
        }
    }
    write_atomic(path, |w| {
        let mut enc = png::Encoder::new(w, (2 * W) as u32, H as u32);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let mut writer = enc.write_header().context("--plot: PNG header")?;
        writer.write_image_data(&img).context("--plot: PNG data")?;
        writer.finish().context("--plot: PNG end")?;
        Ok(())
    })
    .map_err(|e| anyhow::anyhow!("{}", format!("{e:#}").replace("--output", "--plot")))
}
