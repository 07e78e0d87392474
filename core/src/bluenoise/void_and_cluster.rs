//! Ulichney's void-and-cluster method with a truncated toroidal Gaussian energy, updated
//! incrementally, and two tournament trees that find the tightest cluster and the largest void
//! in `O(log N)` after each update.

use crate::Error;
use crate::math::{ONE_MINUS_EPSILON, exp};

/// The standard deviation of the Gaussian energy filter, in pixels (Ulichney 1993 uses 1.5).
pub const SIGMA: f64 = 1.5;

/// The energy kernel is truncated to the `(2R + 1)²` square around its centre, `R = 6` (the
/// Gaussian has fallen to `e^{−8} ≈ 3·10⁻⁴` of its peak at 6 pixels, σ = 1.5).
pub const KERNEL_RADIUS: u32 = 6;

/// The most pixels a mask has: 2²⁰ (1024 × 1024).
pub const MAX_MASK_PIXELS: u32 = 1 << 20;

const TAPS: usize = (2 * KERNEL_RADIUS as usize + 1) * (2 * KERNEL_RADIUS as usize + 1);
const NONE: u32 = u32::MAX;
const UNRANKED: u32 = u32::MAX;

/// The value of rank `rank` in a mask of `n` pixels: `(rank + ½)/n`, in `[0, 1)`. Total:
/// `n == 0` gives 0, and a rank `≥ n` gives the largest value below 1.
///
/// ```
/// use nyquist::bluenoise::rank_to_value;
/// assert_eq!(rank_to_value(0, 4), 0.125);
/// assert_eq!(rank_to_value(3, 4), 0.875);
/// ```
#[inline]
pub fn rank_to_value(rank: u32, n: u32) -> f32 {
    if n == 0 {
        return 0.0;
    }
    (((f64::from(rank) + 0.5) / f64::from(n)) as f32).min(ONE_MINUS_EPSILON)
}

/// Writes [`rank_to_value`] of every rank of `ranks` into `out` (`n = ranks.len()`).
///
/// # Errors
/// [`Error::BufferTooShort`] if `out` is shorter than `ranks`; [`Error::TooMany`] above
/// `u32::MAX` ranks.
///
/// ```
/// use nyquist::bluenoise::ranks_to_values;
/// let mut v = [0.0; 2];
/// ranks_to_values(&[1, 0], &mut v).unwrap();
/// assert_eq!(v, [0.75, 0.25]);
/// ```
pub fn ranks_to_values(ranks: &[u32], out: &mut [f32]) -> Result<(), Error> {
    let n = u32::try_from(ranks.len()).map_err(|_| Error::TooMany {
        what: "ranks",
        value: ranks.len() as u64,
        max: u64::from(u32::MAX),
    })?;
    let out = crate::analysis::check_scratch(out, ranks.len())?;
    for (o, &r) in out.iter_mut().zip(ranks) {
        *o = rank_to_value(r, n);
    }
    Ok(())
}

