//! How the pmj02 table's seed sets `pmj02-bn`'s error, and where the shipped table
//! ([`nyquist::sequence::PMJ02_TABLE_SEED`], OpenQMC's) stands among the tables of other seeds.
//!
//! `pmj02-bn` reads the table through a nested uniform shuffle of the index and a digital
//! shift (XOR), so a pixel's first `n` samples are an aligned block of `n` table points with
//! all their digits flipped alike. That keeps the digits the construction drew below each
//! point's strata, and those digits are not averaged away from block to block: a new point
//! copies its leading digits from an older one, so the leading digits of *every* aligned
//! block come from the random digits of the first few hundred points. The table's seed
//! therefore sets its error on a given integrand. (The Owen scramble of `pmj02` redraws those
//! digits per pixel; its error does not depend on the seed.)
//!
//! [`search`] builds the table of every seed of a range, estimates each one's RMSE under
//! `pmj02-bn`'s randomisation on the [`TRAINING`] integrands at 2 … 32 spp (sample counts
//! where the leading digits decide the error), and ranks the seeds by [`score`]. A seed chosen
//! this way fits these integrands: the one that scores best of 0 … 1023 is not better than
//! the shipped table on integrands neither saw (`docs/blue-noise.md`, "The table"), so
//! the shipped table is OpenQMC's, and `cargo run --release -p nyquist-lab --bin pmj02-seed`
//! prints where it ranks. The training integrands are centred: radial ones, the shape of a pixel filter's
//! weight or of a light's lobe across a pixel, and half-planes and half-spaces through the
//! centre, over one pair of dimensions and over both. None of them is one of the integrands the
//! peer comparison measures ([`HELD_OUT`](crate::blue_tile::HELD_OUT)), which [`held_out`]
//! gives with their integrals for a report.

use crate::blue_tile::BlockIntegrand;
use crate::parallel::map_tasks;
use nyquist::hash::mix64;
use nyquist::scramble::nested_uniform_shuffle;
use nyquist::sequence::{PMJ02_MAX_POINTS, pmj02_build};
use std::convert::Infallible;
use std::f64::consts::PI;

/// The seeds `pmj02-seed` ranks: `0 .. SEEDS`.
pub const SEEDS: u32 = 1024;

/// Pixels per spp and table whose error [`rmse`] averages (the same pixels for every table,
/// so the tables are compared on common random numbers).
pub const TRIALS: u32 = 2000;

/// The spp [`rmse`] measures: 2, 4, 8, 16, 32.
pub const COUNTS: [u32; 5] = [2, 4, 8, 16, 32];

/// A training integrand: a function of a pixel sample's four values (two pairs), and its
/// exact integral over `[0, 1)⁴`.
#[derive(Clone, Copy, Debug)]
pub struct Training {
    /// What it is.
    pub name: &'static str,
    /// The integrand.
    pub f: BlockIntegrand,
    /// `∫ f` over the unit 4-cube.
    pub integral: fn() -> f64,
}

/// `exp(−|v − ½|² / (2σ²))` over the values `v`.
fn gaussian(v: &[f32], s: f64) -> f64 {
    let r2: f64 = v.iter().map(|&x| (f64::from(x) - 0.5).powi(2)).sum();
    libm::exp(-r2 / (2.0 * s * s))
}

/// `∫₀¹ exp(−(x − ½)² / (2σ²)) dx`.
fn gaussian_1d(s: f64) -> f64 {
    s * (2.0 * PI).sqrt() * libm::erf(0.5 / (s * 2f64.sqrt()))
}

/// 1 inside the disk of area `a` centred in the square (`a ≤ π/4`, so it fits).
fn disk(x: f32, y: f32, a: f64) -> f64 {
    let (dx, dy) = (f64::from(x) - 0.5, f64::from(y) - 0.5);
    f64::from(u8::from(dx * dx + dy * dy < a / PI))
}

/// 1 below the hyperplane through the centre with normal `n` (integral ½: the cube is
/// symmetric about its centre).
fn half(v: &[f32; 4], n: [f64; 4]) -> f64 {
    let dot: f64 = v
        .iter()
        .zip(n)
        .map(|(&x, n)| (f64::from(x) - 0.5) * n)
        .sum();
    f64::from(u8::from(dot < 0.0))
}

