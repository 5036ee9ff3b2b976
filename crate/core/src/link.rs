//! Share links: the URL fragment carries the whole scenario as `k1.` followed by the raw-deflated
//! canonical JSON in unpadded base64url. The CLI reads the same links, so a run copied from the
//! page can be repeated in a terminal.
//!
//! Beside the scenario, the JSON carries `model_version`: the behaviour version of its model when
//! the link was made (see [`crate::models::ModelEntry::model_version`]). A link keeps opening
//! after the model changes; [`open`] says which version made it, so the page can warn that the
//! run may differ. Links made before versions were recorded carry none and count as version 1.

use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use base64::Engine as _;
use schemars::JsonSchema;
use serde::Serialize;
use serde_json::Value;

use crate::error::{Error, Result};
use crate::limits::Limits;
use crate::models;
use crate::scenario::{canonical, Scenario};

/// Version prefix of the link payload.
pub const PREFIX: &str = "k1.";
/// The largest scenario a link may expand to, against decompression bombs.
pub const MAX_SCENARIO_BYTES: usize = 4 << 20;

/// The key that carries the model's behaviour version in a link's JSON.
pub const MODEL_VERSION_KEY: &str = "model_version";

/// A scenario read from a link, with the behaviour version of its model then and now.
#[derive(Clone, Debug, PartialEq)]
pub struct Opened {
    pub scenario: Scenario,
    /// The model's behaviour version when the link was made.
    pub made_with: u32,
    /// The model's behaviour version in this program.
    pub current: u32,
}

/// The behaviour versions of a link's model: the one that made the link and this program's. The
/// page warns when they differ.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, JsonSchema)]
pub struct Versions {
    /// The model's behaviour version when the link was made.
    pub made_with: u32,
    /// The model's behaviour version in this program.
    pub current: u32,
}

/// A link's scenario, not yet read, with its model's [`Versions`]: what the page unpacks on its
/// main thread before it knows whether the scenario is small enough to check there.
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Unpacked {
    /// The scenario JSON, indented, as the link holds it.
    pub scenario: String,
    #[serde(flatten)]
    pub versions: Versions,
}

/// A link's scenario as indented JSON, not yet read, and its model's versions (this program's is
/// the link's own when the model is unknown: reading it will say so).
pub fn unpacked(link: &str) -> Result<Unpacked> {
    let (doc, made_with) = unpack(link)?;
    let model = doc.get("model").and_then(Value::as_str).unwrap_or_default();
    let current = models::entry(model).map_or(made_with, |e| e.model_version);
    Ok(Unpacked {
        scenario: serde_json::to_string_pretty(&doc).map_err(|e| Error::json(&e))?,
        versions: Versions { made_with, current },
    })
}

impl Opened {
    /// Its model's versions.
    pub fn versions(&self) -> Versions {
        Versions {
            made_with: self.made_with,
            current: self.current,
        }
    }

    /// True when the link was made with another behaviour of the model than this program's, so
    /// its run may differ from the one its maker saw.
    pub fn version_differs(&self) -> bool {
        self.made_with != self.current
    }
}

/// The fragment payload for a scenario (without the leading `#`).
pub fn encode(scenario: &Scenario) -> String {
    pack(scenario.to_value())
}

/// The fragment payload for a scenario document that was validated before (the JSON a
/// [`Scenario`] writes), without validating it again: rebuilding a large model only to check it
/// twice would hold the page for seconds. A document that is no valid scenario makes a link that
/// [`open`] refuses.
pub fn pack(mut doc: Value) -> String {
    let version = doc
        .get("model")
        .and_then(Value::as_str)
        .and_then(|model| models::entry(model).ok())
        .map_or(1, |e| e.model_version);
    if let Value::Object(map) = &mut doc {
        map.insert(MODEL_VERSION_KEY.into(), version.into());
    }
    let json = canonical(doc).to_string();
    let packed = miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 9);
    format!("{PREFIX}{}", URL_SAFE_NO_PAD.encode(packed))
}

/// Reads a link: a whole URL, a `#fragment`, or the bare payload.
pub fn decode(link: &str) -> Result<Scenario> {
    open(link).map(|o| o.scenario)
}

