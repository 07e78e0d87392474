//! [`TileSpec`]: which part of the film a tile covers.

use crate::bounds::Bounds;

/// Which part of the film a tile covers: its place in the merge order and its pixels.
///
/// ```
/// use nyquist_film::{Bounds, TileSpec};
/// let t = TileSpec { index: 3, bounds: Bounds::new(0, 0, 16, 16) };
/// assert_eq!(t.bounds.area(), 256);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TileSpec {
    /// Position in the merge order (0, 1, 2, …).
    pub index: usize,
    /// The pixels whose samples the tile takes (film coordinates).
    pub bounds: Bounds,
}
