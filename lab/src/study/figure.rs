//! The convergence figure of a study on the unit-square integrands: one log-log panel of RMSE
//! against N per integrand, and a legend of the samplers' slopes.

use super::unit_square::SquareIntegrand;
use super::{Curve, Study};
#[cfg(not(target_family = "wasm"))]
use anyhow::Result;

/// Width of one panel of the plot: the log-log chart and its legend beside it.
pub const PANEL_W: u32 = 640;
/// Height of one panel of the plot.
pub const PANEL_H: u32 = 380;
/// Width of a panel's legend.
const LEGEND_W: u32 = 190;
/// Margin around the plot and between panels.
const MARGIN: u32 = 16;
/// Panels per row.
const COLUMNS: u32 = 3;
/// Pixels of the title block at the top: the command (up to three lines) and the notes (two).
const HEADER_H: u32 = 96;

/// The plot's size for `integrands` panels: at most three panels across.
///
/// ```
/// use nyquist_lab::study::figure::{plot_size, PANEL_W, PANEL_H};
/// assert_eq!(plot_size(5), [16 + 3 * (PANEL_W + 16), 16 + 96 + 2 * (PANEL_H + 16)]);
/// assert_eq!(plot_size(1), [16 + PANEL_W + 16, 16 + 96 + PANEL_H + 16]);
/// ```
pub fn plot_size(integrands: usize) -> [u32; 2] {
    let cells = (integrands as u32).max(1);
    let cols = cells.min(COLUMNS);
    let rows = cells.div_ceil(cols);
    [
        MARGIN + cols * (PANEL_W + MARGIN),
        MARGIN + HEADER_H + rows * (PANEL_H + MARGIN),
    ]
}

/// The convergence plot: per integrand a log-log panel of RMSE against N (decade ticks with
/// 2..9 minors, dashed N^−½ and N^−1 guides) with a legend beside it giving each sampler's
/// colour, marker and fitted slope.
#[derive(Debug)]
pub struct Plot<'a> {
    /// The study the curves come from.
    pub study: &'a Study<SquareIntegrand>,
    /// Its curves.
    pub curves: &'a [Curve<SquareIntegrand>],
    /// The title: e.g. the command line that reproduces the study.
    pub title: &'a str,
}