/// One channel of a void-and-cluster threshold mask of `width × height` pixels.
///
/// The energy of pixel `p` is `Σ_q K(p − q)` over the ones `q` of the current binary pattern,
/// with `K` the Gaussian `exp(−|d|²/2σ²)`, σ = [`SIGMA`], truncated to `|dx|, |dy| ≤ 6` and
/// wrapped on the torus (on masks narrower than 13 pixels the wrapped taps are summed). The
/// method (Ulichney 1993):
///
/// 1. an initial pattern of `⌈N/10⌉` ones at seeded random pixels is relaxed by moving the one
///    of highest energy (the tightest cluster) to the zero of lowest energy (the largest void)
///    until the move would put it back;
/// 2. the ones of that pattern are removed, tightest cluster first, and ranked down from
///    `⌈N/10⌉ − 1` to 0;
/// 3. from the pattern again, the largest void is filled and ranked, up to `N − 1`. (Ulichney's
///    third phase ranks the tightest cluster of zeros of the inverted pattern; with a kernel
///    whose taps sum to the same total everywhere that is the same pixel.)
///
/// Ties go to the lowest pixel index. [`VoidAndCluster::generate`] keeps the energy field and
/// updates only the `13 × 13` pixels around each change, and finds clusters and voids with two
/// tournament trees over the pixels, updated along the changed rows: `O(N (k² + log N))` for
/// `N` pixels and `k² = 169` taps. [`VoidAndCluster::generate_straightforward`] updates every
/// pixel's energy and scans all pixels at every step (`O(N²)`) and gives bit-identical ranks.
///
/// ```
/// use nyquist::bluenoise::VoidAndCluster;
/// let vc = VoidAndCluster::new(16, 16, 7).unwrap();
/// let (energy_len, scratch_len) = vc.scratch_len();
/// let (mut ranks, mut energy, mut scratch) =
///     (vec![0u32; 256], vec![0.0f32; energy_len], vec![0u32; scratch_len]);
/// vc.generate(&mut ranks, &mut energy, &mut scratch).unwrap();
/// let mut sorted = ranks.clone();
/// sorted.sort();
/// assert!(sorted.iter().copied().eq(0..256)); // a permutation of the ranks
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct VoidAndCluster {
    width: u32,
    height: u32,
    seed: u64,
    /// Taps in the x and y directions (`min(13, width)`, `min(13, height)`).
    kw: u32,
    kh: u32,
    /// Offset of the kernel's centre tap: `R` when the kernel fits, 0 when it wraps.
    ox: u32,
    oy: u32,
    kernel: [f32; TAPS],
}

impl VoidAndCluster {
    /// A `width × height` mask with `seed`.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for a zero width or height; [`Error::TooMany`] (`what: "pixels"`)
    /// above [`MAX_MASK_PIXELS`].
    ///
    /// ```
    /// use nyquist::{bluenoise::VoidAndCluster, Error};
    /// assert!(VoidAndCluster::new(256, 256, 0).is_ok());
    /// assert!(VoidAndCluster::new(3, 5, 0).is_ok());
    /// assert_eq!(VoidAndCluster::new(0, 5, 0), Err(Error::ZeroSize { what: "width" }));
    /// assert_eq!(
    ///     VoidAndCluster::new(2048, 1024, 0),
    ///     Err(Error::TooMany { what: "pixels", value: 2048 * 1024, max: 1 << 20 })
    /// );
    /// assert_eq!(
    ///     VoidAndCluster::new(2048, 1024, 0).unwrap_err().to_string(),
    ///     "pixels 2097152 is above 1048576"
    /// );
    /// ```
    pub fn new(width: u32, height: u32, seed: u64) -> Result<VoidAndCluster, Error> {
        if width == 0 {
            return Err(Error::ZeroSize { what: "width" });
        }
        if height == 0 {
            return Err(Error::ZeroSize { what: "height" });
        }
        let pixels = u64::from(width) * u64::from(height);
        if pixels > u64::from(MAX_MASK_PIXELS) {
            return Err(Error::TooMany {
                what: "pixels",
                value: pixels,
                max: u64::from(MAX_MASK_PIXELS),
            });
        }
        let taps = 2 * KERNEL_RADIUS + 1;
        let axis = |size: u32| -> ([f64; 13], u32, u32) {
            let mut g = [0.0f64; 13];
            let r = KERNEL_RADIUS as i64;
            let (k, origin) = if size >= taps {
                (taps, KERNEL_RADIUS)
            } else {
                (size, 0)
            };
            for d in -r..=r {
                let tap = if size >= taps {
                    (d + r) as usize
                } else {
                    d.rem_euclid(i64::from(size)) as usize
                };
                g[tap] += exp(-((d * d) as f64) / (2.0 * SIGMA * SIGMA));
            }
            (g, k, origin)
        };
        let (gx, kw, ox) = axis(width);
        let (gy, kh, oy) = axis(height);
        let mut kernel = [0.0f32; TAPS];
        for ky in 0..kh as usize {
            for kx in 0..kw as usize {
                kernel[ky * kw as usize + kx] = (gx[kx] * gy[ky]) as f32;
            }
        }
        Ok(VoidAndCluster {
            width,
            height,
            seed,
            kw,
            kh,
            ox,
            oy,
            kernel,
        })
    }

