//! Checks every sampler must pass: ConsistentValues (pbrt-v4), thread independence, range.

use super::*;
use std::vec::Vec;

/// Values recorded for one pixel sample: camera sample, a few 1D/2D values and two arrays.
pub(crate) fn record<S: Sampler + ?Sized>(s: &mut S, pixel: [u32; 2], index: u32) -> Vec<f32> {
    let c = camera_sample(s, pixel, index);
    let mut v = std::vec![
        c.p_film[0] - pixel[0] as f32,
        c.p_film[1] - pixel[1] as f32,
        c.time,
        c.lens[0],
        c.lens[1],
    ];
    for _ in 0..3 {
        v.push(s.get_1d());
        v.extend_from_slice(&s.get_2d());
    }
    let mut a1 = [0.0f32; 5];
    s.get_array_1d(&mut a1);
    v.extend_from_slice(&a1);
    let mut a2 = [0.0f32; 8];
    s.get_array_2d(&mut a2);
    v.extend_from_slice(&a2);
    v.push(s.get_1d());
    v
}

/// A camera sample's bits, with the next `get_1d` (where the cursor was left).
fn camera_bits<S: Sampler + ?Sized>(s: &mut S, c: CameraSample) -> Vec<u32> {
    bits(&[
        c.p_film[0],
        c.p_film[1],
        c.time,
        c.lens[0],
        c.lens[1],
        s.get_1d(),
    ])
}

fn bits(v: &[f32]) -> Vec<u32> {
    v.iter().map(|x| x.to_bits()).collect()
}

const PIXELS: [[u32; 2]; 6] = [[0, 0], [1, 0], [0, 1], [5, 3], [17, 11], [2, 9]];

/// pbrt-v4's ConsistentValues: record, visit other pixels, replay in another order; also checks
/// every value lies in `[0, 1)`.
pub(crate) fn consistent_values<S: Sampler + Clone>(sampler: &S) {
    let mut s = sampler.clone();
    let spp = s.samples_per_pixel().min(16);
    let mut first = Vec::new();
    for &p in &PIXELS {
        for i in 0..spp {
            // An override of `camera_sample` returns the default's values and cursor.
            let c = s.camera_sample(p, i);
            let fused = camera_bits(&mut s, c);
            let c = camera_sample_by_parts(&mut s, p, i);
            assert_eq!(fused, camera_bits(&mut s, c), "pixel {p:?} sample {i}");
            let v = record(&mut s, p, i);
            for (k, &x) in v.iter().enumerate() {
                assert!(
                    (0.0..1.0).contains(&x),
                    "pixel {p:?} sample {i} value {k}: {x}"
                );
            }
            first.push(bits(&v));
        }
    }
    // Replay in reverse, interleaving visits to unrelated pixels, on a fresh clone.
    let mut t = sampler.clone();
    let mut k = first.len();
    for &p in PIXELS.iter().rev() {
        for i in (0..spp).rev() {
            record(&mut t, [p[0] + 100, p[1] + 7], i);
            k -= 1;
            assert_eq!(
                bits(&record(&mut t, p, i)),
                first[k],
                "pixel {p:?} sample {i}"
            );
        }
    }
    // Starting mid-way (at dimension 5) gives the values recorded after the camera sample.
    let mut u = sampler.clone();
    u.start_pixel_sample(PIXELS[3], 0, 5);
    let x = u.get_1d();
    assert_eq!(x.to_bits(), first[3 * spp as usize][5], "start at dim 5");
}

/// Same values from one thread and from four.
pub(crate) fn threads_agree<S: Sampler + Clone + Send + Sync>(sampler: &S) {
    let spp = sampler.samples_per_pixel().min(8);
    let pixels: Vec<[u32; 2]> = (0..8).flat_map(|y| (0..8).map(move |x| [x, y])).collect();
    let mut one = sampler.clone();
    let serial: Vec<Vec<u32>> = pixels
        .iter()
        .flat_map(|&p| (0..spp).map(move |i| (p, i)))
        .map(|(p, i)| bits(&record(&mut one, p, i)))
        .collect();
    let per = pixels.len() / 4;
    let mut parallel: Vec<Vec<Vec<u32>>> = Vec::new();
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..4)
            .rev()
            .map(|t| {
                let chunk = &pixels[t * per..(t + 1) * per];
                let mut s = sampler.clone();
                scope.spawn(move || {
                    let mut out = Vec::new();
                    for &p in chunk {
                        for i in 0..spp {
                            out.push(bits(&record(&mut s, p, i)));
                        }
                    }
                    out
                })
            })
            .collect();
        for h in handles {
            parallel.push(h.join().unwrap());
        }
    });
    parallel.reverse();
    let parallel: Vec<Vec<u32>> = parallel.into_iter().flatten().collect();
    assert_eq!(serial, parallel);
}

