//! The Sobol sequence in base 2 with the Joe–Kuo direction numbers (`new-joe-kuo-6.21201`,
//! first 1024 dimensions).
//!
//! Sources: I. M. Sobol', "On the distribution of points in a cube and the approximate evaluation
//! of integrals" (1967); S. Joe and F. Y. Kuo, "Constructing Sobol sequences with better
//! two-dimensional projections", SIAM J. Sci. Comput. 30, 2635–2654 (2008), whose direction
//! numbers `scripts/gen_sobol.py` turns into the checked-in table (attribution in
//! `licenses/joe-kuo.txt`).
//!
//! Point `i` of dimension `d` (natural order) is the XOR of the direction numbers `V_{k+1}` of
//! dimension `d` over the set bits `k` of `i`, read as a 32-bit binary fraction. Point 0 is the
//! origin and dimension 0 is the van der Corput sequence. SciPy's `Sobol(d, scramble=False)`
//! enumerates the same points in Gray-code order: its point `i` is our point `i ^ (i >> 1)`.
//!
//! Speed and memory: the direction numbers take 128 KiB (`1024 × 32 × u32`). Dimensions 0..63
//! also have compile-time byte tables (272 KiB more): a value there is four lookups and three
//! XORs; dimensions 64..1023 use a branch-free masked XOR over the 32 columns, several times
//! slower. Neither path's cost depends on the index (timings: `docs/performance.md`).

use super::{SOBOL_MATRICES, SOBOL_MATRICES_HI, Sequence, check_fill, padded_u32};
use crate::lazy_table::{baked_table, const_unless_lazy};
use crate::math::fraction_to_f32 as to_f32;
use crate::{Error, hash};

/// Number of Sobol dimensions the table holds (Joe–Kuo's first 1024, dimension 0 being van der
/// Corput). Higher dimensions wrap modulo this in [`sobol_u32`] and [`sobol_u64`]; the
/// sequences and samplers pad past it instead ([`Sobol`]).
///
/// ```
/// assert_eq!(nyquist::sequence::SOBOL_DIMS, 1024);
/// ```
pub const SOBOL_DIMS: u32 = 1024;

/// Dimensions `0..FAST_DIMS` also have byte tables: four lookups per value instead of 32
/// masked XORs (several times faster: `docs/performance.md`), at 4¼ KiB per dimension.
const FAST_DIMS: usize = 64;

baked_table! {
    /// `SOBOL_BYTES[d][j][b]` is the XOR of the columns `8j + k` of dimension `d` over the set
    /// bits `k` of the byte `b`: the product restricted to index byte `j`. Built from
    /// [`SOBOL_MATRICES`] ([`baked_table!`]); 272 KiB.
    ///
    /// Each row is padded from 256 to [`BYTE_ROW`] entries: without it the same entry of every
    /// dimension lies a multiple of 4 KiB apart, in one L1 cache set, and a sample's run of
    /// dimensions evicts itself (measured: a pixel fill ran at a third of its instruction rate).
    static SOBOL_BYTES: [[[u32; BYTE_ROW]; 4]; FAST_DIMS] = [[[0; BYTE_ROW]; 4]; FAST_DIMS],
        byte_tables, sobol_bytes_at_first_use_equal_the_baked_table;
}

/// A byte table row: 256 entries and 16 of padding (64 bytes), so that rows and dimensions
/// start in different cache sets.
const BYTE_ROW: usize = 256 + 16;

const_unless_lazy! {
    fn byte_tables(t: &mut [[[u32; BYTE_ROW]; 4]; FAST_DIMS]) {
        let mut d = 0;
        while d < FAST_DIMS {
            let mut j = 0;
            while j < 4 {
                let mut b = 1;
                while b < 256 {
                    // Entry b = entry (b without its lowest set bit) ^ the column of that bit.
                    let k = (b as u32).trailing_zeros() as usize;
                    t[d][j][b] = t[d][j][b & (b - 1)] ^ SOBOL_MATRICES[d][8 * j + k];
                    b += 1;
                }
                j += 1;
            }
            d += 1;
        }
    }
}

