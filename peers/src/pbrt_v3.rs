//! pbrt-v3 (its film tile, filters, RNG, `Shuffle` and `RadicalInverse`), through
//! `shims/pbrt_v3.cpp`.

use std::ffi::c_void;

unsafe extern "C" {
    fn peer_pbrt_v3_mitchell_new(rx: f32, ry: f32, b: f32, c: f32) -> *mut c_void;
    fn peer_pbrt_v3_box_new(rx: f32, ry: f32) -> *mut c_void;
    fn peer_pbrt_v3_lanczos_new(rx: f32, ry: f32, tau: f32) -> *mut c_void;
    fn peer_pbrt_v3_filter_free(f: *mut c_void);
    fn peer_pbrt_v3_filter_evaluate(f: *const c_void, xy: *const f32, n: usize, out: *mut f32);
    fn peer_pbrt_v3_film_new(filter: *mut c_void, res: i32) -> *mut c_void;
    fn peer_pbrt_v3_film_free(film: *mut c_void);
    fn peer_pbrt_v3_tile_new(film: *mut c_void, res: i32) -> *mut c_void;
    fn peer_pbrt_v3_tile_free(tile: *mut c_void);
    fn peer_pbrt_v3_tile_add(tile: *mut c_void, p: *const f32, rgb: *const f32, n: usize);
    fn peer_pbrt_v3_tile_pixel(tile: *const c_void, x: i32, y: i32, out: *mut f32);
    fn peer_pbrt_v3_table_new(filter: *const c_void) -> *mut c_void;
    fn peer_pbrt_v3_table_free(t: *mut c_void);
    fn peer_pbrt_v3_table_lookup(t: *const c_void, xy: *const f32, n: usize, out: *mut f32);
    fn peer_pbrt_v3_radical_inverse(index: *const u64, n: usize, dims: i32, out: *mut f32);
    fn peer_pbrt_v3_rng_new(seq: u64) -> *mut c_void;
    fn peer_pbrt_v3_rng_free(rng: *mut c_void);
    fn peer_pbrt_v3_shuffle(rng: *mut c_void, buf: *mut f32, count: i32, dims: i32);
}

/// A pbrt-v3 filter (`MitchellFilter`, `BoxFilter`, `LanczosSincFilter`), owned.
pub struct Filter(*mut c_void);

impl Filter {
    pub fn mitchell(r: f32, b: f32, c: f32) -> Self {
        // SAFETY: the shim returns a new filter, freed once by `Drop` or owned by a `Film`.
        Filter(unsafe { peer_pbrt_v3_mitchell_new(r, r, b, c) })
    }

    pub fn boxcar(r: f32) -> Self {
        // SAFETY: as above.
        Filter(unsafe { peer_pbrt_v3_box_new(r, r) })
    }

    pub fn lanczos(r: f32, tau: f32) -> Self {
        // SAFETY: as above.
        Filter(unsafe { peer_pbrt_v3_lanczos_new(r, r, tau) })
    }

    /// `Filter::Evaluate` (a virtual call) at each point.
    pub fn evaluate(&self, xy: &[[f32; 2]], out: &mut [f32]) {
        assert_eq!(out.len(), xy.len());
        // SAFETY: the filter is live; `xy` and `out` hold `n` points and values.
        unsafe {
            peer_pbrt_v3_filter_evaluate(self.0, xy.as_ptr().cast(), xy.len(), out.as_mut_ptr())
        }
    }
}

impl Drop for Filter {
    fn drop(&mut self) {
        if !self.0.is_null() {
            // SAFETY: made by a `_new` of the shim, not handed to a film, freed once.
            unsafe { peer_pbrt_v3_filter_free(self.0) }
        }
    }
}

/// A `res × res` `Film` and the `FilmTile` `GetFilmTile` makes for the whole film.
pub struct Tile {
    film: *mut c_void,
    tile: *mut c_void,
}