/// Fraction of the `n × n` image-sample strata of a pixel hit by its first `n²` samples.
pub(crate) fn image_strata_hit<S: Sampler>(s: &mut S, pixel: [u32; 2], n: u32) -> usize {
    let mut seen = std::vec![false; (n * n) as usize];
    for i in 0..n * n {
        s.start_pixel_sample(pixel, i, 0);
        let [x, y] = s.get_pixel_2d();
        seen[((y * n as f32) as u32 * n + (x * n as f32) as u32) as usize] = true;
    }
    seen.iter().filter(|&&b| b).count()
}

/// Whether `points` (pairs in `[0,1)²`, a power-of-two count `n = 2^m`) has exactly one point
/// in every elementary interval of area `1/n`: `2^a × 2^(m−a)` grids for every `a`.
pub(crate) fn is_zero_two_net(points: &[[f32; 2]]) -> bool {
    let n = points.len();
    assert!(n.is_power_of_two());
    let m = n.trailing_zeros();
    (0..=m).all(|a| {
        let (nx, ny) = (1u64 << a, 1u64 << (m - a));
        let mut seen = std::vec![false; n];
        points.iter().all(|&[x, y]| {
            let cx = (f64::from(x) * nx as f64) as u64;
            let cy = (f64::from(y) * ny as f64) as u64;
            !core::mem::replace(&mut seen[(cy * nx + cx) as usize], true)
        })
    })
}

/// Whether each of `n` strata of every axis of the 1D array / 2D array holds one value.
pub(crate) fn is_latin(values: &[f32], dims: usize) -> bool {
    let n = values.len() / dims;
    (0..dims).all(|d| {
        let mut seen = std::vec![false; n];
        values
            .chunks_exact(dims)
            .all(|p| !core::mem::replace(&mut seen[(p[d] * n as f32) as usize], true))
    })
}

#[test]
fn random_is_consistent_and_thread_independent() {
    let s = RandomSampler::new(8, 3).unwrap();
    consistent_values(&s);
    threads_agree(&s);
}

#[test]
fn random_depends_on_pixel_index_and_seed() {
    let mut a = RandomSampler::new(8, 3).unwrap();
    let mut b = RandomSampler::new(8, 4).unwrap();
    let r = record(&mut a, [1, 1], 0);
    assert_ne!(r, record(&mut a, [1, 2], 0));
    assert_ne!(r, record(&mut a, [1, 1], 1));
    assert_ne!(r, record(&mut b, [1, 1], 0));
}

#[test]
fn stratified_and_uniform_are_consistent_and_thread_independent() {
    for jitter in [Jitter::Jittered, Jitter::Centered] {
        let s = StratifiedSampler::new(4, 3, jitter, 5).unwrap();
        consistent_values(&s);
        threads_agree(&s);
    }
}

#[test]
fn stratified_one_image_sample_per_stratum_per_pixel() {
    for n in [1u32, 2, 3, 4, 7, 16] {
        let mut s = StratifiedSampler::new(n, n, Jitter::Jittered, 11).unwrap();
        for &p in &PIXELS {
            assert_eq!(
                image_strata_hit(&mut s, p, n),
                (n * n) as usize,
                "n={n} {p:?}"
            );
        }
    }
}

#[test]
fn stratified_1d_and_2d_dimensions_are_stratified_and_shuffled() {
    let mut s = StratifiedSampler::new(4, 4, Jitter::Jittered, 2).unwrap();
    let mut time = Vec::new();
    let mut lens = Vec::new();
    let mut image = Vec::new();
    for i in 0..16 {
        let c = camera_sample(&mut s, [3, 4], i);
        time.push(c.time);
        lens.extend_from_slice(&c.lens);
        image.push(c.p_film);
    }
    assert!(is_latin(&time, 1));
    let mut seen = [false; 16];
    for l in lens.chunks_exact(2) {
        seen[(l[1] * 4.0) as usize * 4 + (l[0] * 4.0) as usize] = true;
    }
    assert!(seen.iter().all(|&b| b));
    // Shuffled: the time stratum is not a function of the image stratum's order.
    let order: Vec<usize> = time.iter().map(|t| (t * 16.0) as usize).collect();
    assert_ne!(order, (0..16).collect::<Vec<_>>());
}

