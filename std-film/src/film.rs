//! The film: resolution, crop window, filter weights, merged pixel sums, and statistics.

use crate::tile::{FilmTile, Pixel};
use crate::{Bounds, Error, Image};
use nyquist::filter::{FilmTable, Weights};
use std::sync::Arc;

/// How a [`Film`] is set up.
///
/// ```
/// let c = nyquist_film::FilmConfig::new(640, 480);
/// assert_eq!(c.crop_window, [0.0, 1.0, 0.0, 1.0]);
/// assert_eq!(c.max_component, None);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilmConfig {
    /// Full resolution in pixels `[width, height]`.
    pub resolution: [u32; 2],
    /// Crop window in normalised film coordinates `[x0, x1, y0, y1]`, each in `[0, 1]`; the film
    /// stores the pixels `⌈x0·W⌉ … ⌈x1·W⌉ − 1` (and likewise in y), as pbrt does.
    pub crop_window: [f32; 4],
    /// Per-sample clamp: a sample whose largest RGB component exceeds this is scaled down to it
    /// (counted in [`FilmStats::clamped`]). `None` keeps every sample as it is.
    pub max_component: Option<f32>,
}

impl FilmConfig {
    /// A full-frame film of `width × height` pixels with no clamp.
    pub fn new(width: u32, height: u32) -> FilmConfig {
        FilmConfig {
            resolution: [width, height],
            crop_window: [0.0, 1.0, 0.0, 1.0],
            max_component: None,
        }
    }
}

/// Counters kept by tiles and summed by the film.
///
/// ```
/// let s = nyquist_film::FilmStats::default();
/// assert_eq!(s.samples + s.rejected + s.clamped + s.splats, 0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FilmStats {
    /// Samples added (accepted).
    pub samples: u64,
    /// Samples dropped because a radiance component or the weight was NaN or infinite.
    pub rejected: u64,
    /// Accepted samples scaled down by the `max_component` clamp.
    pub clamped: u64,
    /// Splats added (accepted).
    pub splats: u64,
}

impl FilmStats {
    pub(crate) fn add(&mut self, o: &FilmStats) {
        self.samples += o.samples;
        self.rejected += o.rejected;
        self.clamped += o.clamped;
        self.splats += o.splats;
    }
}

/// What resolving the film into an image found.
///
/// ```
/// let r = nyquist_film::ResolveStats::default();
/// assert_eq!(r.negative_components, 0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ResolveStats {
    /// Final pixel components below zero (from negative filter lobes), written as 0.
    pub negative_components: u64,
    /// Pixels whose weight sum was ≤ 0 and that resolved to 0 (before splats).
    pub zero_weight_pixels: u64,
}

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

/// Makes tiles of one film from any thread.
#[derive(Debug)]
pub(crate) struct TileFactory(Arc<Setup>);

impl TileFactory {
    pub(crate) fn tile(&self, spec: TileSpec) -> FilmTile {
        FilmTile::new(spec, Arc::clone(&self.0))
    }
}

/// The parts of a film that tiles share (read-only).
#[derive(Debug)]
pub(crate) struct Setup {
    pub(crate) pixel_bounds: Bounds,
    pub(crate) table: FilmTable,
    pub(crate) max_component: Option<f32>,
}

/// A film: accumulates filtered samples from tiles into `f64` pixel sums and resolves them into
/// an [`Image`].
///
/// Reconstruction is the pixel filtering equation (Dippé and Wold 1985; pbrt-v2's film),
/// I(x, y) = Σ f(x − xᵢ, y − yᵢ)·L(xᵢ, yᵢ) / Σ f(x − xᵢ, y − yᵢ), with the filter read from a
/// table built once. Tiles are merged in tile-index order whatever order they arrive in (a tile
/// that arrives early waits), so the image is bit-identical for any thread count or schedule.
///
/// ```
/// use nyquist_film::{Film, FilmConfig};
/// use nyquist::filter::Boxcar;
/// let mut film = Film::new(FilmConfig::new(4, 4), &Boxcar::default()).unwrap();
/// for spec in film.tiles(2).unwrap() {
///     let mut tile = film.tile(spec);
///     let b = spec.bounds;
///     for y in b.y0..b.y1 {
///         for x in b.x0..b.x1 {
///             tile.add_sample([x as f32 + 0.5, y as f32 + 0.5], [0.25, 0.5, 1.0], 1.0);
///         }
///     }
///     film.merge(tile).unwrap();
/// }
/// let (image, _) = film.image();
/// assert_eq!(image.get(3, 1), [0.25, 0.5, 1.0]);
/// ```
#[derive(Debug)]
pub struct Film {
    setup: Arc<Setup>,
    pixels: Vec<Pixel>,
    splats: Vec<[f64; 3]>,
    next_tile: usize,
    /// Tiles that arrived ahead of `next_tile`, by index, in arrival order (few: a plain list
    /// keeps the ordered-map code out of small builds such as the WebAssembly explorer).
    pending: Vec<(usize, FilmTile)>,
    stats: FilmStats,
}