/// The integrands [`search`] scores tables on: centred Gaussians (σ = 0.1, 0.22, 0.3),
/// centred disks (area ¼, ¾) and a half-plane through the centre over the first pair; a
/// centred Gaussian (σ = 0.35) and two half-spaces through the centre over all four values.
pub const TRAINING: [Training; 9] = [
    Training {
        name: "gaussian σ 0.1",
        f: |v| gaussian(&v[..2], 0.1),
        integral: || gaussian_1d(0.1).powi(2),
    },
    Training {
        name: "gaussian σ 0.22",
        f: |v| gaussian(&v[..2], 0.22),
        integral: || gaussian_1d(0.22).powi(2),
    },
    Training {
        name: "gaussian σ 0.3",
        f: |v| gaussian(&v[..2], 0.3),
        integral: || gaussian_1d(0.3).powi(2),
    },
    Training {
        name: "disk area ¼",
        f: |v| disk(v[0], v[1], 0.25),
        integral: || 0.25,
    },
    Training {
        name: "disk area ¾",
        f: |v| disk(v[0], v[1], 0.75),
        integral: || 0.75,
    },
    Training {
        name: "half-plane 0.3 rad",
        f: |v| half(v, [0.3f64.cos(), 0.3f64.sin(), 0.0, 0.0]),
        integral: || 0.5,
    },
    Training {
        name: "4-D gaussian σ 0.35",
        f: |v| gaussian(v, 0.35),
        integral: || gaussian_1d(0.35).powi(4),
    },
    Training {
        name: "4-D half-space a",
        f: |v| half(v, [1.0, -1.0, 0.5, 1.0]),
        integral: || 0.5,
    },
    Training {
        name: "4-D half-space b",
        f: |v| half(v, [0.2, 1.0, -1.0, 0.7]),
        integral: || 0.5,
    },
];

/// [`HELD_OUT`](crate::blue_tile::HELD_OUT) with its exact integrals, for the report of
/// how a seed does on integrands the search did not see.
pub fn held_out() -> Vec<(&'static str, BlockIntegrand, f64)> {
    let g = gaussian_1d(0.15).powi(2);
    let integrals = [0.5, g, 0.5, g, 0.5, gaussian_1d(0.25).powi(4)];
    crate::blue_tile::HELD_OUT
        .iter()
        .zip(integrals)
        .map(|(&(name, f), i)| (name, f, i))
        .collect()
}

/// A whole pmj02 table: [`PMJ02_MAX_POINTS`] points.
pub type Table = [[u32; 2]; PMJ02_MAX_POINTS];

/// The pmj02 table of `seed` ([`pmj02_build`]).
pub fn table(seed: u32) -> Box<Table> {
    let mut t: Box<Table> = vec![[0u32; 2]; PMJ02_MAX_POINTS]
        .into_boxed_slice()
        .try_into()
        .expect("a buffer of the table's length");
    pmj02_build(seed, &mut t[..]).expect("the table's length is the construction's maximum");
    t
}

/// Each integrand's RMSE at each of [`COUNTS`] for `table` under `pmj02-bn`'s
/// randomisation: per pixel, each pair of values is the table point at a nested uniform
/// shuffle of the sample index (within the table's 2¹⁶ points), XOR-ed with a random shift,
/// the two pairs shuffled and shifted independently. `integrands` are functions with their
/// integrals; the result is `[integrand][count]`, from `trials` pixels per count, the same
/// pixels for every table (`trials = 0` measures nothing: NaN). An integrand is any function
/// of the four values: a [`BlockIntegrand`], or a closure with its parameters.
pub fn rmse<F: Fn(&[f32; 4]) -> f64>(
    table: &Table,
    integrands: &[(F, f64)],
    trials: u32,
) -> Vec<[f64; 5]> {
    let mut out = vec![[0f64; 5]; integrands.len()];
    let mut sums = vec![0f64; integrands.len()];
    for (c, &n) in COUNTS.iter().enumerate() {
        let mut se = vec![0f64; integrands.len()];
        for trial in 0..trials {
            let h = mix64((u64::from(n) << 32) | u64::from(trial));
            let g = mix64(h ^ 0x7061_6972); // "pair"
            let shuffles = [h as u32, g as u32];
            let shifts = [
                (h >> 32) as u32,
                mix64(h) as u32,
                (g >> 32) as u32,
                mix64(g) as u32,
            ];
            sums.fill(0.0);
            for i in 0..n {
                let p = shuffles.map(|s| table[(nested_uniform_shuffle(i, s) & 0xffff) as usize]);
                let v = [
                    p[0][0] ^ shifts[0],
                    p[0][1] ^ shifts[1],
                    p[1][0] ^ shifts[2],
                    p[1][1] ^ shifts[3],
                ]
                .map(to_unit);
                for (s, (f, _)) in sums.iter_mut().zip(integrands) {
                    *s += f(&v);
                }
            }
            for ((e, s), (_, integral)) in se.iter_mut().zip(&sums).zip(integrands) {
                *e += (s / f64::from(n) - integral).powi(2);
            }
        }
        for (row, e) in out.iter_mut().zip(&se) {
            row[c] = (e / f64::from(trials)).sqrt();
        }
    }
    out
}

