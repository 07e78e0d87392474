//! The parallel tile driver.

use crate::{Bounds, Error, Film, FilmTile};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;

/// What a [`render_tiles`] closure is told about its tile, to build the tile's sampler: its
/// place in the merge order, the number of tiles, the pixels to sample, and a per-tile seed.
///
/// Everything here depends only on the film and the tile size, never on the thread or the
/// schedule, so a renderer that derives its sampling from it renders the same bits for any
/// thread count.
///
/// ```
/// use nyquist_film::{Bounds, TileContext};
/// let ctx = TileContext { index: 2, count: 4, bounds: Bounds::new(8, 0, 16, 8) };
/// assert_eq!(ctx.pixel_range(), Some(([8, 0], [16, 8])));
/// assert_eq!(ctx.seed(7), nyquist::hash::hash2(7, 2)); // the base and the tile index
/// assert_ne!(ctx.seed(7), TileContext { index: 3, ..ctx }.seed(7));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TileContext {
    /// The tile's position in the merge order, `0 … count − 1`.
    pub index: usize,
    /// How many tiles the film was split into.
    pub count: usize,
    /// The pixels whose samples the tile takes (the same as [`FilmTile::bounds`]).
    pub bounds: Bounds,
}

impl TileContext {
    /// A seed for this tile's own random numbers, derived from `base` and the tile index with
    /// [`nyquist::hash::hash2`]: different per tile, the same on every run and thread count.
    ///
    /// Core samplers do not need it: their values depend only on (pixel, sample index,
    /// dimension, seed), so one sampler value cloned into every tile is already deterministic.
    /// Use it for anything the renderer draws per tile (a `nyquist::rng::default_rng`).
    ///
    /// ```
    /// use nyquist_film::{Bounds, TileContext};
    /// let ctx = TileContext { index: 0, count: 1, bounds: Bounds::new(0, 0, 4, 4) };
    /// assert_eq!(ctx.seed(1), nyquist::hash::hash2(1, 0));
    /// ```
    pub fn seed(&self, base: u64) -> u64 {
        nyquist::hash::hash2(base, self.index as u64)
    }

    /// The tile's pixels as `(start, end)` corners in `u32`, the form
    /// [`nyquist::sampler::PixelRangeSampler::new`] takes; `None` for an empty tile or one with
    /// a coordinate outside `u32` (never for tiles [`render_tiles`] hands out).
    ///
    /// ```
    /// use nyquist_film::{Bounds, TileContext};
    /// let ctx = TileContext { index: 0, count: 1, bounds: Bounds::new(-1, 0, 4, 4) };
    /// assert_eq!(ctx.pixel_range(), None);
    /// ```
    pub fn pixel_range(&self) -> Option<([u32; 2], [u32; 2])> {
        let b = self.bounds;
        let c = |v: i64| u32::try_from(v).ok();
        if b.is_empty() {
            return None;
        }
        Some(([c(b.x0)?, c(b.y0)?], [c(b.x1)?, c(b.y1)?]))
    }
}

/// Whether this target can start threads. It cannot on `wasm32-unknown-unknown`; there
/// [`render_tiles`] and the command line's parallel studies run on the calling thread whatever
/// thread count they are given, and the code that would start threads is not compiled in.
///
/// ```
/// assert_eq!(nyquist_film::CAN_START_THREADS, !cfg!(target_arch = "wasm32"));
/// ```
pub const CAN_START_THREADS: bool = !cfg!(all(target_arch = "wasm32", target_os = "unknown"));

