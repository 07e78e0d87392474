//! Screen-space blue noise, measured: for each sampler, error images of `size × size` pixels
//! (each pixel's estimate of an integrand from its own samples, minus the integral) at 1 … 32
//! spp, on 2-D integrands of the first pair of dimensions, the second pair and the first pair of
//! the next 4-D block (OpenQMC: the next domain), and on 4-D integrands of the first block.
//!
//! Two numbers per image: the per-pixel RMSE, and the low-frequency ratio (the mean
//! periodogram power below a quarter of the Nyquist radius over the mean power at every
//! non-zero frequency: 1 for white error, lower for blue).
//!
//! Two more tables compare each nyquist blue-noise sampler with OpenQMC's counterpart:
//! - the RMSE ratio and how many standard errors apart the two are. Every pixel integrates the
//!   same function, so an RMSE is a mean over the keys the image holds, and it varies with the
//!   draw of those keys. The standard error of a mean square is the standard deviation of the
//!   squared errors over the √ of the distinct pixels: one period of the sampler's tile
//!   (nyquist 128², OpenQMC 256²), every pixel for per-pixel seeds. The RMSE's is half of that
//!   over the RMSE (the delta method);
//! - the low-frequency ratio's ratio with its `z` (the ratio's standard error from the
//!   periodogram, `ErrorSpectrum::low_frequency_ratio_se`), and the low-frequency power's: the
//!   square of the error an ideal low-pass filter at a quarter of the Nyquist radius leaves
//!   (`ErrorSpectrum::low_frequency_rmse`), which the ratio alone does not say (a sampler with
//!   less error can have a higher ratio and less left).
//!
//! Each table ends with a verdict per sampler: its largest `z` above OpenQMC and how often
//! chance gives one as large over the cells compared (the one-sided normal tail times the
//! number of cells, Bonferroni's bound); a cell is significantly above OpenQMC's when that is
//! below 5 %, so a sampler that is no worse than OpenQMC's is called worse at most one time in
//! 20 per table.
//!
//! With OpenQMC built, the last tables measure the PMJ(0,2) tables: on these integrands, on
//! the seed search's, and on random families of disks and Gaussians (`print_pmj_tables`,
//! `print_random_families`).
//!
//! `cargo run --release --manifest-path peers/Cargo.toml -- --blue-noise [--size N]
//! [--frame F] [--images DIR] [--pmj-tables N]`

use nyquist::sampler::{
    LatticeBlueSampler, OwenSobolBlueSampler, OwenSobolSampler, Pmj02BlueSampler, Pmj02Sampler,
    RandomSampler, Sampler,
};
use nyquist_lab::blue_tile::{BlockIntegrand, HELD_OUT};
use nyquist_lab::error_spectrum::error_spectrum;

/// Four values per (pixel, sample), pixel-major, for block `block` (dimensions `4b .. 4b+4`).
type Draw = Box<dyn Fn(u32, u32, u32, u32) -> Vec<f32>>;

/// A sampler's values through the nyquist `Sampler` interface.
fn nyquist_draw<S: Sampler + Clone + 'static>(s: S) -> Draw {
    Box::new(move |size, spp, frame, block| {
        let _ = frame;
        let mut s = s.clone();
        let mut out = Vec::with_capacity((size * size * spp * 4) as usize);
        for y in 0..size {
            for x in 0..size {
                for i in 0..spp {
                    s.start_pixel_sample([x, y], i, 4 * block);
                    for _ in 0..4 {
                        out.push(s.get_1d());
                    }
                }
            }
        }
        out
    })
}

#[cfg(peer_openqmc)]
fn openqmc_draw(kind: i32) -> Draw {
    Box::new(move |size, spp, frame, block| crate::openqmc::bn_draw(kind, size, frame, spp, block))
}