#[test]
fn stratified_arrays_are_latin_hypercubes_of_any_size() {
    let mut s = StratifiedSampler::new(2, 2, Jitter::Jittered, 1).unwrap();
    for n in [1usize, 2, 5, 7, 16, 33] {
        s.start_pixel_sample([9, 9], 1, 5);
        let mut a1 = std::vec![0.0f32; n];
        s.get_array_1d(&mut a1);
        assert!(is_latin(&a1, 1), "1D n={n}");
        let mut a2 = std::vec![0.0f32; 2 * n];
        s.get_array_2d(&mut a2);
        assert!(is_latin(&a2, 2), "2D n={n}");
    }
}

/// The strata orders of 4-point arrays, over many samples: every one of the 4! orders appears
/// on each axis, about equally often, and the two axes are drawn independently (nearly all of
/// the 24² joint orders appear).
#[test]
fn stratified_array_orders_are_uniform_and_independent_per_axis() {
    let mut s = StratifiedSampler::new(4, 4, Jitter::Jittered, 3).unwrap();
    let order = |a: &[f32], axis: usize| -> u32 {
        (0..4).fold(0, |acc, j| acc * 4 + (a[2 * j + axis] * 4.0) as u32)
    };
    let mut x_count = std::collections::BTreeMap::new();
    let mut joint = std::collections::BTreeSet::new();
    let mut draws = 0;
    for y in 0..24u32 {
        for x in 0..24u32 {
            for i in 0..16 {
                s.start_pixel_sample([x, y], i, 5);
                let mut a = [0.0f32; 8];
                s.get_array_2d(&mut a);
                *x_count.entry(order(&a, 0)).or_insert(0u32) += 1;
                joint.insert((order(&a, 0), order(&a, 1)));
                draws += 1;
            }
        }
    }
    assert_eq!(x_count.len(), 24);
    let expected = draws as f64 / 24.0;
    for (&o, &c) in &x_count {
        assert!(
            (f64::from(c) - expected).abs() < 0.2 * expected,
            "order {o}: {c} of {draws}"
        );
    }
    assert!(joint.len() >= 570, "{} joint orders of 576", joint.len());
}

#[test]
fn uniform_is_cell_centres() {
    let mut s = StratifiedSampler::uniform(4, 2, 0).unwrap();
    for i in 0..8 {
        s.start_pixel_sample([0, 0], i, 0);
        let [x, y] = s.get_pixel_2d();
        assert_eq!((x * 4.0).fract(), 0.5);
        assert_eq!((y * 2.0).fract(), 0.5);
    }
}

#[test]
fn sampler_is_object_safe() {
    let mut r = RandomSampler::new(4, 0).unwrap();
    let mut st = StratifiedSampler::new(2, 2, Jitter::Jittered, 0).unwrap();
    let all: [&mut dyn Sampler; 2] = [&mut r, &mut st];
    for s in all {
        let c = camera_sample(s, [1, 2], 0);
        assert!(c.p_film[0] >= 1.0 && c.p_film[0] < 2.0);
    }
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    fn all_in_unit<S: Sampler>(s: &mut S, pixel: [u32; 2], index: u32, dim: u32) -> bool {
        s.start_pixel_sample(pixel, index, dim);
        let mut v = std::vec![s.get_1d()];
        v.extend_from_slice(&s.get_2d());
        v.extend_from_slice(&s.get_pixel_2d());
        let mut a = [0.0f32; 6];
        s.get_array_2d(&mut a);
        v.extend_from_slice(&a);
        s.get_array_1d(&mut a[..3]);
        v.extend_from_slice(&a[..3]);
        v.iter().all(|x| (0.0..1.0).contains(x))
    }

    proptest! {
        #[test]
        fn every_value_is_in_unit_interval(
            px in any::<u32>(), py in any::<u32>(), index in any::<u32>(),
            dim in any::<u32>(), seed in any::<u64>(), spp in 1u32..300,
        ) {
            let p = [px, py];
            prop_assert!(all_in_unit(&mut RandomSampler::new(spp, seed).unwrap(), p, index, dim));
            let side = spp.isqrt().max(1);
            for j in [Jitter::Jittered, Jitter::Centered] {
                let mut s = StratifiedSampler::new(side, spp / side, j, seed).unwrap();
                prop_assert!(all_in_unit(&mut s, p, index, dim));
            }
            prop_assert!(all_in_unit(&mut BestCandidateSampler::new(spp, seed).unwrap(), p, index, dim));
        }

        #[test]
        fn camera_sample_stays_in_its_pixel(
            px in any::<u32>(), py in any::<u32>(), index in any::<u32>(), seed in any::<u64>(),
        ) {
            let c = camera_sample(&mut RandomSampler::new(4, seed).unwrap(), [px, py], index);
            prop_assert!(c.p_film[0] >= px as f32 && c.p_film[1] >= py as f32);
            prop_assert!(c.p_film[0] < px as f32 + 1.0 || c.p_film[0] == px as f32);
        }
    }
}

