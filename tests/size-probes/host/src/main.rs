//! `nyquist-probe-host PROBE`: the lines the size probe `PROBE` prints under QEMU (eight hex
//! digits per value, then `END`), computed on the host with the table paths.

use nyquist::filter::{Interpolation, Mitchell, SeparableTable};
use nyquist::rng::default_rng;
use nyquist::sampler::{
    HaltonSampler, Jitter, LatticeSampler, OwenSobolSampler, Pmj02Sampler, RandomSampler, Sampler,
    SobolSampler, StratifiedSampler, ZSobolSampler,
};
use nyquist::scramble::Scramble;
use nyquist::sequence::{Halton, OwenSobol, Sequence, Sobol, pmj02_build};
use nyquist::stratify::{Jitter as StrataJitter, latin_hypercube, shuffle, stratified_2d};
use std::io::{BufWriter, Write};
use std::process::ExitCode;

include!("../../src/indices.rs");

/// The probes' `camera_loop`: the camera sample of the pixel and sample index taken from `i`,
/// one `get_1d`, one `get_2d`, eight values.
fn camera_loop(s: &mut impl Sampler, i: u64, emit: &mut impl FnMut(u32)) {
    let c = s.camera_sample([(i & 63) as u32, (i >> 6 & 63) as u32], (i >> 12) as u32);
    let t = s.get_1d();
    let [u, v] = s.get_2d();
    for x in [
        c.p_film[0],
        c.p_film[1],
        c.lens[0],
        c.lens[1],
        c.time,
        t,
        u,
        v,
    ] {
        emit(x.to_bits());
    }
}

fn main() -> ExitCode {
    let Some(probe) = std::env::args().nth(1) else {
        eprintln!("usage: nyquist-probe-host PROBE");
        return ExitCode::from(2);
    };
    let mut out = BufWriter::new(std::io::stdout().lock());
    let mut emit = |x: u32| writeln!(out, "{x:08x}").unwrap();
    let indices = (0..PROBE_POINTS).map(probe_index);
    match probe.as_str() {
        "halton2" | "halton16" => {
            let dims = if probe == "halton2" { 2 } else { 16 };
            let h = Halton::new(dims).unwrap();
            for i in indices {
                (0..dims).for_each(|d| emit(h.sample(i, d).to_bits()));
            }
        }
        "sobol4" => {
            let s = Sobol::new(4).unwrap();
            for i in indices {
                (0..4).for_each(|d| emit(s.sample(i, d).to_bits()));
            }
        }
        "owen4" => {
            let s = OwenSobol::new(4, 7).unwrap();
            for i in indices {
                (0..4).for_each(|d| emit(s.sample(i, d).to_bits()));
                s.sample_4d(i, 0)
                    .iter()
                    .for_each(|x| emit(x.to_bits()));
            }
        }
        "pmj02" => {
            let mut points = [[0u32; 2]; 1024];
            for i in indices {
                if pmj02_build((i >> 10) as u32, &mut points).is_ok() {
                    let [x, y] = points[(i & 1023) as usize];
                    emit(x);
                    emit(y);
                }
            }
        }
        "stratify" => {
            for i in indices {
                let mut rng = default_rng(i);
                let mut grid = [0.0f32; 4 * 4 * 2];
                let mut lhs = [0.0f32; 8 * 3];
                if stratified_2d(&mut grid, 4, 4, StrataJitter::Jittered, &mut rng).is_ok()
                    && latin_hypercube(&mut lhs, 3, &mut rng).is_ok()
                    && shuffle(&mut grid, 16, 2, &mut rng).is_ok()
                {
                    emit(grid[(i % 32) as usize].to_bits());
                    emit(lhs[(i % 24) as usize].to_bits());
                }
            }
        }
        "stratified_sampler" => {
            let mut s = StratifiedSampler::new(4, 4, Jitter::Jittered, 9).unwrap();
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        "lattice_fibonacci" | "lattice_korobov" | "lattice_r2" => {
            let mut s = match probe.as_str() {
                "lattice_fibonacci" => LatticeSampler::fibonacci(16, 7),
                "lattice_korobov" => LatticeSampler::korobov(16, 7),
                _ => LatticeSampler::r2(16, 7),
            }
            .unwrap();
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        "random_sampler" => {
            let mut s = RandomSampler::new(16, 7).unwrap();
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        "owen_sobol_bn_sampler" => {
            let mut s = nyquist::sampler::OwenSobolBlueSampler::new(16, 7)
                .unwrap()
                .with_frame(2);
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        "lattice_bn_sampler" => {
            let mut s = nyquist::sampler::LatticeBlueSampler::new(16, 7)
                .unwrap()
                .with_frame(2);
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        "mitchell" => {
            let t = SeparableTable::<16>::new(&Mitchell::default(), Interpolation::Linear).unwrap();
            for i in indices {
                let d = (i & 0xffff) as f32 / 65536.0;
                let mut w = [0.0f32; 4 * 4];
                if t.footprint([-2.0 + d, -1.75 + 0.5 * d], 4, &mut w).is_ok() {
                    w.iter().for_each(|x| emit(x.to_bits()));
                }
            }
        }
        "owen_sampler" => {
            let mut s = OwenSobolSampler::new(16, 7).unwrap().with_frame(2);
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        "sobol_sampler" => {
            let mut s = SobolSampler::new([64, 64], 16, Scramble::Owen, 7).unwrap();
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        "pmj02_sampler" => {
            let mut s = Pmj02Sampler::new(16, 7).unwrap();
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        "halton_sampler_none"
        | "halton_sampler_permute"
        | "halton_sampler_fast_owen"
        | "halton_sampler_owen" => {
            let scramble = match probe.as_str() {
                "halton_sampler_none" => Scramble::None,
                "halton_sampler_permute" => Scramble::PermuteDigits,
                "halton_sampler_fast_owen" => Scramble::FastOwen,
                _ => Scramble::Owen,
            };
            let mut s = HaltonSampler::new([64, 64], 16, scramble, 7).unwrap();
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        "zsobol_sampler" => {
            let mut s = ZSobolSampler::new([64, 64], 16, Scramble::FastOwen, 7).unwrap();
            indices.for_each(|i| camera_loop(&mut s, i, &mut emit));
        }
        _ => {
            eprintln!("nyquist-probe-host: unknown probe {probe}");
            return ExitCode::from(2);
        }
    }
    writeln!(out, "END").unwrap();
    ExitCode::SUCCESS
}
