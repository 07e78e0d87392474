//! A total decoder of fuzz input: reads little-endian integers and floats from the front of a
//! byte string; past its end every read is zero.

/// A cursor over fuzz input.
#[derive(Clone, Debug)]
pub struct Bytes<'a> {
    data: &'a [u8],
}

impl<'a> Bytes<'a> {
    /// A cursor at the start of `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Bytes { data }
    }

    /// The next `N` bytes, zero-padded past the end.
    pub fn array<const N: usize>(&mut self) -> [u8; N] {
        let mut out = [0u8; N];
        let n = N.min(self.data.len());
        out[..n].copy_from_slice(&self.data[..n]);
        self.data = &self.data[n..];
        out
    }

    /// Next byte.
    pub fn u8(&mut self) -> u8 {
        self.array::<1>()[0]
    }

    /// Next `u16`.
    pub fn u16(&mut self) -> u16 {
        u16::from_le_bytes(self.array())
    }

    /// Next `u32`.
    pub fn u32(&mut self) -> u32 {
        u32::from_le_bytes(self.array())
    }

    /// Next `u64`.
    pub fn u64(&mut self) -> u64 {
        u64::from_le_bytes(self.array())
    }

    /// Next bool.
    pub fn bool(&mut self) -> bool {
        self.u8() & 1 == 1
    }

    /// Next `f32`, any bit pattern (NaN, ±∞, subnormals included).
    pub fn f32_bits(&mut self) -> f32 {
        f32::from_bits(self.u32())
    }

    /// An `f32` that is usually "interesting but ordinary": a tag byte picks a special value
    /// (0, ±0.5, ±1, ±∞, NaN, huge, tiny, raw bits) or a small decimal `u16 / 256 − 128`.
    pub fn f32_mixed(&mut self) -> f32 {
        match self.u8() % 16 {
            0 => 0.0,
            1 => -0.0,
            2 => 0.5,
            3 => 1.0,
            4 => -1.0,
            5 => f32::INFINITY,
            6 => f32::NEG_INFINITY,
            7 => f32::NAN,
            8 => f32::MAX,
            9 => f32::MIN_POSITIVE,
            10 => 1.0e-40,
            11 => self.f32_bits(),
            _ => f32::from(self.u16()) / 256.0 - 128.0,
        }
    }

    /// A value in `0..=max`, small values more likely than by `u32 % (max + 1)` alone when the
    /// tag asks for it.
    pub fn below(&mut self, max: u32) -> u32 {
        let v = if self.bool() {
            u32::from(self.u8())
        } else {
            self.u32()
        };
        v % (max.saturating_add(1).max(1))
    }

    /// Whether the input is used up.
    pub fn rest_is_empty(&self) -> bool {
        self.data.is_empty()
    }

    /// The rest of the input.
    pub fn rest(&mut self) -> &'a [u8] {
        core::mem::take(&mut self.data)
    }

    /// The next `n` bytes (fewer at the end).
    pub fn take(&mut self, n: usize) -> &'a [u8] {
        let n = n.min(self.data.len());
        let (a, b) = self.data.split_at(n);
        self.data = b;
        a
    }
}
