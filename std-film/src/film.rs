//! [`Film`]: the merged pixel sums, their tiles' merge order, and resolving them into an image.

use crate::bounds::Bounds;
use crate::coverage::Coverage;
use crate::error::Error;
use crate::extras::{ChannelImage, Estimate, ExtraImages};
use crate::image::Image;
use crate::pixel::Pixel;
use crate::sample::FilmSample;
use crate::setup::{FilmConfig, Setup};
use crate::stats::{FilmStats, ResolveStats};
use crate::tile::FilmTile;
use crate::tile_spec::TileSpec;
use nyquist::filter::{Filter, Weights};
use std::sync::Arc;

/// A film: accumulates filtered samples from tiles into `f64` pixel sums and resolves them into
/// an [`Image`].
///
/// Reconstruction is the pixel filtering equation (Dippé and Wold 1985; pbrt-v2's film),
/// I(x, y) = Σ f(x − xᵢ, y − yᵢ)·L(xᵢ, yᵢ) / Σ f(x − xᵢ, y − yᵢ), with the filter read from a
/// table built once. Two ways in:
///
/// - **Tiles**, for any number of threads: [`Film::tiles`] splits the film, [`Film::tile`]
///   hands out an owned [`FilmTile`] per part, [`Film::merge`] adds it back ([`render_tiles`]
///   runs that loop). Tiles are merged in tile-index order whatever order they arrive in (a tile
///   that arrives early waits), so the image is bit-identical for any thread count or schedule.
/// - **The film itself**, on one thread: [`Film::add_sample`] and [`Film::add_splat`] add
///   straight into the film's sums, with a tile's arithmetic.
///
/// [`Film::try_image`] resolves the image and refuses while a tile is missing;
/// [`Film::image`] resolves whatever has arrived.
///
/// [`render_tiles`]: crate::render_tiles
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
/// let (image, _) = film.try_image().unwrap();
/// assert_eq!(image.get(3, 1), [0.25, 0.5, 1.0]);
/// ```
#[derive(Debug)]
pub struct Film {
    setup: Arc<Setup>,
    /// The film's sums: a tile over exactly the film's pixels (no guard band), into which
    /// merged tiles are added and [`Film::add_sample`] adds directly. Its counters are the
    /// film's own samples.
    sums: FilmTile,
    next_tile: usize,
    /// Tiles that arrived ahead of `next_tile`, by index, in arrival order (few: a plain list
    /// keeps the ordered-map code out of small builds such as the WebAssembly explorer).
    pending: Vec<(usize, FilmTile)>,
    /// Counters of the merged tiles.
    merged: FilmStats,
    /// The pixels inside a merged tile's bounds.
    coverage: Coverage,
}

impl Film {
    /// A film with `config`, reconstructing through `filter` (tabulated once, here: a
    /// [`FilmTable`](nyquist::filter::FilmTable)).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a zero side or a crop coordinate outside `[0, 1]`;
    /// [`Error::Config`] for an empty crop window (or one that covers no pixel) and a
    /// non-finite or non-positive `max_component`; [`Error::Core`] for a filter that cannot be
    /// tabulated; [`Error::OutOfMemory`] if the allocator cannot provide the pixels (a film of
    /// `w × h` pixels takes `32·w·h` bytes).
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut config = FilmConfig::new(4, 4);
    /// config.crop_window = [0.5, 0.25, 0.0, 1.0];
    /// let e = Film::new(config, &nyquist::filter::Boxcar::default()).unwrap_err();
    /// assert!(e.to_string().contains("x0 0.5 is not below x1 0.25"), "{e}");
    /// ```
    pub fn new(config: FilmConfig, filter: &dyn Filter) -> Result<Film, Error> {
        let setup = Arc::new(Setup::new(&config, filter)?);
        let sums = FilmTile::whole(Arc::clone(&setup))?;
        let coverage = Coverage::new(setup.pixel_bounds)?;
        Ok(Film {
            setup,
            sums,
            next_tile: 0,
            pending: Vec::new(),
            merged: FilmStats::default(),
            coverage,
        })
    }

