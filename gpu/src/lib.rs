//! # nyquist-gpu
//!
//! nyquist's stateless samplers as shader code: WGSL sources that return the core's values bit
//! for bit, and GLSL 450, HLSL (shader model 6), MSL and SPIR-V emitted from them with `naga`.
//!
//! The WGSL is one module, [`WGSL`]: the library functions (prefixed `nyq_`) and one compute
//! kernel, `nyq_fill`, that runs any of them over a buffer of requests. The emitted languages
//! are translations of that module with `nyq_fill` as the entry point; checked-in copies live
//! in `gpu/shaders/` of the repository and a test holds them to what [`emit`] returns.
//!
//! ```
//! use nyquist_gpu::{emit, Language};
//! let glsl = emit(Language::Glsl).unwrap();
//! assert!(glsl.starts_with(b"#version 450"));
//! ```
//!
//! The samplers read three tables from storage buffers the engine binds: the Sobol generator
//! matrices ([`sobol_matrices`], 128 KiB, at [`Bindings::sobol_matrices`]), the Halton
//! per-base constants ([`halton_bases`], 96 KiB, at [`Bindings::halton_bases`]) and the
//! blue-noise samplers' tiles ([`blue_tiles`], 192 KiB, at [`Bindings::blue_tiles`]). Everything
//! else is integer arithmetic on 32-bit words (64-bit words as `vec2<u32>` halves) and exact
//! conversions; `docs/gpu.md` in the repository gives the float rules that keep every device's
//! bits equal to the CPU's.

use std::fmt;

pub mod costs;

/// The library and its `nyq_fill` kernel, in WGSL: the source every other language is emitted
/// from. Bindings: group 0, binding 0 the Sobol matrices; bindings 1–3 the kernel's job,
/// requests and values; binding 4 the Halton bases; binding 5 the blue-noise tiles.
///
/// ```
/// assert!(nyquist_gpu::WGSL.contains("fn nyq_owen_sobol_camera_sample("));
/// ```
pub const WGSL: &str = concat!(
    include_str!("../wgsl/hash.wgsl"),
    "\n",
    include_str!("../wgsl/scramble.wgsl"),
    "\n",
    include_str!("../wgsl/sobol.wgsl"),
    "\n",
    include_str!("../wgsl/owen_sobol.wgsl"),
    "\n",
    include_str!("../wgsl/zsobol.wgsl"),
    "\n",
    include_str!("../wgsl/random.wgsl"),
    "\n",
    include_str!("../wgsl/lattice.wgsl"),
    "\n",
    include_str!("../wgsl/stratified.wgsl"),
    "\n",
    include_str!("../wgsl/pmj02.wgsl"),
    "\n",
    include_str!("../wgsl/halton.wgsl"),
    "\n",
    include_str!("../wgsl/screen_blue.wgsl"),
    "\n",
    include_str!("../wgsl/fill.wgsl"),
);

/// The compute entry point of every emitted module.
pub const ENTRY_POINT: &str = "nyq_fill";

/// Threads per workgroup of [`ENTRY_POINT`].
pub const WORKGROUP_SIZE: u32 = 64;

/// Words `nyq_fill` writes per request.
pub const WORDS_PER_REQUEST: usize = 8;

/// The shader languages [`emit`] writes.
///
/// ```
/// use nyquist_gpu::Language;
/// assert_eq!(Language::from_name("glsl"), Some(Language::Glsl));
/// assert_eq!(Language::SpirV.file_name(), "nyquist.spv");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Language {
    /// WGSL, the source itself.
    Wgsl,
    /// GLSL 450 (core), a compute shader.
    Glsl,
    /// HLSL for shader model 6.0.
    Hlsl,
    /// Metal Shading Language 2.0.
    Msl,
    /// SPIR-V 1.0 (binary).
    SpirV,
}

impl Language {
    /// Every language, in the order above.
    pub const ALL: [Language; 5] = [
        Language::Wgsl,
        Language::Glsl,
        Language::Hlsl,
        Language::Msl,
        Language::SpirV,
    ];

