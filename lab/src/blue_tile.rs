//! The optimiser of the screen-space blue-noise tile ([`nyquist::sampler::screen_blue`]).
//!
//! Every slot of a `size × size` torus starts with the entry [`initial_entry`]`(slot)`: key
//! `slot`, rank 0. An entry's *error vector* holds, for each power-of-two spp `1 … 2^levels`
//! and each test integrand, the error of the estimate from that many samples of a pixel with
//! that entry ([`BlueFamily::values`] of the spec's [`Family`]), each component centred and scaled to unit variance
//! over the entries. The test integrands are oriented Heavisides and Gaussians over dimensions
//! (0, 1) and over (2, 3), and Heavisides and a Gaussian over all four, with parameters drawn
//! from the seed.
//!
//! The energy is the Gaussian-weighted correlation of neighbouring pixels' errors,
//! `E = Σ_p Σ_{q ≠ p, |q − p|∞ ≤ 6} exp(−|q − p|²/σ²) e_p · e_q` with `σ = 3` pixels, which is
//! the error image's power seen through a low-pass filter: lowering it moves the error's power
//! to high frequencies. The filter's response is `exp(−π²σ²f²)`, 0.25 at `f = 1/8` cycle per
//! pixel, the edge of the band the low-frequency ratio measures: Georgiev and Fajardo's
//! `σ = 2.1` (response 0.51 there) spends more of the search on frequencies above the band,
//! and `σ = 4` on a 17 × 17 window less; both left the held-out integrands' error less blue
//! in the band (`docs/blue-noise.md`).
//!
//! **Key stage.** Swapping two pixels' keys swaps their error vectors, so this stage searches
//! permutations. It keeps `S_p = Σ_q w(q − p) e_q`, so a proposed swap of `p` and `q` costs one
//! dot product, `ΔE = 2 (e_q − e_p)·(S_p − S_q) − 2 w(p − q) |e_q − e_p|²`. It takes every
//! swap that lowers `E` and, under simulated annealing, some that raise it early on; half the
//! proposals pair random pixels, half pixels at most 8 apart. All spp are optimised together.
//!
//! **Rank stage.** Then, from the top spp down, each pixel chooses its rank bits, the top three
//! together and then one at a time: which aligned block its first `n` samples are, as Heitz et
//! al. (2019) and OpenQMC rank their pixels, by simulated annealing on the same energy with each
//! pixel's own term kept. The top chunk gives 32 spp eight choices; below it each bit is
//! chosen for its own level, the last (1 spp) on the deviations of the pair's two samples from
//! their mean, so that it cannot favour the larger error.

use crate::parallel::map_tasks;
use nyquist::rng::{default_rng, uniform_below, uniform_f64};
use nyquist::sampler::screen_blue::{
    BlueFamily, LatticeBlue, OwenSobolBlue, Pmj02Blue, initial_entry,
};
use std::convert::Infallible;

/// Radius of the energy's window, in pixels (a 13 × 13 window).
const RADIUS: i32 = 6;
/// The energy kernel's σ, in pixels (module docs).
const SIGMA: f64 = 3.0;
/// Oriented Heavisides over the first pair of dimensions (the image sample's, in the first
/// block): most of the energy, as the first pair is what a renderer's error shows most.
const FIRST_PAIR_HEAVISIDES: usize = 256;
/// Oriented Heavisides over the second pair.
const SECOND_PAIR_HEAVISIDES: usize = 32;

/// The families of nets a tile is optimised for ([`BlueFamily`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// [`OwenSobolBlue`]: `owen-sobol-bn`.
    OwenSobol,
    /// [`Pmj02Blue`]: `pmj02-bn`.
    Pmj02,
    /// [`LatticeBlue`]: `lattice-bn`.
    Lattice,
}

impl Family {
    /// Every family.
    pub const ALL: [Family; 3] = [Family::OwenSobol, Family::Pmj02, Family::Lattice];

    /// The four values of sample `index` of a pixel whose entry is `entry`
    /// ([`BlueFamily::values`]).
    pub fn values(self, entry: u32, index: u32) -> [f32; 4] {
        match self {
            Family::OwenSobol => OwenSobolBlue::values(entry, index),
            Family::Pmj02 => Pmj02Blue::values(entry, index),
            Family::Lattice => LatticeBlue::values(entry, index),
        }
    }