    /// The mask of channel `channel` of a multi-channel mask: the same size, seed
    /// `hash2(seed, channel)` (channel 0 included), so every channel is an independent mask.
    ///
    /// ```
    /// use nyquist::bluenoise::VoidAndCluster;
    /// let vc = VoidAndCluster::new(8, 8, 1).unwrap();
    /// assert_ne!(vc.channel(0).seed(), vc.channel(1).seed());
    /// ```
    #[must_use]
    pub fn channel(&self, channel: u32) -> VoidAndCluster {
        VoidAndCluster {
            seed: crate::hash::hash2(self.seed, u64::from(channel)),
            ..self.clone()
        }
    }

    /// The seed.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// `[width, height]`.
    pub fn size(&self) -> [u32; 2] {
        [self.width, self.height]
    }

    /// The number of pixels `N = width · height`.
    pub fn pixels(&self) -> usize {
        self.width as usize * self.height as usize
    }

    /// The lengths of the two working buffers of [`VoidAndCluster::generate`]: `f32` energy
    /// (`N`) and `u32` scratch (`N` + twice the next power of two of `N`).
    ///
    /// ```
    /// use nyquist::bluenoise::VoidAndCluster;
    /// assert_eq!(VoidAndCluster::new(16, 8, 0).unwrap().scratch_len(), (128, 128 + 256));
    /// ```
    pub fn scratch_len(&self) -> (usize, usize) {
        let n = self.pixels();
        (n, n + 2 * n.next_power_of_two())
    }

    /// Writes the mask's ranks into `ranks` (row-major, `ranks[y·width + x]`), using `energy`
    /// and `scratch` (lengths from [`VoidAndCluster::scratch_len`]; longer buffers are fine).
    /// Allocates: no.
    ///
    /// # Errors
    /// [`Error::BufferTooShort`] if a buffer is shorter than needed (`ranks`: `N`).
    ///
    /// ```
    /// use nyquist::bluenoise::VoidAndCluster;
    /// let vc = VoidAndCluster::new(4, 4, 0).unwrap();
    /// let mut small = [0u32; 3];
    /// assert!(vc.generate(&mut small, &mut [0.0; 16], &mut [0; 48]).is_err());
    /// ```
    pub fn generate(
        &self,
        ranks: &mut [u32],
        energy: &mut [f32],
        scratch: &mut [u32],
    ) -> Result<(), Error> {
        let (el, sl) = self.scratch_len();
        let n = self.pixels();
        let ranks = crate::analysis::check_scratch(ranks, n)?;
        let energy = crate::analysis::check_scratch(energy, el)?;
        let scratch = crate::analysis::check_scratch(scratch, sl)?;
        let p = n.next_power_of_two();
        let (pattern, trees) = scratch.split_at_mut(n);
        let (clusters, voids) = trees.split_at_mut(p);
        let mut state = Fast {
            vc: self,
            n,
            p,
            energy,
            pattern,
            clusters,
            voids,
        };
        run(&mut state, self.seed, ranks);
        Ok(())
    }

    /// The same ranks as [`VoidAndCluster::generate`], bit for bit, by the straightforward
    /// method: every step updates the energy of all `N` pixels and scans them all for the
    /// cluster or void, `O(N²)` in all. The reference for tests and benchmarks. `scratch` needs
    /// only `N` words. Allocates: no.
    ///
    /// # Errors
    /// As [`VoidAndCluster::generate`].
    ///
    /// ```
    /// use nyquist::bluenoise::VoidAndCluster;
    /// let vc = VoidAndCluster::new(8, 8, 3).unwrap();
    /// let (mut a, mut b) = ([0u32; 64], [0u32; 64]);
    /// vc.generate(&mut a, &mut [0.0; 64], &mut [0; 64 + 128]).unwrap();
    /// vc.generate_straightforward(&mut b, &mut [0.0; 64], &mut [0; 64]).unwrap();
    /// assert_eq!(a, b);
    /// ```
    pub fn generate_straightforward(
        &self,
        ranks: &mut [u32],
        energy: &mut [f32],
        scratch: &mut [u32],
    ) -> Result<(), Error> {
        let n = self.pixels();
        let ranks = crate::analysis::check_scratch(ranks, n)?;
        let energy = crate::analysis::check_scratch(energy, n)?;
        let pattern = crate::analysis::check_scratch(scratch, n)?;
        let mut state = Straightforward {
            vc: self,
            energy,
            pattern,
        };
        run(&mut state, self.seed, ranks);
        Ok(())
    }

