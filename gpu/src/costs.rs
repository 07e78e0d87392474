//! What each shader function costs, read from the emitted SPIR-V: its own instructions, and the
//! instructions of everything it calls (each callee counted once, loops once: a static size,
//! not a count of executed instructions). `nyquist shaders --costs` prints the table
//! `docs/gpu.md` quotes.

use std::collections::{BTreeMap, BTreeSet};

use crate::{EmitError, Language, emit};

/// One function of the module.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FunctionCost {
    /// Its name in the WGSL source.
    pub name: String,
    /// SPIR-V instructions in its body.
    pub own: usize,
    /// SPIR-V instructions in its body and in every function it reaches through calls, each
    /// counted once.
    pub total: usize,
}

const OP_NAME: u32 = 5;
const OP_FUNCTION: u32 = 54;
const OP_FUNCTION_END: u32 = 56;
const OP_FUNCTION_CALL: u32 = 57;

/// The cost of every function of [`crate::WGSL`] (the entry point included), by name.
///
/// ```
/// let costs = nyquist_gpu::costs::function_costs().unwrap();
/// let mix = costs.iter().find(|c| c.name == "nyq_mix32").unwrap();
/// assert!(mix.own > 5 && mix.own == mix.total); // a leaf
/// ```
///
/// # Errors
/// [`EmitError`] if the module cannot be emitted as SPIR-V.
pub fn function_costs() -> Result<Vec<FunctionCost>, EmitError> {
    let bytes = emit(Language::SpirV)?;
    let words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
        .collect();
    let mut names = BTreeMap::new();
    // Function id → (own instructions, callees).
    let mut bodies: BTreeMap<u32, (usize, BTreeSet<u32>)> = BTreeMap::new();
    let mut current: Option<u32> = None;
    let mut at = 5; // past the header
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        let op = words[at] & 0xffff;
        if count == 0 || at + count > words.len() {
            break;
        }
        let operands = &words[at + 1..at + count];
        match op {
            OP_NAME => {
                let text: Vec<u8> = operands[1..]
                    .iter()
                    .flat_map(|w| w.to_le_bytes())
                    .take_while(|&b| b != 0)
                    .collect();
                names.insert(operands[0], String::from_utf8_lossy(&text).into_owned());
            }
            OP_FUNCTION => {
                // OpFunction result-type result-id control type.
                current = Some(operands[1]);
                bodies.entry(operands[1]).or_default();
            }
            OP_FUNCTION_END => current = None,
            _ => {}
        }
        if let Some(f) = current {
            let body = bodies.entry(f).or_default();
            body.0 += 1;
            if op == OP_FUNCTION_CALL {
                // OpFunctionCall result-type result-id function args…
                body.1.insert(operands[2]);
            }
        }
        at += count;
    }
    let mut out = Vec::new();
    for (&id, (own, _)) in &bodies {
        let mut seen = BTreeSet::from([id]);
        let mut stack = vec![id];
        while let Some(f) = stack.pop() {
            for &callee in &bodies[&f].1 {
                if seen.insert(callee) {
                    stack.push(callee);
                }
            }
        }
        let total = seen.iter().map(|f| bodies[f].0).sum();
        let name = names.get(&id).cloned().unwrap_or_else(|| format!("%{id}"));
        out.push(FunctionCost {
            name,
            own: *own,
            total,
        });
    }
    out.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(out)
}

/// The functions a renderer calls per sample, one row per sampler: the camera sample, `get_1d`
/// and `get_2d` (their totals), as a Markdown table.
///
/// ```
/// let table = nyquist_gpu::costs::sampler_table().unwrap();
/// assert!(table.contains("| owen-sobol |"));
/// ```
///
/// # Errors
/// [`EmitError`] if the module cannot be emitted as SPIR-V.
pub fn sampler_table() -> Result<String, EmitError> {
    let costs = function_costs()?;
    let total = |name: &str| {
        costs
            .iter()
            .find(|c| c.name == name)
            .map_or_else(|| "–".to_string(), |c| c.total.to_string())
    };
    let mut out = String::from(
        "| sampler | `camera_sample` | `get_1d` | `get_2d` | table bytes read |\n|---|---:|---:|---:|---|\n",
    );
    for (label, prefix, table) in SAMPLERS {
        out.push_str(&format!(
            "| {label} | {} | {} | {} | {table} |\n",
            total(&format!("nyq_{prefix}_camera_sample")),
            total(&format!("nyq_{prefix}_get_1d")),
            total(&format!("nyq_{prefix}_get_2d")),
        ));
    }
    Ok(out)
}

/// Each sampler's label, WGSL prefix and the table it reads.
const SAMPLERS: [(&str, &str, &str); 11] = [
    (
        "owen-sobol",
        "owen_sobol",
        "Sobol matrices: 4 bytes per set index bit per value",
    ),
    (
        "zsobol",
        "zsobol",
        "Sobol matrices (dimension 1): 4 bytes per set index bit",
    ),
    (
        "sobol",
        "sobol_sampler",
        "Sobol matrices: 4 bytes per set index bit per value",
    ),
    (
        "halton",
        "halton_sampler",
        "Halton bases: 96 bytes per dimension",
    ),
    ("pmj02", "pmj02", "none"),
    ("random", "random", "none"),
    ("stratified", "stratified", "none"),
    ("fibonacci, korobov, r2", "lattice", "none"),
    (
        "owen-sobol-bn",
        "owen_sobol_bn",
        "blue tile: 4 bytes per 4-D block; Sobol matrices (dimensions 0–3): 4 bytes per set index bit per value",
    ),
    ("pmj02-bn", "pmj02_bn", "blue tile: 4 bytes per 4-D block"),
    (
        "lattice-bn",
        "lattice_bn",
        "blue tile: 4 bytes per 4-D block",
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn totals_include_callees_once_and_leaves_are_their_own() {
        let costs = function_costs().unwrap();
        let get = |n: &str| costs.iter().find(|c| c.name == n).unwrap().clone();
        let hash2 = get("nyq_hash2");
        let mix64 = get("nyq_mix64");
        // hash2 calls mix64 (twice) and add64: its total counts mix64's body once.
        assert!(hash2.total >= hash2.own + mix64.total);
        assert!(hash2.total < hash2.own + 2 * mix64.total + get("nyq_add64").total + 1);
        for c in &costs {
            assert!(c.total >= c.own, "{}", c.name);
        }
        assert!(costs.iter().any(|c| c.name == "nyq_fill"));
    }
}