    /// The family's entry at `(x, y)` of its shipped tile ([`BlueFamily::entry`]).
    pub fn entry(self, x: u32, y: u32) -> u32 {
        match self {
            Family::OwenSobol => OwenSobolBlue::entry(x, y),
            Family::Pmj02 => Pmj02Blue::entry(x, y),
            Family::Lattice => LatticeBlue::entry(x, y),
        }
    }

    /// The sampler's name.
    pub fn name(self) -> &'static str {
        match self {
            Family::OwenSobol => OwenSobolBlue::NAME,
            Family::Pmj02 => Pmj02Blue::NAME,
            Family::Lattice => LatticeBlue::NAME,
        }
    }

    /// The family named `name` (a sampler name of [`Family::name`]).
    pub fn from_name(name: &str) -> Option<Family> {
        Family::ALL.into_iter().find(|f| f.name() == name)
    }

    /// The test integrands over the whole 4-D block: oriented Heavisides and Gaussians, 8 and 1,
    /// or 32 and 4 for `pmj02-bn`. Its two pairs are shuffled independently, so its 4-D
    /// errors follow its pairs' less than the other families' do: with 8 and 1 its held-out 4-D
    /// Heaviside was white at 16 spp (ratio 1.01 on the lab test's 128² image), with 32 and 4
    /// it is 0.87 (`docs/blue-noise.md`).
    fn block_integrands(self) -> (usize, usize) {
        match self {
            Family::Pmj02 => (32, 4),
            Family::OwenSobol | Family::Lattice => (8, 1),
        }
    }

    /// The shipped tile's file, under `core/src/sampler/screen_blue/`.
    pub fn tile_file(self) -> &'static str {
        match self {
            Family::OwenSobol => "owen_sobol_tile.in",
            Family::Pmj02 => "pmj02_tile.in",
            Family::Lattice => "lattice_tile.in",
        }
    }
}

/// What the optimiser builds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TileSpec {
    /// The family of nets.
    pub family: Family,
    /// Side of the torus (a power of two, at least 16).
    pub size: u32,
    /// The largest spp is `2^levels`.
    pub levels: u32,
    /// Proposed swaps, in multiples of the pixel count.
    pub sweeps: u32,
    /// Seed of the integrands and of the proposals.
    pub seed: u64,
}

impl TileSpec {
    /// The shipped tile's spec for `family`: 128², spp 1 … 256, 256 sweeps, seed 1.
    pub const fn shipped(family: Family) -> TileSpec {
        TileSpec {
            family,
            size: 128,
            levels: 8,
            sweeps: 256,
            seed: 1,
        }
    }
}

/// The optimiser's result.
#[derive(Clone, Debug, PartialEq)]
pub struct Tile {
    /// The keys, row-major.
    pub keys: Vec<u32>,
    /// The energy of the starting layout (slot order) and of the key stage's permutation.
    pub energy: [f64; 2],
    /// Swaps taken.
    pub swaps: u64,
}

/// One test integrand over the first `k` of the dimensions `dims` of a 4-D block.
#[derive(Clone, Copy, Debug)]
struct Test {
    dims: [usize; 4],
    k: usize,
    shape: Shape,
}

#[derive(Clone, Copy, Debug)]
enum Shape {
    /// `1` where `(x − c)·n < 0`.
    Heaviside { n: [f64; 4], c: [f64; 4] },
    /// `exp(−|x − c|² / (2 s²))`.
    Gaussian { c: [f64; 4], s: f64 },
}

impl Test {
    fn eval(&self, x: &[f32; 4]) -> f64 {
        let t = |j: usize, c: &[f64; 4]| f64::from(x[self.dims[j]]) - c[j];
        match self.shape {
            Shape::Heaviside { n, c } => {
                let dot: f64 = (0..self.k).map(|j| t(j, &c) * n[j]).sum();
                f64::from(u8::from(dot < 0.0))
            }
            Shape::Gaussian { c, s } => {
                let r2: f64 = (0..self.k).map(|j| t(j, &c).powi(2)).sum();
                (-r2 / (2.0 * s * s)).exp()
            }
        }
    }
}