    /// The pixels the film stores (the crop window's pixels), in film coordinates.
    ///
    /// ```
    /// use nyquist_film::{Bounds, Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(5, 3), &nyquist::filter::Boxcar::default()).unwrap();
    /// assert_eq!(film.pixel_bounds(), Bounds::new(0, 0, 5, 3));
    /// ```
    pub fn pixel_bounds(&self) -> Bounds {
        self.setup.pixel_bounds
    }

    /// What the film keeps per pixel beside its RGB sums.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// assert!(!film.extras().any());
    /// ```
    pub fn extras(&self) -> crate::PixelExtras {
        self.setup.extras
    }

    /// Starts another pass over the film's tiles: every tile index can be merged again, in
    /// index order as before, adding to what the film holds (adaptive rendering passes,
    /// [`crate::adaptive::render_adaptive`]).
    ///
    /// # Errors
    /// [`Error::Config`] while tiles are held waiting for a predecessor that was never merged
    /// (the pass is not complete).
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// let specs = film.tiles(2).unwrap();
    /// for pass in 0..2 {
    ///     for &spec in &specs {
    ///         let mut tile = film.tile(spec);
    ///         tile.add_sample([spec.bounds.x0 as f32 + 0.5, spec.bounds.y0 as f32 + 0.5], [1.0; 3], 1.0);
    ///         film.merge(tile).unwrap();
    ///     }
    ///     film.next_pass().unwrap();
    /// }
    /// assert_eq!(film.pixel(0, 0).unwrap().weight_sum, 2.0);
    /// film.merge(film.tile(specs[1])).unwrap(); // held: tile 0 of this pass is missing
    /// assert!(film.next_pass().is_err());
    /// ```
    pub fn next_pass(&mut self) -> Result<(), Error> {
        if let Some(held) = self.pending.iter().map(|(i, _)| *i).min() {
            return Err(Error::Config(format!(
                "the pass is not complete: tile {held} is held waiting for tile {}",
                self.next_tile
            )));
        }
        self.next_tile = 0;
        Ok(())
    }

    /// The filter radius the film reconstructs with, `[rx, ry]` in pixels.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(5, 3), &nyquist::filter::Mitchell::default()).unwrap();
    /// assert_eq!(film.filter_radius(), [2.0, 2.0]);
    /// ```
    pub fn filter_radius(&self) -> [f32; 2] {
        self.setup.table.radius()
    }