/// The generator-matrix product: XOR of the columns `m[k]` over the set bits `k` of `index`,
/// as a branch-free masked XOR over all 32 columns (the fallback for dimensions without byte
/// tables; the same speed for any index, unlike a loop over the set bits).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn product(m: &[u32; 32], index: u32) -> u32 {
    let mut v = 0;
    for (k, &col) in m.iter().enumerate() {
        let bit = (index >> k) & 1;
        v ^= col & bit.wrapping_neg();
    }
    v
}

/// Sobol point `index` in each dimension `first, first + 1, …` (as [`sobol_u32`] gives them),
/// each XORed with the matching `shifts` entry, as `f32`s (top 24 bits) into `out`: the run a
/// global sampler reads for one sample's array. `None`, writing nothing, unless all the
/// dimensions have byte tables (below 64) and `shifts` is as long as `out`.
#[inline]
pub(crate) fn sobol_run_f32(
    index: u32,
    first: usize,
    shifts: &[u32],
    out: &mut [f32],
) -> Option<()> {
    let tables = SOBOL_BYTES.get(first..first.checked_add(out.len())?)?;
    let shifts = shifts.get(..out.len())?;
    for ((x, t), &shift) in out.iter_mut().zip(tables).zip(shifts) {
        *x = to_f32(byte_product(t, index) ^ shift);
    }
    Some(())
}

/// The generator-matrix product through one dimension's byte tables: four lookups.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn byte_product(t: &[[u32; BYTE_ROW]; 4], index: u32) -> u32 {
    let [b0, b1, b2, b3] = index.to_le_bytes();
    t[0][b0 as usize] ^ t[1][b1 as usize] ^ t[2][b2 as usize] ^ t[3][b3 as usize]
}

/// The product for dimension `dim < SOBOL_DIMS`, through the byte tables where there are some.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn product_dim(dim: usize, index: u32) -> u32 {
    if let Some(t) = SOBOL_BYTES.get(dim) {
        byte_product(t, index)
    } else {
        product(&SOBOL_MATRICES[dim % SOBOL_DIMS as usize], index)
    }
}

/// Sobol point `index` in dimension `dim`, as a 32-bit binary fraction (`value / 2³²` is the
/// coordinate in `[0, 1)`).
///
/// Natural order: the XOR of dimension `dim`'s direction numbers over the set bits of `index`.
/// Total: `dim >= SOBOL_DIMS` wraps to `dim % SOBOL_DIMS`. Allocates: no.
///
/// ```
/// use nyquist::sequence::sobol_u32;
/// // Dimension 0 is van der Corput: the index's bits reversed.
/// assert_eq!(sobol_u32(6, 0), 6u32.reverse_bits());
/// // Dimension 1, points 0..4: 0, 1/2, 3/4, 1/4.
/// let half = 1u32 << 31;
/// assert_eq!([0, 1, 2, 3].map(|i| sobol_u32(i, 1)), [0, half, 3 * (half >> 1), half >> 1]);
/// assert_eq!(sobol_u32(5, 1024 + 1), sobol_u32(5, 1));
/// ```
#[inline]
pub fn sobol_u32(index: u32, dim: u32) -> u32 {
    product_dim((dim % SOBOL_DIMS) as usize, index)
}

/// Sobol point `index` (64-bit) in dimension `dim`, as a 32-bit binary fraction.
///
/// The index's low half goes through the 32 columns of [`sobol_u32`], its upper half through
/// the columns `V_33 … V_64` read to 32 bits (the Joe–Kuo recurrence run to 64 columns by
/// `scripts/gen_sobol.py`, checked against `scripts/sobol64_reference.py`'s independent
/// computation). So `sobol_u64(i, d) == sobol_u32(i as u32, d)` for `i < 2³²`, and in every
/// pair of dimensions the first `2^k` points stay a (t, k, 2)-net for `k ≤ 64` (at 32-bit
/// resolution: dimension 0, van der Corput, has no digits past 2⁻³² to give, so its values
/// repeat with period 2³²). Total: `dim >= SOBOL_DIMS` wraps to `dim % SOBOL_DIMS`. Allocates: no.
///
/// ```
/// use nyquist::sequence::{sobol_u32, sobol_u64};
/// assert_eq!(sobol_u64(77, 3), sobol_u32(77, 3));
/// // Dimension 1's column 33 is 2^-1 (Pascal's triangle mod 2: C(32, r) is odd for r = 0, 32).
/// assert_eq!(sobol_u64(1 << 32, 1), 1 << 31);
/// assert_eq!(sobol_u64(1 << 32, 0), 0);
/// ```
#[inline]
pub fn sobol_u64(index: u64, dim: u32) -> u32 {
    let dim = (dim % SOBOL_DIMS) as usize;
    product_dim(dim, index as u32) ^ product_hi(dim, index)
}