/// A sampler compared: its name, its draws, and the period of its tile in pixels (`u32::MAX`
/// for one seed per pixel): the pixels of one period hold distinct keys.
type Source = (&'static str, Draw, u32);

/// The side of OpenQMC's blue-noise tables (`include/oqmc/bntables.h`: 2⁸ × 2⁸ pixels).
#[cfg(peer_openqmc)]
const OPENQMC_TILE: u32 = 256;

/// The samplers compared, by name.
fn sources(frame: u32) -> Vec<Source> {
    use nyquist::sampler::screen_blue::TILE_SIZE;
    const PER_PIXEL: u32 = u32::MAX;
    #[cfg_attr(not(peer_openqmc), allow(unused_mut))]
    let mut v: Vec<Source> = vec![
        (
            "nyquist owen-sobol-bn",
            nyquist_draw(OwenSobolBlueSampler::new(1, 0).unwrap().with_frame(frame)),
            TILE_SIZE,
        ),
        (
            "nyquist owen-sobol",
            nyquist_draw(OwenSobolSampler::new(1, 0).unwrap().with_frame(frame)),
            PER_PIXEL,
        ),
        (
            "nyquist pmj02-bn",
            nyquist_draw(Pmj02BlueSampler::new(1, 0).unwrap().with_frame(frame)),
            TILE_SIZE,
        ),
        (
            "nyquist pmj02",
            nyquist_draw(Pmj02Sampler::new(1, frame.into()).unwrap()),
            PER_PIXEL,
        ),
        (
            "nyquist lattice-bn",
            nyquist_draw(LatticeBlueSampler::new(1, 0).unwrap().with_frame(frame)),
            TILE_SIZE,
        ),
        (
            "white (random)",
            nyquist_draw(RandomSampler::new(1, 0).unwrap()),
            PER_PIXEL,
        ),
    ];
    #[cfg(peer_openqmc)]
    {
        v.push(("OpenQMC sobolbn", openqmc_draw(0), OPENQMC_TILE));
        v.push(("OpenQMC pmjbn", openqmc_draw(1), OPENQMC_TILE));
        v.push(("OpenQMC latticebn", openqmc_draw(2), OPENQMC_TILE));
        v.push(("OpenQMC sobol", openqmc_draw(3), PER_PIXEL));
        v.push(("OpenQMC pmj", openqmc_draw(4), PER_PIXEL));
        v.push(("OpenQMC lattice", openqmc_draw(5), PER_PIXEL));
    }
    #[cfg(not(peer_openqmc))]
    eprintln!("OpenQMC: not built (set NYQUIST_OPENQMC; README.md)");
    v
}

/// A test integrand over the four values of a block.
#[derive(Clone, Copy)]
struct Integrand {
    name: &'static str,
    block: u32,
    f: BlockIntegrand,
}

/// The lab's held-out integrands ([`HELD_OUT`]: a disk and a Gaussian on dimensions 0–1 and
/// 2–3, a Heaviside and a Gaussian in 4-D) on the first block, and the disk on the next block.
fn integrands() -> Vec<Integrand> {
    let mut v: Vec<Integrand> = HELD_OUT
        .iter()
        .map(|&(name, f)| Integrand { name, block: 0, f })
        .collect();
    v.insert(
        4,
        Integrand {
            name: "disk 0-1, next block",
            block: 1,
            f: HELD_OUT[0].1,
        },
    );
    v
}

/// The integral of `f`, from 2²⁰ Owen-scrambled Sobol points of four dimensions.
fn reference(f: BlockIntegrand) -> f64 {
    let mut s = OwenSobolSampler::new(1, 12345).unwrap();
    let n = 1u32 << 20;
    let mut sum = 0.0;
    for i in 0..n {
        s.start_pixel_sample([0, 0], i, 0);
        let v = [s.get_1d(), s.get_1d(), s.get_1d(), s.get_1d()];
        sum += f(&v);
    }
    sum / f64::from(n)
}

/// The low-frequency ratio, its standard error and the low-frequency RMSE of a square error
/// image (module docs; [`ErrorSpectrum`](nyquist_lab::error_spectrum::ErrorSpectrum)).
fn low_frequency(image: &[f64], size: u32) -> (f64, f64, f64) {
    error_spectrum(image, size, size).map_or((f64::NAN, f64::NAN, f64::NAN), |s| {
        (
            s.low_frequency_ratio,
            s.low_frequency_ratio_se,
            s.low_frequency_rmse,
        )
    })
}

/// `∫ₐᵇ f` by Simpson's rule on 4096 intervals (for the smooth integrands here its error is far
/// below the figures printed).
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let n = 4096;
    let h = (b - a) / f64::from(n);
    let inner: f64 = (1..n)
        .map(|i| (if i % 2 == 1 { 4.0 } else { 2.0 }) * f(a + f64::from(i) * h))
        .sum();
    (f(a) + inner + f(b)) * h / 3.0
}

