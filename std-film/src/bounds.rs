//! Integer pixel rectangles.

/// A half-open rectangle of pixels `[x0, x1) × [y0, y1)` in film coordinates.
///
/// ```
/// use nyquist_film::Bounds;
/// let b = Bounds::new(0, 0, 4, 3);
/// assert_eq!(b.area(), 12);
/// assert!(b.contains(3, 2) && !b.contains(4, 2));
/// assert!(Bounds::new(5, 5, 2, 9).is_empty());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Bounds {
    /// First column.
    pub x0: i64,
    /// First row.
    pub y0: i64,
    /// One past the last column.
    pub x1: i64,
    /// One past the last row.
    pub y1: i64,
}

impl Bounds {
    /// The rectangle `[x0, x1) × [y0, y1)`.
    #[inline]
    pub const fn new(x0: i64, y0: i64, x1: i64, y1: i64) -> Bounds {
        Bounds { x0, y0, x1, y1 }
    }

    /// Columns covered (0 when empty).
    #[inline]
    pub fn width(&self) -> u64 {
        self.x1.saturating_sub(self.x0).max(0) as u64
    }

    /// Rows covered (0 when empty).
    #[inline]
    pub fn height(&self) -> u64 {
        self.y1.saturating_sub(self.y0).max(0) as u64
    }

    /// Pixels covered.
    #[inline]
    pub fn area(&self) -> u64 {
        self.width().saturating_mul(self.height())
    }

    /// Whether no pixel is covered.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.area() == 0
    }

    /// Whether pixel `(x, y)` is inside.
    #[inline]
    pub fn contains(&self, x: i64, y: i64) -> bool {
        x >= self.x0 && x < self.x1 && y >= self.y0 && y < self.y1
    }

    /// The overlap of two rectangles (possibly empty).
    ///
    /// ```
    /// use nyquist_film::Bounds;
    /// let i = Bounds::new(0, 0, 4, 4).intersect(&Bounds::new(2, -1, 9, 3));
    /// assert_eq!(i, Bounds::new(2, 0, 4, 3));
    /// ```
    #[inline]
    pub fn intersect(&self, other: &Bounds) -> Bounds {
        Bounds::new(
            self.x0.max(other.x0),
            self.y0.max(other.y0),
            self.x1.min(other.x1),
            self.y1.min(other.y1),
        )
    }
}