/// The test integrands of `seed`: over dimensions (0, 1) [`FIRST_PAIR_HEAVISIDES`] and over
/// (2, 3) [`SECOND_PAIR_HEAVISIDES`] oriented Heavisides through a point of `[0, 1)²`, and two
/// Gaussians each (centre in `[0.2, 0.8)²`, σ in `[0.1, 0.3)`); over all four dimensions
/// the family's [`Family::block_integrands`].
fn tests(family: Family, seed: u64) -> Vec<Test> {
    let mut rng = default_rng(seed);
    let mut u = move || uniform_f64(&mut rng);
    let mut out = Vec::new();
    let (block_heavisides, block_gaussians) = family.block_integrands();
    for (dims, k, heavisides, gaussians) in [
        ([0, 1, 0, 0], 2, FIRST_PAIR_HEAVISIDES, 2),
        ([2, 3, 0, 0], 2, SECOND_PAIR_HEAVISIDES, 2),
        ([0, 1, 2, 3], 4, block_heavisides, block_gaussians),
    ] {
        for _ in 0..heavisides {
            let g: [f64; 4] = std::array::from_fn(|j| if j < k { u() - 0.5 } else { 0.0 });
            let len = g.iter().map(|v| v * v).sum::<f64>().sqrt().max(1e-9);
            let c: [f64; 4] = std::array::from_fn(|_| u());
            let shape = Shape::Heaviside {
                n: g.map(|v| v / len),
                c,
            };
            out.push(Test { dims, k, shape });
        }
        for _ in 0..gaussians {
            let c: [f64; 4] = std::array::from_fn(|_| 0.2 + 0.6 * u());
            let shape = Shape::Gaussian {
                c,
                s: 0.1 + 0.2 * u(),
            };
            out.push(Test { dims, k, shape });
        }
    }
    out
}

/// The error vectors of the `count` keys `keys(0..count)`: `components()` values per key,
/// level-major, each component centred and scaled to unit variance over the keys.
pub fn error_vectors(spec: &TileSpec, keys: &[u32]) -> (Vec<f32>, usize) {
    let tests = tests(spec.family, spec.seed);
    let levels = spec.levels as usize + 1;
    let c = levels * tests.len();
    let mut e = vec![0f32; keys.len() * c];
    let rows = per_key(keys, |key| {
        let mut out = vec![0f32; c];
        let mut sums = vec![0f64; tests.len()];
        for i in 0..1u32 << spec.levels {
            let x = spec.family.values(key, i);
            for (s, t) in sums.iter_mut().zip(&tests) {
                *s += t.eval(&x);
            }
            let n = i + 1;
            if n.is_power_of_two() {
                let l = n.trailing_zeros() as usize;
                for (j, s) in sums.iter().enumerate() {
                    out[l * tests.len() + j] = (s / f64::from(n)) as f32;
                }
            }
        }
        out
    });
    for (k, row) in rows.into_iter().enumerate() {
        e[k * c..(k + 1) * c].copy_from_slice(&row);
    }
    // Centre and scale each component over the keys (a constant shift of every pixel's error
    // does not change which permutation is best: the window's weights sum alike everywhere).
    standardise_columns(&mut e, c);
    (e, c)
}

/// Centres every column of `e` (rows of `c` values) and scales it to unit variance over the
/// rows; a column with no variance becomes 0.
fn standardise_columns(e: &mut [f32], c: usize) {
    let rows = e.len() / c;
    let count = rows as f64;
    for k in 0..c {
        let all = || (0..rows).map(|r| f64::from(e[r * c + k]));
        let mean = all().sum::<f64>() / count;
        let var = all().map(|v| (v - mean).powi(2)).sum::<f64>() / count;
        let scale = if var > 0.0 { 1.0 / var.sqrt() } else { 0.0 };
        for r in 0..rows {
            e[r * c + k] = ((f64::from(e[r * c + k]) - mean) * scale) as f32;
        }
    }
}

/// Adds `sign · w(q − p) · d` to `S_q` for every `q` of the window `win` around pixel `p` of the
/// `size`² torus: how `S = blurred(e)` follows when `p`'s error vector moves by `d`.
fn spread(
    s: &mut [f64],
    c: usize,
    size: u32,
    win: &[(i32, i32, f64)],
    p: usize,
    d: &[f64],
    sign: f64,
) {
    let m = size as i32;
    let (cx, cy) = ((p as i32) % m, (p as i32) / m);
    for &(dx, dy, w) in win {
        let r = (((cy + dy) & (m - 1)) * m + ((cx + dx) & (m - 1))) as usize;
        let weight = sign * w;
        // Over slices: one bounds check per row, none per component.
        for (x, dk) in s[r * c..(r + 1) * c].iter_mut().zip(&d[..c]) {
            *x += weight * dk;
        }
    }
}