    /// The filter weight the film uses at offset `(dx, dy)` from a pixel centre (the table
    /// lookup, not a direct evaluation).
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(5, 3), &nyquist::filter::Boxcar::default()).unwrap();
    /// assert_eq!((film.filter_weight(0.5, 0.0), film.filter_weight(0.51, 0.0)), (1.0, 0.0));
    /// ```
    pub fn filter_weight(&self, dx: f32, dy: f32) -> f32 {
        self.setup.table.weight(dx, dy)
    }

    /// Splits the film's pixels into tiles of at most `size × size`, row by row from the top
    /// left; the order is the merge order.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if `size` is zero.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(5, 3), &nyquist::filter::Boxcar::default()).unwrap();
    /// let tiles = film.tiles(2).unwrap();
    /// assert_eq!(tiles.len(), 6);
    /// assert_eq!(tiles.iter().map(|t| t.bounds.area()).sum::<u64>(), 15);
    /// assert_eq!(film.tiles(0).unwrap_err().to_string(), "tile size 0 is outside 1..=4294967295");
    /// ```
    pub fn tiles(&self, size: u32) -> Result<Vec<TileSpec>, Error> {
        if size == 0 {
            return Err(Error::below_one("tile size", 0, f64::from(u32::MAX)));
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
    ///
    /// ```
    /// use nyquist_film::{Bounds, Film, FilmConfig, TileSpec};
    /// let film = Film::new(FilmConfig::new(8, 8), &nyquist::filter::Mitchell::default()).unwrap();
    /// let tile = film.tile(TileSpec { index: 0, bounds: Bounds::new(2, 2, 4, 4) });
    /// // The bounds grown by the radius (2), clipped to the film.
    /// assert_eq!(tile.pixel_bounds(), Bounds::new(0, 0, 6, 6));
    /// ```
    pub fn tile(&self, spec: TileSpec) -> FilmTile {
        FilmTile::new(spec, Arc::clone(&self.setup))
    }

    /// The setup the film's tiles share (for the tile driver's worker threads).
    pub(crate) fn setup(&self) -> &Arc<Setup> {
        &self.setup
    }

    /// Adds a sample to the film itself, on the calling thread: the single-threaded way in,
    /// with no tiles to make or merge. The same arithmetic as [`FilmTile::add_sample`] (its
    /// rejection of non-finite values, clamp and counters); the film then counts as one
    /// whole-film tile, so [`Film::try_image`] finds nothing missing.
    ///
    /// ```
    /// use nyquist::filter::Mitchell;
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(8, 6), &Mitchell::default()).unwrap();
    /// for y in 0..6 {
    ///     for x in 0..8 {
    ///         film.add_sample([x as f32 + 0.5, y as f32 + 0.5], [0.5, 0.25, 1.0], 1.0);
    ///     }
    /// }
    /// film.add_sample([1.0, 1.0], [f32::NAN; 3], 1.0); // dropped and counted
    /// assert_eq!((film.stats().samples, film.rejected()), (48, 1));
    /// let (image, _) = film.try_image().unwrap();
    /// let p = image.get(4, 3);
    /// assert!((p[0] - 0.5).abs() < 1e-6 && (p[2] - 1.0).abs() < 1e-6);
    /// ```
    pub fn add_sample(&mut self, p_film: [f32; 2], rgb: [f32; 3], weight: f32) {
        self.sums.add_sample_now(p_film, rgb, weight);
        self.coverage.mark_all();
    }

    /// Adds a sample with its index and channel values to the film itself, as
    /// [`FilmTile::add`] does to a tile; the film then counts as one whole-film tile.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig, FilmSample, PixelExtras};
    /// let mut config = FilmConfig::new(2, 2);
    /// config.extras.halves = true;
    /// let mut film = Film::new(config, &nyquist::filter::Boxcar::default()).unwrap();
    /// for i in 0..4u64 {
    ///     let v = if nyquist_film::extras::sample_half(i) == 0 { 1.0 } else { 2.0 };
    ///     film.add(&FilmSample { index: i, ..FilmSample::new([0.5, 1.5], [v; 3], 1.0) });
    /// }
    /// let e = film.estimate(0, 1).unwrap();
    /// assert_eq!(e.halves, Some([[1.0; 3], [2.0; 3]]));
    /// assert_eq!(e.half_difference(), Some([0.5; 3]));
    /// ```
    pub fn add(&mut self, sample: &FilmSample) {
        self.sums.add(sample);
        self.coverage.mark_all();
    }

    /// Adds a splat to the film itself, on the calling thread, as [`FilmTile::add_splat`] does
    /// to a tile; the film then counts as one whole-film tile.
    ///
    /// ```
    /// use nyquist::filter::Boxcar;
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &Boxcar::default()).unwrap();
    /// film.add_splat([1.5, 2.5], [2.0, 0.0, 0.0]);
    /// let (image, _) = film.try_image().unwrap();
    /// assert_eq!(image.get(1, 2), [2.0, 0.0, 0.0]); // a box's integral is 1
    /// assert_eq!(film.stats().splats, 1);
    /// ```
    pub fn add_splat(&mut self, p_film: [f32; 2], rgb: [f32; 3]) {
        self.sums.add_splat(p_film, rgb);
        self.coverage.mark_all();
    }

    /// Adds a tile's pixels, splats and counters to the film. Tiles are applied in index order:
    /// a tile whose predecessors have not arrived is held until they do (or until
    /// [`Film::image`] applies what is held, in index order).
    ///
    /// # Errors
    /// [`Error::Config`] if a tile with this index was already merged or is held, or if the
    /// tile was made by another film (its pixels are not this film's).
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// let spec = film.tiles(4).unwrap()[0];
    /// film.merge(film.tile(spec)).unwrap();
    /// assert_eq!(film.merge(film.tile(spec)).unwrap_err().to_string(),
    ///            "invalid configuration: tile 0 merged twice");
    /// ```
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
            for (dst, src) in self.sums.pixels_mut()[frow..frow + tw]
                .iter_mut()
                .zip(&tile.pixels()[trow..trow + tw])
            {
                dst.add(src);
            }
            if let (Some(dst), Some(src)) = (self.sums.extras_mut(), tile.extras()) {
                for i in 0..tw {
                    dst.merge_pixel(frow + i, src, trow + i);
                }
            }
            if tile.splats().is_empty() {
                continue;
            }
            for (dst, src) in self.sums.splats_mut()[frow..frow + tw]
                .iter_mut()
                .zip(&tile.splats()[trow..trow + tw])
            {
                for c in 0..3 {
                    dst[c] += src[c];
                }
            }
        }
        self.merged.add(&tile.stats());
        self.coverage.mark(tile.bounds());
    }

    /// Applies held tiles in index order, whatever gaps remain.
    fn flush(&mut self) {
        while let Some(at) = (0..self.pending.len()).min_by_key(|&k| self.pending[k].0) {
            let (index, tile) = self.pending.swap_remove(at);
            self.apply(&tile);
            self.next_tile = index + 1;
        }
    }

    /// Counters over every merged tile and the film's own samples: samples, rejected
    /// (non-finite) samples, clamps, splats.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// film.add_sample([0.5, 0.5], [1.0; 3], 1.0);
    /// assert_eq!(film.stats().samples, 1);
    /// ```
    pub fn stats(&self) -> FilmStats {
        let mut s = self.merged;
        s.add(&self.sums.stats());
        s
    }

    /// Samples dropped because a radiance component or weight was NaN or infinite.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// film.add_sample([0.5, 0.5], [1.0; 3], f32::INFINITY);
    /// assert_eq!(film.rejected(), 1);
    /// ```
    pub fn rejected(&self) -> u64 {
        self.stats().rejected
    }

    /// Bytes of pixel storage the film holds: the [`Pixel`] sums (32 bytes a pixel), plus 24
    /// bytes a pixel of splat sums once a splat has reached the film.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(100, 10), &nyquist::filter::Boxcar::default()).unwrap();
    /// assert_eq!(film.storage_bytes(), 1000 * 32);
    /// ```
    pub fn storage_bytes(&self) -> usize {
        self.sums.storage_bytes()
    }

    /// The accumulated sums of pixel `(x, y)` (film coordinates), or `None` outside the film.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// film.add_sample([2.5, 1.5], [3.0; 3], 1.0);
    /// assert_eq!(film.pixel(2, 1).unwrap().weight_sum, 1.0);
    /// assert_eq!(film.pixel(4, 1), None);
    /// ```
    pub fn pixel(&self, x: i64, y: i64) -> Option<Pixel> {
        let b = self.setup.pixel_bounds;
        b.contains(x, y).then(|| {
            self.sums.pixels()[(y - b.y0) as usize * b.width() as usize + (x - b.x0) as usize]
        })
    }

    /// Pixel `(x, y)`'s value and the error estimates the film keeps for it (film coordinates),
    /// or `None` outside the film. Reads the merged sums (held tiles are not applied); see
    /// [`crate::extras`] for the estimators.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut config = FilmConfig::new(4, 4);
    /// config.extras.variance = true;
    /// let mut film = Film::new(config, &nyquist::filter::Boxcar::default()).unwrap();
    /// for v in [1.0, 2.0, 3.0] {
    ///     film.add_sample([2.5, 1.5], [v; 3], 1.0);
    /// }
    /// let e = film.estimate(2, 1).unwrap();
    /// assert_eq!(e.value, [2.0; 3]);
    /// assert_eq!(e.variance, Some([1.0 / 3.0; 3])); // s² = 1 over n = 3
    /// assert_eq!(e.halves, None); // not kept
    /// assert_eq!(film.estimate(0, 0).unwrap().variance, None); // no sample
    /// ```
    pub fn estimate(&self, x: i64, y: i64) -> Option<Estimate> {
        let b = self.setup.pixel_bounds;
        if !b.contains(x, y) {
            return None;
        }
        let i = (y - b.y0) as usize * b.width() as usize + (x - b.x0) as usize;
        let p = self.sums.pixels()[i];
        Some(match self.sums.extras() {
            Some(e) => e.estimate(i, &p),
            None => Estimate::from_sums(p.rgb_sum, p.weight_sum, None, None),
        })
    }

    /// The extra channels' values of pixel `(x, y)`, Σ f·a / Σ f each (0 where Σ f ≤ 0), or
    /// `None` outside the film; empty when the film keeps no channels.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig, FilmSample};
    /// let mut config = FilmConfig::new(4, 4);
    /// config.extras.channels = 2;
    /// let mut film = Film::new(config, &nyquist::filter::Boxcar::default()).unwrap();
    /// for a in [[0.5, 10.0], [1.5, 20.0]] {
    ///     film.add(&FilmSample { channels: &a, ..FilmSample::new([1.5, 1.5], [1.0; 3], 3.0) });
    /// }
    /// assert_eq!(film.channel_values(1, 1).unwrap(), [1.0, 15.0]);
    /// assert_eq!(film.channel_values(4, 1), None);
    /// ```
    pub fn channel_values(&self, x: i64, y: i64) -> Option<Vec<f64>> {
        let b = self.setup.pixel_bounds;
        if !b.contains(x, y) {
            return None;
        }
        let i = (y - b.y0) as usize * b.width() as usize + (x - b.x0) as usize;
        let w = self.sums.pixels()[i].weight_sum;
        Some(
            self.sums
                .extras()
                .map(|e| e.channel_means(i, w).collect())
                .unwrap_or_default(),
        )
    }

    /// The images of what the film keeps beside RGB ([`crate::PixelExtras`]), each `None`
    /// when not kept: the variance of each pixel's value (NaN where it is undefined: fewer than
    /// two effective samples), the A and B halves' means (0 where a half has no weight), and
    /// the extra channels. Held tiles are applied first, as [`Film::image`] does. Values are
    /// not clamped (a negative filter lobe can make a mean negative).
    ///
    /// # Errors
    /// [`Error::OutOfMemory`] if the allocator cannot provide the images.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig, PixelExtras};
    /// let mut config = FilmConfig::new(3, 2);
    /// config.extras = PixelExtras { variance: true, halves: true, channels: 0 };
    /// let mut film = Film::new(config, &nyquist::filter::Boxcar::default()).unwrap();
    /// film.add_sample([0.5, 0.5], [1.0; 3], 1.0);
    /// film.add_sample([0.5, 0.5], [3.0; 3], 1.0);
    /// let layers = film.extra_images().unwrap();
    /// let variance = layers.variance.unwrap();
    /// assert_eq!(variance.get(0, 0), [1.0; 3]);
    /// assert!(variance.get(1, 0)[0].is_nan());
    /// assert_eq!(layers.halves.unwrap()[0].get(0, 0), [2.0; 3]); // index 0: both in A
    /// assert!(layers.channels.is_none());
    /// ```
    pub fn extra_images(&mut self) -> Result<ExtraImages, Error> {
        self.flush();
        let b = self.setup.pixel_bounds;
        let (w, h) = (b.width() as u32, b.height() as u32);
        let extras = self.setup.extras;
        let pixels = self.sums.pixels();
        let mut out = ExtraImages::default();
        let Some(sums) = self.sums.extras() else {
            return Ok(out);
        };
        if extras.variance {
            let mut image = Image::new(w, h)?;
            for (i, (o, p)) in image.data_mut().chunks_exact_mut(3).zip(pixels).enumerate() {
                let v = sums.estimate(i, p).variance;
                for c in 0..3 {
                    o[c] = v.map_or(f32::NAN, |v| v[c] as f32);
                }
            }
            out.variance = Some(image);
        }
        if extras.halves {
            let mut images = [Image::new(w, h)?, Image::new(w, h)?];
            for (i, p) in pixels.iter().enumerate() {
                let b = sums.half_b[i];
                let a = Pixel {
                    rgb_sum: [0, 1, 2].map(|c| p.rgb_sum[c] - b.rgb_sum[c]),
                    weight_sum: p.weight_sum - b.weight_sum,
                };
                for (image, half) in images.iter_mut().zip([a, b]) {
                    let m = Estimate::from_sums(half.rgb_sum, half.weight_sum, None, None).value;
                    image.data_mut()[3 * i..3 * i + 3].copy_from_slice(&m.map(|v| v as f32));
                }
            }
            out.halves = Some(images);
        }
        if extras.channels > 0 {
            let mut image = ChannelImage::new(w, h, usize::from(extras.channels))?;
            let n = image.channels();
            for (i, (o, p)) in image.data_mut().chunks_exact_mut(n).zip(pixels).enumerate() {
                for (o, v) in o.iter_mut().zip(sums.channel_means(i, p.weight_sum)) {
                    *o = v as f32;
                }
            }
            out.channels = Some(image);
        }
        Ok(out)
    }

    /// Resolves the film once every part of it has arrived, as [`Film::image`] does; the film
    /// is unchanged by an error, so the missing tiles can still be merged.
    ///
    /// # Errors
    /// [`Error::Incomplete`] while a film pixel lies in no merged tile's bounds, or a tile is
    /// held waiting for a predecessor that was never merged: a tile is missing. Samples added
    /// to the film itself ([`Film::add_sample`]) count as one whole-film tile.
    /// [`Error::OutOfMemory`] if the allocator cannot provide the image.
    ///
    /// ```
    /// use nyquist_film::{Error, Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// let specs = film.tiles(2).unwrap(); // four 2 × 2 tiles
    /// for &spec in &specs[..3] {
    ///     film.merge(film.tile(spec)).unwrap();
    /// }
    /// assert!(matches!(film.try_image(), Err(Error::Incomplete { uncovered: 4, pixels: 16, held: 0 })));
    /// film.merge(film.tile(specs[3])).unwrap();
    /// assert!(film.try_image().is_ok());
    /// ```
    pub fn try_image(&mut self) -> Result<(Image, ResolveStats), Error> {
        // Held tiles wait for a missing predecessor: count what they would cover, without
        // applying them (that would move the film past the missing tile for good).
        let mut coverage = self.coverage.clone();
        for (_, tile) in &self.pending {
            coverage.mark(tile.bounds());
        }
        let (uncovered, held) = (coverage.uncovered(), self.pending.len());
        if uncovered > 0 || held > 0 {
            return Err(Error::Incomplete {
                uncovered,
                pixels: self.setup.pixel_bounds.area(),
                held,
            });
        }
        self.resolve()
    }

    /// Resolves the film into an image, complete or not: each pixel is `rgb_sum / weight_sum`
    /// (0 where `weight_sum ≤ 0`) plus its splats divided by the filter integral; negative
    /// components become 0 and are counted. Held tiles are applied first, in index order, past
    /// any gap: the film then moves past them, and a missing tile can no longer be merged.
    ///
    /// A film with a missing tile resolves to an image whose missing part holds only what
    /// other tiles' filters spread into it: [`ResolveStats::uncovered_pixels`] counts the
    /// pixels no merged tile covered. Use [`Film::try_image`] to refuse such a film; this method
    /// is for a partial image on purpose (a preview while tiles are still arriving).
    ///
    /// # Panics
    /// If the allocator cannot provide the image (12 bytes a pixel, against the film's 32);
    /// [`Film::try_image`] returns [`Error::OutOfMemory`] instead.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// let spec = film.tiles(2).unwrap()[0];
    /// let mut tile = film.tile(spec);
    /// tile.add_sample([0.5, 0.5], [1.0; 3], 1.0);
    /// film.merge(tile).unwrap();
    /// let (preview, stats) = film.image();
    /// assert_eq!((preview.get(0, 0), stats.uncovered_pixels), ([1.0; 3], 12));
    /// ```
    pub fn image(&mut self) -> (Image, ResolveStats) {
        // Display, not Debug: the error's Debug form would carry a path formatter into every
        // program that resolves a film (about 1 KB of the explorer's WebAssembly).
        self.resolve()
            .unwrap_or_else(|e| panic!("the film's image could not be allocated: {e}"))
    }

    /// [`Film::image`], with the image's allocation failure as an error.
    fn resolve(&mut self) -> Result<(Image, ResolveStats), Error> {
        self.flush();
        let b = self.setup.pixel_bounds;
        let mut image = Image::new(b.width() as u32, b.height() as u32)?;
        let integral = f64::from(self.setup.table.integral());
        let splat_scale = if integral.is_finite() && integral != 0.0 {
            1.0 / integral
        } else {
            0.0
        };
        let mut stats = ResolveStats {
            uncovered_pixels: self.coverage.uncovered(),
            ..ResolveStats::default()
        };
        let pixels = self.sums.pixels();
        let no_splats = [[0.0f64; 3]];
        let splats = self
            .sums
            .splats()
            .iter()
            .chain(no_splats.iter().cycle())
            .take(pixels.len());
        for ((out, p), s) in image.data_mut().chunks_exact_mut(3).zip(pixels).zip(splats) {
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
        Ok((image, stats))
    }
}