impl Tile {
    pub fn new(mut filter: Filter, res: u32) -> Self {
        let f = std::mem::replace(&mut filter.0, std::ptr::null_mut());
        // SAFETY: the film takes ownership of the filter (a `unique_ptr`); the tile points into
        // the film's filter table and is freed first.
        unsafe {
            let film = peer_pbrt_v3_film_new(f, res as i32);
            Tile {
                film,
                tile: peer_pbrt_v3_tile_new(film, res as i32),
            }
        }
    }

    /// `FilmTile::AddSample(p, rgb, 1)` for each sample.
    pub fn add(&mut self, p: &[[f32; 2]], rgb: &[[f32; 3]]) {
        assert_eq!(p.len(), rgb.len());
        // SAFETY: the tile is live and ours; both arrays hold `n` samples.
        unsafe { peer_pbrt_v3_tile_add(self.tile, p.as_ptr().cast(), rgb.as_ptr().cast(), p.len()) }
    }

    /// The pixel's RGB contribution sums and filter weight sum.
    pub fn pixel(&self, x: u32, y: u32) -> [f32; 4] {
        let mut out = [0.0; 4];
        // SAFETY: the tile is live; `out` holds 4 floats; (x, y) is inside the film.
        unsafe { peer_pbrt_v3_tile_pixel(self.tile, x as i32, y as i32, out.as_mut_ptr()) };
        out
    }
}

impl Drop for Tile {
    fn drop(&mut self) {
        // SAFETY: made by the shim, freed once, tile before film.
        unsafe {
            peer_pbrt_v3_tile_free(self.tile);
            peer_pbrt_v3_film_free(self.film);
        }
    }
}

/// A 16 × 16 table of a pbrt-v3 filter, filled and indexed in the shim as pbrt-v3's `Film` and
/// `FilmTile::AddSample` do.
pub struct Table(*mut c_void);

impl Table {
    pub fn new(filter: &Filter) -> Self {
        // SAFETY: the filter is live; the table copies what it needs.
        Table(unsafe { peer_pbrt_v3_table_new(filter.0) })
    }

    pub fn lookup(&self, xy: &[[f32; 2]], out: &mut [f32]) {
        assert_eq!(out.len(), xy.len());
        // SAFETY: the table is live; `xy` and `out` hold `n` points and values.
        unsafe { peer_pbrt_v3_table_lookup(self.0, xy.as_ptr().cast(), xy.len(), out.as_mut_ptr()) }
    }
}

impl Drop for Table {
    fn drop(&mut self) {
        // SAFETY: made by `peer_pbrt_v3_table_new`, freed once.
        unsafe { peer_pbrt_v3_table_free(self.0) }
    }
}

/// pbrt-v3's `RNG` (PCG32) on a sequence.
pub struct Rng(*mut c_void);

impl Rng {
    pub fn new(seq: u64) -> Self {
        // SAFETY: a new RNG, freed once by `Drop`.
        Rng(unsafe { peer_pbrt_v3_rng_new(seq) })
    }

    /// `Shuffle(buf, count, dims, rng)`.
    pub fn shuffle(&mut self, buf: &mut [f32], count: usize, dims: usize) {
        assert!(count * dims <= buf.len());
        // SAFETY: the RNG is live and ours; `buf` holds `count × dims` floats.
        unsafe { peer_pbrt_v3_shuffle(self.0, buf.as_mut_ptr(), count as i32, dims as i32) }
    }
}

impl Drop for Rng {
    fn drop(&mut self) {
        // SAFETY: made by `peer_pbrt_v3_rng_new`, freed once.
        unsafe { peer_pbrt_v3_rng_free(self.0) }
    }
}

/// `RadicalInverse(d, a)` for every index and `d` in `0..dims`, index-major.
pub fn radical_inverse(index: &[u64], dims: u32, out: &mut [f32]) {
    assert_eq!(out.len(), index.len() * dims as usize);
    // SAFETY: `out` holds `dims` floats per index; pbrt-v3 has 1024 bases.
    unsafe {
        peer_pbrt_v3_radical_inverse(index.as_ptr(), index.len(), dims as i32, out.as_mut_ptr())
    }
}