/// The columns past 32 of dimension `dim < SOBOL_DIMS` over the upper half of `index` (0 below
/// 2³², without reading the table).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn product_hi(dim: usize, index: u64) -> u32 {
    let hi = (index >> 32) as u32;
    if hi == 0 {
        0
    } else {
        product(&SOBOL_MATRICES_HI[dim], hi)
    }
}

/// A 32-bit binary fraction as an `f64`, exactly.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn to_f64(v: u32) -> f64 {
    f64::from(v) * crate::math::TWO_POW_MINUS_32
}

/// The Sobol sequence (Joe–Kuo direction numbers), optionally with a per-dimension digital shift
/// (random XOR).
///
/// - `f32` values are the top 24 bits of the 32-bit fraction (truncation, so never 1);
///   `f64` values are all 32 bits, exactly.
/// - Indices are 64-bit ([`sobol_u64`]; [`Sequence::point_count`] is `None`). Below 2³² the
///   values are the 32-bit sequence's, bit for bit.
/// - Dimensions `0 .. SOBOL_DIMS` are Joe and Kuo's; from [`SOBOL_DIMS`] on they are padding:
///   independently seeded Owen-scrambled 4-D blocks (Burley 2020, §6) keyed by the seed (0
///   for [`Sobol::new`]), so no dimension repeats a lower one. `dim >= dims()` wraps modulo
///   `dims()`.
/// - Unscrambled, the first `2^m` points of dimensions (0, 1) form a (0, m, 2)-net; a digital
///   shift keeps every such net property.
///
/// Allocates: no. Stateless, `&self` everywhere: share one instance across threads.
///
/// ```
/// use nyquist::sequence::{Sequence, Sobol};
/// let s = Sobol::new(4).unwrap();
/// // Published first points (dimension 1, natural order): 0, .5, .75, .25, .625, .125, …
/// let dim1: Vec<f32> = (0..6).map(|i| s.sample(i, 1)).collect();
/// assert_eq!(dim1, [0.0, 0.5, 0.75, 0.25, 0.625, 0.125]);
/// assert_ne!(s.sample(1 << 32 | 3, 1), s.sample(3, 1)); // 64-bit indices
/// assert!(Sobol::new(5000).is_ok()); // dimensions past 1024 are padded
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sobol {
    dims: u32,
    seed: u64,
    scrambled: bool,
}

impl Sobol {
    /// The unscrambled sequence with `dims` dimensions.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `dims == 0`.
    ///
    /// ```
    /// use nyquist::{sequence::Sobol, Error};
    /// assert!(Sobol::new(1024).is_ok());
    /// assert!(Sobol::new(u32::MAX).is_ok());
    /// assert_eq!(Sobol::new(0), Err(Error::ZeroSize { what: "dims" }));
    /// ```
    pub fn new(dims: u32) -> Result<Sobol, Error> {
        if dims == 0 {
            return Err(Error::ZeroSize { what: "dims" });
        }
        Ok(Sobol {
            dims,
            seed: 0,
            scrambled: false,
        })
    }

    /// The sequence with a digital shift: dimension `d`'s 32-bit values are XOR-ed with a hash
    /// of `(seed, d)`. Every seed, 0 included, gives a shift. Net properties are kept.
    ///
    /// # Errors
    /// As [`Sobol::new`].
    ///
    /// ```
    /// use nyquist::sequence::{Sequence, Sobol};
    /// let s = Sobol::with_digital_shift(2, 7).unwrap();
    /// let plain = Sobol::new(2).unwrap();
    /// assert_ne!(s.sample(0, 1), plain.sample(0, 1));
    /// // A digital shift is a bijection on the 2^m strata: 8 points, 8 distinct eighths.
    /// let mut seen = [false; 8];
    /// for i in 0..8 {
    ///     seen[(s.sample(i, 1) * 8.0) as usize] = true;
    /// }
    /// assert!(seen.iter().all(|&x| x));
    /// ```
    pub fn with_digital_shift(dims: u32, seed: u64) -> Result<Sobol, Error> {
        Ok(Sobol {
            seed,
            scrambled: true,
            ..Sobol::new(dims)?
        })
    }