/// For samplers whose arrays take one dimension per value (the global samplers): an array
/// override gives, bit for bit, the values `get_1d` / `get_2d` give one at a time, from any
/// starting dimension (including the wrap at 1024 into the pixel dimensions 0 and 1), and
/// leaves the cursor where they do. An odd last value of a 2D array is left untouched.
pub(crate) fn arrays_are_values_in_order<S: Sampler + Clone>(s0: &S) {
    /// A 1D or 2D array: the override, and the same values taken one call at a time.
    type Fill<S> = fn(&mut S, &mut [f32]);
    let cases: [(&str, Fill<S>, Fill<S>); 2] = [
        (
            "1d",
            |s, a| s.get_array_1d(a),
            |s, a| {
                for x in a {
                    *x = s.get_1d();
                }
            },
        ),
        (
            "2d",
            |s, a| s.get_array_2d(a),
            |s, a| {
                for p in a.chunks_exact_mut(2) {
                    p.copy_from_slice(&s.get_2d());
                }
            },
        ),
    ];
    let mut s = s0.clone();
    for (pixel, index) in [([3u32, 7u32], 5u32), ([639, 479], 15), ([0, 0], 0)] {
        for start in [0u32, 2, 5, 30, 60, 1017, 1021, 1023, u32::MAX - 2] {
            for len in [0usize, 1, 3, 8, 9, 40] {
                for (what, array, one_at_a_time) in cases {
                    let mut batch = std::vec![-1.0f32; len];
                    s.start_pixel_sample(pixel, index, start);
                    array(&mut s, &mut batch);
                    let after = s.get_1d();
                    let mut one = std::vec![-1.0f32; len];
                    s.start_pixel_sample(pixel, index, start);
                    one_at_a_time(&mut s, &mut one);
                    assert_eq!(batch, one, "{what} {pixel:?} {start} {len}");
                    assert_eq!(after.to_bits(), s.get_1d().to_bits(), "{what} cursor");
                }
            }
        }
    }
}

/// `p_film` stays in its pixel and keeps the sample where its offset put it: the nearest `f32`
/// to `pixel + offset`, except where that rounds onto the next pixel's edge, which gives the
/// largest `f32` below the edge (so a sample at the far end of a pixel is not moved to its
/// near corner). Checked at every pixel below 2¹⁰, at powers of two and beside them up to
/// 2²⁴, for offsets near 0, ½ and 1.
#[test]
fn film_coordinates_stay_in_the_pixel_at_the_offset() {
    let last = 1.0 - f32::EPSILON / 2.0;
    let offsets = [
        0.0,
        1e-7,
        0.25,
        0.5,
        0.75,
        1.0 - 1e-6,
        last.next_down(),
        last,
    ];
    let mut pixels: Vec<u32> = (0..1024).collect();
    for k in 10..=24 {
        pixels.extend([(1 << k) - 1, 1 << k, (1 << k) + 1]);
    }
    for &p in &pixels {
        for &o in &offsets {
            let y = film_coordinate(p, o);
            let (lo, hi) = (f64::from(p), f64::from(p) + 1.0);
            if p < 1 << 24 {
                assert!(
                    lo <= f64::from(y) && f64::from(y) < hi,
                    "pixel {p}, offset {o}: {y}"
                );
                // Within one f32 step of the exact sum (half a step when no edge was hit).
                let step = f64::from((p as f32 + 1.0).next_up() - (p as f32 + 1.0));
                assert!(
                    (f64::from(y) - (lo + f64::from(o))).abs() <= step,
                    "{p} {o}: {y}"
                );
            } else {
                assert_eq!(y, p as f32, "pixel {p} has no f32 inside it but its own");
            }
        }
    }
    // The case that moved a sample across its pixel: 105 + (1 − 2⁻²⁴) rounds to 106.
    assert_eq!(film_coordinate(105, last), 106.0f32.next_down());
}