    /// The language's name on the command line: `wgsl`, `glsl`, `hlsl`, `msl`, `spirv`.
    ///
    /// ```
    /// assert_eq!(nyquist_gpu::Language::Msl.name(), "msl");
    /// ```
    pub const fn name(self) -> &'static str {
        match self {
            Language::Wgsl => "wgsl",
            Language::Glsl => "glsl",
            Language::Hlsl => "hlsl",
            Language::Msl => "msl",
            Language::SpirV => "spirv",
        }
    }

    /// The language called `name` (ASCII case ignored), `None` for any other string.
    ///
    /// ```
    /// use nyquist_gpu::Language;
    /// assert_eq!(Language::from_name("SPIRV"), Some(Language::SpirV));
    /// assert_eq!(Language::from_name("cuda"), None);
    /// ```
    pub fn from_name(name: &str) -> Option<Language> {
        Language::ALL
            .into_iter()
            .find(|l| l.name().eq_ignore_ascii_case(name))
    }

    /// The file the checked-in copy and `nyquist shaders` use: `nyquist.wgsl`, `nyquist.comp.glsl`,
    /// `nyquist.hlsl`, `nyquist.metal`, `nyquist.spv`.
    ///
    /// ```
    /// assert_eq!(nyquist_gpu::Language::Glsl.file_name(), "nyquist.comp.glsl");
    /// ```
    pub const fn file_name(self) -> &'static str {
        match self {
            Language::Wgsl => "nyquist.wgsl",
            Language::Glsl => "nyquist.comp.glsl",
            Language::Hlsl => "nyquist.hlsl",
            Language::Msl => "nyquist.metal",
            Language::SpirV => "nyquist.spv",
        }
    }
}

/// Why [`emit`] failed: naga rejected the module or could not translate it. Each names the
/// stage; the message is naga's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EmitError {
    /// `parse`, `validate` or the language being written.
    pub stage: &'static str,
    /// naga's message.
    pub message: String,
}

impl fmt::Display for EmitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "shader {}: {}", self.stage, self.message)
    }
}

impl std::error::Error for EmitError {}

/// Where the engine binds the library's buffers. The defaults are the ones in [`WGSL`].
///
/// ```
/// use nyquist_gpu::Bindings;
/// let b = Bindings { group: 2, sobol_matrices: 7, halton_bases: 8, blue_tiles: 9 };
/// let wgsl = b.apply(nyquist_gpu::WGSL);
/// assert!(wgsl.contains("@group(2) @binding(7) var<storage, read> nyq_sobol_matrices"));
/// assert!(wgsl.contains("@group(2) @binding(8) var<storage, read> nyq_halton_bases"));
/// assert!(wgsl.contains("@group(2) @binding(9) var<storage, read> nyq_blue_tiles"));
/// assert_eq!(Bindings::default().apply(nyquist_gpu::WGSL), nyquist_gpu::WGSL);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bindings {
    /// The bind group of every buffer.
    pub group: u32,
    /// The binding of the Sobol matrices.
    pub sobol_matrices: u32,
    /// The binding of the Halton bases.
    pub halton_bases: u32,
    /// The binding of the blue-noise samplers' tiles.
    pub blue_tiles: u32,
}

impl Default for Bindings {
    /// Group 0, the Sobol matrices at binding 0, the Halton bases at 4 and the blue-noise
    /// tiles at 5, as in [`WGSL`].
    fn default() -> Bindings {
        Bindings {
            group: 0,
            sobol_matrices: 0,
            halton_bases: 4,
            blue_tiles: 5,
        }
    }
}