    /// Writes a mask of `channels` channels into `ranks`, channel-major (channel `c` at
    /// `ranks[c·N .. (c + 1)·N]`, each row-major), `channels = ranks.len() / N`. Channel `c` is
    /// the mask of [`VoidAndCluster::channel`]`(c)`, and for `c ≥ 1` shifted on the torus by
    /// the offset, among the 64 offsets `(i·W/8, j·H/8)`, that minimises its largest absolute
    /// Pearson correlation with the channels before it (first such offset on ties). A toroidal
    /// shift keeps the mask's spectrum and tiling; independent seeds alone leave correlations
    /// of the order `1/√N`, the shift search removes the unlucky ones. Allocates: no.
    ///
    /// # Errors
    /// [`Error::BufferLength`] unless `ranks.len()` is a positive multiple of `N`; otherwise as
    /// [`VoidAndCluster::generate`].
    ///
    /// ```
    /// use nyquist::bluenoise::VoidAndCluster;
    /// let vc = VoidAndCluster::new(16, 16, 1).unwrap();
    /// let (el, sl) = vc.scratch_len();
    /// let mut rgba = vec![0u32; 4 * 256];
    /// vc.generate_channels(&mut rgba, &mut vec![0.0; el], &mut vec![0; sl]).unwrap();
    /// assert!(rgba[256..512].iter().all(|&r| r < 256));
    /// ```
    pub fn generate_channels(
        &self,
        ranks: &mut [u32],
        energy: &mut [f32],
        scratch: &mut [u32],
    ) -> Result<(), Error> {
        let n = self.pixels();
        if ranks.is_empty() || !ranks.len().is_multiple_of(n) {
            return Err(Error::BufferLength {
                multiple_of: n,
                actual: ranks.len(),
            });
        }
        let channels = ranks.len() / n;
        for c in 0..channels {
            let (done, rest) = ranks.split_at_mut(c * n);
            let this = &mut rest[..n];
            self.channel(c as u32).generate(this, energy, scratch)?;
            if c == 0 {
                continue;
            }
            let (w, h) = (self.width as usize, self.height as usize);
            let mut best = (f64::INFINITY, 0, 0);
            for j in 0..8 {
                for i in 0..8 {
                    let (dx, dy) = (i * w / 8, j * h / 8);
                    let worst = done
                        .chunks_exact(n)
                        .map(|other| correlation(other, this, w, h, dx, dy).abs())
                        .fold(0.0f64, f64::max);
                    if worst < best.0 {
                        best = (worst, dx, dy);
                    }
                }
            }
            let (_, dx, dy) = best;
            let tmp = &mut scratch[..n];
            tmp.copy_from_slice(this);
            for y in 0..h {
                for x in 0..w {
                    this[y * w + x] = tmp[(y + dy) % h * w + (x + dx) % w];
                }
            }
        }
        Ok(())
    }

    /// The kernel tap that pixel offset `(dx, dy)` (each reduced modulo the size) falls on, or
    /// `None` outside the truncated kernel.
    #[inline]
    fn tap(&self, dx: u32, dy: u32) -> Option<usize> {
        let kx = (dx + self.ox) % self.width;
        let ky = (dy + self.oy) % self.height;
        (kx < self.kw && ky < self.kh).then(|| (ky * self.kw + kx) as usize)
    }
}

/// Pearson correlation of the permutations `a` and `b` shifted by `(dx, dy)` on the torus
/// (`b'(x, y) = b(x + dx, y + dy)`).
fn correlation(a: &[u32], b: &[u32], w: usize, h: usize, dx: usize, dy: usize) -> f64 {
    let n = a.len() as f64;
    let mean = (n - 1.0) / 2.0;
    let mut sum = 0.0;
    for y in 0..h {
        let (ra, rb) = (&a[y * w..(y + 1) * w], &b[(y + dy) % h * w..][..w]);
        for x in 0..w {
            sum += (f64::from(ra[x]) - mean) * (f64::from(rb[(x + dx) % w]) - mean);
        }
    }
    // The variance of a permutation of 0 … N − 1 is (N² − 1)/12.
    if n > 1.0 {
        sum / n / ((n * n - 1.0) / 12.0)
    } else {
        0.0
    }
}

