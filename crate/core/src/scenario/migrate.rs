//! The scenario format's migrations: every step from an older format to [`FORMAT_VERSION`], so
//! that every scenario file and share link made before a format change keeps opening.

use serde_json::{Map, Value};

use super::FORMAT_VERSION;
use crate::error::{Error, Result};

/// A scenario document as JSON keys and values, before it is read into a [`Scenario`].
pub type Document = Map<String, Value>;

/// One step of the scenario format, from version `from` to `from + 1`: it rewrites a document of
/// the older format (without its `version` key) into the newer one.
pub struct Migration {
    pub from: u64,
    pub apply: fn(Document) -> Result<Document>,
}

/// Every step from an older scenario format to [`FORMAT_VERSION`]. Empty while version 1 is the
/// only format there has been; a change to the format adds a step here, so that every scenario
/// file and share link made before it keeps opening.
pub const MIGRATIONS: &[Migration] = &[];

/// Brings a scenario document of format `version` (its `version` key taken out) up to
/// [`FORMAT_VERSION`], one step at a time.
pub fn migrate(version: u64, doc: Document) -> Result<Document> {
    migrate_with(MIGRATIONS, FORMAT_VERSION, version, doc)
}

fn migrate_with(
    chain: &[Migration],
    current: u64,
    version: u64,
    mut doc: Document,
) -> Result<Document> {
    if version > current {
        return Err(Error::field(
            "version",
            format!(
                "scenario version {version} was made by a newer Kumiki; this one reads versions up to {current}"
            ),
        ));
    }
    for from in version..current {
        let step = chain.iter().find(|m| m.from == from).ok_or_else(|| {
            Error::field(
                "version",
                format!(
                    "this Kumiki reads scenario versions from {} to {current}, not {version}",
                    current - chain.len() as u64
                ),
            )
        })?;
        doc = (step.apply)(doc).map_err(|e| match e {
            Error::Field { path, reason } => Error::field(
                path,
                format!(
                    "{reason} (while reading scenario version {from} as {})",
                    from + 1
                ),
            ),
            other => other,
        })?;
    }
    Ok(doc)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scenario;
    use serde_json::json;

    /// A synthetic format 0, older than any real one: it called the step limit `steps` and
    /// wrote the seed as text. Version 1 is the first real format, so the real chain is empty and
    /// the chain mechanism is tested with this one.
    fn from_0(mut doc: Document) -> Result<Document> {
        if let Some(steps) = doc.remove("steps") {
            doc.insert("max_steps".into(), steps);
        }
        if let Some(Value::String(seed)) = doc.get("seed") {
            let seed: u64 = seed
                .parse()
                .map_err(|_| Error::field("seed", format!("'{seed}' is not a whole number")))?;
            doc.insert("seed".into(), seed.into());
        }
        Ok(doc)
    }

    const SYNTHETIC: &[Migration] = &[Migration {
        from: 0,
        apply: from_0,
    }];

    fn object(v: Value) -> Map<String, Value> {
        match v {
            Value::Object(m) => m,
            _ => unreachable!(),
        }
    }

    #[test]
    fn a_version_0_document_migrates_to_the_current_format_and_runs() {
        let v0 = object(json!({
            "model": "amas", "name": "old", "seed": "7", "steps": 40,
            "robots": 2, "target": "##\n##\n"
        }));
        let mut doc = migrate_with(SYNTHETIC, 1, 0, v0).unwrap();
        assert_eq!(doc["max_steps"], json!(40));
        assert_eq!(doc["seed"], json!(7));
        doc.insert("version".into(), json!(1));
        let scenario = Scenario::from_value(Value::Object(doc)).unwrap();
        assert_eq!((scenario.seed, scenario.max_steps), (7, 40));
        // Errors raised by a step name the field and the step.
        let bad = object(json!({"model": "amas", "seed": "seven"}));
        let err = migrate_with(SYNTHETIC, 1, 0, bad).unwrap_err().to_string();
        assert_eq!(
            err,
            "seed: 'seven' is not a whole number (while reading scenario version 0 as 1)"
        );
    }

    #[test]
    fn versions_without_a_path_to_the_current_one_are_refused_by_name() {
        let doc = || object(json!({"model": "amas"}));
        assert!(migrate_with(SYNTHETIC, 1, 2, doc())
            .unwrap_err()
            .to_string()
            .contains("made by a newer Kumiki"));
        // The real chain: version 1 reads as it is; 0 has no step to 1.
        assert_eq!(migrate(1, doc()).unwrap(), doc());
        let err = Scenario::from_value(json!({"version": 0, "model": "amas"}))
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "version: this Kumiki reads scenario versions from 1 to 1, not 0"
        );
        let err = Scenario::from_value(json!({"version": 2, "model": "amas"}))
            .unwrap_err()
            .to_string();
        assert!(err.contains("newer Kumiki"), "{err}");
    }
}