impl Film {
    /// A film with `config`, reconstructing through `filter` (tabulated once, here).
    ///
    /// # Errors
    /// [`Error::Config`] for a zero resolution, a crop window outside `[0, 1]` or empty, or a
    /// non-finite or non-positive `max_component`; [`Error::OutOfMemory`] if the allocator cannot
    /// provide the pixels (a film of `w × h` pixels takes `32·w·h` bytes).
    pub fn new(config: FilmConfig, filter: &dyn nyquist::filter::Filter) -> Result<Film, Error> {
        let [w, h] = config.resolution;
        if w == 0 || h == 0 {
            return Err(Error::Config(format!(
                "resolution {w}x{h}: both sides must be positive"
            )));
        }
        let c = config.crop_window;
        if !(c.iter().all(|v| (0.0..=1.0).contains(v)) && c[0] < c[1] && c[2] < c[3]) {
            return Err(Error::Config(format!(
                "crop window {c:?} must be [x0, x1, y0, y1] with 0 ≤ x0 < x1 ≤ 1 and 0 ≤ y0 < y1 ≤ 1"
            )));
        }
        if let Some(m) = config.max_component
            && !(m.is_finite() && m > 0.0)
        {
            return Err(Error::Config(format!(
                "max component {m} must be finite and positive"
            )));
        }
        // In f32, as pbrt does, so that 0.2 × 10 is 2 (not 2.0000000298 → 3).
        let ceil = |v: f32, n: u32| (v * n as f32).ceil() as i64;
        let pixel_bounds = Bounds::new(ceil(c[0], w), ceil(c[2], h), ceil(c[1], w), ceil(c[3], h));
        if pixel_bounds.is_empty() {
            return Err(Error::Config(format!(
                "crop window {c:?} covers no pixel of {w}x{h}"
            )));
        }
        let n = pixel_bounds.area() as usize;
        let pixels = crate::error::try_filled(n, Pixel::default(), "the film's pixels")?;
        Ok(Film {
            setup: Arc::new(Setup {
                pixel_bounds,
                table: FilmTable::new(filter)?,
                max_component: config.max_component,
            }),
            pixels,
            // Allocated when the first tile with splats is merged.
            splats: Vec::new(),
            next_tile: 0,
            pending: Vec::new(),
            stats: FilmStats::default(),
        })
    }

    /// The pixels the film stores (the crop window's pixels), in film coordinates.
    pub fn pixel_bounds(&self) -> Bounds {
        self.setup.pixel_bounds
    }

    /// The filter radius the film reconstructs with, `[rx, ry]` in pixels.
    pub fn filter_radius(&self) -> [f32; 2] {
        self.setup.table.radius()
    }

    /// The filter weight the film uses at offset `(dx, dy)` from a pixel centre (the table
    /// lookup, not a direct evaluation).
    pub fn filter_weight(&self, dx: f32, dy: f32) -> f32 {
        self.setup.table.weight(dx, dy)
    }

    /// Splits the film's pixels into tiles of at most `size × size`, row by row from the top
    /// left; the order is the merge order.
    ///
    /// # Errors
    /// [`Error::Config`] if `size` is zero.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(5, 3), &nyquist::filter::Boxcar::default()).unwrap();
    /// let tiles = film.tiles(2).unwrap();
    /// assert_eq!(tiles.len(), 6);
    /// assert_eq!(tiles.iter().map(|t| t.bounds.area()).sum::<u64>(), 15);
    /// ```
    pub fn tiles(&self, size: u32) -> Result<Vec<TileSpec>, Error> {
        if size == 0 {
            return Err(Error::Config("tile size must be positive".into()));
        }
        let b = self.setup.pixel_bounds;
        let s = i64::from(size);
        let mut out = Vec::new();
        let mut y = b.y0;
        while y < b.y1 {
            let mut x = b.x0;
            while x < b.x1 {
                out.push(TileSpec {
                    index: out.len(),
                    bounds: Bounds::new(x, y, (x + s).min(b.x1), (y + s).min(b.y1)),
                });
                x += s;
            }
            y += s;
        }
        Ok(out)
    }

    /// An owned tile for `spec`: it takes samples whose film positions lie in `spec.bounds`
    /// and stores every pixel they reach, `⌈p − ½ − r⌉ … ⌊p − ½ + r⌋` clipped to the film.
    pub fn tile(&self, spec: TileSpec) -> FilmTile {
        FilmTile::new(spec, Arc::clone(&self.setup))
    }

    /// A handle that makes tiles without borrowing the film (for worker threads).
    pub(crate) fn tile_factory(&self) -> TileFactory {
        TileFactory(Arc::clone(&self.setup))
    }

