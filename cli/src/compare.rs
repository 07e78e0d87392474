//! `nyquist compare`: render one scene with every combination of samplers, filters and sample
//! counts, in parallel, and write one labelled contact sheet, a Markdown table and JSON.

use crate::progress::Progress;
use crate::render::{
    Rendered, SamplerName, ScrambleName, build_sampler, check_output, default_threads, json_number,
    json_string, parse_filter, parse_size, psnr, reference, reference_kind, render, rmse,
    tile_count,
};
use anyhow::{Result, anyhow, bail};
use clap::Args;
use nyquist::filter::FilterKind;
use nyquist::sampler::{NamedSampler, SCRAMBLE_NAMES, Sampler};
use nyquist_lab::clock::Stopwatch;
use nyquist_lab::raster::{Canvas, LINE, text_width};
use nyquist_lab::scene::Scene;
use std::fmt::Write as _;
use std::path::PathBuf;

/// Space between cells and around the sheet, in pixels.
pub const PAD: u32 = 8;
/// Gap between a crop and its label.
const GAP: u32 = 5;
/// Text lines under each crop: sampler; filter and spp; RMSE.
const LABEL_LINES: u32 = 3;
/// Title lines at the top of the sheet.
const TITLE_LINES: u32 = 2;
/// The most cells one sheet takes.
const MAX_CELLS: usize = 400;
/// The largest crop side.
const MAX_CROP: u32 = 256;

/// Filter specs as typed, with the filters they parse to.
#[derive(Clone, Debug)]
pub struct FilterList(pub Vec<(String, FilterKind)>);

/// Parses a comma-separated list of filter specs. A spec's own `key=value` pairs are also
/// separated by commas, so a piece with `=` and no `:` continues the spec before it:
/// `box,mitchell:b=0.5,c=0.25,gaussian` is three specs.
pub fn parse_filters(s: &str) -> Result<FilterList, String> {
    let mut specs: Vec<String> = Vec::new();
    for piece in s.split(',').map(str::trim) {
        match specs.last_mut() {
            Some(last) if piece.contains('=') && !piece.contains(':') => {
                last.push(',');
                last.push_str(piece);
            }
            _ => specs.push(piece.to_owned()),
        }
    }
    let mut out = Vec::with_capacity(specs.len());
    for spec in specs {
        if spec.is_empty() {
            return Err(format!(
                "'{s}' has an empty filter spec (e.g. box,mitchell)"
            ));
        }
        let f = parse_filter(&spec)?;
        out.push((spec, f));
    }
    Ok(FilterList(out))
}

/// Arguments of `nyquist compare`.
#[derive(Debug, Args)]
#[command(
    after_help = "Example: nyquist compare --samplers uniform,stratified,sobol \
    --filters box,gaussian:alpha=2,mitchell --spp 1,4,16 -o sheet.png"
)]
pub struct CompareArgs {
    /// The scene.
    #[arg(long, value_enum, default_value = "zoneplate")]
    pub scene: Scene,
    /// Samplers, comma-separated (one row of the sheet each).
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        default_value = "uniform,random,stratified,halton,best-candidate,sobol,zero-two,owen-sobol,zsobol,pmj02"
    )]
    pub samplers: Vec<SamplerName>,
    /// Filter specs, comma-separated (e.g. box,mitchell:b=0.5,c=0.25,gaussian:alpha=2).
    #[arg(long, value_name = "SPECS", default_value = "box,mitchell", value_parser = parse_filters)]
    pub filters: FilterList,
    /// Samples per pixel, comma-separated (uniform and stratified take a √spp × √spp grid for a
    /// square, else the squarest rectangle of spp cells).
    #[arg(long, value_delimiter = ',', default_value = "1,4,16",
          value_parser = nyquist_lab::flags::whole(1u32, 65536))]
    pub spp: Vec<u32>,
    /// Image size of every render (the sheet shows a crop of at most 256 × 256).
    #[arg(long, value_name = "WxH", default_value = "256x256", value_parser = parse_size)]
    pub size: [u32; 2],
    /// Worker threads [default: the number of cores]; renders run in parallel, one per thread.
    #[arg(long, value_parser = nyquist_lab::flags::whole(1u16, 1024))]
    pub threads: Option<u16>,
    /// Seed of every sampler.
    #[arg(long, default_value_t = 0, value_parser = nyquist_lab::flags::whole(0, u64::MAX))]
    pub seed: u64,
    /// Scramble of the halton, hammersley, sobol and zsobol rows (the other rows have none)
    /// [default: each sampler's own, as in `render`].
    #[arg(long, value_enum, value_name = "SCRAMBLE")]
    pub scramble: Option<ScrambleName>,
    /// The contact sheet (PNG) [default: compare.png; with --json, no sheet is written unless
    /// --output is given].
    #[arg(short, long, value_name = "FILE.png")]
    pub output: Option<PathBuf>,
    /// Print JSON (one entry per cell) instead of the Markdown table; writes no sheet unless
    /// --output is given.
    #[arg(long)]
    pub json: bool,
}

