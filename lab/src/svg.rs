//! A small SVG writer for point sets: the unit square (a pixel, or the sampling domain) with an
//! optional strata grid, and one dot per point.

use anyhow::Result;
use std::io::Write;

/// Side of the drawn unit square, in SVG user units.
const SIDE: f64 = 512.0;
/// Margin around the square.
const MARGIN: f64 = 16.0;

/// Writes an SVG picture of `points` (point-major, `dims` values each): dimensions 0 and 1 as
/// x and y in the unit square (y down, like image rows), or, for `dims == 1`, the values on a
/// horizontal line. `grid` draws `nx × ny` strata lines; `title` goes in a `<title>`.
pub fn write_svg(
    w: &mut dyn Write,
    points: &[f32],
    dims: usize,
    grid: Option<(u32, u32)>,
    title: &str,
) -> Result<()> {
    let size = SIDE + 2.0 * MARGIN;
    writeln!(
        w,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" viewBox="0 0 {size} {size}">"#
    )?;
    writeln!(w, "<title>{}</title>", escape(title))?;
    writeln!(w, r#"<rect width="{size}" height="{size}" fill="white"/>"#)?;
    if let Some((nx, ny)) = grid {
        // Strata lines; at most 256 per axis so the picture stays readable.
        write!(
            w,
            r##"<path stroke="#bbb" stroke-width="0.5" fill="none" d=""##
        )?;
        if nx > 1 && nx <= 256 {
            for i in 1..nx {
                let x = MARGIN + SIDE * f64::from(i) / f64::from(nx);
                write!(w, "M{x:.3} {MARGIN}V{:.3}", MARGIN + SIDE)?;
            }
        }
        if ny > 1 && ny <= 256 {
            for j in 1..ny {
                let y = MARGIN + SIDE * f64::from(j) / f64::from(ny);
                write!(w, "M{MARGIN} {y:.3}H{:.3}", MARGIN + SIDE)?;
            }
        }
        writeln!(w, r#""/>"#)?;
    }
    writeln!(
        w,
        r##"<rect x="{MARGIN}" y="{MARGIN}" width="{SIDE}" height="{SIDE}" fill="none" stroke="black" stroke-width="1"/>"##
    )?;
    let n = points.len() / dims.max(1);
    let r = (SIDE / (4.0 * (n.max(1) as f64).sqrt())).clamp(0.75, 4.0);
    write!(w, r##"<g fill="#c03">"##)?;
    for p in points.chunks_exact(dims.max(1)) {
        let x = MARGIN + SIDE * f64::from(p[0]);
        let y = MARGIN + SIDE * if dims >= 2 { f64::from(p[1]) } else { 0.5 };
        write!(w, r#"<circle cx="{x:.3}" cy="{y:.3}" r="{r:.2}"/>"#)?;
    }
    writeln!(w, "</g>")?;
    writeln!(w, "</svg>")?;
    Ok(())
}

/// Draws the same picture as [`write_svg`] into a [`Canvas`](crate::raster::Canvas) (for PNG):
/// the unit square with its `grid` strata lines, and one dot per point.
pub fn plot_points(
    points: &[f32],
    dims: usize,
    grid: Option<(u32, u32)>,
    title: &str,
) -> crate::raster::Canvas {
    use crate::raster::{Canvas, LINE};
    let size = (SIDE + 2.0 * MARGIN) as u32;
    let mut c = Canvas::new(size, size + LINE, [255; 3]);
    let (m, side) = (MARGIN as i64, SIDE as u32);
    if let Some((nx, ny)) = grid {
        if nx > 1 && nx <= 256 {
            for i in 1..nx {
                let x = MARGIN + SIDE * f64::from(i) / f64::from(nx);
                c.fill_rect(x.round() as i64, m, 1, side, [187; 3]);
            }
        }
        if ny > 1 && ny <= 256 {
            for j in 1..ny {
                let y = MARGIN + SIDE * f64::from(j) / f64::from(ny);
                c.fill_rect(m, y.round() as i64, side, 1, [187; 3]);
            }
        }
    }
    // The square's border, just outside it.
    c.fill_rect(m - 1, m - 1, side + 2, 1, [0; 3]);
    c.fill_rect(m - 1, m + i64::from(side), side + 2, 1, [0; 3]);
    c.fill_rect(m - 1, m - 1, 1, side + 2, [0; 3]);
    c.fill_rect(m + i64::from(side), m - 1, 1, side + 2, [0; 3]);
    let n = points.len() / dims.max(1);
    let r = (SIDE / (4.0 * (n.max(1) as f64).sqrt())).clamp(1.0, 4.0);
    for p in points.chunks_exact(dims.max(1)) {
        let x = MARGIN + SIDE * f64::from(p[0]);
        let y = MARGIN + SIDE * if dims >= 2 { f64::from(p[1]) } else { 0.5 };
        c.disc(x, y, r, [204, 0, 51]);
    }
    c.text(m, i64::from(size) - 4, title, [0; 3]);
    c
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn png_plot_draws_dots_and_grid() {
        let c = plot_points(&[0.25, 0.25], 2, Some((2, 2)), "t");
        let m = MARGIN as u32;
        let at = |u: f64, v: f64| c.get((MARGIN + SIDE * u) as u32, (MARGIN + SIDE * v) as u32);
        assert_eq!(at(0.25, 0.25), [204, 0, 51]); // the dot
        assert_eq!(at(0.75, 0.75), [255; 3]); // empty
        assert_eq!(c.get(m + 256, m + 100), [187; 3]); // the grid line at x = ½
        assert_eq!(c.get(m - 1, m + 100), [0; 3]); // the border
    }

    #[test]
    fn svg_has_one_circle_per_point_and_the_grid() {
        let mut out = Vec::new();
        write_svg(
            &mut out,
            &[0.1, 0.2, 0.6, 0.7, 0.3, 0.9],
            2,
            Some((2, 3)),
            "a<b",
        )
        .unwrap();
        let s = String::from_utf8(out).unwrap();
        assert!(s.starts_with("<svg") && s.trim_end().ends_with("</svg>"));
        assert_eq!(s.matches("<circle").count(), 3);
        assert!(s.contains("a&lt;b"));
        // 1 vertical + 2 horizontal strata lines.
        assert_eq!(s.matches('M').count(), 3);
    }
}
