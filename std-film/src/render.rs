//! The parallel tile driver.

use crate::{Error, Film, FilmTile};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;

/// Renders every tile of `film` on `threads` worker threads and merges them.
///
/// `render` is called once per tile with a fresh [`FilmTile`] (its [`FilmTile::bounds`] and
/// [`FilmTile::index`] say which pixels to sample, so the closure can make the tile's sampler);
/// workers take tiles in index order from a shared counter, and the calling thread merges them
/// in index order, so the image is bit-identical for any `threads` and any schedule, and at most
/// a few tiles per thread wait in memory. `progress(done, total)` is called on the calling thread
/// after each merge.
///
/// # Errors
/// [`Error::Config`] if `tile_size` or `threads` is zero.
///
/// # Panics
/// If `render` panics (the panic is propagated after the other workers stop).
///
/// ```
/// use nyquist_film::{render_tiles, Film, FilmConfig};
/// let mut film = Film::new(FilmConfig::new(8, 8), &nyquist::filter::Boxcar::default()).unwrap();
/// render_tiles(&mut film, 4, 2, |tile| {
///     let b = tile.bounds();
///     for y in b.y0..b.y1 {
///         for x in b.x0..b.x1 {
///             tile.add_sample([x as f32 + 0.5, y as f32 + 0.5], [1.0; 3], 1.0);
///         }
///     }
/// }, |_, _| {}).unwrap();
/// assert_eq!(film.stats().samples, 64);
/// ```
pub fn render_tiles(
    film: &mut Film,
    tile_size: u32,
    threads: usize,
    render: impl Fn(&mut FilmTile) + Sync,
    mut progress: impl FnMut(usize, usize),
) -> Result<(), Error> {
    if threads == 0 {
        return Err(Error::Config("thread count must be positive".into()));
    }
    let specs = film.tiles(tile_size)?;
    let total = specs.len();
    let next = AtomicUsize::new(0);
    let factory = film.tile_factory();
    let (tx, rx) = mpsc::channel::<FilmTile>();
    std::thread::scope(|scope| -> Result<(), Error> {
        for _ in 0..threads.min(total.max(1)) {
            let tx = tx.clone();
            let (specs, next, render, factory) = (&specs, &next, &render, &factory);
            scope.spawn(move || {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&spec) = specs.get(i) else { break };
                    let mut tile = factory.tile(spec);
                    render(&mut tile);
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