/// Through a sampler, the case that found it: a Halton sampler with permuted digits (1024²
/// image, 16 spp, seed 1) draws the offset 1 − 2⁻²⁴ for pixel (105, 51)'s sample 0, whose
/// film coordinate rounded to 106 and was moved to 105.0, the wrong end of the pixel.
#[test]
fn a_far_end_offset_stays_at_the_far_end_of_its_pixel() {
    let mut s =
        HaltonSampler::new([1024; 2], 16, crate::scramble::Scramble::PermuteDigits, 1).unwrap();
    s.start_pixel_sample([105, 51], 0, 0);
    let offset = s.get_pixel_2d();
    let c = s.camera_sample([105, 51], 0);
    assert_eq!(c.p_film[0], film_coordinate(105, offset[0]));
    assert!(c.p_film[0] > 105.99, "{c:?} from offset {offset:?}");
}

/// The progressive contract past the spp hint: sample indices up to `2^20` of `pixel` give
/// pairwise distinct first four dimensions (the image sample and the next pair), so no sample
/// repeats an earlier one. Returns the number of samples checked.
pub(crate) fn progressive_samples_are_distinct<S: Sampler>(s: &mut S, pixel: [u32; 2]) -> usize {
    let n = 1u32 << 20;
    let mut seen: Vec<[u32; 4]> = (0..n)
        .map(|i| {
            s.start_pixel_sample(pixel, i, 0);
            let [a, b] = s.get_pixel_2d();
            let [c, d] = s.get_2d();
            [a, b, c, d].map(f32::to_bits)
        })
        .collect();
    seen.sort_unstable();
    let before = seen.len();
    seen.dedup();
    assert_eq!(seen.len(), before, "a sample repeats an earlier one");
    before
}

/// The image samples (and, given `pair`, the 2D request at dimensions `pair`, `pair + 1`) of
/// `pixel`'s first `2^k` samples are (0, k, 2)-nets for every `k ≤ max_k`, whatever the spp
/// hint.
pub(crate) fn progressive_nets<S: Sampler>(
    s: &mut S,
    pixel: [u32; 2],
    pair: Option<u32>,
    max_k: u32,
) {
    let (mut image, mut request) = (Vec::new(), Vec::new());
    for i in 0..1u32 << max_k {
        s.start_pixel_sample(pixel, i, 0);
        image.push(s.get_pixel_2d());
        if let Some(d) = pair {
            s.start_pixel_sample(pixel, i, d);
            request.push(s.get_2d());
        }
        if (i + 1).is_power_of_two() {
            assert!(is_zero_two_net(&image), "image samples, {} samples", i + 1);
            assert!(
                pair.is_none() || is_zero_two_net(&request),
                "dimensions {pair:?}, {} samples",
                i + 1
            );
        }
    }
}

/// The padding dimensions (from 1024 on) of a sampler at `pixel`: each block's first pair a
/// (0, k, 2)-net over the pixel's first `2^k ≤ n` samples, not the values 1024 dimensions
/// below, different in `other` pixel, and the same in `same` pixel (one the sampler wraps onto
/// `pixel`, or `pixel` itself).
pub(crate) fn padding_holds<S: Sampler>(
    s: &mut S,
    pixel: [u32; 2],
    other: [u32; 2],
    same: [u32; 2],
    n: u32,
) {
    let mut pair = |p: [u32; 2], d: u32| -> Vec<[f32; 2]> {
        (0..n)
            .map(|i| {
                s.start_pixel_sample(p, i, d);
                s.get_2d()
            })
            .collect()
    };
    for d in [1024u32, 5000, 1 << 30] {
        let a = pair(pixel, d);
        for k in 0..=n.trailing_zeros() {
            assert!(
                is_zero_two_net(&a[..1 << k]),
                "dimension {d}, {} samples",
                1 << k
            );
        }
        assert_ne!(pair(pixel, d - 1024), a, "dimension {d}");
        assert_ne!(pair(other, d), a, "dimension {d}");
        assert_eq!(pair(same, d), a, "dimension {d}");
    }
}