/// The operations the method needs from a pattern with its energy field.
trait Pattern {
    fn len(&self) -> usize;
    fn clear(&mut self);
    fn is_one(&self, i: usize) -> bool;
    /// Sets pixel `i` to `one` and adds (`one`) or removes its kernel from the energy.
    fn set(&mut self, i: usize, one: bool);
    /// The one of highest energy (lowest index on ties), or `None` without ones.
    fn tightest_cluster(&self) -> Option<usize>;
    /// The zero of lowest energy (lowest index on ties), or `None` without zeros.
    fn largest_void(&self) -> Option<usize>;
}

/// Ulichney's three phases over any [`Pattern`].
fn run(pat: &mut impl Pattern, seed: u64, ranks: &mut [u32]) {
    let n = pat.len();
    pat.clear();
    let ones = n.div_ceil(10);
    let key = crate::hash::mix64(seed) as u32;
    for i in 0..ones {
        pat.set(crate::hash::permute(i as u32, n as u32, key) as usize, true);
    }
    // Phase 0: relax the initial pattern; each swap lowers the energy, N swaps bound it.
    for _ in 0..n {
        let Some(c) = pat.tightest_cluster() else {
            break;
        };
        pat.set(c, false);
        let v = pat.largest_void().unwrap_or(c);
        pat.set(v, true);
        if v == c {
            break;
        }
    }
    ranks.fill(UNRANKED);
    // Phase 1: remove the prototype's ones, tightest cluster first.
    for rank in (0..ones).rev() {
        let Some(c) = pat.tightest_cluster() else {
            break;
        };
        pat.set(c, false);
        ranks[c] = rank as u32;
    }
    for i in 0..n {
        if ranks[i] != UNRANKED {
            pat.set(i, true);
        }
    }
    // Phases 2 and 3: fill the largest void, up to the full pattern.
    for rank in ones..n {
        let Some(v) = pat.largest_void() else {
            break;
        };
        pat.set(v, true);
        ranks[v] = rank as u32;
    }
}

/// Energy `e` of pixel `p` beats energy `f` of pixel `q` as a cluster (higher, then lower index).
#[inline]
fn denser(e: f32, p: usize, f: f32, q: usize) -> bool {
    e > f || (e == f && p < q)
}

/// Energy `e` of pixel `p` beats energy `f` of pixel `q` as a void (lower, then lower index).
#[inline]
fn emptier(e: f32, p: usize, f: f32, q: usize) -> bool {
    e < f || (e == f && p < q)
}

/// The incremental pattern: energy updated over the kernel's footprint, clusters and voids from
/// two tournament trees (`p` leaves, node `i`'s children `2i` and `2i + 1`, leaves `p + j`).
struct Fast<'a> {
    vc: &'a VoidAndCluster,
    n: usize,
    p: usize,
    energy: &'a mut [f32],
    pattern: &'a mut [u32],
    clusters: &'a mut [u32],
    voids: &'a mut [u32],
}

impl Fast<'_> {
    /// The winner at tree node `i` (a leaf when `i ≥ p`) of the cluster tree (`ones`) or the
    /// void tree.
    #[inline]
    fn node(&self, i: usize, ones: bool) -> u32 {
        if i >= self.p {
            let j = i - self.p;
            if j < self.n && (self.pattern[j] == 1) == ones {
                j as u32
            } else {
                NONE
            }
        } else if ones {
            self.clusters[i]
        } else {
            self.voids[i]
        }
    }

    #[inline]
    fn recompute(&mut self, i: usize) {
        for ones in [true, false] {
            let (a, b) = (self.node(2 * i, ones), self.node(2 * i + 1, ones));
            let w = match (a, b) {
                (NONE, _) => b,
                (_, NONE) => a,
                _ => {
                    let (ea, eb) = (self.energy[a as usize], self.energy[b as usize]);
                    let a_wins = if ones {
                        denser(ea, a as usize, eb, b as usize)
                    } else {
                        emptier(ea, a as usize, eb, b as usize)
                    };
                    if a_wins { a } else { b }
                }
            };
            if ones {
                self.clusters[i] = w;
            } else {
                self.voids[i] = w;
            }
        }
    }

    /// Recomputes the ancestors of leaves `lo ..= hi` (pixel indices).
    fn update_range(&mut self, lo: usize, hi: usize) {
        let (mut lo, mut hi) = ((self.p + lo) / 2, (self.p + hi) / 2);
        while lo >= 1 {
            for i in lo..=hi {
                self.recompute(i);
            }
            if lo == 1 {
                break;
            }
            (lo, hi) = (lo / 2, hi / 2);
        }
    }
}

