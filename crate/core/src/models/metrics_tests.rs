//! The metric tables ([`super::MetricInfo`]) against what the models report.

use std::collections::{BTreeMap, BTreeSet};

use super::{metric_info, metric_table, MODELS};
use crate::{lessons, presets, Run, Scenario};

/// Every metric name each model reports, over every preset and lesson, at the start and after
/// some steps (some metrics exist only with two targets or a light).
fn reported() -> BTreeMap<&'static str, BTreeSet<&'static str>> {
    let scenarios: Vec<Scenario> = presets::names()
        .map(|n| presets::scenario(n).unwrap())
        .chain(lessons::names().map(|n| lessons::scenario(n).unwrap()))
        .collect();
    let mut seen: BTreeMap<&'static str, BTreeSet<&'static str>> = BTreeMap::new();
    for scenario in scenarios {
        let model = scenario.model();
        let mut run = Run::new(scenario).unwrap();
        for _ in 0..2 {
            run.model().each_metric(&mut |name, _| {
                seen.entry(model).or_default().insert(name);
            });
            run.advance(20);
        }
    }
    seen
}

#[test]
fn every_reported_metric_has_an_entry_and_every_entry_is_reported() {
    let seen = reported();
    for m in MODELS {
        let names = &seen[m.name];
        for name in names {
            assert!(
                metric_info(m.name, name).is_some(),
                "{}: metric '{name}' has no entry in {}/metrics.rs",
                m.name,
                m.name
            );
        }
        for info in m.metrics {
            assert!(
                names.contains(info.name),
                "{}: '{}' is in the table but no preset or lesson reports it",
                m.name,
                info.name
            );
        }
    }
}

#[test]
fn tables_name_each_metric_once_with_a_unit_and_a_sentence() {
    for m in MODELS {
        let mut names = BTreeSet::new();
        for info in metric_table(m.name).unwrap() {
            assert!(names.insert(info.name), "{}: '{}' twice", m.name, info.name);
            assert!(
                !info.unit.is_empty(),
                "{}: '{}' has no unit",
                m.name,
                info.name
            );
            assert!(
                info.about.ends_with('.') && info.about.len() > 20,
                "{}: '{}' needs a sentence",
                m.name,
                info.name
            );
        }
    }
    assert!(metric_table("nope").is_err());
    assert_eq!(
        metric_info("amas", "total_steps").unwrap().unit,
        "robot steps"
    );
}