/// Reads a link within the page's limits and says which behaviour version of its model made it.
pub fn open(link: &str) -> Result<Opened> {
    open_within(link, &Limits::PAGE)
}

/// [`open`] within `limits`.
pub fn open_within(link: &str, limits: &'static Limits) -> Result<Opened> {
    let (doc, made_with) = unpack(link)?;
    let scenario = Scenario::from_value_within(doc, limits)?;
    let current = models::entry(scenario.model())?.model_version;
    Ok(Opened {
        scenario,
        made_with,
        current,
    })
}

/// The scenario document inside a link, not yet validated, and the behaviour version of its
/// model that made it, with the settings that version pins (`ModelEntry::pins`) where the link
/// does not set them. Nothing is built: the page reads a large scenario's size this way and
/// leaves its validation to the simulation worker, which opens it with [`Scenario::from_value`].
pub fn unpack(link: &str) -> Result<(Value, u32)> {
    #[cfg(test)]
    crate::counts::parse();
    let mut doc: Value = serde_json::from_str(&decode_json(link)?).map_err(|e| Error::json(&e))?;
    let made_with = match doc
        .as_object_mut()
        .and_then(|m| m.remove(MODEL_VERSION_KEY))
    {
        None => 1,
        Some(v) => v
            .as_u64()
            .and_then(|n| u32::try_from(n).ok())
            .filter(|&n| n >= 1)
            .ok_or_else(|| {
                Error::field(
                    MODEL_VERSION_KEY,
                    format!("expected a version from 1, found {v}"),
                )
            })?,
    };
    // The settings its model's earlier behaviour pins, so it replays as it did.
    let entry = doc
        .get("model")
        .and_then(Value::as_str)
        .and_then(|model| models::entry(model).ok());
    if let (Some(entry), Value::Object(map)) = (entry, &mut doc) {
        entry.pin(made_with, map);
    }
    Ok((doc, made_with))
}

/// A byte as a person can read it: a visible character in quotes, anything else by its code.
fn shown_byte(byte: u8) -> String {
    match byte {
        b'!'..=b'~' => format!("'{}'", byte as char),
        _ => format!("the byte 0x{byte:02x}"),
    }
}

/// Version prefix of an experiment link's payload.
pub const EXPERIMENT_PREFIX: &str = "x1.";

/// The fragment payload for an experiment (a checked experiment's JSON, without the `#`): `x1.`
/// and the raw-deflated canonical JSON in unpadded base64url, like a scenario link.
pub fn pack_experiment(doc: &Value) -> String {
    let json = canonical(doc.clone()).to_string();
    let packed = miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 9);
    format!("{EXPERIMENT_PREFIX}{}", URL_SAFE_NO_PAD.encode(packed))
}

/// The experiment JSON inside an experiment link (a URL, a `#fragment` or the payload), not yet
/// checked.
pub fn unpack_experiment(link: &str) -> Result<String> {
    decode_payload(link, EXPERIMENT_PREFIX)
}

/// The JSON inside a link (the scenario and its model version), not yet validated.
pub fn decode_json(link: &str) -> Result<String> {
    decode_payload(link, PREFIX)
}

fn decode_payload(link: &str, prefix: &str) -> Result<String> {
    let link = link.trim();
    let fragment = match link.rfind('#') {
        Some(i) => &link[i + 1..],
        None => link,
    };
    let kind = prefix.as_bytes()[0];
    let payload = fragment.strip_prefix(prefix).ok_or_else(|| {
        if fragment.len() > 1 && fragment.as_bytes()[0] == kind && fragment.contains('.') {
            Error::Link(format!(
                "made by another Kumiki version ('{}'); this one reads '{prefix}' links",
                fragment.split('.').next().unwrap_or_default()
            ))
        } else {
            Error::Link(format!(
                "a Kumiki link starts with '{prefix}' after the '#'"
            ))
        }
    })?;
    let packed = URL_SAFE_NO_PAD
        .decode(payload.trim_end_matches('='))
        .map_err(|e| match e {
            base64::DecodeError::InvalidByte(at, byte) => Error::Link(format!(
                "the link is damaged: it holds {}, which no Kumiki link has (character {} after '{prefix}')",
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
