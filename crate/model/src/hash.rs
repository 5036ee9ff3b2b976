//! The 64-bit state hash shown in the page and checked by the golden tests. FNV-1a over a
//! little-endian byte encoding of the state, so it is the same on every target.

const OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const PRIME: u64 = 0x0000_0100_0000_01b3;

#[derive(Clone, Debug)]
pub struct StateHasher(u64);

impl Default for StateHasher {
    fn default() -> Self {
        StateHasher(OFFSET)
    }
}

impl StateHasher {
    pub fn new() -> Self {
        Self::default()
    }

    #[inline]
    pub fn bytes(&mut self, bytes: &[u8]) {
        let mut h = self.0;
        for &b in bytes {
            h ^= u64::from(b);
            h = h.wrapping_mul(PRIME);
        }
        self.0 = h;
    }

    #[inline]
    pub fn u8(&mut self, v: u8) {
        self.bytes(&[v]);
    }
    #[inline]
    pub fn u16(&mut self, v: u16) {
        self.bytes(&v.to_le_bytes());
    }
    #[inline]
    pub fn u32(&mut self, v: u32) {
        self.bytes(&v.to_le_bytes());
    }
    #[inline]
    pub fn u64(&mut self, v: u64) {
        self.bytes(&v.to_le_bytes());
    }
    #[inline]
    pub fn bool(&mut self, v: bool) {
        self.u8(u8::from(v));
    }
    /// Floats are hashed by their bits: the hash checks bit-identical runs.
    #[inline]
    pub fn f32(&mut self, v: f32) {
        self.u32(v.to_bits());
    }
    #[inline]
    pub fn f64(&mut self, v: f64) {
        self.u64(v.to_bits());
    }
    pub fn u16s(&mut self, vs: &[u16]) {
        for &v in vs {
            self.u16(v);
        }
    }
    pub fn f32s(&mut self, vs: &[f32]) {
        for &v in vs {
            self.f32(v);
        }
    }

    pub fn finish(&self) -> u64 {
        self.0
    }
}

/// Hex form used in the page, the CLI and the golden fixtures.
pub fn hex(hash: u64) -> String {
    format!("{hash:016x}")
}

/// Hash of a byte string (the canonical scenario text, for instance).
pub fn of_bytes(bytes: &[u8]) -> u64 {
    let mut h = StateHasher::new();
    h.bytes(bytes);
    h.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_reference_values() {
        // Published FNV-1a 64 test vectors.
        assert_eq!(of_bytes(b""), 0xcbf29ce484222325);
        assert_eq!(of_bytes(b"a"), 0xaf63dc4c8601ec8c);
        assert_eq!(of_bytes(b"foobar"), 0x85944171f73967e8);
    }

    #[test]
    fn order_matters() {
        let mut a = StateHasher::new();
        a.u32(1);
        a.u32(2);
        let mut b = StateHasher::new();
        b.u32(2);
        b.u32(1);
        assert_ne!(a.finish(), b.finish());
    }
}