#[cfg(not(target_family = "wasm"))]
impl crate::plot::Figure for Plot<'_> {
    fn size(&self) -> (u32, u32) {
        let [w, h] = plot_size(self.study.integrands.len());
        (w, h)
    }

    fn draw<DB: plotters::prelude::DrawingBackend>(
        &self,
        root: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    ) -> Result<Vec<crate::plot::Raster>>
    where
        DB::ErrorType: 'static,
    {
        use crate::plot::{Axes, GUIDE, INK, bold, color, font, marker, panel, title, wrap};
        use plotters::prelude::*;
        use plotters::style::text_anchor::{HPos, Pos, VPos};
        let study = self.study;
        let (w, _) = self.size();
        // The command in up to three lines, smaller when it is long.
        let m = MARGIN as i32;
        let sizes = [(18.0, 2), (14.0, 3)];
        let mut y = m + title(root, self.title, (m, m), w - 2 * MARGIN, &sizes)?;
        let notes = format!(
            "RMSE of the mean over N samples against N, {} per N; slope: least-squares fit of \
             log RMSE on log N; grey dashed: slopes −1/2 and −1 for scale",
            crate::words::count(study.runs, "independent run")
        );
        for line in wrap(&notes, w - 2 * MARGIN, 13.0).iter().take(2) {
            root.draw_text(line, &font(13.0).color(&INK), (m, y + 2))?;
            y += 17;
        }
        let ni = study.integrands.len();
        let cols = (ni as u32).clamp(1, COLUMNS);
        for (i, &integrand) in study.integrands.iter().enumerate() {
            let (col, row) = (i as u32 % cols, i as u32 / cols);
            let ox = (MARGIN + col * (PANEL_W + MARGIN)) as i32;
            let oy = (MARGIN + HEADER_H + row * (PANEL_H + MARGIN)) as i32;
            let cell = root.clone().shrink((ox, oy), (PANEL_W, PANEL_H));
            let (chart_area, legend) = cell.split_horizontally(PANEL_W - LEGEND_W);
            let mine: Vec<&Curve<SquareIntegrand>> = self
                .curves
                .iter()
                .filter(|c| c.integrand == integrand)
                .collect();
            let finite = |c: &Curve<SquareIntegrand>| {
                c.spp
                    .iter()
                    .zip(&c.rmse)
                    .filter(|&(_, &e)| e.is_finite() && e > 0.0)
                    .map(|(&n, &e)| (f64::from(n).log10(), e.log10()))
                    .collect::<Vec<_>>()
            };
            let all: Vec<(f64, f64)> = mine.iter().flat_map(|c| finite(c)).collect();
            let (mut x0, mut x1, mut y0, mut y1) = all.iter().fold(
                (
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                ),
                |(a, b, c, d), &(x, y)| (a.min(x), b.max(x), c.min(y), d.max(y)),
            );
            if !(x0.is_finite() && y0.is_finite()) {
                let n = study.counts.first().copied().unwrap_or(1).max(1);
                let m = study.counts.last().copied().unwrap_or(2).max(n + 1);
                (x0, x1, y0, y1) = (f64::from(n).log10(), f64::from(m).log10(), -2.0, -1.0);
            }
            // Guides of slope −½ and −1 from just above the highest first point, so that
            // they run above the curves' start and read as a scale, not as data.
            let guide_y = mine
                .iter()
                .filter_map(|c| finite(c).first().map(|p| p.1))
                .fold(f64::NEG_INFINITY, f64::max)
                + 0.15;
            if guide_y.is_finite() {
                y1 = y1.max(guide_y);
            }
            let (xpad, ypad) = (0.04 * (x1 - x0).max(0.3), 0.06 * (y1 - y0).max(0.5));
            let mut axes = Axes::log_log(
                10f64.powf(x0 - xpad)..10f64.powf(x1 + xpad),
                10f64.powf(y0 - ypad)..10f64.powf(y1 + ypad),
            );
            axes.caption = format!("{}: {}", integrand.name(), integrand.formula());
            axes.x_desc = "N (samples)".to_owned();
            axes.y_desc = "RMSE".to_owned();
            let mut chart = panel(&chart_area, &axes)?;
            if guide_y.is_finite() {
                for slope in [-0.5, -1.0] {
                    // Clipped at the bottom of the panel.
                    let end_x = x1.min(x0 + (guide_y - axes.y.start) / -slope);
                    let (a, b) = ((x0, guide_y), (end_x, guide_y + slope * (end_x - x0)));
                    chart.draw_series(DashedLineSeries::new(
                        [a, b],
                        6,
                        4,
                        GUIDE.stroke_width(1),
                    ))?;
                }
            }
            for (k, curve) in mine.iter().enumerate() {
                let s = study
                    .samplers
                    .iter()
                    .position(|s| *s == curve.sampler)
                    .unwrap_or(k);
                let pts = finite(curve);
                chart.draw_series(LineSeries::new(
                    pts.iter().copied(),
                    color(s).stroke_width(2),
                ))?;
                for p in &pts {
                    marker(root, chart.backend_coord(p), s, color(s))?;
                }
            }
            // Legend: colour, marker, name and slope of each sampler.
            let (lx, ly) = (10, 12);
            legend.draw_text("sampler", &bold(13.0).color(&INK), (lx, ly))?;
            legend.draw_text(
                "slope",
                &bold(13.0).color(&INK).pos(Pos::new(HPos::Right, VPos::Top)),
                (LEGEND_W as i32 - 8, ly),
            )?;
            let base = legend.get_base_pixel();
            for (k, curve) in mine.iter().enumerate() {
                let s = study
                    .samplers
                    .iter()
                    .position(|s| *s == curve.sampler)
                    .unwrap_or(k);
                let row_y = ly + 22 + 19 * k as i32;
                let mid = row_y + 7;
                legend.draw(&PathElement::new(
                    vec![(lx, mid), (lx + 24, mid)],
                    color(s).stroke_width(2),
                ))?;
                marker(root, (base.0 + lx + 12, base.1 + mid), s, color(s))?;
                legend.draw_text(&curve.sampler, &font(13.0).color(&INK), (lx + 30, row_y))?;
                legend.draw_text(
                    &curve
                        .slope
                        .map_or_else(|| "n/a".to_owned(), |v| format!("{v:.2}").replace('-', "−")),
                    &font(13.0)
                        .color(&color(s))
                        .pos(Pos::new(HPos::Right, VPos::Top)),
                    (LEGEND_W as i32 - 8, row_y),
                )?;
            }
        }
        Ok(Vec::new())
    }
}

#[cfg(all(test, not(target_family = "wasm")))]
mod tests {
    use super::*;

    #[test]
    fn the_plot_has_its_size_and_draws_every_sampler_colour() {
        use crate::plot::{Figure, Kind, color, render};
        let s = Study {
            samplers: vec!["random".into(), "stratified".into(), "zero-two".into()],
            integrands: SquareIntegrand::ALL.to_vec(),
            counts: crate::study::powers_of_two(4, 64),
            runs: 8,
            seed: 11,
            spp_hint: None,
        };
        let o = s.run(2).unwrap();
        let figure = Plot {
            study: &s,
            curves: &o.curves,
            title: "nyquist converge --samplers random,stratified,zero-two",
        };
        assert_eq!(figure.size(), (plot_size(5)[0], plot_size(5)[1]));
        let png = render(&figure, Kind::Png).unwrap();
        let mut reader = png::Decoder::new(std::io::Cursor::new(png))
            .read_info()
            .unwrap();
        let mut rgb = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut rgb).unwrap();
        assert_eq!((info.width, info.height), figure.size());
        for k in 0..3 {
            let c = color(k);
            let count = rgb
                .chunks_exact(3)
                .filter(|p| p == &[c.0, c.1, c.2])
                .count();
            // Five curves with their markers, five legend rows: well over 500 pixels.
            assert!(count > 500, "sampler {k}: {count} pixels");
        }
        // The outer margin stays white.
        assert_eq!(rgb[rgb.len() - 3..], [255; 3]);
        let svg = String::from_utf8(render(&figure, Kind::Svg).unwrap()).unwrap();
        assert!(svg.contains(figure.title));
        assert!(svg.contains("zero-two"));
    }
}
