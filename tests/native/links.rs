//! Share links: round trips for every preset and clear errors for damaged links.

use kumiki_core::{link, presets, Error};

#[test]
fn every_preset_survives_a_link_round_trip() {
    for name in presets::names() {
        let scenario = presets::scenario(name).unwrap();
        let encoded = link::encode(&scenario);
        assert!(encoded.starts_with(link::PREFIX));
        assert!(encoded[3..]
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_'));
        for form in [
            encoded.clone(),
            format!("#{encoded}"),
            format!("https://example.org/sub/path/index.html?x=1#{encoded}"),
        ] {
            assert_eq!(link::decode(&form).unwrap(), scenario, "{name} via {form}");
        }
    }
}

#[test]
fn damaged_links_are_errors_that_say_so() {
    let good = link::encode(&presets::scenario("amas-L").unwrap());
    let cases = [
        ("", "starts with"),
        ("#hello", "starts with"),
        ("#k9.abcdef", "another Kumiki version"),
        (
            "#k1.***",
            "damaged: it holds '*', which no Kumiki link has (character 1",
        ),
        ("#k1.ab%20", "'%'"),
        (&good[..good.len() / 2], "damaged"),
    ];
    for (input, expect) in cases {
        let err = link::decode(input).unwrap_err();
        assert!(matches!(err, Error::Link(_)), "{input}: {err}");
        assert!(err.to_string().contains(expect), "{input}: {err}");
        assert!(
            !err.to_string().contains("Invalid symbol"),
            "{input}: {err}"
        );
    }
}

#[test]
fn a_link_to_an_invalid_scenario_names_the_field() {
    use base64::Engine as _;
    let json = r###"{"version":1,"model":"amas","target":"##","robots":0}"###;
    let packed = miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 6);
    let payload = format!(
        "k1.{}",
        base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(packed)
    );
    let err = link::decode(&payload).unwrap_err().to_string();
    assert!(err.starts_with("robots:"), "{err}");
}

#[test]
fn decompression_bombs_are_refused() {
    use base64::Engine as _;
    let huge = vec![b' '; link::MAX_SCENARIO_BYTES + 10];
    let packed = miniz_oxide::deflate::compress_to_vec(&huge, 9);
    let payload = format!(
        "k1.{}",
        base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(packed)
    );
    assert!(link::decode(&payload)
        .unwrap_err()
        .to_string()
        .contains("larger than"));
}

#[test]
fn canonical_scenarios_state_every_default() {
    // fracta-triangle10's file leaves K, L, G and I_th at their defaults; the canonical form, and
    // so every link, writes them out.
    let s = presets::scenario("fracta-triangle10").unwrap();
    for key in ["K", "L", "G", "I_th"] {
        assert!(
            s.body.contains_key(key),
            "{key} missing from the canonical scenario"
        );
    }
    // Reading the canonical form again changes nothing.
    let again = kumiki_core::Scenario::from_json(&s.to_json()).unwrap();
    assert_eq!(again, s);
}
