// The indices each probe runs under QEMU, shared (through `include!`) with the host-side
// comparison in `host/`: the first 64 integers, then hashed 64-bit values cut to every length.

/// Index `k` of the probe run.
pub fn probe_index(k: u32) -> u64 {
    if k < 64 {
        return u64::from(k);
    }
    // splitmix64's finaliser (Steele, Lea & Flood 2014), then a shift by k mod 64.
    let mut z = u64::from(k).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^= z >> 31;
    z >> (k % 64)
}

/// Points each probe runs under QEMU.
pub const PROBE_POINTS: u32 = 256;