/// One render of the sheet.
struct Cell {
    sampler_name: SamplerName,
    sampler: NamedSampler,
    filter: usize,
    spp: u32,
    row: usize,
    column: usize,
}

/// The crop of a render the sheet shows, `[x, y, w, h]`: at most 256 × 256 pixels where the
/// scene aliases most. For the zone plate (and the disk and stripes) it is the quadrant from the
/// centre to the bottom-right corner: frequency 0 at its top-left corner, the Nyquist limit
/// (r = W/2) on the arc through its top-right and bottom-left corners, and frequencies above
/// Nyquist, up to 0.71 cycles per pixel, towards its bottom-right corner. For the checkerboard
/// it starts just above the horizon; for the edge it is centred.
pub fn crop(scene: Scene, size: [u32; 2]) -> [u32; 4] {
    let [w, h] = size;
    let cw = w.div_ceil(2).min(MAX_CROP);
    let ch = h.div_ceil(2).min(MAX_CROP);
    let (x, y) = match scene {
        Scene::Zoneplate | Scene::Disk | Scene::Stripes | Scene::Dots => (w / 2, h / 2),
        Scene::Checkerboard => (w / 2, ((h * 3) / 10).saturating_sub(ch / 8)),
        Scene::Edge => (w / 2 - cw / 2, h / 2 - ch / 2),
    };
    [x.min(w - cw), y.min(h - ch), cw, ch]
}

/// The three label lines of a cell.
fn label(sampler: SamplerName, filter: &str, spp: u32, rmse: f64, sampling: f64) -> [String; 3] {
    [
        sampler.name().to_owned(),
        format!("{filter} {spp}spp"),
        format!("RMSE {rmse:.4} ({sampling:.4})"),
    ]
}