/// The probability that a standard normal variable exceeds `z` (Simpson's rule on the
/// density from `|z|` to `|z| + 12`; the tail past that is below 10⁻³³).
fn normal_tail(z: f64) -> f64 {
    if z < 0.0 {
        return 1.0 - normal_tail(-z);
    }
    simpson(
        |x| (-x * x / 2.0).exp() / std::f64::consts::TAU.sqrt(),
        z,
        z + 12.0,
    )
}

/// The difference of two estimates in standard errors of the difference; 0 where they are
/// the same (two standard errors of 0 would divide 0 by 0).
fn z_score(a: f64, se_a: f64, b: f64, se_b: f64) -> f64 {
    let d = a - b;
    if d == 0.0 { 0.0 } else { d / se_a.hypot(se_b) }
}

/// The standard error of an image's RMSE (module docs): from the squared errors of the pixels
/// of one `period × period` window (the whole image if the period is larger).
fn rmse_standard_error(err: &[f64], size: u32, period: u32, rmse: f64) -> f64 {
    let p = period.min(size) as usize;
    let squares: Vec<f64> = (0..p)
        .flat_map(|y| (0..p).map(move |x| y * size as usize + x))
        .map(|i| err[i] * err[i])
        .collect();
    let n = squares.len() as f64;
    let mean = squares.iter().sum::<f64>() / n;
    let var = squares.iter().map(|q| (q - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (var / n).sqrt() / (2.0 * rmse)
}

/// The sample counts measured.
const SPPS: [u32; 6] = [1, 2, 4, 8, 16, 32];

/// One image's figures: RMSE, its standard error, the low-frequency ratio and its, and the
/// low-frequency RMSE (what an ideal low-pass filter at a quarter of the Nyquist radius leaves
/// of the error).
#[derive(Clone, Copy, Default)]
struct Cell {
    rmse: f64,
    se: f64,
    ratio: f64,
    ratio_se: f64,
    low_rmse: f64,
}

impl Cell {
    /// The power a low-pass filter (a denoiser, the eye) leaves of the error: the square of the
    /// low-frequency RMSE, which is the ratio times the error's variance times the band's share
    /// of the frequencies. The ratio says only how the error is spread.
    fn low_frequency_power(&self) -> f64 {
        self.low_rmse * self.low_rmse
    }
}

/// Runs the study and prints its tables.
pub fn run(size: u32, frame: u32, images: Option<&std::path::Path>, pmj_tables: u32) {
    let integrands = integrands();
    let exact: Vec<f64> = integrands.iter().map(|g| reference(g.f)).collect();
    let sources = sources(frame);
    // results[source][integrand][spp]
    let mut results = vec![vec![[Cell::default(); SPPS.len()]; integrands.len()]; sources.len()];
    for (si, (name, draw, period)) in sources.iter().enumerate() {
        eprintln!("blue noise: {name}");
        for (k, &spp) in SPPS.iter().enumerate() {
            for block in [0, 1] {
                let values = draw(size, spp, frame, block);
                for (ii, g) in integrands.iter().enumerate() {
                    if g.block != block {
                        continue;
                    }
                    let err: Vec<f64> = values
                        .chunks(4 * spp as usize)
                        .map(|px| {
                            px.chunks_exact(4)
                                .map(|v| (g.f)(&[v[0], v[1], v[2], v[3]]))
                                .sum::<f64>()
                                / f64::from(spp)
                                - exact[ii]
                        })
                        .collect();
                    let rmse = (err.iter().map(|e| e * e).sum::<f64>() / err.len() as f64).sqrt();
                    let (ratio, ratio_se, low_rmse) = low_frequency(&err, size);
                    results[si][ii][k] = Cell {
                        rmse,
                        se: rmse_standard_error(&err, size, *period, rmse),
                        ratio,
                        ratio_se,
                        low_rmse,
                    };
                    if let Some(dir) = images
                        && spp == 4
                        && ii == 1
                    {
                        write_error_image(dir, name, &err, size);
                    }
                }
            }
        }
    }
    println!(
        "Screen-space error, {size} × {size} pixels, frame {frame}: per-pixel RMSE and \
         low-frequency ratio (1 = white) at 1, 2, 4, 8, 16, 32 spp.\n"
    );
    let header = SPPS.map(|s| format!("{s} spp")).join(" | ");
    for (ii, g) in integrands.iter().enumerate() {
        println!("### {}\n", g.name);
        println!("| sampler | {header} |");
        println!("|---|{}", "---:|".repeat(SPPS.len()));
        for (si, (name, _, _)) in sources.iter().enumerate() {
            let cells: Vec<String> = results[si][ii]
                .iter()
                .map(|c| format!("{:.4} / {:.2}", c.rmse, c.ratio))
                .collect();
            println!("| {name} | {} |", cells.join(" | "));
        }
        println!();
    }
    print_against_openqmc(&sources, &integrands, &results, &header);
    #[cfg(peer_openqmc)]
    print_pmj_tables(pmj_tables);
    #[cfg(not(peer_openqmc))]
    let _ = pmj_tables;
}

/// `pmj02-bn`'s error is its table's (`docs/blue-noise.md`, "The table"), and so is
/// OpenQMC's `pmjbn`'s. This measures OpenQMC's table under `pmj02-bn`'s randomisation
/// beside the tables of seeds `0 .. tables` of the same construction
/// (`nyquist_lab::pmj02_seed::rmse`, the same pixels for every table), on the integrands of
/// the tables above: per cell, the shipped table's RMSE, OpenQMC's, and how many
/// of the seeds' tables are at or below OpenQMC's.
#[cfg(peer_openqmc)]
fn print_pmj_tables(tables: u32) {
    use nyquist::sequence::PMJ02_TABLE_SEED;
    use nyquist_lab::pmj02_seed::{COUNTS, TRIALS, held_out, rmse, search, table, training};
    use std::convert::Infallible;
    let integrands: Vec<(&str, BlockIntegrand, f64)> = held_out()
        .into_iter()
        .filter(|(name, _, _)| !name.contains("2-3"))
        .collect();
    let fs: Vec<(BlockIntegrand, f64)> = integrands.iter().map(|&(_, f, i)| (f, i)).collect();
    let mut theirs = table(0);
    theirs.copy_from_slice(&crate::openqmc::PmjTable::new().first_pair());
    let openqmc = rmse(&theirs, &fs, TRIALS);
    let seeds: Vec<usize> = (0..tables as usize).collect();
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let all = nyquist_lab::parallel::map_tasks(&seeds, threads, |s| {
        Ok::<_, Infallible>(rmse(&table(s as u32), &fs, TRIALS))
    })
    .unwrap_or_else(|never| match never {});
    let shipped_table = table(PMJ02_TABLE_SEED);
    let shipped = rmse(&shipped_table, &fs, TRIALS);
    println!(
        "### PMJ(0,2) tables under pmj02-bn's randomisation: the shipped table (seed \
         {PMJ02_TABLE_SEED}) / OpenQMC's (RMSE, {TRIALS} pixels), and how many of the tables of \
         seeds 0 … {} are at or below OpenQMC's\n",
        tables - 1
    );
    println!(
        "| integrand | {} |",
        COUNTS.map(|n| format!("{n} spp")).join(" | ")
    );
    println!("|---|{}", "---:|".repeat(COUNTS.len()));
    for (k, (name, _, _)) in integrands.iter().enumerate() {
        let cells: Vec<String> = (0..COUNTS.len())
            .map(|c| {
                let below = all.iter().filter(|r| r[k][c] <= openqmc[k][c]).count();
                format!("{:.4} / {:.4}, {below}", shipped[k][c], openqmc[k][c])
            })
            .collect();
        println!("| {name} | {} |", cells.join(" | "));
    }
    let every = all
        .iter()
        .filter(|r| {
            (0..integrands.len()).all(|k| (0..COUNTS.len()).all(|c| r[k][c] <= openqmc[k][c]))
        })
        .count();
    println!("\nTables at or below OpenQMC's in every cell: {every} of {tables}.");
    // The same tables on the integrands the seed was chosen by (`pmj02-seed`'s score: the sum
    // of log RMSE ratios to the average table, lower is better).
    let search = search(0..tables, TRIALS).expect("a non-empty range of seeds");
    let (theirs_score, below) = search.standing(&rmse(&theirs, &training(), TRIALS));
    let (shipped_score, _) = search.standing(&rmse(&shipped_table, &training(), TRIALS));
    println!(
        "On pmj02-seed's training integrands: the shipped table scores {shipped_score:.2}, \
         OpenQMC's {theirs_score:.2}; {below} of the {tables} tables score lower.\n"
    );
    print_random_families(&shipped_table, &theirs, tables.min(64));
}

/// A sampler's integrand with its parameters, for [`print_random_families`].
#[cfg(peer_openqmc)]
type Bump = Box<dyn Fn(&[f32; 4]) -> f64 + Sync>;

/// ∫₀¹ exp(−(x − c)² / (2σ²)) dx ([`simpson`]).
#[cfg(peer_openqmc)]
fn gaussian_integral(c: f64, sigma: f64) -> f64 {
    simpson(
        |x| (-(x - c) * (x - c) / (2.0 * sigma * sigma)).exp(),
        0.0,
        1.0,
    )
}

/// Families of integrands that neither the seed search nor the comparison saw, with
/// parameters drawn from a fixed seed: 64 disks over dimensions 0–1 (centre anywhere the disk
/// fits, radius 0.1 … 0.4), 64 Gaussians over dimensions 0–1 and 64 over all four (centre in
/// `[0.2, 0.8)`, σ 0.05 … 0.3). Per family and spp: in how many the shipped table's RMSE is
/// below OpenQMC's table's (both under `pmj02-bn`'s randomisation, the same pixels), and the
/// geometric means of the shipped table's RMSE and of OpenQMC's over the average table's (the
/// root mean square over the tables of seeds `0 .. tables`).
#[cfg(peer_openqmc)]
fn print_random_families(
    shipped: &nyquist_lab::pmj02_seed::Table,
    theirs: &nyquist_lab::pmj02_seed::Table,
    tables: u32,
) {
    use nyquist::hash::mix64;
    use nyquist_lab::pmj02_seed::{COUNTS, TRIALS, rmse, root_mean_square, table};
    let mut state = 0x6661_6d69_6c79u64; // "family"
    let mut next = move || {
        state = mix64(state.wrapping_add(0x9e37_79b9_7f4a_7c15));
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut families: Vec<(&str, Vec<(Bump, f64)>)> = Vec::new();
    let disks: Vec<(Bump, f64)> = (0..64)
        .map(|_| {
            let r = 0.1 + 0.3 * next();
            let (cx, cy) = (r + (1.0 - 2.0 * r) * next(), r + (1.0 - 2.0 * r) * next());
            let f: Bump = Box::new(move |v: &[f32; 4]| {
                let (dx, dy) = (f64::from(v[0]) - cx, f64::from(v[1]) - cy);
                f64::from(u8::from(dx * dx + dy * dy < r * r))
            });
            (f, std::f64::consts::PI * r * r)
        })
        .collect();
    families.push(("disks, dims 0–1", disks));
    for dims in [2usize, 4] {
        let bumps: Vec<(Bump, f64)> = (0..64)
            .map(|_| {
                let sigma = 0.05 + 0.25 * next();
                let c: Vec<f64> = (0..dims).map(|_| 0.2 + 0.6 * next()).collect();
                let integral = c.iter().map(|&c| gaussian_integral(c, sigma)).product();
                let f: Bump = Box::new(move |v: &[f32; 4]| {
                    let d2: f64 = c
                        .iter()
                        .zip(v)
                        .map(|(c, x)| (f64::from(*x) - c).powi(2))
                        .sum();
                    (-d2 / (2.0 * sigma * sigma)).exp()
                });
                (f, integral)
            })
            .collect();
        families.push((
            if dims == 2 {
                "Gaussians, dims 0–1"
            } else {
                "Gaussians, 4-D"
            },
            bumps,
        ));
    }
    println!(
        "### PMJ(0,2) tables on random integrands: in how many of 64 the shipped table's RMSE is \
         below OpenQMC's table's; the geometric means of the shipped table's RMSE and of \
         OpenQMC's over the average of the tables of seeds 0 … {}\n",
        tables - 1
    );
    println!(
        "| family | {} |",
        COUNTS.map(|n| format!("{n} spp")).join(" | ")
    );
    println!("|---|{}", "---:|".repeat(COUNTS.len()));
    for (name, fs) in &families {
        let ours = rmse(shipped, fs, TRIALS);
        let other = rmse(theirs, fs, TRIALS);
        let seeds: Vec<Vec<[f64; 5]>> = (0..tables).map(|s| rmse(&table(s), fs, TRIALS)).collect();
        let average = root_mean_square(&seeds);
        // The geometric mean over the family of a's RMSE over b's, at spp index c.
        let ratio = |a: &[[f64; 5]], b: &[[f64; 5]], c: usize| {
            let log: f64 = a.iter().zip(b).map(|(x, y)| (x[c] / y[c]).ln()).sum();
            (log / a.len() as f64).exp()
        };
        let cells: Vec<String> = (0..COUNTS.len())
            .map(|c| {
                let below = ours.iter().zip(&other).filter(|(a, b)| a[c] < b[c]).count();
                format!(
                    "{below}, {:.3} / {:.3}",
                    ratio(&ours, &average, c),
                    ratio(&other, &average, c)
                )
            })
            .collect();
        println!("| {name} | {} |", cells.join(" | "));
    }
    println!();
}

/// The nyquist samplers and their OpenQMC counterparts in the RMSE comparison.
const COUNTERPARTS: [(&str, &str); 3] = [
    ("nyquist owen-sobol-bn", "OpenQMC sobolbn"),
    ("nyquist pmj02-bn", "OpenQMC pmjbn"),
    ("nyquist lattice-bn", "OpenQMC latticebn"),
];

/// For each pair of [`COUNTERPARTS`] that ran, two tables per integrand and spp: nyquist's RMSE
/// over OpenQMC's with the difference in standard errors of the difference (`z`; |z| > 2 is a
/// difference the draw of the keys explains less than one time in twenty), and nyquist's
/// low-frequency ratio and power over OpenQMC's.
fn print_against_openqmc(
    sources: &[Source],
    integrands: &[Integrand],
    results: &[Vec<[Cell; SPPS.len()]>],
    header: &str,
) {
    let index = |name: &str| sources.iter().position(|s| s.0 == name);
    let pairs: Vec<(usize, usize)> = COUNTERPARTS
        .iter()
        .filter_map(|&(a, b)| Some((index(a)?, index(b)?)))
        .collect();
    if pairs.is_empty() {
        return;
    }
    // One table: a row per integrand and pair, a cell per spp from the two samplers' cells
    // (its text and its z), then the verdict per pair (module docs).
    let table = |title: &str, cell: &dyn Fn(&Cell, &Cell) -> (String, f64)| {
        println!("### {title}\n");
        println!("| integrand | sampler | {header} |");
        println!("|---|---|{}", "---:|".repeat(SPPS.len()));
        for (ii, g) in integrands.iter().enumerate() {
            for &(a, b) in &pairs {
                let cells: Vec<String> = results[a][ii]
                    .iter()
                    .zip(&results[b][ii])
                    .map(|(x, y)| cell(x, y).0)
                    .collect();
                println!("| {} | {} | {} |", g.name, sources[a].0, cells.join(" | "));
            }
        }
        println!();
        for &(a, b) in &pairs {
            // (z, integrand, spp, the two cells): the distinct cells compared.
            let mut zs: Vec<(f64, &str, u32, &Cell, &Cell)> = Vec::new();
            let mut unmeasured = 0;
            let close = |p: f64, q: f64| (p - q).abs() <= 1e-9 * p.abs().max(q.abs());
            let same = |c: &Cell, d: &Cell| close(c.rmse, d.rmse) && close(c.ratio, d.ratio);
            for (ii, g) in integrands.iter().enumerate() {
                for (k, (x, y)) in results[a][ii].iter().zip(&results[b][ii]).enumerate() {
                    let z = cell(x, y).1;
                    // Two figures that are the same compare nothing, and a cell that repeats
                    // another up to rounding (the next block's first pair: both samplers
                    // shift their tiles per block, which sums the same errors in another
                    // order) is not a second test.
                    let repeat = zs
                        .iter()
                        .any(|c| c.2 == SPPS[k] && same(c.3, x) && same(c.4, y));
                    if !z.is_finite() {
                        unmeasured += 1;
                    } else if z != 0.0 && !repeat {
                        zs.push((z, g.name, SPPS[k], x, y));
                    }
                }
            }
            if unmeasured > 0 {
                println!(
                    "{}: {unmeasured} cells without a z (no spectrum).",
                    sources[a].0
                );
            }
            let Some(&(z, name, spp, _, _)) = zs.iter().max_by(|p, q| p.0.total_cmp(&q.0)) else {
                continue;
            };
            let p = (normal_tail(z) * zs.len() as f64).min(1.0);
            let above = zs
                .iter()
                .filter(|c| normal_tail(c.0) * (zs.len() as f64) < 0.05)
                .count();
            println!(
                "{}: largest z {z:+.1} ({name}, {spp} spp); over its {} cells chance gives one as \
                 large with probability at most {p:.2e}; {above} cell{} significantly above \
                 OpenQMC's (family-wise false-alarm rate 5 %).",
                sources[a].0,
                zs.len(),
                if above == 1 { "" } else { "s" }
            );
        }
        println!();
    };
    table(
        "RMSE against OpenQMC's: nyquist / OpenQMC (z = difference / its standard error)",
        &|x, y| {
            let z = z_score(x.rmse, x.se, y.rmse, y.se);
            (format!("{:.3} ({z:+.1})", x.rmse / y.rmse), z)
        },
    );
    table(
        "Low-frequency ratio (z) and low-frequency power (the low-frequency RMSE squared): \
         nyquist's over OpenQMC's",
        &|x, y| {
            let z = z_score(x.ratio, x.ratio_se, y.ratio, y.ratio_se);
            let power = x.low_frequency_power() / y.low_frequency_power();
            (
                format!("{:.3} ({z:+.1}) / {power:.3}", x.ratio / y.ratio),
                z,
            )
        },
    );
}

/// `½ + 4·error` as grey, a PNG named after the sampler (the Gaussian of the first pair at 4
/// spp).
fn write_error_image(dir: &std::path::Path, name: &str, err: &[f64], size: u32) {
    use nyquist_film::output::png::{PngColor, PngLayout, write_png_pixels};
    let grey: Vec<u8> = err
        .iter()
        .map(|e| ((0.5 + 4.0 * e).clamp(0.0, 1.0) * 255.0).round() as u8)
        .collect();
    let file = dir.join(format!(
        "blue-error-{}.png",
        name.to_lowercase()
            .replace(['(', ')'], "")
            .replace(' ', "-")
    ));
    let mut out = Vec::new();
    write_png_pixels(&mut out, &PngLayout::new(size, size, PngColor::Grey), &grey).unwrap();
    std::fs::write(&file, out).unwrap();
    eprintln!("wrote {}", file.display());
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The normal tail at published quantiles: ½ at 0, 0.025 at 1.959964, 0.001 at 3.090232.
    #[test]
    fn normal_tail_is_the_published_one() {
        for (z, p) in [
            (0.0, 0.5),
            (1.959_964, 0.025),
            (3.090_232, 0.001),
            (-1.959_964, 0.975),
        ] {
            assert!((normal_tail(z) - p).abs() < 1e-6, "{z}: {}", normal_tail(z));
        }
    }
}