    /// Whether this instance applies a digital shift.
    ///
    /// ```
    /// use nyquist::sequence::Sobol;
    /// assert!(!Sobol::new(3).unwrap().is_shifted());
    /// assert!(Sobol::with_digital_shift(3, 0).unwrap().is_shifted());
    /// ```
    pub fn is_shifted(&self) -> bool {
        self.scrambled
    }

    /// The XOR applied to dimension `dim` (0 when unscrambled).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn shift(&self, dim: u32) -> u32 {
        if self.scrambled {
            (hash::hash2(self.seed, u64::from(dim)) >> 32) as u32
        } else {
            0
        }
    }

    /// Point `index`, dimension `dim` as a 32-bit fraction, with the scramble applied.
    /// Total: `dim` wraps modulo [`Sequence::dims`].
    ///
    /// ```
    /// use nyquist::sequence::{Sobol, sobol_u32, sobol_u64};
    /// let s = Sobol::new(8).unwrap();
    /// assert_eq!(s.sample_u32(77, 5), sobol_u32(77, 5));
    /// assert_eq!(s.sample_u32(77, 8 + 5), sobol_u32(77, 5));
    /// assert_eq!(s.sample_u32(3 << 40, 5), sobol_u64(3 << 40, 5));
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn sample_u32(&self, index: u64, dim: u32) -> u32 {
        // The branch skips a division in the common case.
        let dim = if dim < self.dims {
            dim
        } else {
            dim % self.dims
        };
        if (index >> 32) as u32 != 0 || dim >= SOBOL_DIMS {
            return self.wide_u32(index, dim);
        }
        product_dim(dim as usize, index as u32) ^ self.shift(dim)
    }

    /// [`Sobol::sample_u32`] past the 32-bit path: an index past 2³² or a padding dimension.
    #[cold]
    #[inline(never)]
    fn wide_u32(&self, index: u64, dim: u32) -> u32 {
        if dim >= SOBOL_DIMS {
            return self.padded(index, dim);
        }
        (product_dim(dim as usize, index as u32) ^ product_hi(dim as usize, index))
            ^ self.shift(dim)
    }

    /// A padding dimension (`dim >= SOBOL_DIMS`), keyed by the seed.
    #[inline(never)]
    fn padded(&self, index: u64, dim: u32) -> u32 {
        padded_u32(
            (hash::hash2(self.seed, 0x5041_4444) >> 32) as u32,
            index,
            dim,
        ) // "PADD"
    }
}

impl Sequence for Sobol {
    fn dims(&self) -> u32 {
        self.dims
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        to_f32(self.sample_u32(index, dim))
    }