impl Pattern for Fast<'_> {
    fn len(&self) -> usize {
        self.n
    }

    fn clear(&mut self) {
        self.energy[..self.n].fill(0.0);
        self.pattern.fill(0);
        for i in (1..self.p).rev() {
            self.recompute(i);
        }
    }

    #[inline]
    fn is_one(&self, i: usize) -> bool {
        self.pattern[i] == 1
    }

    fn set(&mut self, i: usize, one: bool) {
        if self.is_one(i) == one {
            return;
        }
        self.pattern[i] = u32::from(one);
        let sign = if one { 1.0 } else { -1.0 };
        let vc = self.vc;
        let (w, h) = (vc.width as usize, vc.height as usize);
        let (cx, cy) = (i % w, i / w);
        let (kw, kh) = (vc.kw as usize, vc.kh as usize);
        // Top-left pixel of the kernel's footprint, on the torus.
        let x0 = (cx + w - vc.ox as usize) % w;
        let y0 = (cy + h - vc.oy as usize) % h;
        for ky in 0..kh {
            let row = (y0 + ky) % h * w;
            let taps = &vc.kernel[ky * kw..(ky + 1) * kw];
            for (kx, &k) in taps.iter().enumerate() {
                let x = (x0 + kx) % w;
                let e = &mut self.energy[row + x];
                *e += sign * k;
            }
            if self.p > 1 {
                if x0 + kw <= w {
                    self.update_range(row + x0, row + x0 + kw - 1);
                } else {
                    self.update_range(row + x0, row + w - 1);
                    self.update_range(row, row + (x0 + kw - w) - 1);
                }
            }
        }
    }

    fn tightest_cluster(&self) -> Option<usize> {
        let w = self.node(1, true);
        (w != NONE).then_some(w as usize)
    }

    fn largest_void(&self) -> Option<usize> {
        let w = self.node(1, false);
        (w != NONE).then_some(w as usize)
    }
}

/// The straightforward pattern: every change adds the kernel to all pixels' energy (zero
/// outside its footprint), every search scans all pixels.
struct Straightforward<'a> {
    vc: &'a VoidAndCluster,
    energy: &'a mut [f32],
    pattern: &'a mut [u32],
}

impl Pattern for Straightforward<'_> {
    fn len(&self) -> usize {
        self.pattern.len()
    }

    fn clear(&mut self) {
        self.energy.fill(0.0);
        self.pattern.fill(0);
    }

    fn is_one(&self, i: usize) -> bool {
        self.pattern[i] == 1
    }

    fn set(&mut self, i: usize, one: bool) {
        if self.is_one(i) == one {
            return;
        }
        self.pattern[i] = u32::from(one);
        let sign = if one { 1.0 } else { -1.0 };
        let (w, h) = (self.vc.width, self.vc.height);
        let (cx, cy) = (i as u32 % w, i as u32 / w);
        for (j, e) in self.energy.iter_mut().enumerate() {
            let (x, y) = (j as u32 % w, j as u32 / w);
            let k = self
                .vc
                .tap((x + w - cx) % w, (y + h - cy) % h)
                .map_or(0.0, |t| self.vc.kernel[t]);
            *e += sign * k;
        }
    }

    fn tightest_cluster(&self) -> Option<usize> {
        let mut best: Option<usize> = None;
        for (j, &e) in self.energy.iter().enumerate() {
            if self.is_one(j) && best.is_none_or(|b| denser(e, j, self.energy[b], b)) {
                best = Some(j);
            }
        }
        best
    }

    fn largest_void(&self) -> Option<usize> {
        let mut best: Option<usize> = None;
        for (j, &e) in self.energy.iter().enumerate() {
            if !self.is_one(j) && best.is_none_or(|b| emptier(e, j, self.energy[b], b)) {
                best = Some(j);
            }
        }
        best
    }
}