impl Bindings {
    /// `source` (the [`WGSL`] module or a copy of its library part) with the tables'
    /// declarations moved to these bindings. The kernel's own bindings keep their numbers in
    /// the new group.
    pub fn apply(&self, source: &str) -> String {
        source
            .replace(
                "@group(0) @binding(0) var<storage, read> nyq_sobol_matrices",
                &format!(
                    "@group({}) @binding({}) var<storage, read> nyq_sobol_matrices",
                    self.group, self.sobol_matrices
                ),
            )
            .replace(
                "@group(0) @binding(4) var<storage, read> nyq_halton_bases",
                &format!(
                    "@group({}) @binding({}) var<storage, read> nyq_halton_bases",
                    self.group, self.halton_bases
                ),
            )
            .replace(
                "@group(0) @binding(5) var<storage, read> nyq_blue_tiles",
                &format!(
                    "@group({}) @binding({}) var<storage, read> nyq_blue_tiles",
                    self.group, self.blue_tiles
                ),
            )
            .replace(
                "@group(0) @binding(",
                &format!("@group({}) @binding(", self.group),
            )
    }
}

/// The Sobol generator matrices the shaders read: 1024 dimensions × 32 columns, column `k` of
/// dimension `d` at `32·d + k` (the core's Joe–Kuo matrices, `sobol_u32(1 << k, d)`).
///
/// ```
/// let m = nyquist_gpu::sobol_matrices();
/// assert_eq!(m.len(), 1024 * 32);
/// assert_eq!(m[0], 1 << 31); // dimension 0 is the van der Corput sequence
/// ```
pub fn sobol_matrices() -> Vec<u32> {
    let mut out = Vec::with_capacity(1024 * 32);
    for d in 0..nyquist::sequence::SOBOL_DIMS {
        for k in 0..32 {
            out.push(nyquist::sequence::sobol_u32(1 << k, d));
        }
    }
    out
}

/// The side of each blue-noise tile ([`blue_tiles`]).
pub const BLUE_TILE_SIZE: u32 = nyquist::sampler::screen_blue::TILE_SIZE;

/// The blue-noise families in the order of [`blue_tiles`]: each sampler's name (the core's
/// `BlueFamily::NAME`).
pub const BLUE_FAMILIES: [&str; 3] = [
    <nyquist::sampler::screen_blue::OwenSobolBlue as nyquist::sampler::screen_blue::BlueFamily>::NAME,
    <nyquist::sampler::screen_blue::Pmj02Blue as nyquist::sampler::screen_blue::BlueFamily>::NAME,
    <nyquist::sampler::screen_blue::LatticeBlue as nyquist::sampler::screen_blue::BlueFamily>::NAME,
];

/// One family's tile as the shaders read it: entry `(x, y)` (`key << 8 | rank`) at
/// `y · 128 + x`, from the core's `F::entry`.
fn blue_tile<F: nyquist::sampler::screen_blue::BlueFamily>() -> impl Iterator<Item = u32> {
    (0..BLUE_TILE_SIZE).flat_map(|y| (0..BLUE_TILE_SIZE).map(move |x| F::entry(x, y)))
}

/// The tiles the blue-noise samplers (`owen-sobol-bn`, `pmj02-bn`, `lattice-bn`) read:
/// 3 × 128 × 128 words, family-major in the order of [`BLUE_FAMILIES`], each tile row-major:
/// entry `(x, y)` of family `f` at `f · 16384 + y · 128 + x`, the core's
/// `BlueFamily::entry(x, y)` (a 24-bit key and an 8-bit rank, `key << 8 | rank`). 192 KiB.
/// Read from the core at run time: the tiles are the optimiser's output, so take them from the
/// `nyquist` version the shaders are held to.
///
/// ```
/// use nyquist::sampler::screen_blue::{BlueFamily, LatticeBlue};
/// let t = nyquist_gpu::blue_tiles();
/// assert_eq!(t.len(), 3 * 128 * 128);
/// assert_eq!(t[2 * 16384 + 77 * 128 + 5], LatticeBlue::entry(5, 77));
/// ```
pub fn blue_tiles() -> Vec<u32> {
    use nyquist::sampler::screen_blue::{LatticeBlue, OwenSobolBlue, Pmj02Blue};
    let mut out = Vec::with_capacity(3 * (BLUE_TILE_SIZE * BLUE_TILE_SIZE) as usize);
    out.extend(blue_tile::<OwenSobolBlue>());
    out.extend(blue_tile::<Pmj02Blue>());
    out.extend(blue_tile::<LatticeBlue>());
    out
}