/// `f` of every key, in order, on as many threads as the machine has: the lab's work queue
/// ([`map_tasks`]) over chunks of 256 keys, so the result does not depend on the thread count.
fn per_key<T: Send>(keys: &[u32], f: impl Fn(u32) -> T + Sync) -> Vec<T> {
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let chunks: Vec<&[u32]> = keys.chunks(256).collect();
    let order: Vec<usize> = (0..chunks.len()).collect();
    map_tasks(&order, threads, |i| {
        Ok::<_, Infallible>(chunks[i].iter().map(|&k| f(k)).collect::<Vec<T>>())
    })
    .unwrap_or_else(|never| match never {})
    .into_iter()
    .flatten()
    .collect()
}

/// The window's offsets and weights (the centre left out).
fn window() -> Vec<(i32, i32, f64)> {
    let mut w = Vec::new();
    for dy in -RADIUS..=RADIUS {
        for dx in -RADIUS..=RADIUS {
            if (dx, dy) != (0, 0) {
                w.push((
                    dx,
                    dy,
                    (-f64::from(dx * dx + dy * dy) / (SIGMA * SIGMA)).exp(),
                ));
            }
        }
    }
    w
}

/// The energy of error vectors `e` (`c` per pixel) laid out on a `size`² torus.
pub fn energy(e: &[f32], c: usize, size: u32) -> f64 {
    let s = blurred(e, c, size);
    (0..e.len()).map(|i| f64::from(e[i]) * s[i]).sum()
}

/// `S_p = Σ_q w(q − p) e_q` for every pixel.
fn blurred(e: &[f32], c: usize, size: u32) -> Vec<f64> {
    let n = size as i32;
    let mut s = vec![0f64; e.len()];
    let win = window();
    for y in 0..n {
        for x in 0..n {
            let p = (y * n + x) as usize;
            for &(dx, dy, w) in &win {
                let q = (((y + dy) & (n - 1)) * n + ((x + dx) & (n - 1))) as usize;
                for j in 0..c {
                    s[p * c + j] += w * f64::from(e[q * c + j]);
                }
            }
        }
    }
    s
}

/// Optimises a tile (module docs): the keys' permutation, then the ranks. `progress(done,
/// total)` is called once per sweep of the permutation.
pub fn optimise(spec: &TileSpec, progress: &dyn Fn(u32, u32)) -> Tile {
    let mut tile = permute_keys(spec, progress);
    choose_ranks(spec, &mut tile.keys);
    tile
}

/// Simulated annealing's temperature in sweep `sweep` of `sweeps`: `t0` times `scale` (the mean
/// |ΔE| of the first proposals), falling quadratically to 0.
fn temperature(t0: f64, scale: f64, sweep: u32, sweeps: u32) -> f64 {
    t0 * scale * (1.0 - f64::from(sweep) / f64::from(sweeps)).powi(2)
}

/// Whether a move that changes the energy by `delta` is taken: always if it lowers it, and
/// with probability `exp(−delta / temperature)` if not (never at temperature 0).
fn accepts(delta: f64, temperature: f64, rng: &mut nyquist::rng::DefaultRng) -> bool {
    delta < 0.0 || (temperature > 0.0 && uniform_f64(rng) < (-delta / temperature).exp())
}

/// Sweeps of the rank stage's annealing (each pixel proposes one other option per sweep on
/// average). Against coordinate descent alone, the annealing lowers the mean low-frequency
/// ratio at 1 … 32 spp of integrands of the training families it was not trained on by 0.02 to
/// 0.03 (`docs/blue-noise.md`).
const RANK_ANNEALED_SWEEPS: u32 = 128;
/// Sweeps of the rank stage's coordinate descent after the annealing (each pixel takes its
/// best option).
const RANK_GREEDY_SWEEPS: u32 = 8;

/// How many rank bits the rank stage chooses together, from the top ([`choose_ranks`]); bits
/// past these are chosen one at a time.
const RANK_CHUNKS: [u32; 1] = [3];

