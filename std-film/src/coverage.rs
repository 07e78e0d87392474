//! [`Coverage`]: which film pixels lie inside the bounds of a merged tile.

use crate::bounds::Bounds;
use crate::error::Error;

/// One bit per film pixel, set once a merged tile's bounds (the pixels whose samples it takes)
/// contain the pixel, so a film can tell when a tile is missing.
#[derive(Clone, Debug)]
pub(crate) struct Coverage {
    /// The film's pixels.
    bounds: Bounds,
    /// Row-major bits, 64 pixels a word.
    bits: Vec<u64>,
    /// Set bits.
    covered: u64,
}

impl Coverage {
    /// No pixel covered.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`] if the allocator cannot provide the bits (`area / 8` bytes).
    pub(crate) fn new(bounds: Bounds) -> Result<Coverage, Error> {
        let words = bounds.area().div_ceil(64);
        let words = usize::try_from(words).unwrap_or(usize::MAX);
        Ok(Coverage {
            bounds,
            bits: crate::error::try_filled(words, 0, "the film's tile coverage")?,
            covered: 0,
        })
    }

    /// Marks the film pixels inside `b`.
    pub(crate) fn mark(&mut self, b: Bounds) {
        let i = b.intersect(&self.bounds);
        if i.is_empty() {
            return;
        }
        let w = self.bounds.width();
        let dx = (i.x0 - self.bounds.x0) as u64;
        for y in i.y0..i.y1 {
            let start = (y - self.bounds.y0) as u64 * w + dx;
            self.covered += set_range(&mut self.bits, start, start + i.width());
        }
    }

    /// Marks every film pixel.
    pub(crate) fn mark_all(&mut self) {
        self.mark(self.bounds);
    }

    /// Film pixels not yet marked.
    pub(crate) fn uncovered(&self) -> u64 {
        self.bounds.area() - self.covered
    }
}

/// Sets bits `start .. end` (`end ≤ 64 · bits.len()`) and returns how many were clear.
fn set_range(bits: &mut [u64], start: u64, end: u64) -> u64 {
    let mut newly = 0;
    let mut k = start;
    while k < end {
        let (word, bit) = ((k / 64) as usize, k % 64);
        let n = (end - k).min(64 - bit);
        let mask = if n == 64 {
            u64::MAX
        } else {
            ((1u64 << n) - 1) << bit
        };
        if let Some(w) = bits.get_mut(word) {
            newly += u64::from((mask & !*w).count_ones());
            *w |= mask;
        }
        k += n;
    }
    newly
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Overlapping and out-of-film rectangles count each film pixel once; runs that cross word
    /// boundaries set exactly their bits.
    #[test]
    fn marks_count_each_film_pixel_once() {
        let film = Bounds::new(-3, 2, 67, 5); // 70 × 3: rows cross 64-bit words
        let mut c = Coverage::new(film).unwrap();
        assert_eq!(c.uncovered(), 210);
        c.mark(Bounds::new(0, 0, 10, 3)); // rows 2 and outside: 10 pixels in the film
        assert_eq!(c.uncovered(), 200);
        c.mark(Bounds::new(5, 2, 70, 3)); // overlaps 5 of them; 62 columns inside the film
        assert_eq!(c.uncovered(), 200 - 57);
        c.mark(Bounds::new(i64::MIN, i64::MIN, i64::MAX, i64::MAX));
        assert_eq!(c.uncovered(), 0);
        let mut d = Coverage::new(film).unwrap();
        d.mark(Bounds::new(100, 0, 200, 9));
        assert_eq!(d.uncovered(), 210);
        d.mark_all();
        assert_eq!(d.uncovered(), 0);
        let mut bits = [0u64; 3];
        assert_eq!(set_range(&mut bits, 60, 130), 70);
        assert_eq!(bits, [0xF << 60, u64::MAX, 0b11]);
        assert_eq!(set_range(&mut bits, 0, 192), 192 - 70);
    }
}
