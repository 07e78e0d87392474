//! The parallel tile driver.

use crate::bounds::Bounds;
use crate::error::Error;
use crate::film::Film;
use crate::tile::FilmTile;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, mpsc};

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
/// [`Error::OutOfRange`] if `tile_size` or `threads` is zero; [`Error::Config`] if a tile cannot
/// be merged.
///
/// # Panics
/// If `render` panics: the other workers take no further tile, and once they have stopped the
/// panic continues on the calling thread with the closure's own payload, so its message reaches
/// the caller (and a `std::panic::catch_unwind` around this call receives it).
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
        return Err(Error::below_one("thread count", 0, f64::INFINITY));
    }
    let specs = film.tiles(tile_size)?;
    let total = specs.len();
    let setup = Arc::clone(film.setup());
    // Tile `i` rendered; `None` past the last.
    let render_tile = |i: usize| {
        let spec = *specs.get(i)?;
        let ctx = TileContext {
            index: spec.index,
            count: total,
            bounds: spec.bounds,
        };
        let mut tile = FilmTile::new(spec, Arc::clone(&setup));
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
    // Raised when a worker panics or the calling thread stops merging: no worker takes
    // another tile.
    let stop = AtomicBool::new(false);
    let (tx, rx) = mpsc::channel::<FilmTile>();
    std::thread::scope(|scope| -> Result<(), Error> {
        let workers: Vec<_> = (0..threads.min(total.max(1)))
            .map(|_| {
                let tx = tx.clone();
                let (next, stop, render_tile) = (&next, &stop, &render_tile);
                scope.spawn(move || {
                    let _stop = StopOnPanic(stop);
                    while !stop.load(Ordering::Relaxed) {
                        let Some(tile) = render_tile(next.fetch_add(1, Ordering::Relaxed)) else {
                            break;
                        };
                        if tx.send(tile).is_err() {
                            break;
                        }
                    }
                })
            })
            .collect();
        drop(tx);
        let merged = {
            // A panic in `progress` stops the workers too, before the scope waits for them.
            let _stop = StopOnPanic(&stop);
            let mut merged = Ok(());
            for (done, tile) in rx.iter().enumerate() {
                if let Err(e) = film.merge(tile) {
                    merged = Err(e);
                    stop.store(true, Ordering::Relaxed);
                    break;
                }
                progress(done + 1, total);
            }
            merged
        };
        // Join every worker, then carry the first panic (in worker order) on with its own
        // payload: the scope's own report would replace it with "a scoped thread panicked".
        let mut panic = None;
        for worker in workers {
            if let Err(payload) = worker.join() {
                panic.get_or_insert(payload);
            }
        }
        if let Some(payload) = panic {
            std::panic::resume_unwind(payload);
        }
        merged
    })
}

/// Raises its flag when dropped by a panic unwinding: the workers' signal to stop.
struct StopOnPanic<'a>(&'a AtomicBool);

impl Drop for StopOnPanic<'_> {
    fn drop(&mut self) {
        if std::thread::panicking() {
            self.0.store(true, Ordering::Relaxed);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup::FilmConfig;
    use nyquist::filter::Boxcar;
    use std::panic::{AssertUnwindSafe, catch_unwind};

    /// The text of a panic payload (`panic!` with a literal or with arguments).
    fn message(payload: &(dyn std::any::Any + Send)) -> Option<&str> {
        payload
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| payload.downcast_ref::<&str>().copied())
    }

    /// A panic inside the closure reaches the caller with its own message on one thread and
    /// on several, and the other workers stop taking tiles: of 64 tiles that each take 10 ms,
    /// far fewer than 64 are rendered once tile 0 has panicked.
    #[test]
    fn a_workers_panic_reaches_the_caller_with_its_message() {
        for threads in [1, 2, 3] {
            let mut film = Film::new(FilmConfig::new(16, 16), &Boxcar::default()).unwrap();
            let rendered = AtomicUsize::new(0);
            let result = catch_unwind(AssertUnwindSafe(|| {
                render_tiles(
                    &mut film,
                    2,
                    threads,
                    |_, ctx| {
                        if ctx.index == 0 {
                            panic!("tile {} of {} exploded", ctx.index, ctx.count);
                        }
                        std::thread::sleep(std::time::Duration::from_millis(10));
                        rendered.fetch_add(1, Ordering::Relaxed);
                    },
                    |_, _| {},
                )
            }));
            let payload = result.expect_err("the panic propagates");
            assert_eq!(
                message(&*payload),
                Some("tile 0 of 64 exploded"),
                "{threads} threads"
            );
            assert!(rendered.load(Ordering::Relaxed) < 63, "{threads} threads");
        }
    }

    /// One thread renders every tile on the calling thread; more threads render them on that
    /// many workers, none of them the caller (where threads can start).
    #[test]
    fn tiles_render_on_the_threads_asked_for() {
        let caller = std::thread::current().id();
        for threads in [1, 2] {
            let mut film = Film::new(FilmConfig::new(16, 16), &Boxcar::default()).unwrap();
            let seen = std::sync::Mutex::new(Vec::new());
            render_tiles(
                &mut film,
                4,
                threads,
                |_, _| {
                    // Long enough that every worker takes a tile.
                    std::thread::sleep(std::time::Duration::from_millis(10));
                    let id = std::thread::current().id();
                    let mut seen = seen.lock().unwrap();
                    if !seen.contains(&id) {
                        seen.push(id);
                    }
                },
                |_, _| {},
            )
            .unwrap();
            let seen = seen.into_inner().unwrap();
            if threads == 1 || !CAN_START_THREADS {
                assert_eq!(seen, [caller], "{threads} threads");
            } else {
                assert_eq!(seen.len(), threads, "{threads} threads");
                assert!(!seen.contains(&caller), "{threads} threads");
            }
        }
        assert_eq!(
            CAN_START_THREADS,
            !cfg!(all(target_arch = "wasm32", target_os = "unknown"))
        );
    }

    /// A panic in the progress callback stops the workers and reaches the caller too.
    #[test]
    fn a_progress_panic_reaches_the_caller() {
        let mut film = Film::new(FilmConfig::new(8, 8), &Boxcar::default()).unwrap();
        let result = catch_unwind(AssertUnwindSafe(|| {
            render_tiles(
                &mut film,
                2,
                2,
                |_, _| {},
                |done, _| {
                    assert!(done < 3, "progress stops at {done}");
                },
            )
        }));
        let payload = result.expect_err("the panic propagates");
        assert_eq!(message(&*payload), Some("progress stops at 3"));
    }

    /// Zero threads or a zero tile size are errors that name the value and the range.
    #[test]
    fn zero_threads_or_tile_size_are_range_errors() {
        let mut film = Film::new(FilmConfig::new(8, 8), &Boxcar::default()).unwrap();
        let e = render_tiles(&mut film, 4, 0, |_, _| {}, |_, _| {}).unwrap_err();
        assert_eq!(e.to_string(), "thread count 0 is outside 1..");
        let e = render_tiles(&mut film, 0, 2, |_, _| {}, |_, _| {}).unwrap_err();
        assert_eq!(e.to_string(), "tile size 0 is outside 1..=4294967295");
    }
}