/// Sets rank bits `low .. high` of every entry (whose bits above are set and below are 0):
/// each pixel chooses which aligned block of `2^low` of its first `2^high` samples comes
/// first, by coordinate descent on the summed energy of the errors at levels `low .. high`.
fn choose_rank_bits(
    spec: &TileSpec,
    tests: &[Test],
    entries: &mut [u32],
    rng: &mut nyquist::rng::DefaultRng,
    low: u32,
    high: u32,
) {
    let t = tests.len();
    let n = entries.len();
    let top = high - low;
    let options = 1usize << top;
    let levels = top as usize;
    // Per pixel and option, the errors at levels low .. high − 1: option `o` puts the first
    // 2^l samples in the aligned block of 2^l containing sample o · 2^low (of the samples in
    // the pixel's current order, whose rank bits from `high` up are set).
    let c = levels * t;
    let rows = per_key(entries, |entry| {
        let mut block = vec![0f64; options * t];
        for i in 0..1u32 << high {
            let x = spec.family.values(entry, i);
            let b = (i >> low) as usize;
            for (j, test) in tests.iter().enumerate() {
                block[b * t + j] += test.eval(&x);
            }
        }
        let mut out = vec![0f32; options * c];
        for o in 0..options {
            for li in 0..levels {
                let start = (o >> li) << li;
                let count = f64::from(1u32 << (low as usize + li));
                for j in 0..t {
                    let sum: f64 = (start..start + (1 << li)).map(|b| block[b * t + j]).sum();
                    out[o * c + li * t + j] = (sum / count) as f32;
                }
            }
        }
        out
    });
    let mut e: Vec<f32> = rows.into_iter().flatten().collect();
    if options == 2 && low == 0 {
        // The last bit: each option's vector becomes its deviation from the pair's mean
        // ([`choose_ranks`]), so the two options differ only in sign.
        for row in e.chunks_exact_mut(2 * c) {
            let (first, second) = row.split_at_mut(c);
            for (a, b) in first.iter_mut().zip(second) {
                let d = (*a - *b) / 2.0;
                (*a, *b) = (d, -d);
            }
        }
    }
    // One centring and scale per component, over every pixel and option.
    standardise_columns(&mut e, c);
    let at = |p: usize, o: usize| &e[(p * options + o) * c..(p * options + o + 1) * c];
    let mut chosen = vec![0usize; n];
    let current: Vec<f32> = (0..n).flat_map(|p| at(p, 0).to_vec()).collect();
    let mut s = blurred(&current, c, spec.size);
    let win = window();
    let norm = |v: &[f32]| v.iter().map(|&x| f64::from(x).powi(2)).sum::<f64>();
    let norms: Vec<f64> = e.chunks_exact(c).map(norm).collect();
    // The energy's change when pixel `p` moves from its option to option `o`.
    let change = |s: &[f64], chosen: &[usize], p: usize, o: usize| {
        let (from, to) = (at(p, chosen[p]), at(p, o));
        let dot: f64 = to
            .iter()
            .zip(from)
            .zip(&s[p * c..(p + 1) * c])
            .map(|((t, f), s)| (f64::from(*t) - f64::from(*f)) * s)
            .sum();
        2.0 * dot + norms[p * options + o] - norms[p * options + chosen[p]]
    };
    let mut d = vec![0f64; c];
    let mut scale = 0.0;
    for sweep in 0..RANK_ANNEALED_SWEEPS + RANK_GREEDY_SWEEPS {
        for t in 0..n {
            let p = uniform_below(rng, n as u32) as usize;
            let mut best = (0.0, chosen[p]);
            if sweep < RANK_ANNEALED_SWEEPS {
                // One other option, taken under the annealing's rule.
                let mut o = uniform_below(rng, options as u32 - 1) as usize;
                o += usize::from(o >= chosen[p]);
                let delta = change(&s, &chosen, p, o);
                if sweep == 0 && t < 4096 {
                    scale += delta.abs() / 4096.0;
                }
                let temperature = temperature(0.3, scale, sweep, RANK_ANNEALED_SWEEPS);
                if accepts(delta, temperature, rng) {
                    best = (delta, o);
                }
            } else {
                // The best option.
                for o in (0..options).filter(|&o| o != chosen[p]) {
                    let delta = change(&s, &chosen, p, o);
                    if delta < best.0 {
                        best = (delta, o);
                    }
                }
            }
            if best.1 == chosen[p] {
                continue;
            }
            let (from, to) = (at(p, chosen[p]), at(p, best.1));
            for ((dk, t), f) in d.iter_mut().zip(to).zip(from) {
                *dk = f64::from(*t) - f64::from(*f);
            }
            chosen[p] = best.1;
            spread(&mut s, c, spec.size, &win, p, &d, 1.0);
        }
    }
    for (entry, o) in entries.iter_mut().zip(chosen) {
        *entry |= (o as u32) << low;
    }
}

