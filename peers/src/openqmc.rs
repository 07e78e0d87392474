//! OpenQMC (header-only, `include/oqmc`), through `shims/openqmc.cpp`.

use std::ffi::c_void;

unsafe extern "C" {
    fn peer_oqmc_pmj_cache_new() -> *mut c_void;
    fn peer_oqmc_pmj_cache_free(cache: *mut c_void);
    fn peer_oqmc_pmj_camera(
        cache: *const c_void,
        x0: i32,
        y0: i32,
        nx: i32,
        ny: i32,
        spp: i32,
        out: *mut f32,
    );
    fn peer_oqmc_pmj_table_new() -> *mut [u32; 4];
    fn peer_oqmc_pmj_table_free(table: *mut [u32; 4]);
    fn peer_oqmc_pmj_lookup_2d(
        table: *const [u32; 4],
        hash: u32,
        index: *const u32,
        n: usize,
        out: *mut f32,
    );
    fn peer_oqmc_sobol_4d(n_points: u32, seeds: *const u32, n_seeds: u32, out: *mut f32);
    fn peer_oqmc_bn_draw(
        kind: i32,
        nx: i32,
        ny: i32,
        frame: i32,
        spp: i32,
        domain: i32,
        out: *mut f32,
    ) -> i32;
}

/// `PmjSampler`'s cache, initialised by OpenQMC.
pub struct PmjCache(*mut c_void);

impl PmjCache {
    pub fn new() -> Self {
        // SAFETY: the shim allocates and initialises `PmjSampler::cacheSize` bytes.
        PmjCache(unsafe { peer_oqmc_pmj_cache_new() })
    }

    /// Camera samples (5 floats each) of `n × n` pixels from `origin`, `spp` each.
    pub fn camera(&self, origin: [u32; 2], n: u32, spp: u32, out: &mut [f32]) {
        assert_eq!(out.len(), (5 * n * n * spp) as usize);
        // SAFETY: the cache is live; `out` holds the 5 floats per sample the shim writes.
        unsafe {
            peer_oqmc_pmj_camera(
                self.0,
                origin[0] as i32,
                origin[1] as i32,
                n as i32,
                n as i32,
                spp as i32,
                out.as_mut_ptr(),
            )
        }
    }
}

impl Drop for PmjCache {
    fn drop(&mut self) {
        // SAFETY: allocated by `peer_oqmc_pmj_cache_new`, freed once.
        unsafe { peer_oqmc_pmj_cache_free(self.0) }
    }
}

/// The 2¹⁶ × 4 stochastic PMJ table `PmjSampler` reads.
pub struct PmjTable(*mut [u32; 4]);

impl PmjTable {
    pub fn new() -> Self {
        // SAFETY: the shim allocates and fills 2^16 rows.
        PmjTable(unsafe { peer_oqmc_pmj_table_new() })
    }

    /// The table's first pair of dimensions, the points of OpenQMC's construction (its last two
    /// columns are a randomisation of these).
    pub fn first_pair(&self) -> Vec<[u32; 2]> {
        // SAFETY: the table is live and holds 2^16 rows of 4 words.
        let rows = unsafe { std::slice::from_raw_parts(self.0, 1 << 16) };
        rows.iter().map(|r| [r[0], r[1]]).collect()
    }

    /// The lookup core's 2-D values of `index` under `hash`, 2 floats per index.
    pub fn lookup_2d(&self, hash: u32, index: &[u32], out: &mut [f32]) {
        assert_eq!(out.len(), 2 * index.len());
        // SAFETY: the table is live; `out` holds 2 floats per index.
        unsafe {
            peer_oqmc_pmj_lookup_2d(self.0, hash, index.as_ptr(), index.len(), out.as_mut_ptr())
        }
    }
}

impl Drop for PmjTable {
    fn drop(&mut self) {
        // SAFETY: allocated by `peer_oqmc_pmj_table_new`, freed once.
        unsafe { peer_oqmc_pmj_table_free(self.0) }
    }
}

/// Owen-scrambled Sobol, 4 values per (index, seed) for indices `0..points`, index-major.
pub fn sobol_4d(points: u32, seeds: &[u32], out: &mut [f32]) {
    assert_eq!(out.len(), 4 * points as usize * seeds.len());
    // SAFETY: `out` holds 4 floats per (index, seed).
    unsafe { peer_oqmc_sobol_4d(points, seeds.as_ptr(), seeds.len() as u32, out.as_mut_ptr()) }
}

/// `drawSample<4>` of domain `domain` (0: the pixel's; `d`: `newDomain(d)`) for `spp` samples
/// of every pixel of a `size × size` image in `frame`, by sampler kind (0 SobolBn, 1 PmjBn,
/// 2 LatticeBn, 3 Sobol, 4 Pmj, 5 Lattice): 4 floats per sample, pixel-major.
pub fn bn_draw(kind: i32, size: u32, frame: u32, spp: u32, domain: u32) -> Vec<f32> {
    let mut out = vec![0f32; 4 * (size * size * spp) as usize];
    // SAFETY: `out` holds the 4 floats per (pixel, sample) the shim writes.
    let status = unsafe {
        peer_oqmc_bn_draw(
            kind,
            size as i32,
            size as i32,
            frame as i32,
            spp as i32,
            domain as i32,
            out.as_mut_ptr(),
        )
    };
    assert_eq!(status, 0, "unknown OpenQMC sampler kind {kind}");
    out
}