/// Runs `nyquist compare`.
pub fn run(args: &CompareArgs) -> Result<()> {
    let output = sheet_path(args);
    if let Some(p) = &output {
        if crate::output::is_stdout(p) {
            bail!(
                "--output -: stdout carries the {}: give --output FILE.png",
                if args.json { "JSON" } else { "table" }
            );
        }
        check_output(p, "--output", &["png"])?;
    }
    if args.samplers.is_empty() {
        bail!("--samplers: give at least one sampler");
    }
    if args.spp.is_empty() {
        bail!("--spp: give at least one sample count");
    }
    let filters = &args.filters.0;
    let columns = filters.len() * args.spp.len();
    let count = args.samplers.len() * columns;
    if count > MAX_CELLS {
        bail!(
            "--samplers × --filters × --spp is {}; a sheet takes at most {MAX_CELLS}",
            nyquist_lab::words::count(count as u64, "render")
        );
    }
    let pixels = u64::from(args.size[0]) * u64::from(args.size[1]) * count as u64;
    if pixels > crate::render::MAX_PIXELS {
        bail!(
            "--size {}x{} × {} is more than {} pixels in all",
            args.size[0],
            args.size[1],
            nyquist_lab::words::count(count as u64, "render"),
            crate::render::MAX_PIXELS
        );
    }
    // Every render's image is kept for the sheet; up to one film per thread is rendering; the
    // references (the pixel means and one per filter) stay for the error table.
    let threads = args.threads.map_or_else(default_threads, usize::from);
    let per_pixel = count as u64 * crate::render::IMAGE_PIXEL_BYTES
        + threads as u64 * crate::render::FILM_PIXEL_BYTES
        + (filters.len() as u64 + 1) * 8;
    nyquist_lab::memory::check(
        &format!(
            "--size {}x{} × {}",
            args.size[0],
            args.size[1],
            nyquist_lab::words::count(count as u64, "render")
        ),
        nyquist_lab::memory::bytes(u64::from(args.size[0]) * u64::from(args.size[1]), per_pixel)
            .saturating_add(crate::render::render_bytes(args.scene, args.size, true)),
    )?;
    // Every sampler is built (and every combination checked) before anything renders.
    let mut cells = Vec::with_capacity(count);
    for (row, &name) in args.samplers.iter().enumerate() {
        for f in 0..filters.len() {
            for (k, &spp) in args.spp.iter().enumerate() {
                let scramble = args
                    .scramble
                    .filter(|_| SCRAMBLE_NAMES.contains(&name.name()));
                let sampler =
                    build_sampler(name, spp, args.size, args.seed, scramble).map_err(|e| {
                        anyhow!("{}", e.to_string().replace("--sampler ", "--samplers "))
                    })?;
                cells.push(Cell {
                    sampler_name: name,
                    sampler,
                    filter: f,
                    spp,
                    row,
                    column: f * args.spp.len() + k,
                });
            }
        }
    }
    let pixels = f64::from(args.size[0]) * f64::from(args.size[1]);
    let work: f64 = cells
        .iter()
        .map(|c| {
            pixels
                * f64::from(c.sampler.samples_per_pixel())
                * crate::render::footprint_pixels(args.size, &filters[c.filter].1)
        })
        .sum();
    let large = crate::render::warn_if_large(
        work,
        &format!("{count} render{}", if count == 1 { "" } else { "s" }),
    );
    let start = Stopwatch::start();
    let means = reference(args.scene, args.size, None, threads)?
        .ok_or_else(|| anyhow!("no reference for this scene"))?;
    let mut filtered = Vec::with_capacity(filters.len());
    for (_, f) in filters {
        filtered.push(reference(args.scene, args.size, Some(f), threads)?);
    }
    let results = render_cells(args, &cells, threads, large)?;
    let seconds = start.seconds();

    let errors: Vec<f64> = results.iter().map(|r| rmse(&r.image, &means)).collect();
    let sampling: Vec<f64> = cells
        .iter()
        .zip(&results)
        .map(|(c, r)| {
            filtered[c.filter]
                .as_ref()
                .map_or(f64::NAN, |f| rmse(&r.image, f))
        })
        .collect();
    let [cx, cy, cw, ch] = crop(args.scene, args.size);
    let labels: Vec<[String; 3]> = cells
        .iter()
        .zip(errors.iter().zip(&sampling))
        .map(|(c, (&e, &s))| {
            label(
                c.sampler_name,
                &filters[c.filter].0,
                c.sampler.samples_per_pixel(),
                e,
                s,
            )
        })
        .collect();
    let label_w = labels
        .iter()
        .flat_map(|l| l.iter().map(|s| text_width(s)))
        .max()
        .unwrap_or(0);
    let cell_w = cw.max(label_w);
    let cell_h = ch + GAP + LABEL_LINES * LINE;
    let rows = args.samplers.len() as u32;
    let title = [
        format!(
            "{} {}x{}, crop x {}..{} y {}..{}",
            args.scene.name(),
            args.size[0],
            args.size[1],
            cx,
            cx + cw,
            cy,
            cy + ch
        ),
        format!(
            "RMSE vs {} pixel means (vs converged same filter)",
            if args.scene == Scene::Zoneplate {
                "exact"
            } else {
                "1024spp"
            }
        ),
    ];
    let title_w = title.iter().map(|t| text_width(t)).max().unwrap_or(0);
    let sheet_w = (PAD + columns as u32 * (cell_w + PAD)).max(2 * PAD + title_w);
    let sheet_h = PAD + TITLE_LINES * LINE + PAD + rows * (cell_h + PAD);
    let mut sheet = Canvas::new(sheet_w, sheet_h, [255; 3]);
    for (i, t) in title.iter().enumerate() {
        sheet.text(i64::from(PAD), i64::from(PAD + i as u32 * LINE), t, [0; 3]);
    }
    let top = PAD + TITLE_LINES * LINE + PAD;
    for ((c, r), l) in cells.iter().zip(&results).zip(&labels) {
        let x = i64::from(PAD + c.column as u32 * (cell_w + PAD));
        let y = i64::from(top + c.row as u32 * (cell_h + PAD));
        sheet.blit(&r.image, cx, cy, cw, ch, x, y);
        for (i, line) in l.iter().enumerate() {
            let ly = y + i64::from(ch + GAP + i as u32 * LINE);
            sheet.text(x, ly, line, if i == 2 { [160, 0, 0] } else { [0; 3] });
        }
    }
    if let Some(p) = &output {
        crate::pictures::write_bytes(p, "--output", &sheet.png()?)?;
    }

    let samples: u64 = results.iter().map(|r| r.stats.samples).sum();
    let mut out = String::new();
    if args.json {
        let mut s = format!(
            "{{\"scene\":{},\"size\":[{},{}],\"reference\":{},\"output\":{},\"sheet\":{{\"width\":{sheet_w},\"height\":{sheet_h}}},\"crop\":{{\"x\":{cx},\"y\":{cy},\"width\":{cw},\"height\":{ch}}},\"threads\":{threads},\"seconds\":{},\"samples\":{samples},\"cells\":[",
            json_string(args.scene.name()),
            args.size[0],
            args.size[1],
            json_string(&reference_kind(args.scene)),
            output
                .as_ref()
                .map_or_else(|| "null".to_owned(), |p| json_string(&p.to_string_lossy())),
            json_number(seconds),
        );
        for (k, ((c, r), (&e, &smp))) in cells
            .iter()
            .zip(&results)
            .zip(errors.iter().zip(&sampling))
            .enumerate()
        {
            if k > 0 {
                s.push(',');
            }
            s.push_str(&format!(
                "{{\"sampler\":{},\"filter\":{},\"filter_spec\":{},\"spp\":{},\"spp_requested\":{},\"row\":{},\"column\":{},\"rmse\":{},\"psnr\":{},\"sampling_rmse\":{},\"samples\":{},\"rejected\":{},\"seconds\":{},\"samples_per_second\":{}}}",
                json_string(c.sampler_name.name()),
                json_string(&filters[c.filter].0),
                json_string(&filters[c.filter].1.to_string()),
                c.sampler.samples_per_pixel(),
                c.spp,
                c.row,
                c.column,
                json_number(e),
                json_number(psnr(e)),
                json_number(smp),
                r.stats.samples,
                r.stats.rejected,
                json_number(r.seconds),
                json_number(r.stats.samples as f64 / r.seconds.max(1e-9)),
            ));
        }
        s.push_str("]}");
        writeln!(out, "{s}")?;
    } else {
        writeln!(
            out,
            "RMSE of {} {}x{} against the {}, and in brackets against the converged image through the same filter (sampling error alone); sheet: {}",
            args.scene.name(),
            args.size[0],
            args.size[1],
            reference_kind(args.scene),
            output
                .as_ref()
                .map_or_else(|| "none".to_owned(), |p| p.display().to_string())
        )?;
        writeln!(out)?;
        let mut header = String::from("| sampler |");
        let mut rule = String::from("|---|");
        for (spec, _) in filters {
            for spp in &args.spp {
                header.push_str(&format!(" {spec} {spp} |"));
                rule.push_str("---:|");
            }
        }
        writeln!(out, "{header}")?;
        writeln!(out, "{rule}")?;
        for (row, name) in args.samplers.iter().enumerate() {
            let mut line = format!("| {} |", name.name());
            for (c, (&e, &smp)) in cells
                .iter()
                .zip(errors.iter().zip(&sampling))
                .filter(|(c, _)| c.row == row)
            {
                line.push_str(&format!(" {e:.4} ({smp:.4})"));
                if c.sampler.samples_per_pixel() != c.spp {
                    line.push_str(&format!(" [{} spp]", c.sampler.samples_per_pixel()));
                }
                line.push_str(" |");
            }
            writeln!(out, "{line}")?;
        }
        writeln!(out)?;
        writeln!(
            out,
            "{}, {:.1} M samples in {seconds:.2} s on {threads} thread{}",
            nyquist_lab::words::count(count as u64, "render"),
            samples as f64 / 1e6,
            if threads == 1 { "" } else { "s" }
        )?;
    }
    crate::output::print(&out)
}

