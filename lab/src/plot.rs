//! Figures drawn with `plotters`: the output format from the file's extension (PNG through the
//! bitmap backend and the `png` crate, SVG through the SVG backend), text in DejaVu Sans embedded
//! in the binary (no system fonts, so a PNG has the same bytes on every machine; an SVG names the
//! font family, `DejaVu Sans`, and keeps its text as text), atomic writes, and the pieces the
//! CLI's plots share: log-log and linear panels with major and minor ticks, a frame, and legend
//! rows.
//!
//! A figure implements [`Figure`]; [`render`] draws it as the PNG or SVG bytes that [`kind`] picks from the
//! output path (the front end writes the file).

use anyhow::{Context, Result};
use nyquist_film::output::png::{PngColor, PngLayout};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::FontStyle;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::ops::Range;
use std::path::Path;

/// The font family every figure uses; registered from the embedded DejaVu Sans.
pub const FONT: &str = "DejaVu Sans";
/// Ink for text, frames and ticks.
pub const INK: RGBColor = RGBColor(0, 0, 0);
/// Major grid lines.
pub const GRID: RGBColor = RGBColor(222, 222, 222);
/// Minor grid lines.
pub const GRID_MINOR: RGBColor = RGBColor(242, 242, 242);
/// Reference lines (guides, Nyquist limit, white-noise level).
pub const GUIDE: RGBColor = RGBColor(120, 120, 120);

/// Line colours, one per series: matplotlib's "tab10", then six darker hues, repeating after sixteen.
pub const PALETTE: [RGBColor; 16] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
    // Past ten series: darker hues, apart from the first ten.
    RGBColor(0, 0, 0),
    RGBColor(0, 60, 140),
    RGBColor(150, 70, 0),
    RGBColor(0, 100, 50),
    RGBColor(120, 0, 70),
    RGBColor(90, 90, 0),
];

/// Colour of series `k`.
pub fn color(k: usize) -> RGBColor {
    PALETTE[k % PALETTE.len()]
}

/// Registers the embedded fonts with plotters (once per process).
pub fn register_fonts() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // The bytes are a valid TrueType font (the dejavu crate's own file); a failure here
        // would show as missing text, which the tests catch.
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular());
        let _ = plotters::style::register_font(FONT, FontStyle::Bold, dejavu::sans::bold());
    });
}

/// The embedded font at `px` pixels (plotters' size: the em is `px / 1.24`).
pub fn font(px: f64) -> TextStyle<'static> {
    register_fonts();
    TextStyle::from((FONT, px).into_font())
}

/// The bold embedded font at `px` pixels.
pub fn bold(px: f64) -> TextStyle<'static> {
    register_fonts();
    TextStyle::from(FontDesc::new(FontFamily::Name(FONT), px, FontStyle::Bold))
}

/// Width in pixels of `text` in the embedded font at `px`.
pub fn text_width(text: &str, px: f64) -> u32 {
    styled_width(text, px, FontStyle::Normal)
}

/// Width in pixels of `text` in the embedded font at `px`, in `style` (bold is about a tenth
/// wider than regular).
fn styled_width(text: &str, px: f64, style: FontStyle) -> u32 {
    register_fonts();
    FontDesc::new(FontFamily::Name(FONT), px, style)
        .box_size(text)
        .map_or(0, |(w, _)| w)
}

/// The file formats of a plot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// PNG, 8-bit RGB.
    Png,
    /// SVG with text as text.
    Svg,
}

/// The format `path` names by its extension: `.svg` (any case) is SVG, anything else PNG
/// (front ends check the extension and the folder before drawing).
///
/// ```
/// use nyquist_lab::plot::{Kind, kind};
/// assert_eq!(kind(std::path::Path::new("a.SVG")), Kind::Svg);
/// assert_eq!(kind(std::path::Path::new("a.png")), Kind::Png);
/// ```
pub fn kind(path: &Path) -> Kind {
    let svg = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    if svg { Kind::Svg } else { Kind::Png }
}