/// [`TRAINING`] as [`rmse`] takes it.
pub fn training() -> Vec<(BlockIntegrand, f64)> {
    TRAINING.iter().map(|t| (t.f, (t.integral)())).collect()
}

/// A 32-bit binary fraction as the samplers return it: its top 24 bits as an `f32` in `[0, 1)`.
fn to_unit(x: u32) -> f32 {
    (x >> 8) as f32 / 16_777_216.0
}

/// A table's score against `reference` (per cell, the RMSE of the mean squared error over
/// the tables searched): `Σ ln(r / ref) + 2 Σ max(0, ln(r / ref))` over every integrand and
/// count. Lower is better; the second sum makes a cell worse than the average table cost
/// three times what an equal gain elsewhere earns, so a table does not buy one integrand's
/// error with another's.
pub fn score(rmse: &[[f64; 5]], reference: &[[f64; 5]]) -> f64 {
    rmse.iter()
        .flatten()
        .zip(reference.iter().flatten())
        .map(|(r, m)| {
            let l = (r / m).ln();
            l + 2.0 * l.max(0.0)
        })
        .sum()
}

/// What [`search`] found.
#[derive(Clone, Debug)]
pub struct Search {
    /// The seed of the lowest score.
    pub best: u32,
    /// Every seed's score, in seed order.
    pub scores: Vec<(u32, f64)>,
    /// Per cell, the RMSE of the mean squared error over the tables.
    pub reference: Vec<[f64; 5]>,
}

impl Search {
    /// Where a table with RMSE `rmse` on the training integrands stands among the searched
    /// ones: its [`score`] against the average table, and how many seeds score lower.
    pub fn standing(&self, rmse: &[[f64; 5]]) -> (f64, usize) {
        let s = score(rmse, &self.reference);
        (s, self.scores.iter().filter(|x| x.1 < s).count())
    }
}

/// Per cell, the root mean square of several tables' RMSE (`[table][integrand][count]`): the
/// RMSE of the average table. Empty for no tables.
pub fn root_mean_square(rmses: &[Vec<[f64; 5]>]) -> Vec<[f64; 5]> {
    let Some(first) = rmses.first() else {
        return Vec::new();
    };
    let mut out = vec![[0f64; 5]; first.len()];
    for r in rmses {
        for (m, v) in out.iter_mut().flatten().zip(r.iter().flatten()) {
            *m += v * v / rmses.len() as f64;
        }
    }
    for m in out.iter_mut().flatten() {
        *m = m.sqrt();
    }
    out
}