/// The rank stage: rank bits in chunks from the top ([`RANK_CHUNKS`]: bits 5 … 7 together,
/// then each of bits 4 … 0 alone, for the shipped spec). For a chunk of bits `low .. high`,
/// each pixel chooses which aligned block of `2^low` of its first `2^high` samples comes first
/// (eight choices for the top chunk) to lower the summed energy of the errors at levels
/// `low .. high`: by simulated annealing, each proposal a random pixel and another of its
/// options ([`RANK_ANNEALED_SWEEPS`]), then by coordinate descent over the pixels in a random
/// order ([`RANK_GREEDY_SWEEPS`]). The top chunk gives 32 spp, the top of the band the
/// comparison measures, eight choices, where one bit at a time from the top would leave it
/// one. Below it each bit is chosen for its own level alone, as OpenQMC's optimiser chooses
/// every bit: a chunk's top level has one bit of choice however the chunk is cut, and in a
/// joint chunk the levels below it outweigh it (`docs/blue-noise.md` measures both).
///
/// Here the energy keeps each pixel's own term, `Σ_p |e_p|²` (the kernel's weight at distance
/// 0 is 1): the key stage permutes the error vectors, which leaves that sum alone, but a rank
/// chooses between errors, and without the term the larger error of opposite sign to its
/// neighbours would win.
///
/// The last bit (1 spp) is chosen on deviations instead, as OpenQMC's optimiser chooses every
/// bit: a pixel's 1-spp error is its 2-spp error `m` plus or minus a deviation `d`, and the bit
/// chooses the sign of `d` to make the image of the chosen deviations blue. Both options have
/// the same `|d|`, so the choice cannot favour the larger error. Chosen on the errors
/// themselves, the self term did not stop that: `lattice-bn`'s 1-spp mean squared error on the
/// held-out Gaussian was 8.0 % above the plain lattice's (`docs/blue-noise.md`).
fn choose_ranks(spec: &TileSpec, entries: &mut [u32]) {
    let tests = tests(spec.family, spec.seed);
    let mut rng = default_rng(spec.seed ^ 0x5241_4e4b); // "RANK"
    let mut high = spec.levels;
    let mut chunks = RANK_CHUNKS.iter();
    while high > 0 {
        let low = high.saturating_sub(*chunks.next().unwrap_or(&1));
        choose_rank_bits(spec, &tests, entries, &mut rng, low, high);
        high = low;
    }
}

/// The key stage: the permutation of the initial entries (module docs).
fn permute_keys(spec: &TileSpec, progress: &dyn Fn(u32, u32)) -> Tile {
    let size = spec.size;
    let n = (size * size) as usize;
    let mut keys: Vec<u32> = (0..size * size).map(initial_entry).collect();
    let (mut e, c) = error_vectors(spec, &keys);
    let mut s = blurred(&e, c, size);
    let before: f64 = (0..e.len()).map(|i| f64::from(e[i]) * s[i]).sum();
    let win = window();
    let weight = |p: usize, q: usize| -> f64 {
        let m = size as i32;
        let (px, py) = ((p as i32) % m, (p as i32) / m);
        let (qx, qy) = ((q as i32) % m, (q as i32) / m);
        let wrap = |d: i32| {
            let d = d.rem_euclid(m);
            if d > m / 2 { d - m } else { d }
        };
        let (dx, dy) = (wrap(qx - px), wrap(qy - py));
        if dx.abs() > RADIUS || dy.abs() > RADIUS || (dx, dy) == (0, 0) {
            0.0
        } else {
            (-f64::from(dx * dx + dy * dy) / (SIGMA * SIGMA)).exp()
        }
    };
    let mut rng = default_rng(spec.seed ^ 0x5357_4150); // "SWAP"
    let mut swaps = 0u64;
    let mut d = vec![0f64; c];
    // The mean |ΔE| of the first proposals: the annealing's temperature scale.
    let mut scale = 0.0;
    for sweep in 0..spec.sweeps {
        for t in 0..n {
            let p = uniform_below(&mut rng, n as u32) as usize;
            let q = if t % 2 == 0 {
                uniform_below(&mut rng, n as u32) as usize
            } else {
                let m = size as i32;
                let dx = uniform_below(&mut rng, 17) as i32 - 8;
                let dy = uniform_below(&mut rng, 17) as i32 - 8;
                let (px, py) = ((p as i32) % m, (p as i32) / m);
                (((py + dy) & (m - 1)) * m + ((px + dx) & (m - 1))) as usize
            };
            if p == q {
                continue;
            }
            let (mut dot, mut norm) = (0.0, 0.0);
            for j in 0..c {
                let dj = f64::from(e[q * c + j]) - f64::from(e[p * c + j]);
                d[j] = dj;
                dot += dj * (s[p * c + j] - s[q * c + j]);
                norm += dj * dj;
            }
            let delta = 2.0 * dot - 2.0 * weight(p, q) * norm;
            if sweep == 0 && t < 4096 {
                scale += delta.abs() / 4096.0;
            }
            if !accepts(
                delta,
                temperature(0.05, scale, sweep, spec.sweeps),
                &mut rng,
            ) {
                continue;
            }
            swaps += 1;
            keys.swap(p, q);
            for j in 0..c {
                e.swap(p * c + j, q * c + j);
            }
            // S moves by +w·d around p and −w·d around q.
            spread(&mut s, c, size, &win, p, &d, 1.0);
            spread(&mut s, c, size, &win, q, &d, -1.0);
        }
        progress(sweep + 1, spec.sweeps);
    }
    let after = energy(&e, c, size);
    Tile {
        keys,
        energy: [before, after],
        swaps,
    }
}