/// An RGB picture placed on a figure after drawing: in a PNG its pixels are copied in, in an
/// SVG it becomes an `<image>` (a PNG data URI) under the vector drawing.
#[derive(Clone, Debug)]
pub struct Raster {
    /// Left edge in figure pixels.
    pub x: i32,
    /// Top edge in figure pixels.
    pub y: i32,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height` RGB triples, row-major.
    pub rgb: Vec<u8>,
}

/// A picture plotters can draw on any backend.
pub trait Figure {
    /// Width and height in pixels (SVG user units).
    fn size(&self) -> (u32, u32);
    /// Draws the figure on `root`, a white page (the figure draws no background, so that
    /// rasters can lie under it); returns the rasters to place under the drawing. It may be
    /// called twice for one PNG: it must draw the same each time.
    ///
    /// # Errors
    /// A drawing error of the backend.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<Vec<Raster>>
    where
        DB::ErrorType: 'static;
}

/// The bytes of `fig` as a PNG or an SVG file.
///
/// # Errors
/// A drawing or encoding error.
pub fn render(fig: &impl Figure, kind: Kind) -> Result<Vec<u8>> {
    register_fonts();
    let (w, h) = fig.size();
    match kind {
        Kind::Png => {
            // Drawn at twice the size and averaged down, so that lines, markers and text are
            // anti-aliased (plotters' bitmap backend draws lines without coverage).
            let (w2, h2) = (2 * w, 2 * h);
            let draw = |big: &mut Vec<u8>| -> Result<Vec<Raster>> {
                let inner = BitMapBackend::with_buffer(big, (w2, h2));
                let root = supersample::Doubled(inner).into_drawing_area();
                let rasters = fig.draw(&root)?;
                root.present()?;
                Ok(rasters)
            };
            let white = vec![255u8; 3 * w2 as usize * h2 as usize];
            let mut big = white.clone();
            let rasters = draw(&mut big)?;
            if !rasters.is_empty() {
                // Rasters go under the drawing, as in the SVG: lay them on a white page, then
                // draw again on top.
                big = white;
                for r in &rasters {
                    blit(&mut big, w2, h2, &doubled_raster(r));
                }
                draw(&mut big)?;
            }
            encode_png(&halve(&big, w, h), w, h)
        }
        Kind::Svg => {
            let mut svg = String::new();
            let rasters = {
                let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
                root.fill(&WHITE)?;
                let rasters = fig.draw(&root)?;
                root.present()?;
                rasters
            };
            embed_rasters(&mut svg, &rasters)?;
            Ok(svg.into_bytes())
        }
    }
}

/// `r` at twice the size (each pixel a 2 × 2 block).
fn doubled_raster(r: &Raster) -> Raster {
    let (w, h) = (r.width as usize, r.height as usize);
    let mut rgb = Vec::with_capacity(12 * w * h);
    for j in 0..2 * h {
        for i in 0..2 * w {
            let o = 3 * ((j / 2) * w + i / 2);
            rgb.extend_from_slice(&r.rgb[o..o + 3]);
        }
    }
    Raster {
        x: 2 * r.x,
        y: 2 * r.y,
        width: 2 * r.width,
        height: 2 * r.height,
        rgb,
    }
}

/// The `w × h` RGB picture whose pixels are the rounded means of the 2 × 2 blocks of `big`
/// (`2w × 2h`).
fn halve(big: &[u8], w: u32, h: u32) -> Vec<u8> {
    let (w, h) = (w as usize, h as usize);
    let mut out = Vec::with_capacity(3 * w * h);
    for y in 0..h {
        for x in 0..w {
            for c in 0..3 {
                let at = |dx: usize, dy: usize| {
                    u32::from(big[3 * ((2 * y + dy) * 2 * w + 2 * x + dx) + c])
                };
                out.push(((at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1) + 2) / 4) as u8);
            }
        }
    }
    out
}

/// Drawing at twice the size: see [`supersample::Doubled`].
mod supersample {
    use plotters::prelude::{DrawingBackend, FontDesc, TextStyle};
    use plotters_backend::{
        BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind,
    };

    /// A backend of a given logical size that draws on `B`, twice as large: coordinates, stroke
    /// widths, radii and text sizes doubled. Layout (text extents) is measured at the logical size,
    /// so a figure lays out exactly as on a plain backend.
    pub(super) struct Doubled<B>(pub(super) B);

    /// A style with its stroke width doubled.
    struct Thick<'a, S>(&'a S);

    impl<S: BackendStyle> BackendStyle for Thick<'_, S> {
        fn color(&self) -> BackendColor {
            self.0.color()
        }
        fn stroke_width(&self) -> u32 {
            2 * self.0.stroke_width()
        }
    }

    fn twice((x, y): BackendCoord) -> BackendCoord {
        (2 * x, 2 * y)
    }

    impl<B: DrawingBackend> DrawingBackend for Doubled<B> {
        type ErrorType = B::ErrorType;

        fn get_size(&self) -> (u32, u32) {
            let (w, h) = self.0.get_size();
            (w / 2, h / 2)
        }

        fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
            self.0.ensure_prepared()
        }

        fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
            self.0.present()
        }

        fn draw_pixel(
            &mut self,
            point: BackendCoord,
            color: BackendColor,
        ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
            let (x, y) = twice(point);
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                self.0.draw_pixel((x + dx, y + dy), color)?;
            }
            Ok(())
        }

        fn draw_line<S: BackendStyle>(
            &mut self,
            from: BackendCoord,
            to: BackendCoord,
            style: &S,
        ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
            self.0.draw_path([twice(from), twice(to)], &Thick(style))
        }

        fn draw_rect<S: BackendStyle>(
            &mut self,
            upper_left: BackendCoord,
            bottom_right: BackendCoord,
            style: &S,
            fill: bool,
        ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
            let (a, b) = (twice(upper_left), twice(bottom_right));
            if fill {
                self.0.draw_rect(a, (b.0 + 1, b.1 + 1), style, true)
            } else {
                let corners = [a, (b.0, a.1), b, (a.0, b.1), a];
                self.0.draw_path(corners, &Thick(style))
            }
        }

        fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
            &mut self,
            path: I,
            style: &S,
        ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
            self.0.draw_path(
                path.into_iter().map(twice).collect::<Vec<_>>(),
                &Thick(style),
            )
        }

        fn draw_circle<S: BackendStyle>(
            &mut self,
            center: BackendCoord,
            radius: u32,
            style: &S,
            fill: bool,
        ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
            self.0
                .draw_circle(twice(center), 2 * radius, &Thick(style), fill)
        }

        fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
            &mut self,
            vert: I,
            style: &S,
        ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
            self.0
                .fill_polygon(vert.into_iter().map(twice).collect::<Vec<_>>(), style)
        }

        fn draw_text<TStyle: BackendTextStyle>(
            &mut self,
            text: &str,
            style: &TStyle,
            pos: BackendCoord,
        ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
            let font = FontDesc::new(style.family(), 2.0 * style.size(), style.style())
                .transform(style.transform());
            let big = TextStyle {
                font,
                color: style.color(),
                pos: style.anchor(),
            };
            self.0.draw_text(text, &big, twice(pos))
        }

        fn estimate_text_size<TStyle: BackendTextStyle>(
            &self,
            text: &str,
            style: &TStyle,
        ) -> Result<(u32, u32), DrawingErrorKind<Self::ErrorType>> {
            self.0.estimate_text_size(text, style)
        }
    }
}

/// Copies `r` into the `w × h` RGB buffer (clipped).
fn blit(rgb: &mut [u8], w: u32, h: u32, r: &Raster) {
    for j in 0..r.height {
        let y = r.y + j as i32;
        if y < 0 || y >= h as i32 {
            continue;
        }
        for i in 0..r.width {
            let x = r.x + i as i32;
            if x < 0 || x >= w as i32 {
                continue;
            }
            let src = 3 * (j as usize * r.width as usize + i as usize);
            let dst = 3 * (y as usize * w as usize + x as usize);
            rgb[dst..dst + 3].copy_from_slice(&r.rgb[src..src + 3]);
        }
    }
}

/// An 8-bit RGB PNG of `rgb` (`w × h`).
///
/// # Errors
/// An encoder error.
pub fn encode_png(rgb: &[u8], w: u32, h: u32) -> Result<Vec<u8>> {
    let mut out = Vec::new();
    let layout = PngLayout::new(w, h, PngColor::Rgb);
    nyquist_film::output::png::write_png_pixels(&mut out, &layout, rgb)?;
    Ok(out)
}

/// Puts each raster into the SVG as an `<image>` right after the white background (the first
/// element), so that frames, ticks and text stay on top.
fn embed_rasters(svg: &mut String, rasters: &[Raster]) -> Result<()> {
    if rasters.is_empty() {
        return Ok(());
    }
    let mut images = String::new();
    for r in rasters {
        let png = encode_png(&r.rgb, r.width, r.height)?;
        images.push_str(&format!(
            "<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" preserveAspectRatio=\"none\" \
             style=\"image-rendering:pixelated\" href=\"data:image/png;base64,{}\"/>\n",
            r.x,
            r.y,
            r.width,
            r.height,
            base64(&png)
        ));
    }
    // After the opening tag and the background rectangle that every figure fills first.
    let open = svg.find("<svg").context("SVG without <svg>")?;
    let after_open = open + svg[open..].find('>').context("SVG tag")? + 1;
    let at = match svg[after_open..].find("<rect") {
        Some(r) => {
            let start = after_open + r;
            start + svg[start..].find("/>").context("SVG rect")? + 2
        }
        None => after_open,
    };
    svg.insert_str(at, &format!("\n{images}"));
    Ok(())
}

/// Standard base64 (RFC 4648, with padding).
pub fn base64(bytes: &[u8]) -> String {
    const ABC: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = u32::from(b[0]) << 16 | u32::from(b[1]) << 8 | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ABC[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// `10^k` with a superscript exponent, e.g. `10⁻³`.
pub fn power_of_ten(k: i32) -> String {
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::from("10");
    if k < 0 {
        s.push('⁻');
    }
    for d in k.unsigned_abs().to_string().bytes() {
        s.push(SUP[usize::from(d - b'0')]);
    }
    s
}

/// A number for a linear axis label: as short as the tick spacing allows, with a true minus.
pub fn number(v: f64, step: f64) -> String {
    let decimals = if step > 0.0 && step.is_finite() {
        (-step.log10().floor()).clamp(0.0, 6.0) as usize
    } else {
        2
    };
    let v = if v.abs() < step * 1e-9 { 0.0 } else { v };
    format!("{v:.decimals$}").replace('-', "−")
}

/// The ticks of a log10 axis over `[lo, hi]` (in log10 units): majors at the decades inside,
/// minors at 2..9 times each decade. When fewer than two decades fall inside, the 2× and 5×
/// minors are promoted to labelled majors so the axis always has a scale.
pub fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    let mut major = Vec::new();
    let mut minor = Vec::new();
    let inside = |v: f64| v >= lo - 1e-9 && v <= hi + 1e-9;
    let decades = (lo.floor() as i32 - 1)..=(hi.ceil() as i32);
    let n_decades = decades.clone().filter(|&d| inside(f64::from(d))).count();
    for d in decades {
        if inside(f64::from(d)) {
            major.push(f64::from(d));
        }
        for m in 2..=9 {
            let v = f64::from(d) + f64::from(m).log10();
            if inside(v) {
                if n_decades < 2 && (m == 2 || m == 5) {
                    major.push(v);
                } else {
                    minor.push(v);
                }
            }
        }
    }
    major.sort_by(f64::total_cmp);
    (major, minor)
}

/// The label of a log10 tick at `v`: `10ᵏ` at a decade; elsewhere the plain number from 0.001
/// to 9000 (`0.02`, `50`), `m×10ᵏ` beyond.
pub fn log_label(v: f64) -> String {
    let k = v.floor();
    let m = 10f64.powf(v - k);
    if (m - 1.0).abs() < 1e-6 || (m - 10.0).abs() < 1e-6 {
        power_of_ten(v.round() as i32)
    } else if (-3.0..=3.0).contains(&k) {
        number(m.round() * 10f64.powf(k), 10f64.powf(k))
    } else {
        format!("{}×{}", m.round(), power_of_ten(k as i32))
    }
}

/// Ticks of a linear axis over `[lo, hi]` with about `target` labelled majors at 1, 2 or 5
/// times a power of ten, and the minors between them (5 per major step for 1 and 5, 4 for 2).
/// Returns (majors, minors, major step).
pub fn linear_ticks(lo: f64, hi: f64, target: usize) -> (Vec<f64>, Vec<f64>, f64) {
    let span = (hi - lo).abs().max(1e-12);
    let raw = span / target.max(1) as f64;
    let p = 10f64.powf(raw.log10().floor());
    let (step, parts) = [(1.0, 5), (2.0, 4), (5.0, 5), (10.0, 5)]
        .into_iter()
        .map(|(m, parts)| (m * p, parts))
        .find(|&(s, _)| s >= raw)
        .unwrap_or((10.0 * p, 5));
    let minor_step = step / f64::from(parts);
    let (mut major, mut minor) = (Vec::new(), Vec::new());
    let first = (lo / minor_step).ceil() as i64;
    let last = (hi / minor_step).floor() as i64;
    for k in first..=last {
        let v = k as f64 * minor_step;
        if k.rem_euclid(i64::from(parts)) == 0 {
            major.push(v);
        } else {
            minor.push(v);
        }
    }
    (major, minor, step)
}

/// One panel's axes: ranges, ticks, labels and captions.
#[derive(Clone, Debug)]
pub struct Axes {
    /// The x range in plot units (log10 units on a log axis).
    pub x: Range<f64>,
    /// The y range in plot units.
    pub y: Range<f64>,
    /// Labelled x ticks.
    pub x_major: Vec<f64>,
    /// Unlabelled x ticks.
    pub x_minor: Vec<f64>,
    /// Labelled y ticks.
    pub y_major: Vec<f64>,
    /// Unlabelled y ticks.
    pub y_minor: Vec<f64>,
    /// Label of an x tick.
    pub x_label: fn(f64, f64) -> String,
    /// Label of a y tick.
    pub y_label: fn(f64, f64) -> String,
    /// Major x step (passed to `x_label`; 0 on log axes).
    pub x_step: f64,
    /// Major y step.
    pub y_step: f64,
    /// Caption under the x axis.
    pub x_desc: String,
    /// Caption beside the y axis.
    pub y_desc: String,
    /// Caption above the panel.
    pub caption: String,
    /// The panel shows a raster: no grid lines, ticks outside the frame.
    pub image: bool,
}

fn log_tick_label(v: f64, _: f64) -> String {
    log_label(v)
}

impl Axes {
    /// Log-log axes over `[x0, x1] × [y0, y1]` in data units (all positive).
    pub fn log_log(x: Range<f64>, y: Range<f64>) -> Axes {
        let (xl, xh) = (x.start.log10(), x.end.log10());
        let (yl, yh) = (y.start.log10(), y.end.log10());
        let (x_major, x_minor) = log_ticks(xl, xh);
        let (y_major, y_minor) = log_ticks(yl, yh);
        Axes {
            x: xl..xh,
            y: yl..yh,
            x_major,
            x_minor,
            y_major,
            y_minor,
            x_label: log_tick_label,
            y_label: log_tick_label,
            x_step: 0.0,
            y_step: 0.0,
            x_desc: String::new(),
            y_desc: String::new(),
            caption: String::new(),
            image: false,
        }
    }

    /// Linear axes with about 6 labelled ticks on x and 5 on y.
    pub fn linear(x: Range<f64>, y: Range<f64>) -> Axes {
        let (x_major, x_minor, x_step) = linear_ticks(x.start, x.end, 6);
        let (y_major, y_minor, y_step) = linear_ticks(y.start, y.end, 5);
        Axes {
            x,
            y,
            x_major,
            x_minor,
            y_major,
            y_minor,
            x_label: number,
            y_label: number,
            x_step,
            y_step,
            x_desc: String::new(),
            y_desc: String::new(),
            caption: String::new(),
            image: false,
        }
    }
}

/// The chart type of a panel: plot units on both axes.
pub type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Label size in pixels.
pub const LABEL_PX: f64 = 14.0;
/// Caption size in pixels.
pub const CAPTION_PX: f64 = 16.0;

/// Draws a framed panel on `area`: the caption above, grid lines at every tick (minors
/// lighter), ticks inside the frame on all four sides (majors 6 px, minors 3 px), labels at the
/// majors and the axis captions. Returns the chart to draw series on.
///
/// # Errors
/// A drawing error.
pub fn panel<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    axes: &Axes,
) -> Result<Chart<'a, DB>>
where
    DB::ErrorType: 'static,
{
    // Label areas only reserve room: ticks, labels and captions are drawn below, so that log
    // axes get decade majors with 2..9 minors and every side of the frame gets ticks.
    let mut chart = ChartBuilder::on(area)
        .margin_top(6)
        .margin_right(14)
        .x_label_area_size(44)
        .y_label_area_size(66)
        .caption_if(&axes.caption)
        .build_cartesian_2d(axes.x.clone(), axes.y.clone())?;
    let xl = axes.x_label;
    let yl = axes.y_label;
    let (xs, ys) = (axes.x_step, axes.y_step);
    let x_fmt = move |v: &f64| xl(*v, xs);
    let y_fmt = move |v: &f64| yl(*v, ys);
    chart
        .configure_mesh()
        .disable_mesh()
        .x_labels(0)
        .y_labels(0)
        .axis_style(TRANSPARENT)
        .draw()?;
    let plot = chart.plotting_area();
    let (x0, x1, y0, y1) = (axes.x.start, axes.x.end, axes.y.start, axes.y.end);
    if !axes.image {
        for (values, style) in [(&axes.x_minor, GRID_MINOR), (&axes.x_major, GRID)] {
            for &v in values {
                plot.draw(&PathElement::new(vec![(v, y0), (v, y1)], style))?;
            }
        }
        for (values, style) in [(&axes.y_minor, GRID_MINOR), (&axes.y_major, GRID)] {
            for &v in values {
                plot.draw(&PathElement::new(vec![(x0, v), (x1, v)], style))?;
            }
        }
    }
    // Ticks on all four sides: inside the frame, or outside around a raster.
    let out = if axes.image { -1 } else { 1 };
    for (values, len) in [(&axes.x_minor, 3 * out), (&axes.x_major, 6 * out)] {
        for &v in values {
            plot.draw(
                &(EmptyElement::at((v, y0)) + PathElement::new(vec![(0, 0), (0, -len)], INK)),
            )?;
            plot.draw(
                &(EmptyElement::at((v, y1)) + PathElement::new(vec![(0, 0), (0, len)], INK)),
            )?;
        }
    }
    for (values, len) in [(&axes.y_minor, 3 * out), (&axes.y_major, 6 * out)] {
        for &v in values {
            plot.draw(
                &(EmptyElement::at((x0, v)) + PathElement::new(vec![(0, 0), (len, 0)], INK)),
            )?;
            plot.draw(
                &(EmptyElement::at((x1, v)) + PathElement::new(vec![(0, 0), (-len, 0)], INK)),
            )?;
        }
    }
    // Labels outside the frame (and outside the ticks of a raster).
    let gap = if axes.image { 6 } else { 0 };
    let label = font(LABEL_PX).color(&INK);
    for &v in &axes.x_major {
        let at = chart.backend_coord(&(v, y0));
        area.draw_text(
            &x_fmt(&v),
            &label.pos(Pos::new(HPos::Center, VPos::Top)),
            (
                at.0 - area.get_base_pixel().0,
                at.1 + 5 + gap - area.get_base_pixel().1,
            ),
        )?;
    }
    for &v in &axes.y_major {
        let at = chart.backend_coord(&(x0, v));
        area.draw_text(
            &y_fmt(&v),
            &label.pos(Pos::new(HPos::Right, VPos::Center)),
            (
                at.0 - 6 - gap - area.get_base_pixel().0,
                at.1 - area.get_base_pixel().1,
            ),
        )?;
    }
    // Axis captions.
    let (left, top) = chart.backend_coord(&(x0, y1));
    let (right, bottom) = chart.backend_coord(&(x1, y0));
    let base = area.get_base_pixel();
    if !axes.x_desc.is_empty() {
        area.draw_text(
            &axes.x_desc,
            &font(LABEL_PX)
                .color(&INK)
                .pos(Pos::new(HPos::Center, VPos::Top)),
            ((left + right) / 2 - base.0, bottom + 24 - base.1),
        )?;
    }
    if !axes.y_desc.is_empty() {
        area.draw_text(
            &axes.y_desc,
            &font(LABEL_PX)
                .color(&INK)
                .transform(FontTransform::Rotate270)
                .pos(Pos::new(HPos::Center, VPos::Top)),
            (left - 62 - base.0, (top + bottom) / 2 - base.1),
        )?;
    }
    // The frame.
    plot.draw(&Rectangle::new([(x0, y0), (x1, y1)], INK.stroke_width(1)))?;
    Ok(chart)
}

trait CaptionIf {
    fn caption_if(&mut self, caption: &str) -> &mut Self;
}

impl<DB: DrawingBackend> CaptionIf for ChartBuilder<'_, '_, DB> {
    fn caption_if(&mut self, caption: &str) -> &mut Self {
        if caption.is_empty() {
            self
        } else {
            self.caption(caption, bold(CAPTION_PX))
        }
    }
}

/// A marker of shape `k` (circle, square, triangle, diamond, then the same hollow) at `at`.
pub fn marker<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    at: (i32, i32),
    k: usize,
    col: RGBColor,
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let filled = k % 8 < 4;
    let style = if filled {
        col.filled()
    } else {
        col.stroke_width(1)
    };
    let (x, y) = at;
    let r = 3;
    match k % 4 {
        0 => area.draw(&Circle::new(at, r, style))?,
        1 => area.draw(&Rectangle::new([(x - r, y - r), (x + r, y + r)], style))?,
        2 => area.draw(&Polygon::new(
            vec![(x, y - r - 1), (x + r + 1, y + r), (x - r - 1, y + r)],
            style,
        ))?,
        _ => area.draw(&Polygon::new(
            vec![
                (x, y - r - 1),
                (x + r + 1, y),
                (x, y + r + 1),
                (x - r - 1, y),
            ],
            style,
        ))?,
    }
    if !filled && k % 4 >= 2 {
        // Polygons only fill; outline the hollow ones.
        let pts: Vec<(i32, i32)> = if k % 4 == 2 {
            vec![
                (x, y - r - 1),
                (x + r + 1, y + r),
                (x - r - 1, y + r),
                (x, y - r - 1),
            ]
        } else {
            vec![
                (x, y - r - 1),
                (x + r + 1, y),
                (x, y + r + 1),
                (x - r - 1, y),
                (x, y - r - 1),
            ]
        };
        area.draw(&PathElement::new(pts, col.stroke_width(1)))?;
    }
    Ok(())
}

/// Breaks `text` into lines no wider than `width` pixels at `px`: at spaces, and after the
/// commas of a long list (a single piece wider than that gets a line of its own).
pub fn wrap(text: &str, width: u32, px: f64) -> Vec<String> {
    wrap_measured(text, width, &|t| text_width(t, px))
}

/// [`wrap`] with the width of a line given by `measure` (the title measures in bold).
fn wrap_measured(text: &str, width: u32, measure: &dyn Fn(&str) -> u32) -> Vec<String> {
    // Pieces with the separator that joins them to the one before: " " or "".
    let mut pieces: Vec<(&str, &str)> = Vec::new();
    for (i, word) in text.split(' ').enumerate() {
        let mut sep = if i == 0 { "" } else { " " };
        for part in word.split_inclusive(',') {
            pieces.push((sep, part));
            sep = "";
        }
    }
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for (sep, piece) in pieces {
        let candidate = format!("{line}{sep}{piece}");
        if !line.is_empty() && measure(&candidate) > width {
            lines.push(std::mem::take(&mut line));
            line = piece.to_owned();
        } else {
            line = candidate;
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// Writes `text` in bold at `(x, y)` of `area` in lines no wider than `width`: at the first
/// `(pixels, most lines)` of `sizes` at which it fits, else at the last, cut after its most
/// lines. Returns the height used.
///
/// # Errors
/// A drawing error.
pub fn title<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    (x, y): (i32, i32),
    width: u32,
    sizes: &[(f64, usize)],
) -> Result<i32>
where
    DB::ErrorType: 'static,
{
    let mut chosen = (16.0, 1, Vec::new());
    for &(px, max_lines) in sizes {
        let lines = wrap_measured(text, width, &|t| styled_width(t, px, FontStyle::Bold));
        let fits = lines.len() <= max_lines;
        chosen = (px, max_lines, lines);
        if fits {
            break;
        }
    }
    let (px, max_lines, lines) = chosen;
    let step = (px * 1.3).round() as i32;
    let mut at = y;
    for line in lines.iter().take(max_lines) {
        area.draw_text(line, &bold(px).color(&INK), (x, at))?;
        at += step;
    }
    Ok(at - y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648_vectors() {
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded, "{plain}");
        }
    }

    #[test]
    fn halving_averages_2x2_blocks_and_keeps_doubled_rasters() {
        // 4 × 2 RGB: a black/white block (mean 127.5, rounded up) and a grey one.
        let mut big = vec![0u8; 3 * 8];
        for (i, v) in [0u8, 255, 100, 100, 255, 0, 100, 100]
            .into_iter()
            .enumerate()
        {
            big[3 * i..3 * i + 3].fill(v);
        }
        assert_eq!(halve(&big, 2, 1), [128, 128, 128, 100, 100, 100]);
        let r = Raster {
            x: 1,
            y: 2,
            width: 2,
            height: 1,
            rgb: vec![1, 2, 3, 4, 5, 6],
        };
        let d = doubled_raster(&r);
        assert_eq!((d.x, d.y, d.width, d.height), (2, 4, 4, 2));
        assert_eq!(halve(&d.rgb, 2, 1), r.rgb);
    }

    #[test]
    fn log_ticks_have_decade_majors_and_2_to_9_minors() {
        let (major, minor) = log_ticks(16f64.log10(), 4096f64.log10());
        assert_eq!(major, [2.0, 3.0]);
        assert_eq!(minor.len(), 8 + 8 + 3); // 20..90, 200..900, 2000..4000
        assert!((minor[0] - 20f64.log10()).abs() < 1e-12);
        // Less than two decades: 2× and 5× become labelled.
        let (major, _) = log_ticks(-2.5, -1.5);
        assert_eq!(major.len(), 3); // 5e-3, 1e-2, 2e-2
        assert_eq!(log_label(-2.0), "10⁻²");
        assert_eq!(log_label(2f64.log10() - 2.0), "0.02");
        assert_eq!(log_label(5f64.log10() + 1.0), "50");
        assert_eq!(log_label(2f64.log10() - 5.0), "2×10⁻⁵");
    }

    #[test]
    fn linear_ticks_are_1_2_5_steps() {
        let (major, minor, step) = linear_ticks(-2.0, 2.0, 6);
        assert_eq!(step, 1.0);
        assert_eq!(major, [-2.0, -1.0, 0.0, 1.0, 2.0]);
        assert_eq!(minor.len(), 16);
        assert_eq!(number(-0.5, 0.5), "−0.5");
        assert_eq!(number(2.0, 1.0), "2");
    }

    /// Titles are drawn in bold, so they are wrapped by bold widths: every line of a long
    /// command fits, where wrapping by regular widths leaves a line wider than the figure.
    #[test]
    fn titles_wrap_by_their_bold_width() {
        let text = "nyquist converge --samplers random,stratified,halton,hammersley,zero-two,sobol,\
                    best-candidate,owen-sobol,zsobol,pmj02,bluenoise-dithered,fibonacci,r2 \
                    --integrands disk,triangle,step,gaussian,bilinear --min-spp 16 --max-spp 4096";
        let width = 1900;
        let bold = |t: &str| styled_width(t, 18.0, FontStyle::Bold);
        let lines = wrap_measured(text, width, &bold);
        assert!(lines.iter().all(|l| bold(l) <= width), "{lines:?}");
        assert!(
            wrap(text, width, 18.0).iter().any(|l| bold(l) > width),
            "the regular-width wrap no longer overflows: the test lost its point"
        );
    }

    #[test]
    fn text_is_measured_and_wrapped() {
        let w = text_width("nyquist converge", 14.0);
        assert!((80..200).contains(&w), "{w}");
        let lines = wrap("aaa bbb ccc ddd", text_width("aaa bbb", 14.0), 14.0);
        assert_eq!(lines, ["aaa bbb", "ccc ddd"]);
        let lines = wrap(
            "--samplers a1,b2,c3,d4 --seed 0",
            text_width("--samplers a1,b2,", 14.0),
            14.0,
        );
        assert_eq!(lines, ["--samplers a1,b2,", "c3,d4 --seed 0"]);
    }
}
