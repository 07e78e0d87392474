//! A small 8-bit RGB canvas for the CLI's pictures (contact sheets, point plots): rectangles,
//! discs, image crops and anti-aliased text in the embedded DejaVu Sans (through
//! [`crate::plot`]), encoded as PNG.

use anyhow::Result;

/// Text size in pixels (plotters' size: the em is `TEXT_PX / 1.24`).
pub const TEXT_PX: f64 = 14.0;
/// Height of a text line in pixels.
pub const LINE: u32 = 16;
/// Shift down that puts the top of the tallest glyphs at the `y` of [`Canvas::text`].
const TOP: i64 = 3;

/// An RGB image in 8-bit sRGB, row-major.
#[derive(Clone, Debug)]
pub struct Canvas {
    width: u32,
    height: u32,
    rgb: Vec<u8>,
}

impl Canvas {
    /// A `width × height` canvas filled with `color`.
    pub fn new(width: u32, height: u32, color: [u8; 3]) -> Canvas {
        let n = width as usize * height as usize;
        Canvas {
            width,
            height,
            rgb: color.iter().copied().cycle().take(3 * n).collect(),
        }
    }

    /// Width in pixels.
    #[cfg(test)]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    #[cfg(test)]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Sets pixel `(x, y)`; outside the canvas nothing happens.
    #[inline]
    pub fn put(&mut self, x: i64, y: i64, color: [u8; 3]) {
        if x >= 0 && y >= 0 && x < i64::from(self.width) && y < i64::from(self.height) {
            let o = 3 * (y as usize * self.width as usize + x as usize);
            self.rgb[o..o + 3].copy_from_slice(&color);
        }
    }

    /// The colour of pixel `(x, y)` (black outside).
    #[cfg_attr(not(test), allow(dead_code))]
    pub fn get(&self, x: u32, y: u32) -> [u8; 3] {
        if x < self.width && y < self.height {
            let o = 3 * (y as usize * self.width as usize + x as usize);
            [self.rgb[o], self.rgb[o + 1], self.rgb[o + 2]]
        } else {
            [0; 3]
        }
    }

    /// Fills the rectangle `[x, x + w) × [y, y + h)`.
    pub fn fill_rect(&mut self, x: i64, y: i64, w: u32, h: u32, color: [u8; 3]) {
        for j in 0..i64::from(h) {
            for i in 0..i64::from(w) {
                self.put(x + i, y + j, color);
            }
        }
    }

    /// A filled disc of radius `r` centred at `(cx, cy)` (pixel centres inside are set).
    pub fn disc(&mut self, cx: f64, cy: f64, r: f64, color: [u8; 3]) {
        let (x0, x1) = ((cx - r).floor() as i64, (cx + r).ceil() as i64);
        let (y0, y1) = ((cy - r).floor() as i64, (cy + r).ceil() as i64);
        for y in y0..=y1 {
            for x in x0..=x1 {
                let (dx, dy) = (x as f64 + 0.5 - cx, y as f64 + 0.5 - cy);
                if dx * dx + dy * dy <= r * r {
                    self.put(x, y, color);
                }
            }
        }
    }

    /// Copies the `w × h` block at `(sx, sy)` of `img` (linear RGB, converted to 8-bit sRGB)
    /// to `(x, y)`.
    #[allow(clippy::too_many_arguments)]
    pub fn blit(
        &mut self,
        img: &nyquist_film::Image,
        sx: u32,
        sy: u32,
        w: u32,
        h: u32,
        x: i64,
        y: i64,
    ) {
        use nyquist_film::output::png::srgb_byte;
        for j in 0..h.min(img.height().saturating_sub(sy)) {
            for i in 0..w.min(img.width().saturating_sub(sx)) {
                let p = img.get(sx + i, sy + j);
                let c = [
                    srgb_byte(p[0], None),
                    srgb_byte(p[1], None),
                    srgb_byte(p[2], None),
                ];
                self.put(x + i64::from(i), y + i64::from(j), c);
            }
        }
    }

    /// Writes `text` with its top-left corner at `(x, y)` in the embedded font, anti-aliased;
    /// pixels outside the canvas are clipped.
    pub fn text(&mut self, x: i64, y: i64, text: &str, color: [u8; 3]) {
        let clamp = |v: i64| v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32;
        text_on_rgb(
            &mut self.rgb,
            (self.width, self.height),
            // plotters places the top of a tall glyph (l, d) about 0.25 em above the point given.
            (clamp(x), clamp(y.saturating_add(TOP))),
            text,
            TEXT_PX,
            color,
        );
    }

    /// The canvas as an 8-bit RGB PNG file's bytes.
    ///
    /// # Errors
    /// An encoding error.
    pub fn png(&self) -> Result<Vec<u8>> {
        use nyquist_film::output::png::{PngColor, PngLayout, write_png_pixels};
        let mut out = Vec::new();
        let layout = PngLayout::new(self.width, self.height, PngColor::Rgb);
        write_png_pixels(&mut out, &layout, &self.rgb)?;
        Ok(out)
    }
}