/// Renders every tile of `film` on `threads` worker threads (std scoped threads) and merges
/// them. Where threads cannot be started ([`CAN_START_THREADS`]) it renders on the calling
/// thread, with the same result.
///
/// `render(tile, ctx)` is called once per tile with a fresh [`FilmTile`] and its
/// [`TileContext`] (index, tile count, bounds and a per-tile seed), from which the closure builds
/// the tile's sampler. Workers take tiles in index order from a shared counter, and the calling
/// thread merges them in index order, so the image is bit-identical for any `threads` and any
/// schedule (as long as `render` depends only on its arguments), and only tiles that finished
/// ahead of a slower predecessor wait in memory. `progress(done, total)` is called on the
/// calling thread after each merge (a CLI turns it into a progress bar).
///
/// # Errors
/// [`Error::Config`] if `tile_size` or `threads` is zero.
///
/// # Panics
/// If `render` panics (the panic is propagated after the other workers stop).
///
/// # Examples
///
/// A constant scene:
///
/// ```
/// use nyquist_film::{render_tiles, Film, FilmConfig};
/// let mut film = Film::new(FilmConfig::new(8, 8), &nyquist::filter::Boxcar::default()).unwrap();
/// let mut calls = Vec::new();
/// render_tiles(&mut film, 4, 2, |tile, ctx| {
///     let b = ctx.bounds;
///     for y in b.y0..b.y1 {
///         for x in b.x0..b.x1 {
///             tile.add_sample([x as f32 + 0.5, y as f32 + 0.5], [1.0; 3], 1.0);
///         }
///     }
/// }, |done, total| calls.push((done, total))).unwrap();
/// assert_eq!(film.stats().samples, 64);
/// assert_eq!(calls, [(1, 4), (2, 4), (3, 4), (4, 4)]);
/// ```
///
/// With a core sampler: a [`nyquist::sampler::PixelRangeSampler`] over the tile's pixels walks
/// each pixel's samples (here 2 × 2 jittered strata) and fills a
/// [`nyquist::sampler::Sample`] whose `image()` is the film position. The sampler is stateless
/// (values depend on pixel, sample index and seed only), so each tile clones the same one.
///
/// ```
/// use nyquist::sampler::{Jitter, PixelRangeSampler, Sample, SampleLayout, StratifiedSampler};
/// use nyquist_film::{render_tiles, Film, FilmConfig};
/// let sampler = StratifiedSampler::new(2, 2, Jitter::Jittered, 7).unwrap();
/// let layout = SampleLayout::<0>::new();
/// let render = |threads| {
///     let mut film = Film::new(FilmConfig::new(16, 12), &nyquist::filter::Mitchell::default()).unwrap();
///     render_tiles(&mut film, 8, threads, |tile, ctx| {
///         let (start, end) = ctx.pixel_range().unwrap();
///         let mut pixels = PixelRangeSampler::new(sampler.clone(), start, end).unwrap();
///         let mut buf = vec![0.0f32; layout.len()];
///         let mut sample = Sample::new(&layout, &mut buf).unwrap();
///         while pixels.next_sample(&mut sample) {
///             let [x, y] = sample.image();
///             let l = 0.5 + 0.5 * (x * 0.7).sin() * (y * 0.3).cos(); // the scene
///             tile.add_sample([x, y], [l, l, l], 1.0);
///         }
///     }, |_, _| {}).unwrap();
///     assert_eq!(film.stats().samples, 16 * 12 * 4);
///     film.image().0
/// };
/// assert_eq!(render(1), render(2));
/// ```
pub fn render_tiles(
    film: &mut Film,
    tile_size: u32,
    threads: usize,
    render: impl Fn(&mut FilmTile, &TileContext) + Sync,
    mut progress: impl FnMut(usize, usize),
) -> Result<(), Error> {
    if threads == 0 {
        return Err(Error::Config("thread count must be positive".into()));
    }
    let specs = film.tiles(tile_size)?;
    let total = specs.len();
    let factory = film.tile_factory();
    // Tile `i` rendered; `None` past the last.
    let render_tile = |i: usize| {
        let spec = *specs.get(i)?;
        let ctx = TileContext {
            index: spec.index,
            count: total,
            bounds: spec.bounds,
        };
        let mut tile = factory.tile(spec);
        render(&mut tile, &ctx);
        Some(tile)
    };
    if threads == 1 || !CAN_START_THREADS {
        // On the calling thread, with no thread spawned: the same tiles merged in the same
        // order.
        let mut done = 0;
        while let Some(tile) = render_tile(done) {
            film.merge(tile)?;
            done += 1;
            progress(done, total);
        }
        return Ok(());
    }
    let next = AtomicUsize::new(0);
    let (tx, rx) = mpsc::channel::<FilmTile>();
    std::thread::scope(|scope| -> Result<(), Error> {
        for _ in 0..threads.min(total.max(1)) {
            let tx = tx.clone();
            let (next, render_tile) = (&next, &render_tile);
            scope.spawn(move || {
                while let Some(tile) = render_tile(next.fetch_add(1, Ordering::Relaxed)) {
                    if tx.send(tile).is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        for (done, tile) in rx.iter().enumerate() {
            film.merge(tile)?;
            progress(done + 1, total);
        }
        Ok(())
    })
}
