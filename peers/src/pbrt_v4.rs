//! pbrt-v4 (its samplers, `SobolSample` and `RadicalInverse`), through `shims/pbrt_v4.cpp`.

use std::ffi::c_void;

unsafe extern "C" {
    fn peer_pbrt_v4_halton_new(spp: i32, res: i32, seed: i32) -> *mut c_void;
    fn peer_pbrt_v4_halton_free(s: *mut c_void);
    fn peer_pbrt_v4_halton_camera(
        s: *mut c_void,
        x0: i32,
        y0: i32,
        n: i32,
        spp: i32,
        out: *mut f32,
    );
    fn peer_pbrt_v4_zsobol_new(spp: i32, res: i32, seed: i32) -> *mut c_void;
    fn peer_pbrt_v4_zsobol_free(s: *mut c_void);
    fn peer_pbrt_v4_zsobol_camera(
        s: *mut c_void,
        x0: i32,
        y0: i32,
        n: i32,
        spp: i32,
        out: *mut f32,
    );
    fn peer_pbrt_v4_sobol(index: *const u32, n: usize, dims: i32, out: *mut f32);
    fn peer_pbrt_v4_radical_inverse(index: *const u64, n: usize, dims: i32, out: *mut f32);
    fn peer_pbrt_v4_pmj02bn_new(spp: i32, seed: i32) -> *mut c_void;
    fn peer_pbrt_v4_pmj02bn_free(s: *mut c_void);
    fn peer_pbrt_v4_pmj02bn_lookup(index: *const u32, n: usize, out: *mut f32);
    fn peer_pbrt_v4_pmj02bn_camera(
        s: *mut c_void,
        x0: i32,
        y0: i32,
        n: i32,
        spp: i32,
        out: *mut f32,
    );
}

type Camera = unsafe extern "C" fn(*mut c_void, i32, i32, i32, i32, *mut f32);

/// One of pbrt-v4's pixel samplers, owned.
pub struct Sampler {
    ptr: *mut c_void,
    camera: Camera,
    free: unsafe extern "C" fn(*mut c_void),
}

impl Sampler {
    /// `HaltonSampler` with `RandomizeStrategy::PermuteDigits`, `res × res` image.
    pub fn halton(spp: u32, res: u32, seed: i32) -> Self {
        Sampler {
            // SAFETY: the shim returns a new sampler, freed once by `Drop`.
            ptr: unsafe { peer_pbrt_v4_halton_new(spp as i32, res as i32, seed) },
            camera: peer_pbrt_v4_halton_camera,
            free: peer_pbrt_v4_halton_free,
        }
    }

    /// `ZSobolSampler` with `RandomizeStrategy::FastOwen`, `res × res` image.
    pub fn zsobol(spp: u32, res: u32, seed: i32) -> Self {
        Sampler {
            // SAFETY: as above.
            ptr: unsafe { peer_pbrt_v4_zsobol_new(spp as i32, res as i32, seed) },
            camera: peer_pbrt_v4_zsobol_camera,
            free: peer_pbrt_v4_zsobol_free,
        }
    }

    /// `PMJ02BNSampler`.
    pub fn pmj02bn(spp: u32, seed: i32) -> Self {
        Sampler {
            // SAFETY: as above.
            ptr: unsafe { peer_pbrt_v4_pmj02bn_new(spp as i32, seed) },
            camera: peer_pbrt_v4_pmj02bn_camera,
            free: peer_pbrt_v4_pmj02bn_free,
        }
    }

    /// Camera samples (5 floats each: `GetPixel2D`, `Get1D`, `Get2D`) of `n × n` pixels from
    /// `origin`, `spp` each.
    pub fn camera(&mut self, origin: [u32; 2], n: u32, spp: u32, out: &mut [f32]) {
        assert_eq!(out.len(), (5 * n * n * spp) as usize);
        // SAFETY: the sampler is live and ours; `out` holds 5 floats per sample.
        unsafe {
            (self.camera)(
                self.ptr,
                origin[0] as i32,
                origin[1] as i32,
                n as i32,
                spp as i32,
                out.as_mut_ptr(),
            )
        }
    }
}

impl Drop for Sampler {
    fn drop(&mut self) {
        // SAFETY: made by the matching `_new`, freed once.
        unsafe { (self.free)(self.ptr) }
    }
}

/// `SobolSample(i, d, NoRandomizer())` for every index and `d` in `0..dims`, index-major.
pub fn sobol(index: &[u32], dims: u32, out: &mut [f32]) {
    assert_eq!(out.len(), index.len() * dims as usize);
    // SAFETY: `out` holds `dims` floats per index.
    unsafe { peer_pbrt_v4_sobol(index.as_ptr(), index.len(), dims as i32, out.as_mut_ptr()) }
}

/// `RadicalInverse(d, a)` for every index and `d` in `0..dims`, index-major.
pub fn radical_inverse(index: &[u64], dims: u32, out: &mut [f32]) {
    assert_eq!(out.len(), index.len() * dims as usize);
    // SAFETY: `out` holds `dims` floats per index; pbrt-v4 has 1000 bases.
    unsafe {
        peer_pbrt_v4_radical_inverse(index.as_ptr(), index.len(), dims as i32, out.as_mut_ptr())
    }
}

/// `GetPMJ02BNSample(0, i)` for each index, 2 floats per index.
pub fn pmj02bn_lookup(index: &[u32], out: &mut [f32]) {
    assert_eq!(out.len(), 2 * index.len());
    assert!(index.iter().all(|&i| i < 65536));
    // SAFETY: `out` holds 2 floats per index; every index is inside the 2^16-point table.
    unsafe { peer_pbrt_v4_pmj02bn_lookup(index.as_ptr(), index.len(), out.as_mut_ptr()) }
}
