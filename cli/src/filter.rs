//! `nyquist filter`: print a reconstruction filter on a grid, its precomputed table, its
//! integral, and plot its profile and frequency response.

use crate::output::to_stdout_or_file;
use anyhow::{Context, Result};
use clap::{Args, ValueEnum};
use nyquist::filter::{Axis, Filter, FilterKind, FilterTable, Interpolation};
pub use nyquist_lab::filter::{profile, spectrum};
use std::io::Write;
use std::path::PathBuf;

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
    /// Filter spec `name[:key=value,…]`: box, triangle, gaussian, mitchell, catmull-rom,
    /// blackman-harris, lanczos; keys radius, rx, ry, alpha, sigma (gaussian), b, c (mitchell),
    /// tau (lanczos).
    #[arg(long, value_name = "SPEC", value_parser = parse_spec)]
    pub filter: FilterKind,
    /// Grid points per axis over [−rx, rx] × [−ry, ry], ends included.
    #[arg(long, value_name = "N", default_value_t = 9,
          value_parser = nyquist_lab::flags::whole(1u32, 4096))]
    pub grid: u32,
    /// Print the precomputed 16 × 16 lookup table (the quadrant [0, rx] × [0, ry]) instead of
    /// the grid.
    #[arg(long)]
    pub table: bool,
    /// Output format.
    #[arg(long, value_enum, default_value = "csv")]
    pub format: Format,
    /// Also draw the 1D profile and its frequency response (|Fourier transform|): SVG for
    /// FILE.svg, PNG for FILE.png.
    #[arg(long, value_name = "FILE.png|FILE.svg")]
    pub plot: Option<PathBuf>,
}

fn parse_spec(s: &str) -> std::result::Result<FilterKind, String> {
    FilterKind::parse(s).map_err(|e| e.to_string())
}

/// Runs the subcommand: rows on stdout, `radius` and `integral` lines on stderr.
pub fn run(args: &FilterArgs) -> Result<()> {
    if let Some(path) = &args.plot {
        crate::pictures::kind_of(path, "--plot")?;
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
        nyquist_lab::memory::check(
            &format!("--grid {n}"),
            nyquist_lab::memory::bytes(u64::from(n) * u64::from(n), 12),
        )?;
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
        crate::pictures::save(&Plot { filter: f }, path, "--plot")?;
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

/// Size of one panel of the filter plot.
const PANEL: (u32, u32) = (560, 400);
/// Margin around and between the panels.
const MARGIN: u32 = 16;
/// Height of the title block.
const HEADER: u32 = 58;
/// Points per curve.
const STEPS: usize = 600;

/// Two panels: the 1D profile over [−r, r], and |F(ν)| / |F(0)| for ν ∈ [0, 2] cycles per
/// pixel with the Nyquist limit ν = ½ marked.
struct Plot<'a> {
    filter: &'a FilterKind,
}

#[cfg(not(target_family = "wasm"))]
impl nyquist_lab::plot::Figure for Plot<'_> {
    fn size(&self) -> (u32, u32) {
        (3 * MARGIN + 2 * PANEL.0, 2 * MARGIN + HEADER + PANEL.1)
    }

    fn draw<DB: plotters::prelude::DrawingBackend>(
        &self,
        root: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    ) -> Result<Vec<nyquist_lab::plot::Raster>>
    where
        DB::ErrorType: 'static,
    {
        use nyquist_lab::plot::{Axes, GUIDE, INK, color, font, panel, title};
        use plotters::prelude::*;
        use plotters::style::text_anchor::{HPos, Pos, VPos};
        let f: &dyn Filter = self.filter.as_dyn();
        let m = MARGIN as i32;
        let (w, _) = self.size();
        let text = format!("nyquist filter --filter {}", self.filter);
        let used = title(root, &text, (m, m), w - 2 * MARGIN, &[(18.0, 1), (14.0, 2)])?;
        let [rx, ry] = f.radius();
        let separable = f.eval_1d(Axis::X, 0.0).is_some();
        root.draw_text(
            &format!(
                "radius {rx} × {ry}, integral {}; {}",
                f.integral(),
                if separable {
                    "separable: the x factor shown"
                } else {
                    "not separable: the profile f(x, 0) shown"
                }
            ),
            &font(14.0).color(&INK),
            (m, m + used + 3),
        )?;
        let r = f64::from(rx);
        let prof: Vec<(f64, f64)> = (0..=STEPS)
            .map(|i| {
                let x = -r + 2.0 * r * i as f64 / STEPS as f64;
                (x, profile(f, x as f32))
            })
            .collect();
        let dc = spectrum(f, 0.0).max(1e-300);
        let spec: Vec<(f64, f64)> = (0..=STEPS / 2)
            .map(|i| {
                let nu = 2.0 * i as f64 / (STEPS / 2) as f64;
                (nu, spectrum(f, nu) / dc)
            })
            .collect();
        let range = |v: &[(f64, f64)]| {
            let lo = v.iter().map(|p| p.1).fold(0.0f64, f64::min);
            let hi = v.iter().map(|p| p.1).fold(0.0f64, f64::max).max(1e-12);
            let pad = 0.06 * (hi - lo);
            (lo - if lo < 0.0 { pad } else { 0.0 })..(hi + pad)
        };
        let top = m + HEADER as i32;
        for (k, (points, x_range)) in [(&prof, -r..r), (&spec, 0.0..2.0)].into_iter().enumerate() {
            let x0 = m + k as i32 * (PANEL.0 + MARGIN) as i32;
            let area = root.clone().shrink((x0, top), PANEL);
            let mut axes = Axes::linear(x_range, range(points));
            if k == 0 {
                axes.caption = "profile".to_owned();
                axes.x_desc = "x (pixels)".to_owned();
                axes.y_desc = if separable { "f(x)" } else { "f(x, 0)" }.to_owned();
            } else {
                axes.caption = "frequency response".to_owned();
                axes.x_desc = "ν (cycles per pixel)".to_owned();
                axes.y_desc = "|F(ν)| / |F(0)|".to_owned();
            }
            let mut chart = panel(&area, &axes)?;
            // The zero line.
            chart.draw_series(std::iter::once(PathElement::new(
                vec![(axes.x.start, 0.0), (axes.x.end, 0.0)],
                GUIDE.stroke_width(1),
            )))?;
            if k == 1 {
                let (a, b) = ((0.5, axes.y.start), (0.5, axes.y.end));
                chart.draw_series(DashedLineSeries::new([a, b], 6, 4, GUIDE.stroke_width(1)))?;
                let at = chart.backend_coord(&b);
                root.draw_text(
                    "Nyquist ν = ½",
                    &font(13.0)
                        .color(&GUIDE)
                        .pos(Pos::new(HPos::Left, VPos::Top)),
                    (at.0 + 5, at.1 + 6),
                )?;
            }
            chart.draw_series(LineSeries::new(
                points.iter().copied(),
                color(0).stroke_width(2),
            ))?;
        }
        Ok(Vec::new())
    }
}