/// Pixels a line of `text` takes.
#[cfg(not(target_family = "wasm"))]
pub fn text_width(text: &str) -> u32 {
    crate::plot::text_width(text, TEXT_PX)
}

/// Pixels a line of `text` takes: its advances and kerning in the embedded font (where
/// plotters, which measures natively, is not linked).
#[cfg(target_family = "wasm")]
pub fn text_width(text: &str) -> u32 {
    use ab_glyph::{Font, FontRef, ScaleFont};
    let Ok(font) = FontRef::try_from_slice(dejavu::sans::regular()) else {
        return 0;
    };
    let scaled = font.as_scaled(TEXT_PX as f32);
    let mut width = 0.0;
    let mut prev = None;
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        if let Some(p) = prev {
            width += scaled.kern(p, id);
        }
        width += scaled.h_advance(id);
        prev = Some(id);
    }
    width.ceil() as u32
}

/// Draws `text` on an RGB buffer of `size = (w, h)` pixels (row-major) at `at = (x, y)` (the
/// point plotters anchors text to: the baseline is `px / 2` below it), in the embedded font at
/// `px` pixels, anti-aliased, with kerning; pixels outside the buffer are clipped.
///
/// The glyphs are laid out here rather than by plotters, whose bitmap text drops each glyph's
/// left side bearing (a "1" then sits a pixel or two left of its place, so "16" reads "1 6").
pub fn text_on_rgb(
    rgb: &mut [u8],
    size: (u32, u32),
    (x, y): (i32, i32),
    text: &str,
    px: f64,
    color: [u8; 3],
) {
    use ab_glyph::{Font, FontRef, ScaleFont, point};
    let (w, h) = size;
    // The bytes are the dejavu crate's TrueType file, which always parses.
    let Ok(font) = FontRef::try_from_slice(dejavu::sans::regular()) else {
        return;
    };
    let scaled = font.as_scaled(px as f32);
    let baseline = y as f32 + px as f32 / 2.0;
    let mut caret = x as f32;
    let mut prev = None;
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        if let Some(p) = prev {
            caret += scaled.kern(p, id);
        }
        prev = Some(id);
        let glyph = id.with_scale_and_position(scaled.scale(), point(caret, baseline));
        caret += scaled.h_advance(id);
        let Some(outline) = font.outline_glyph(glyph) else {
            continue;
        };
        let bounds = outline.px_bounds();
        outline.draw(|gx, gy, coverage| {
            let (px_x, px_y) = (
                bounds.min.x as i64 + i64::from(gx),
                bounds.min.y as i64 + i64::from(gy),
            );
            if px_x < 0 || px_y < 0 || px_x >= i64::from(w) || px_y >= i64::from(h) {
                return;
            }
            let at = 3 * (px_y as usize * w as usize + px_x as usize);
            let a = coverage.clamp(0.0, 1.0);
            for (dst, &ink) in rgb[at..at + 3].iter_mut().zip(&color) {
                *dst = (f32::from(*dst) * (1.0 - a) + f32::from(ink) * a).round() as u8;
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_anti_aliased_within_its_line_and_clips() {
        let mut c = Canvas::new(60, 20, [255; 3]);
        c.text(2, 2, "Il", [0; 3]);
        let dark: Vec<(u32, u32)> = (0..20)
            .flat_map(|y| (0..60).map(move |x| (x, y)))
            .filter(|&(x, y)| c.get(x, y) != [255; 3])
            .collect();
        assert!(!dark.is_empty());
        // Within the line below (2, 2) and the measured width.
        assert!(
            dark.iter()
                .all(|&(x, y)| x >= 2 && (2..2 + LINE).contains(&y))
        );
        assert!(dark.iter().all(|&(x, _)| x <= 2 + text_width("Il")));
        // Grey edge pixels, not only black and white.
        assert!((0..20).any(|y| (0..60).any(|x| {
            let g = c.get(x, y)[0];
            g > 0 && g < 255
        })));
        c.text(50, 15, "WWW", [0; 3]); // runs off the canvas: no panic
        assert_eq!(c.width(), 60);
        assert!(text_width("abc") > text_width("ab"));
    }

    #[test]
    fn disc_covers_its_centre_only_within_radius() {
        let mut c = Canvas::new(10, 10, [0; 3]);
        c.disc(5.0, 5.0, 2.0, [9; 3]);
        assert_eq!(c.get(5, 5), [9; 3]);
        assert_eq!(c.get(4, 4), [9; 3]);
        assert_eq!(c.get(8, 5), [0; 3]);
        assert_eq!(c.get(5, 1), [0; 3]);
    }
}