/// The low-frequency ratio of a `size`² image
/// ([`ErrorSpectrum::low_frequency_ratio`](crate::error_spectrum::ErrorSpectrum)): the
/// mean periodogram power at the frequencies `0 < |f| < size/8` (below a quarter of the Nyquist
/// radius), divided by the mean over every frequency but 0, which is what white noise of the
/// same variance has at every frequency. Blue error is well below 1; white error near 1. An
/// image with no error has no spectrum: `NaN`.
pub fn low_frequency_ratio(image: &[f64], size: usize) -> f64 {
    crate::error_spectrum::error_spectrum(image, size as u32, size as u32)
        .map_or(f64::NAN, |s| s.low_frequency_ratio)
}

/// The mean [`low_frequency_ratio`] over the test integrands of the error images of `keys`
/// laid out on the spec's torus, at each spp `2^level`, `level = 0 ..= spec.levels`.
pub fn level_ratios(spec: &TileSpec, keys: &[u32]) -> Vec<f64> {
    let (e, c) = error_vectors(spec, keys);
    let levels = spec.levels as usize + 1;
    let per_level = c / levels;
    let size = spec.size as usize;
    (0..levels)
        .map(|level| {
            // A component with no error at this spp (a Heaviside no first sample crosses) has
            // no spectrum; it is left out.
            let ratios: Vec<f64> = (0..per_level)
                .map(|j| {
                    let comp = level * per_level + j;
                    let img: Vec<f64> = (0..keys.len())
                        .map(|k| f64::from(e[k * c + comp]))
                        .collect();
                    low_frequency_ratio(&img, size)
                })
                .filter(|r| r.is_finite())
                .collect();
            ratios.iter().sum::<f64>() / ratios.len().max(1) as f64
        })
        .collect()
}

/// A function of the four values of a 4-D block of dimensions.
pub type BlockIntegrand = fn(&[f32; 4]) -> f64;

/// Integrands none of the optimiser's: a disk of area ½ and a Gaussian bump (σ = 0.15) over
/// dimensions (0, 1) and over (2, 3), and a Heaviside and a Gaussian over all four — as the
/// peer comparison measures them (`peers/src/blue_noise.rs`).
pub const HELD_OUT: [(&str, BlockIntegrand); 6] = [
    ("disk 0-1", |v| disk(v[0], v[1])),
    ("gaussian 0-1", |v| bump(v[0], v[1])),
    ("disk 2-3", |v| disk(v[2], v[3])),
    ("gaussian 2-3", |v| bump(v[2], v[3])),
    ("heaviside 4-D", |v| {
        let s: f64 = v.iter().map(|&x| f64::from(x) - 0.5).sum::<f64>()
            + 0.3 * (f64::from(v[0]) - f64::from(v[3]));
        f64::from(u8::from(s < 0.0))
    }),
    ("gaussian 4-D", |v| {
        let r2: f64 = v.iter().map(|&x| (f64::from(x) - 0.5).powi(2)).sum();
        (-r2 / (2.0 * 0.25 * 0.25)).exp()
    }),
];

fn disk(x: f32, y: f32) -> f64 {
    let (dx, dy) = (f64::from(x) - 0.5, f64::from(y) - 0.5);
    f64::from(u8::from(dx * dx + dy * dy < 0.5 / std::f64::consts::PI))
}

fn bump(x: f32, y: f32) -> f64 {
    let (dx, dy) = (f64::from(x) - 0.5, f64::from(y) - 0.5);
    (-(dx * dx + dy * dy) / (2.0 * 0.15 * 0.15)).exp()
}

