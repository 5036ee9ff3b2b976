//! The view's records that cross to and from the page: the page's marks, what a frame drew and
//! what is under the pointer. Their TypeScript types (`web/view.gen.ts`) are generated from these
//! Rust types by the contract's generator, and a test holds the file to them (re-written with
//! `KUMIKI_BLESS=1 cargo test -p kumiki-view contract`).

use schemars::generate::SchemaSettings;
use serde_json::{json, Map, Value};

use crate::camera::Picked;
use crate::scene::{Marks, RenderStats};

/// Where the generated types live, from the repository root.
pub const TYPESCRIPT_FILE: &str = "web/view.gen.ts";

/// The JSON Schema of the view's records, one definition each.
pub fn schema() -> Value {
    let mut generator = SchemaSettings::draft2020_12().into_generator();
    generator.subschema_for::<Marks>();
    generator.subschema_for::<RenderStats>();
    generator.subschema_for::<Picked>();
    let defs: Map<String, Value> = generator.take_definitions(true).into_iter().collect();
    json!({ "$defs": defs })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// web/view.gen.ts is what the view's records say.
    #[test]
    fn the_views_contract_is_current() {
        let text = format!(
            "// Generated from the view's records (crate/view/src/contract.rs): do not edit.\n{}",
            kumiki_model::typescript::declarations(&schema())
        );
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join(TYPESCRIPT_FILE);
        if std::env::var_os("KUMIKI_BLESS").is_some() {
            std::fs::write(&path, &text).unwrap();
        }
        let published = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            published == text,
            "{TYPESCRIPT_FILE} is stale: run 'KUMIKI_BLESS=1 cargo test -p kumiki-view contract' and commit it"
        );
    }
}