/// Words per base in [`halton_bases`].
pub const HALTON_BASE_WORDS: usize = 24;

/// The Halton per-base constants the shaders read: 1024 bases × [`HALTON_BASE_WORDS`] words,
/// base `d` (the `d`-th prime) at `24·d`. Word 0 is `b`; 1 is `b^k`, `k` the largest with
/// `b^k < 2³²` (indices below take the core's short path); 2 and 3 hold, in byte `c`, the
/// digits `N_c` the short path's reversal spans for an index of `c + 1` nibbles; 4 is the
/// largest power of `b` up to 2¹⁶ and 5 its exponent; 6 and 7 are zero; `8 + 2c` and `9 + 2c`
/// are the low and high words of the `f64` bits of `1/b^N_c`, the reciprocal the core's short
/// path multiplies by (its `fast_class`, rebuilt here from the primes).
///
/// ```
/// let t = nyquist_gpu::halton_bases();
/// assert_eq!(t.len(), 1024 * nyquist_gpu::HALTON_BASE_WORDS);
/// assert_eq!((t[24], t[25]), (3, 3486784401)); // base 3, 3²⁰
/// assert_eq!((t[1023 * 24], t[1023 * 24 + 4]), (8161, 8161));
/// ```
pub fn halton_bases() -> Vec<u32> {
    use nyquist::radical::{PRIME_COUNT, prime};
    let mut out = Vec::with_capacity(PRIME_COUNT as usize * HALTON_BASE_WORDS);
    for d in 0..PRIME_COUNT {
        let b = u64::from(prime(d));
        // k: the largest with b^k < 2³².
        let mut k = 0u32;
        while b.pow(k + 1) < 1 << 32 {
            k += 1;
        }
        // The core's digits per table chunk (`chunk_len`): its short path's reversal spans
        // whole chunks, which fixes how it rounds.
        let chunk_limit = if b == 3 { 6561 } else { 4096 };
        let mut j = 0u32;
        while b.pow(j + 1) <= chunk_limit {
            j += 1;
        }
        if j < 2 {
            j = if b <= 83 { 2 } else { 1 };
        }
        let mut places = [0u32; 8];
        let mut inverses = [0u64; 8];
        for c in 1..=8u32 {
            let mut x = (1u64 << (4 * c)) - 1;
            let mut n = 0u32;
            while x > 0 {
                x /= b;
                n += 1;
            }
            let spanned = n.min(k).div_ceil(j) * j;
            places[c as usize - 1] = spanned;
            inverses[c as usize - 1] = (1.0 / b.pow(spanned) as f64).to_bits();
        }
        let mut run = 0u32;
        while b.pow(run + 1) <= 1 << 16 {
            run += 1;
        }
        let bytes =
            |c: usize| places[c] | places[c + 1] << 8 | places[c + 2] << 16 | places[c + 3] << 24;
        out.extend([b as u32, b.pow(k) as u32, bytes(0), bytes(4)]);
        out.extend([b.pow(run) as u32, run, 0, 0]);
        for inv in inverses {
            out.extend([inv as u32, (inv >> 32) as u32]);
        }
    }
    out
}

/// The parsed and validated [`WGSL`] module.
fn module() -> Result<(naga::Module, naga::valid::ModuleInfo), EmitError> {
    let module = naga::front::wgsl::parse_str(WGSL).map_err(|e| EmitError {
        stage: "parse",
        message: e.emit_to_string(WGSL),
    })?;
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .map_err(|e| EmitError {
        stage: "validate",
        message: e.emit_to_string(WGSL),
    })?;
    Ok((module, info))
}

