//! Share links: the URL fragment carries the whole scenario as `k1.` followed by the raw-deflated
//! canonical JSON in unpadded base64url. The CLI reads the same links, so a run copied from the
//! page can be repeated in a terminal.

use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use base64::Engine as _;

use crate::error::{Error, Result};
use crate::scenario::Scenario;

/// Version prefix of the link payload.
pub const PREFIX: &str = "k1.";
/// The largest scenario a link may expand to, against decompression bombs.
pub const MAX_SCENARIO_BYTES: usize = 4 << 20;

/// The fragment payload for a scenario (without the leading `#`).
pub fn encode(scenario: &Scenario) -> String {
    let json = scenario.to_json();
    let packed = miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 9);
    format!("{PREFIX}{}", URL_SAFE_NO_PAD.encode(packed))
}

/// Reads a link: a whole URL, a `#fragment`, or the bare payload.
pub fn decode(link: &str) -> Result<Scenario> {
    Scenario::from_json(&decode_json(link)?)
}

/// A byte as a person can read it: a visible character in quotes, anything else by its code.
fn shown_byte(byte: u8) -> String {
    match byte {
        b'!'..=b'~' => format!("'{}'", byte as char),
        _ => format!("the byte 0x{byte:02x}"),
    }
}

/// The scenario JSON inside a link, not yet validated.
pub fn decode_json(link: &str) -> Result<String> {
    let link = link.trim();
    let fragment = match link.rfind('#') {
        Some(i) => &link[i + 1..],
        None => link,
    };
    let payload = fragment.strip_prefix(PREFIX).ok_or_else(|| {
        if fragment.len() > 1 && fragment.as_bytes()[0] == b'k' && fragment.contains('.') {
            Error::Link(format!(
                "made by another Kumiki version ('{}'); this one reads '{PREFIX}' links",
                fragment.split('.').next().unwrap_or_default()
            ))
        } else {
            Error::Link(format!(
                "a Kumiki link starts with '{PREFIX}' after the '#'"
            ))
        }
    })?;
    let packed = URL_SAFE_NO_PAD
        .decode(payload.trim_end_matches('='))
        .map_err(|e| match e {
            base64::DecodeError::InvalidByte(at, byte) => Error::Link(format!(
                "the link is damaged: it holds {}, which no Kumiki link has (character {} after '{PREFIX}')",
                shown_byte(byte),
                at + 1
            )),
            _ => Error::Link("the link is damaged or cut short".into()),
        })?;
    let bytes = miniz_oxide::inflate::decompress_to_vec_with_limit(&packed, MAX_SCENARIO_BYTES)
        .map_err(|e| match e.status {
            miniz_oxide::inflate::TINFLStatus::HasMoreOutput => Error::Link(format!(
                "the scenario inside is larger than {} MiB",
                MAX_SCENARIO_BYTES >> 20
            )),
            _ => Error::Link("the link is damaged or cut short (it does not inflate)".into()),
        })?;
    String::from_utf8(bytes)
        .map_err(|_| Error::Link("the scenario inside is not UTF-8 text".into()))
}