/// Scores the tables of `seeds` ([`rmse`] with `trials`, [`score`]) on every core (the lab's
/// work queue, [`map_tasks`]) and keeps the best (the lowest seed on a tie); `None` for an
/// empty range.
pub fn search(seeds: std::ops::Range<u32>, trials: u32) -> Option<Search> {
    let all: Vec<u32> = seeds.collect();
    let integrands = training();
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let order: Vec<usize> = (0..all.len()).collect();
    let measured = map_tasks(&order, threads, |i| {
        Ok::<_, Infallible>(rmse(&table(all[i]), &integrands, trials))
    })
    .unwrap_or_else(|never| match never {});
    let reference = root_mean_square(&measured);
    let scores: Vec<(u32, f64)> = all
        .iter()
        .zip(&measured)
        .map(|(&s, r)| (s, score(r, &reference)))
        .collect();
    let &(best, _) = scores
        .iter()
        .min_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)))?;
    Some(Search {
        best,
        scores,
        reference,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The midpoint rule on an `m`² grid with both pairs at the grid's point (for integrands
    /// of one pair), or on an `m`⁴ grid over all four values.
    fn midpoint(f: BlockIntegrand, m: u32, four: bool) -> f64 {
        let x = |i: u32| ((f64::from(i) + 0.5) / f64::from(m)) as f32;
        let mut s = 0.0;
        let cells = if four { m.pow(4) } else { m * m };
        for i in 0..cells {
            let (a, b) = (x(i % m), x(i / m % m));
            s += if four {
                f(&[a, b, x(i / m / m % m), x(i / m / m / m)])
            } else {
                f(&[a, b, a, b])
            };
        }
        s / f64::from(cells)
    }

    /// The integrals are the exact ones: the midpoint rule agrees, on a 512² grid for the
    /// integrands of one pair, on a 24⁴ grid for those of all four values (to 3·10⁻³: the
    /// half-spaces' boundaries cross the coarse grid).
    #[test]
    fn the_integrals_are_exact() {
        let training = TRAINING.iter().map(|t| (t.name, t.f, (t.integral)()));
        let all: Vec<_> = training.chain(held_out()).collect();
        assert_eq!(all.len(), 15);
        for (name, f, integral) in all {
            let four = name.starts_with("4-D") || name.ends_with("4-D");
            let (got, tolerance) = if four {
                (midpoint(f, 24, true), 3e-3)
            } else {
                (midpoint(f, 512, false), 2e-4)
            };
            assert!(
                (got - integral).abs() < tolerance,
                "{name}: {got} against {integral}"
            );
        }
    }

    /// The shipped table (OpenQMC's) against the tables of seeds 0 … 1023 on the training
    /// integrands: it scores below the average table (a negative score: −2.29, where 236 of
    /// the 1024 seeds score lower) and beats it in 23 of the 45 cells, though it was not
    /// chosen on them.
    #[test]
    fn the_shipped_table_beats_the_average_table() {
        let found = search(0..SEEDS, TRIALS).expect("seeds");
        let shipped = rmse(
            &table(nyquist::sequence::PMJ02_TABLE_SEED),
            &training(),
            TRIALS,
        );
        let better = shipped
            .iter()
            .flatten()
            .zip(found.reference.iter().flatten())
            .filter(|(b, r)| b < r)
            .count();
        let (s, rank) = found.standing(&shipped);
        eprintln!("score {s}, better in {better} of 45 cells, {rank} seeds score lower");
        assert!(s < 0.0 && better > 20, "score {s}, {better} of 45 cells");
        // The best seed's own table stands first, at the score the search gave it.
        let best = rmse(&table(found.best), &training(), TRIALS);
        let (b, lower) = found.standing(&best);
        assert_eq!(lower, 0);
        assert_eq!(
            Some(b),
            found.scores.iter().find(|x| x.0 == found.best).map(|x| x.1)
        );
    }

    /// The RMSE falls with the count (the table's prefixes are nets), and a table whose
    /// points all sit at one corner is scored worse than a real one.
    #[test]
    fn rmse_falls_with_the_count_and_a_degenerate_table_scores_worse() {
        let t = table(3);
        let r = rmse(&t, &training(), 400);
        for row in &r {
            assert!(row[4] < row[0] / 2.0, "{row:?}");
        }
        let mut corner = table(3);
        corner.fill([0, 0]);
        let bad = rmse(&corner, &training(), 400);
        assert!(search(5..5, 10).is_none());
        assert!(root_mean_square(&[]).is_empty());
        let rms = root_mean_square(&[vec![[3.0; 5]], vec![[4.0; 5]]]);
        assert!((rms[0][2] - 12.5f64.sqrt()).abs() < 1e-12);
        assert!(rmse(&t, &training(), 0)[0][0].is_nan());
        assert!(score(&bad, &r) > 5.0);
        assert_eq!(score(&r, &r), 0.0);
    }
}