/// Where the sheet goes: `--output`, else `compare.png` unless `--json` was asked for alone.
fn sheet_path(args: &CompareArgs) -> Option<PathBuf> {
    match (&args.output, args.json) {
        (Some(p), _) => Some(p.clone()),
        (None, false) => Some(PathBuf::from("compare.png")),
        (None, true) => None,
    }
}

/// Renders every cell, `threads` at a time (each render on one thread, the longest first),
/// with one progress bar over all tiles of the sheet (shown at once when `large`).
fn render_cells(
    args: &CompareArgs,
    cells: &[Cell],
    threads: usize,
    large: bool,
) -> Result<Vec<Rendered>> {
    let per_cell = tile_count(args.size);
    let bar = Progress::new(per_cell * cells.len() as u64, "compare");
    if large {
        bar.show_now();
    }
    let mut order: Vec<usize> = (0..cells.len()).collect();
    order.sort_by_key(|&i| std::cmp::Reverse(cells[i].sampler.samples_per_pixel()));
    let out = nyquist_lab::parallel::map_tasks(&order, threads, |i| {
        let c = &cells[i];
        render(
            args.scene,
            args.size,
            &c.sampler,
            &args.filters.0[c.filter].1,
            1,
            &mut || bar.inc(1),
        )
    });
    bar.finish();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn filter_lists_keep_parameters_with_their_spec() {
        let l = parse_filters("box,mitchell:b=0.5,c=0.25,gaussian").unwrap();
        let names: Vec<&str> = l.0.iter().map(|(s, _)| s.as_str()).collect();
        assert_eq!(names, ["box", "mitchell:b=0.5,c=0.25", "gaussian"]);
        assert!(parse_filters("box,,mitchell").is_err());
        assert!(parse_filters("box,sinc").is_err());
    }

    #[test]
    fn crops_stay_inside_the_image() {
        for scene in [
            Scene::Zoneplate,
            Scene::Checkerboard,
            Scene::Disk,
            Scene::Edge,
            Scene::Stripes,
            Scene::Dots,
        ] {
            for size in [[1, 1], [3, 7], [256, 256], [1000, 300]] {
                let [x, y, w, h] = crop(scene, size);
                assert!(w >= 1 && h >= 1 && x + w <= size[0] && y + h <= size[1]);
                assert!(w <= MAX_CROP && h <= MAX_CROP);
            }
        }
        assert_eq!(crop(Scene::Zoneplate, [256, 256]), [128, 128, 128, 128]);
    }
}