/// The module in `language`: text for the shading languages, a SPIR-V binary (little-endian
/// words) for [`Language::SpirV`]. Deterministic: the same bytes every call.
///
/// # Errors
/// [`EmitError`] if naga rejects the module or a backend cannot write it (a defect of the
/// sources, which the crate's tests rule out for every language).
pub fn emit(language: Language) -> Result<Vec<u8>, EmitError> {
    if language == Language::Wgsl {
        module()?;
        return Ok(WGSL.as_bytes().to_vec());
    }
    let (module, info) = module()?;
    let fail = |message: String| EmitError {
        stage: language.name(),
        message,
    };
    let text = match language {
        Language::Wgsl => unreachable!("returned above"),
        Language::Glsl => {
            // Binding b of group 0 as `layout(binding = b)`: the numbers the other languages use.
            let binding_map = (0..6)
                .map(|b| {
                    let target = naga::ResourceBinding {
                        group: 0,
                        binding: b,
                    };
                    (target, b as u8)
                })
                .collect();
            let options = naga::back::glsl::Options {
                version: naga::back::glsl::Version::Desktop(450),
                writer_flags: naga::back::glsl::WriterFlags::empty(),
                binding_map,
                ..Default::default()
            };
            let pipeline = naga::back::glsl::PipelineOptions {
                shader_stage: naga::ShaderStage::Compute,
                entry_point: ENTRY_POINT.to_string(),
                multiview: None,
            };
            let mut out = String::new();
            let mut writer = naga::back::glsl::Writer::new(
                &mut out,
                &module,
                &info,
                &options,
                &pipeline,
                naga::proc::BoundsCheckPolicies::default(),
            )
            .map_err(|e| fail(e.to_string()))?;
            writer.write().map_err(|e| fail(e.to_string()))?;
            out
        }
        Language::Hlsl => {
            let options = naga::back::hlsl::Options {
                shader_model: naga::back::hlsl::ShaderModel::V6_0,
                ..Default::default()
            };
            let pipeline = naga::back::hlsl::PipelineOptions {
                entry_point: Some((naga::ShaderStage::Compute, ENTRY_POINT.to_string())),
            };
            let mut out = String::new();
            naga::back::hlsl::Writer::new(&mut out, &options, &pipeline)
                .write(&module, &info, None)
                .map_err(|e| fail(e.to_string()))?;
            out
        }
        Language::Msl => {
            // Binding b of group 0 as [[buffer(b)]] (binding 3, the values, writable), and the
            // buffer-size table naga needs for the runtime-sized arrays at [[buffer(6)]].
            let resources = (0..6)
                .map(|b| {
                    let target = naga::back::msl::BindTarget {
                        buffer: Some(b as u8),
                        mutable: b == 3,
                        ..Default::default()
                    };
                    (
                        naga::ResourceBinding {
                            group: 0,
                            binding: b,
                        },
                        target,
                    )
                })
                .collect();
            let entry = naga::back::msl::EntryPointResources {
                resources,
                immediates_buffer: None,
                sizes_buffer: Some(6),
            };
            let options = naga::back::msl::Options {
                lang_version: (2, 0),
                per_entry_point_map: [(ENTRY_POINT.to_string(), entry)].into_iter().collect(),
                fake_missing_bindings: false,
                ..Default::default()
            };
            let pipeline = naga::back::msl::PipelineOptions {
                entry_point: Some((naga::ShaderStage::Compute, ENTRY_POINT.to_string())),
                ..Default::default()
            };
            naga::back::msl::write_string(&module, &info, &options, &pipeline)
                .map_err(|e| fail(e.to_string()))?
                .0
        }
        Language::SpirV => {
            let options = naga::back::spv::Options::default();
            let pipeline = naga::back::spv::PipelineOptions {
                shader_stage: naga::ShaderStage::Compute,
                entry_point: ENTRY_POINT.to_string(),
            };
            let words = naga::back::spv::write_vec(&module, &info, &options, Some(&pipeline))
                .map_err(|e| fail(e.to_string()))?;
            return Ok(words.iter().flat_map(|w| w.to_le_bytes()).collect());
        }
    };
    Ok(text.into_bytes())
}