/// The low-frequency ratio of each [`HELD_OUT`] integrand's error image at spp `1, 2, … 2^max`
/// from `keys` on the spec's torus: `[integrand][level]`.
pub fn held_out_ratios(spec: &TileSpec, keys: &[u32], max: u32) -> Vec<Vec<f64>> {
    let size = spec.size as usize;
    HELD_OUT
        .iter()
        .map(|(_, f)| {
            (0..=max)
                .map(|level| {
                    let n = 1u32 << level;
                    let img: Vec<f64> = keys
                        .iter()
                        .map(|&k| {
                            (0..n).map(|i| f(&spec.family.values(k, i))).sum::<f64>() / f64::from(n)
                        })
                        .collect();
                    low_frequency_ratio(&img, size)
                })
                .collect()
        })
        .collect()
}

/// The tile as `screen_blue_tile.in` holds it: a Rust array literal of three bytes per entry
/// (the key's low and high byte, the rank), four entries a line.
pub fn source(tile: &Tile, spec: &TileSpec) -> String {
    // The command that makes this tile: the flags that differ from the shipped spec's.
    let shipped = TileSpec::shipped(spec.family);
    let mut flags = String::new();
    if spec.sweeps != shipped.sweeps {
        flags.push_str(&format!(" --sweeps {}", spec.sweeps));
    }
    if spec.seed != shipped.seed {
        flags.push_str(&format!(" --seed {}", spec.seed));
    }
    let mut s = format!(
        "// Generated by `cargo run --release -p nyquist-lab --bin blue-tile -- --family {}{flags}` \
         ({}², spp 1 … {}, {} sweeps, seed {}); do not edit.\n[\n",
        spec.family.name(),
        spec.size,
        1u32 << spec.levels,
        spec.sweeps,
        spec.seed
    );
    for row in tile.keys.chunks(4) {
        s.push_str("   ");
        for e in row {
            let [lo, hi] = ((e >> 8) as u16).to_le_bytes();
            s.push_str(&format!(" [0x{lo:02x}, 0x{hi:02x}, 0x{:02x}],", e & 0xff));
        }
        s.push('\n');
    }
    s.push_str("]\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    const SMALL: TileSpec = TileSpec {
        family: Family::OwenSobol,
        size: 32,
        levels: 3,
        sweeps: 16,
        seed: 5,
    };

    /// The optimised layout's error images are blue at every level (low-frequency ratio
    /// below 0.7 in the mean over the integrands; the 32² torus's band has about 50
    /// frequencies), the slot order's are white (0.6 to 1.6);
    /// the energy falls, the keys are a permutation of the initial ones, and the run is
    /// deterministic.
    #[test]
    fn optimisation_makes_the_error_blue_and_permutes_the_keys() {
        let t = optimise(&SMALL, &|_, _| {});
        assert!(t.energy[1] < t.energy[0] - 1000.0, "{:?}", t.energy);
        let mut k: Vec<u32> = t.keys.iter().map(|e| e & !0xff).collect();
        k.sort_unstable();
        let mut want: Vec<u32> = (0..32 * 32).map(initial_entry).collect();
        want.sort_unstable();
        assert_eq!(k, want);
        let start: Vec<u32> = (0..32 * 32).map(initial_entry).collect();
        let (blue, white) = (level_ratios(&SMALL, &t.keys), level_ratios(&SMALL, &start));
        eprintln!("{blue:?} {white:?}");
        for level in 0..=3 {
            let (blue, white) = (blue[level], white[level]);
            assert!(blue < 0.7, "level {level}: {blue}");
            assert!((0.6..1.6).contains(&white), "level {level}: {white}");
        }
        assert_eq!(optimise(&SMALL, &|_, _| {}), t, "deterministic");
    }

    #[test]
    fn white_noise_has_a_low_frequency_ratio_near_one() {
        let mut rng = default_rng(3);
        let mut r = Vec::new();
        for _ in 0..8 {
            let img: Vec<f64> = (0..32 * 32).map(|_| uniform_f64(&mut rng)).collect();
            r.push(low_frequency_ratio(&img, 32));
        }
        let mean = r.iter().sum::<f64>() / 8.0;
        assert!((0.7..1.3).contains(&mean), "{r:?}");
        // A smooth image is all low frequencies.
        let smooth: Vec<f64> = (0..32 * 32)
            .map(|i| ((i % 32) as f64 * std::f64::consts::TAU / 32.0).sin())
            .collect();
        assert!(low_frequency_ratio(&smooth, 32) > 10.0);
    }
}
