//! Transcendental functions for models. The platform `f64::exp` calls the system libm natively and
//! a different implementation in wasm; the two may differ in the last bit, which is enough to send
//! a seeded run down another path. These wrappers use the `libm` crate on every target.

#[inline]
pub fn exp(x: f64) -> f64 {
    libm::exp(x)
}

#[inline]
pub fn ln(x: f64) -> f64 {
    libm::log(x)
}

#[inline]
pub fn ln_1p(x: f64) -> f64 {
    libm::log1p(x)
}

#[inline]
pub fn pow(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}
