//! Screen-space blue noise, measured: for each sampler, error images of `size × size` pixels
//! (each pixel's estimate of an integrand from its own samples, minus the integral) at 1 … 32
//! spp, on 2-D integrands of the first pair of dimensions, the second pair and the first pair of
//! the next 4-D block (OpenQMC: the next domain), and on 4-D integrands of the first block.
//!
//! Two numbers per image: the per-pixel RMSE, and the low-frequency ratio (the mean
//! periodogram power below a quarter of the Nyquist radius over the mean power at every
//! non-zero frequency: 1 for white error, lower for blue).
//!
//! `cargo run --release --manifest-path peers/Cargo.toml -- --blue-noise [--size N]
//! [--frame F] [--images DIR]`

use nyquist::sampler::{
    LatticeBlueSampler, OwenSobolBlueSampler, OwenSobolSampler, Pmj02BlueSampler, Pmj02Sampler,
    RandomSampler, Sampler,
};
use nyquist_lab::error_spectrum::error_spectrum;
use nyquist_lab::blue_tile::{BlockIntegrand, HELD_OUT};

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

/// The samplers compared, by name.
fn sources(frame: u32) -> Vec<(&'static str, Draw)> {
    #[cfg_attr(not(peer_openqmc), allow(unused_mut))]
    let mut v: Vec<(&'static str, Draw)> = vec![
        (
            "nyquist owen-sobol-bn",
            nyquist_draw(OwenSobolBlueSampler::new(1, 0).unwrap().with_frame(frame)),
        ),
        (
            "nyquist owen-sobol",
            nyquist_draw(OwenSobolSampler::new(1, 0).unwrap().with_frame(frame)),
        ),
        (
            "nyquist pmj02-bn",
            nyquist_draw(Pmj02BlueSampler::new(1, 0).unwrap().with_frame(frame)),
        ),
        (
            "nyquist pmj02",
            nyquist_draw(Pmj02Sampler::new(1, frame.into()).unwrap()),
        ),
        (
            "nyquist lattice-bn",
            nyquist_draw(LatticeBlueSampler::new(1, 0).unwrap().with_frame(frame)),
        ),
        (
            "white (random)",
            nyquist_draw(RandomSampler::new(1, 0).unwrap()),
        ),
    ];
    #[cfg(peer_openqmc)]
    {
        v.push(("OpenQMC sobolbn", openqmc_draw(0)));
        v.push(("OpenQMC pmjbn", openqmc_draw(1)));
        v.push(("OpenQMC latticebn", openqmc_draw(2)));
        v.push(("OpenQMC sobol", openqmc_draw(3)));
        v.push(("OpenQMC pmj", openqmc_draw(4)));
        v.push(("OpenQMC lattice", openqmc_draw(5)));
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

/// The low-frequency ratio of a square error image (module docs).
fn low_frequency_ratio(image: &[f64], size: u32) -> f64 {
    error_spectrum(image, size, size).map_or(f64::NAN, |s| s.low_frequency_ratio)
}

/// Runs the study and prints its tables.
pub fn run(size: u32, frame: u32, images: Option<&std::path::Path>) {
    const SPPS: [u32; 6] = [1, 2, 4, 8, 16, 32];
    let integrands = integrands();
    let exact: Vec<f64> = integrands.iter().map(|g| reference(g.f)).collect();
    let sources = sources(frame);
    // results[source][integrand][spp] = (rmse, ratio)
    let mut results = vec![vec![vec![(0.0, 0.0); SPPS.len()]; integrands.len()]; sources.len()];
    for (si, (name, draw)) in sources.iter().enumerate() {
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
                    results[si][ii][k] = (rmse, low_frequency_ratio(&err, size));
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
    for (ii, g) in integrands.iter().enumerate() {
        println!("### {}\n", g.name);
        println!(
            "| sampler | {} |",
            SPPS.map(|s| format!("{s} spp")).join(" | ")
        );
        println!("|---|{}", "---:|".repeat(SPPS.len()));
        for (si, (name, _)) in sources.iter().enumerate() {
            let cells: Vec<String> = results[si][ii]
                .iter()
                .map(|(rmse, ratio)| format!("{rmse:.4} / {ratio:.2}"))
                .collect();
            println!("| {name} | {} |", cells.join(" | "));
        }
        println!();
    }
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