    #[inline]
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        to_f64(self.sample_u32(index, dim))
    }

    /// Point-major fill, computed dimension by dimension with the natural-order increment:
    /// going from point `i` to `i + 1` flips bits `0..=t` of the index (`t` the trailing zeros
    /// of `i + 1`), so the value changes by the XOR of the first `t + 1` of the 64 columns.
    /// Equal, bit for bit, to repeated [`Sequence::sample`] (padding dimensions are computed
    /// value by value).
    fn fill(&self, first: u64, dims: u32, out: &mut [f32]) -> Result<u64, Error> {
        let n = check_fill(self.dims, None, first, dims, out.len())?;
        for dim in 0..dims.min(SOBOL_DIMS) {
            let d = dim as usize;
            let mut prefix = [0u32; 64];
            let mut acc = 0;
            let columns = SOBOL_MATRICES[d].iter().chain(&SOBOL_MATRICES_HI[d]);
            for (p, &col) in prefix.iter_mut().zip(columns) {
                acc ^= col;
                *p = acc;
            }
            let shift = self.shift(dim);
            let mut v = product_dim(d, first as u32) ^ product_hi(d, first);
            let mut index = first;
            for point in out.chunks_exact_mut(dims as usize) {
                point[d] = to_f32(v ^ shift);
                index = index.wrapping_add(1);
                v ^= prefix[(index.trailing_zeros() & 63) as usize];
            }
        }
        for (k, point) in (0..n).zip(out.chunks_exact_mut(dims as usize)) {
            for dim in SOBOL_DIMS..dims {
                point[dim as usize] = to_f32(self.padded(first + k, dim));
            }
        }
        Ok(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tests::sobol_oracle;

    /// The "table is current" check: recompute every direction number from the data file with
    /// the Joe–Kuo recurrence and compare with the generated table.
    #[test]
    fn table_is_current() {
        let text = include_str!("../../../data/sobol/new-joe-kuo-6.1024.txt");
        let table = sobol_oracle::matrices_from_joe_kuo(text);
        assert_eq!(table.len(), SOBOL_DIMS as usize);
        for (d, row) in table.iter().enumerate() {
            assert_eq!(row, &SOBOL_MATRICES[d], "dimension {d}");
        }
    }

    #[test]
    fn matches_bit_by_bit_oracle_in_all_dims() {
        let mut indices: std::vec::Vec<u32> = (0..256).collect();
        indices.extend((0..256u32).map(|i| hash::mix32(i.wrapping_mul(0x9e37_79b9))));
        indices.extend([u32::MAX, 1 << 31, (1 << 31) - 1, 0xaaaa_aaaa, 0x5555_5555]);
        for dim in 0..SOBOL_DIMS {
            let m = sobol_oracle::generator_matrix(&SOBOL_MATRICES[dim as usize]);
            for &i in &indices {
                assert_eq!(
                    sobol_u32(i, dim),
                    sobol_oracle::gf2_product(&m, i),
                    "dim {dim} index {i}"
                );
            }
        }
    }

    #[test]
    fn byte_tables_agree_with_the_masked_product() {
        for (dim, m) in SOBOL_MATRICES.iter().enumerate().take(FAST_DIMS + 2) {
            for i in (0..2048u32).chain((0..2048).map(|i| hash::mix32(i ^ 0x55))) {
                assert_eq!(product_dim(dim, i), product(m, i), "dim {dim} index {i}");
            }
        }
    }

    #[test]
    fn dimension_zero_is_van_der_corput() {
        for i in (0..4096u32).chain([u32::MAX, 0x1234_5678, 1 << 31]) {
            assert_eq!(sobol_u32(i, 0), i.reverse_bits());
        }
    }

    /// The first 8 points of dimensions 0..4, natural order, as multiples of 1/8.
    ///
    /// Computed by hand from the recurrence (data/sobol/README.md): dimension 1 has s = 1,
    /// m = (1): V = .1, .11, .101 (binary); dimension 2 has s = 2, a = 1, m = (1, 3):
    /// V = .1, .11, .011; dimension 3 has s = 3, a = 1, m = (1, 3, 1): V = .1, .11, .001.
    /// Cross-check with SciPy: `scipy.stats.qmc.Sobol(4, scramble=False).random(8)` lists the
    /// same points in Gray-code order (its row i is our point i ^ (i >> 1)); e.g. its rows 2 and
    /// 3 are (.75, .25, .25, .25) and (.25, .75, .75, .75), our points 3 and 2. The data file's
    /// README records that all 1024 dimensions were checked against SciPy 1.17.1 this way.
    const FIRST_8_POINTS_IN_EIGHTHS: [[u32; 4]; 8] = [
        [0, 0, 0, 0],
        [4, 4, 4, 4],
        [2, 6, 6, 6],
        [6, 2, 2, 2],
        [1, 5, 3, 1],
        [5, 1, 7, 5],
        [3, 3, 5, 7],
        [7, 7, 1, 3],
    ];

    #[test]
    fn first_points_match_published_values() {
        let s = Sobol::new(4).unwrap();
        for (i, point) in FIRST_8_POINTS_IN_EIGHTHS.iter().enumerate() {
            for (d, &eighths) in point.iter().enumerate() {
                assert_eq!(
                    sobol_u32(i as u32, d as u32),
                    eighths << 29,
                    "point {i} dim {d}"
                );
                assert_eq!(s.sample(i as u64, d as u32), eighths as f32 / 8.0);
                assert_eq!(s.sample_f64(i as u64, d as u32), f64::from(eighths) / 8.0);
            }
        }
        // Dimension 1 is pbrt-v2's `Sobol2(i, 0)`, the (0,2)-sequence's second coordinate.
        let dim1: std::vec::Vec<f32> = (0..8).map(|i| s.sample(i, 1)).collect();
        assert_eq!(dim1, [0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875]);
    }

    #[test]
    fn first_two_dims_are_0_m_2_nets() {
        for m in 1..=12 {
            let pts: std::vec::Vec<[u32; 2]> = (0..1u32 << m)
                .map(|i| [sobol_u32(i, 0), sobol_u32(i, 1)])
                .collect();
            sobol_oracle::assert_elementary_intervals(&pts, m);
            let s = Sobol::with_digital_shift(2, 99).unwrap();
            let pts: std::vec::Vec<[u32; 2]> = (0..1u64 << m)
                .map(|i| [s.sample_u32(i, 0), s.sample_u32(i, 1)])
                .collect();
            sobol_oracle::assert_elementary_intervals(&pts, m);
        }
    }

    /// Past 2³² against `scripts/sobol64_reference.py`: Bratley and Fox's integer recurrence in
    /// Python big integers, an independent computation of the columns past 32.
    #[test]
    fn agrees_with_the_python_reference_past_2_32() {
        let text = include_str!("sobol64_reference.txt");
        let mut checked = 0;
        for line in text.lines().filter(|l| !l.starts_with('#')) {
            let f: std::vec::Vec<u64> = line.split(' ').map(|x| x.parse().unwrap()).collect();
            let (dim, index, value) = (f[0] as u32, f[1], f[2] as u32);
            assert!(index >> 32 != 0);
            assert_eq!(sobol_u64(index, dim), value, "dim {dim} index {index:#x}");
            assert_eq!(Sobol::new(1024).unwrap().sample_u32(index, dim), value);
            checked += 1;
        }
        assert_eq!(checked, 16 * 24);
    }

    /// Aligned blocks past 2³² are digitally shifted copies of the first block: the same
    /// t-value in every pair of dimensions, and (0, m, 2)-nets in dimensions 0 and 1.
    #[test]
    fn aligned_blocks_past_2_32_keep_the_first_blocks_t_value() {
        use crate::analysis::{PointSet, net_t_value};
        let t_value = |first: u64, m: u32, pair: [u32; 2]| {
            let coords: std::vec::Vec<f64> = (first..first + (1 << m))
                .flat_map(|i| pair.map(|d| f64::from(sobol_u64(i, d)) / 4_294_967_296.0))
                .collect();
            let mut scratch = std::vec![0; (1 << m) + 2];
            net_t_value(&PointSet::new(&coords, 2).unwrap(), &mut scratch).unwrap()
        };
        for base in [1u64 << 32, 0xdead_beef << 32, u64::MAX - 0xffff] {
            for m in [4u32, 8, 12] {
                let first = base & !((1 << m) - 1);
                for pair in [[0u32, 1], [2, 3], [7, 8], [100, 900]] {
                    assert_eq!(
                        t_value(first, m, pair),
                        t_value(0, m, pair),
                        "{pair:?} m {m}"
                    );
                }
                let pts: std::vec::Vec<[u32; 2]> = (first..first + (1 << m))
                    .map(|i| [sobol_u64(i, 0), sobol_u64(i, 1)])
                    .collect();
                sobol_oracle::assert_elementary_intervals(&pts, m);
            }
        }
    }

    /// `fill` past 1024 dimensions: the padding, value for value, at any first index.
    #[test]
    fn fill_with_padding_equals_repeated_sample() {
        let s = Sobol::with_digital_shift(1030, 3).unwrap();
        for first in [0u64, 9, 1 << 33] {
            let mut buf = std::vec![0.0f32; 1030 * 3];
            assert_eq!(s.fill(first, 1030, &mut buf), Ok(3));
            for (k, p) in buf.chunks_exact(1030).enumerate() {
                for d in [0usize, 1023, 1024, 1029] {
                    assert_eq!(
                        p[d],
                        s.sample(first + k as u64, d as u32),
                        "{first} {k} {d}"
                    );
                }
            }
        }
    }

    /// Padding dimensions: values in range, keyed by the seed, no copy of a lower dimension.
    #[test]
    fn padding_dimensions_are_not_wraps() {
        let s = Sobol::new(3000).unwrap();
        let shifted = Sobol::with_digital_shift(3000, 5).unwrap();
        for i in 0..64u64 {
            assert_eq!(s.sample_u32(i, 1024 + 3000), s.sample_u32(i, 1024));
            assert_ne!(s.sample_u32(i | 1 << 40, 1030), s.sample_u32(i, 1030));
        }
        let differs = |a: u32, b: u32| (0..64u64).any(|i| s.sample_u32(i, a) != s.sample_u32(i, b));
        assert!(differs(1024, 0) && differs(2048, 0) && differs(1025, 1));
        assert!((0..64u64).any(|i| s.sample_u32(i, 1500) != shifted.sample_u32(i, 1500)));
    }

    #[test]
    fn every_dimension_stratifies_each_power_of_two() {
        // Each one-dimensional projection is a (0, m, 1)-net: 2^m points, 2^m distinct strata.
        for dim in (0..SOBOL_DIMS).step_by(7) {
            let m = 10;
            let mut seen = [false; 1 << 10];
            for i in 0..1u32 << m {
                let s = (sobol_u32(i, dim) >> (32 - m)) as usize;
                assert!(!core::mem::replace(&mut seen[s], true), "dim {dim}");
            }
        }
    }

    #[test]
    fn f32_is_top_24_bits_truncated_and_f64_is_exact() {
        let s = Sobol::new(1024).unwrap();
        for i in [u32::MAX, 0xffff_ff80, 12345, 1 << 31] {
            for d in [0u32, 1, 17, 1023] {
                let v = sobol_u32(i, d);
                let x = s.sample(u64::from(i), d);
                assert_eq!(x, (v >> 8) as f32 / 16_777_216.0);
                assert!(x < 1.0);
                assert_eq!(
                    s.sample_f64(u64::from(i), d),
                    f64::from(v) / 4_294_967_296.0
                );
            }
        }
        // Index 2^32 - 1 in dimension 0 is 1 - 2^-32: f32 truncates to 1 - 2^-24, never 1.
        assert_eq!(s.sample(u64::from(u32::MAX), 0), crate::ONE_MINUS_EPSILON);
    }

    #[test]
    fn wrapping_of_dim_and_64_bit_indices() {
        let s = Sobol::new(5).unwrap();
        assert_eq!(s.point_count(), None);
        assert_eq!(s.dims(), 5);
        for i in [0u64, 3, 1000, u64::from(u32::MAX)] {
            for hi in [1u64, 7, u64::from(u32::MAX)] {
                let j = i | hi << 32;
                assert_eq!(s.sample_u32(j, 2), sobol_u64(j, 2));
                // The upper half adds the columns past 32 to the lower half's value.
                let upper = product(&SOBOL_MATRICES_HI[2], hi as u32);
                assert_ne!(upper, 0);
                assert_eq!(sobol_u64(j, 2), sobol_u32(i as u32, 2) ^ upper);
            }
            assert_eq!(s.sample(i, 5 + 3), s.sample(i, 3));
            assert_eq!(s.sample(i, 5), s.sample(i, 0)); // the first dimension past the end
            let last = sobol_u32(i as u32, 4) >> 8; // the last dimension in it, unwrapped
            assert_eq!(s.sample(i, 4), last as f32 / 16_777_216.0);
            assert_eq!(s.sample(i, u32::MAX), s.sample(i, u32::MAX % 5));
        }
        assert_eq!(sobol_u32(9, SOBOL_DIMS * 3 + 4), sobol_u32(9, 4));
        // Total in `dim`: the largest dimension number wraps like any other.
        assert_eq!(sobol_u32(9, u32::MAX), sobol_u32(9, u32::MAX % SOBOL_DIMS));
    }

    #[test]
    fn is_shifted_says_which_constructor_made_it() {
        assert!(!Sobol::new(3).unwrap().is_shifted());
        for seed in [0, 1, u64::MAX] {
            assert!(Sobol::with_digital_shift(3, seed).unwrap().is_shifted());
        }
    }

    /// The global samplers' run: dimension `first + k` of point `index`, XORed with `shifts[k]`,
    /// the top 24 bits as an `f32`; `None` and nothing written when a dimension has no byte
    /// table (64 and up) or `shifts` is short.
    #[test]
    fn sobol_runs_are_shifted_products_of_consecutive_dimensions() {
        let shifts: std::vec::Vec<u32> = (0..16).map(|k| hash::mix32(k * 7 + 1)).collect();
        for index in [0u32, 1, 77, 0x8000_0001, u32::MAX] {
            for (first, len) in [(0usize, 16usize), (5, 3), (FAST_DIMS - 16, 16), (10, 0)] {
                let mut out = [f32::NAN; 16];
                assert_eq!(
                    sobol_run_f32(index, first, &shifts, &mut out[..len]),
                    Some(())
                );
                for k in 0..len {
                    let v = sobol_u32(index, (first + k) as u32) ^ shifts[k];
                    assert_eq!(out[k], (v >> 8) as f32 / 16_777_216.0, "dim {}", first + k);
                }
            }
            let mut out = [f32::NAN; 4];
            assert_eq!(sobol_run_f32(index, FAST_DIMS - 3, &shifts, &mut out), None);
            assert_eq!(sobol_run_f32(index, usize::MAX, &shifts, &mut out), None);
            assert_eq!(sobol_run_f32(index, 0, &shifts[..3], &mut out), None);
            assert!(out.iter().all(|x| x.is_nan()), "nothing written");
        }
    }

    #[test]
    fn scramble_is_a_per_dimension_xor() {
        let plain = Sobol::new(16).unwrap();
        let a = Sobol::with_digital_shift(16, 1).unwrap();
        let b = Sobol::with_digital_shift(16, 2).unwrap();
        for d in 0..16 {
            let shift = a.sample_u32(0, d);
            for i in [1u64, 2, 77, 4095] {
                assert_eq!(a.sample_u32(i, d), plain.sample_u32(i, d) ^ shift);
            }
            assert_ne!(a.sample_u32(0, d), b.sample_u32(0, d));
        }
        let shifts: std::collections::BTreeSet<u32> = (0..16).map(|d| a.sample_u32(0, d)).collect();
        assert_eq!(shifts.len(), 16, "distinct shifts per dimension");
    }

    #[test]
    fn fill_equals_repeated_sample_and_checks_sizes() {
        for s in [
            Sobol::new(7).unwrap(),
            Sobol::with_digital_shift(7, 3).unwrap(),
        ] {
            for first in [
                0u64,
                1,
                5,
                1023,
                (1 << 32) - 20,
                (3 << 40) - 7,
                u64::MAX - 40,
            ] {
                for dims in 1..=7u32 {
                    let mut buf = [0.0f32; 7 * 40];
                    let len = 40 * dims as usize;
                    assert_eq!(s.fill(first, dims, &mut buf[..len]), Ok(40));
                    for (k, p) in buf[..len].chunks_exact(dims as usize).enumerate() {
                        for (d, &x) in p.iter().enumerate() {
                            assert_eq!(x, s.sample(first + k as u64, d as u32));
                        }
                    }
                }
            }
            let mut buf = [0.0f32; 8];
            assert_eq!(
                s.fill(u64::MAX - 2, 2, &mut buf),
                Err(Error::TooMany {
                    what: "first",
                    value: u64::MAX - 2,
                    max: u64::MAX - 4
                })
            );
            assert_eq!(
                s.fill(0, 0, &mut buf),
                Err(Error::ZeroSize { what: "dims" })
            );
            assert!(s.fill(0, 8, &mut buf).is_err());
            assert!(s.fill(0, 3, &mut buf).is_err());
            assert!(s.fill(0, 1, &mut []).is_err());
        }
    }

    proptest::proptest! {
        #[test]
        fn values_in_unit_interval(index: u64, dim: u32, seed: u64) {
            for s in [Sobol::new(1024).unwrap(), Sobol::with_digital_shift(1024, seed).unwrap()] {
                let x = s.sample(index, dim);
                proptest::prop_assert!((0.0..1.0).contains(&x));
                let y = s.sample_f64(index, dim);
                proptest::prop_assert!((0.0..1.0).contains(&y));
            }
        }

        #[test]
        fn linear_over_gf2(a: u32, b: u32, dim in 0u32..1024) {
            // The product with a fixed matrix is linear: P(a ^ b) = P(a) ^ P(b).
            proptest::prop_assert_eq!(sobol_u32(a ^ b, dim), sobol_u32(a, dim) ^ sobol_u32(b, dim));
        }

        #[test]
        fn constructors_never_panic(dims: u32, seed: u64) {
            let ok = dims >= 1;
            proptest::prop_assert_eq!(Sobol::new(dims).is_ok(), ok);
            proptest::prop_assert_eq!(Sobol::with_digital_shift(dims, seed).is_ok(), ok);
        }
    }
}