    /// Adds a tile's pixels, splats and counters to the film. Tiles are applied in index order:
    /// a tile whose predecessors have not arrived is held until they do (or until
    /// [`Film::image`] applies what is held, in index order).
    ///
    /// # Errors
    /// [`Error::Config`] if a tile with this index was already merged or is held, or if the
    /// tile was made by another film (its pixels are not this film's).
    pub fn merge(&mut self, mut tile: FilmTile) -> Result<(), Error> {
        tile.drain_queue();
        let index = tile.index();
        if !Arc::ptr_eq(tile.setup(), &self.setup) {
            return Err(Error::Config(format!(
                "tile {index} was made by another film"
            )));
        }
        if index < self.next_tile || self.pending.iter().any(|(i, _)| *i == index) {
            return Err(Error::Config(format!("tile {index} merged twice")));
        }
        self.pending.push((index, tile));
        while let Some(at) = self.pending.iter().position(|(i, _)| *i == self.next_tile) {
            let (_, tile) = self.pending.swap_remove(at);
            self.apply(&tile);
            self.next_tile += 1;
        }
        Ok(())
    }

    fn apply(&mut self, tile: &FilmTile) {
        let fb = self.setup.pixel_bounds;
        // The merged pixels, `tb`, inside the stored ones, `sb` (see `FilmTile::stored_bounds`).
        let tb = tile.pixel_bounds();
        let sb = tile.stored_bounds();
        let fw = fb.width() as usize;
        let tw = tb.width() as usize;
        let sw = sb.width() as usize;
        for y in tb.y0..tb.y1 {
            let frow = (y - fb.y0) as usize * fw + (tb.x0 - fb.x0) as usize;
            let trow = (y - sb.y0) as usize * sw + (tb.x0 - sb.x0) as usize;
            for (dst, src) in self.pixels[frow..frow + tw]
                .iter_mut()
                .zip(&tile.pixels()[trow..trow + tw])
            {
                dst.add(src);
            }
            if tile.splats().is_empty() {
                continue;
            }
            if self.splats.is_empty() {
                self.splats = vec![[0.0; 3]; self.pixels.len()];
            }
            for (dst, src) in self.splats[frow..frow + tw]
                .iter_mut()
                .zip(&tile.splats()[trow..trow + tw])
            {
                for c in 0..3 {
                    dst[c] += src[c];
                }
            }
        }
        self.stats.add(&tile.stats());
    }

    /// Applies held tiles in index order, whatever gaps remain.
    fn flush(&mut self) {
        while let Some(at) = (0..self.pending.len()).min_by_key(|&k| self.pending[k].0) {
            let (index, tile) = self.pending.swap_remove(at);
            self.apply(&tile);
            self.next_tile = index + 1;
        }
    }

    /// Counters over every merged tile: samples, rejected (non-finite) samples, clamps, splats.
    pub fn stats(&self) -> FilmStats {
        self.stats
    }

    /// Samples dropped because a radiance component or weight was NaN or infinite.
    pub fn rejected(&self) -> u64 {
        self.stats.rejected
    }

    /// Bytes of pixel storage the film holds: the [`Pixel`] sums (32 bytes a pixel), plus 24
    /// bytes a pixel of splat sums once a tile with splats has been merged.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(100, 10), &nyquist::filter::Boxcar::default()).unwrap();
    /// assert_eq!(film.storage_bytes(), 1000 * 32);
    /// ```
    pub fn storage_bytes(&self) -> usize {
        self.pixels.len() * size_of::<Pixel>() + self.splats.len() * size_of::<[f64; 3]>()
    }

    /// The accumulated sums of pixel `(x, y)` (film coordinates), or `None` outside the film.
    pub fn pixel(&self, x: i64, y: i64) -> Option<Pixel> {
        let b = self.setup.pixel_bounds;
        b.contains(x, y)
            .then(|| self.pixels[(y - b.y0) as usize * b.width() as usize + (x - b.x0) as usize])
    }

    /// Resolves the film: each pixel is `rgb_sum / weight_sum` (0 where `weight_sum ≤ 0`) plus
    /// its splats divided by the filter integral; negative components become 0 and are counted.
    /// Applies any held tiles first.
    pub fn image(&mut self) -> (Image, ResolveStats) {
        self.flush();
        let b = self.setup.pixel_bounds;
        let mut image = Image::new(b.width() as u32, b.height() as u32)
            .expect("the film has at least one pixel");
        let integral = f64::from(self.setup.table.integral());
        let splat_scale = if integral.is_finite() && integral != 0.0 {
            1.0 / integral
        } else {
            0.0
        };
        let mut stats = ResolveStats::default();
        let no_splats = [[0.0f64; 3]];
        let splats = self
            .splats
            .iter()
            .chain(no_splats.iter().cycle())
            .take(self.pixels.len());
        for ((out, p), s) in image
            .data_mut()
            .chunks_exact_mut(3)
            .zip(&self.pixels)
            .zip(splats)
        {
            let inv = if p.weight_sum > 0.0 {
                1.0 / p.weight_sum
            } else {
                stats.zero_weight_pixels += 1;
                0.0
            };
            for c in 0..3 {
                let v = p.rgb_sum[c] * inv + s[c] * splat_scale;
                out[c] = if v >= 0.0 {
                    (v as f32).min(f32::MAX)
                } else {
                    stats.negative_components += 1;
                    0.0
                };
            }
        }
        (image, stats)
    }
}
