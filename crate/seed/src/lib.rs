//! Fresh seeds for new runs. "New seed" in the page and `kumiki run --seed random` draw one here,
//! from the operating system natively and from `crypto.getRandomValues` in wasm (getrandom's
//! `wasm_js` backend). The seed drawn is written into the scenario, so the run stays replayable
//! from its link; the simulation itself never draws entropy, and this crate sits beside the core,
//! never inside it.

use kumiki_core::scenario::MAX_SEED;

/// A seed drawn from the system's entropy, uniform over the seeds a scenario accepts
/// (0 to 2^53 − 1, so it survives JavaScript numbers and JSON unchanged).
pub fn fresh_seed() -> Result<u64, getrandom::Error> {
    Ok(getrandom::u64()? & MAX_SEED)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeds_are_fresh_and_fit_a_scenario() {
        let draws: Vec<u64> = (0..8).map(|_| fresh_seed().unwrap()).collect();
        assert!(draws.iter().all(|&s| s <= MAX_SEED));
        // Eight draws of 53 bits all equal would mean the entropy source is broken.
        assert!(draws.iter().any(|&s| s != draws[0]), "{draws:?}");
    }
}
