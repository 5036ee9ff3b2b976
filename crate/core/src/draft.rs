//! The scenario the page shows and edits, held read between edits ([`Draft`]).
//!
//! The page's simulation worker keeps one draft, beside the run it builds from it. Opening a text
//! (a preset, a link, the JSON editor, undo) reads and checks it once; an edit applies its changes
//! to the scenario held and checks the result once, without reading any text; either answers with
//! a [`Proposal`]: the text to run, or why it was refused (its own problem, or an exercise's lock).
//! The run is then built from the checked scenario the draft holds ([`Draft::start`]), checking
//! nothing again. A scenario too large to check at once (its shapes span more than
//! [`Draft::new`]'s cells, counted from the text) is proposed unchecked, so that the page can say
//! so first; the run that checks it as it opens gives it back ([`Draft::ran`]).

use schemars::JsonSchema;
use serde::Serialize;
use serde_json::Value;

use crate::error::{Error, Result};
use crate::exercise::Goal;
use crate::scenario::set_path;
use crate::{grading, json, link, shape, Run, Scenario};

/// What an edit or an opening would make of the scenario in view.
#[derive(Clone, Debug, Default, PartialEq, Serialize, JsonSchema)]
pub struct Proposal {
    /// The scenario to run, as indented JSON: canonical, every default written out, when it was
    /// checked here; as written when it is too large to check here. Empty when refused.
    pub text: String,
    /// Why it was refused, briefly (under 200 characters): the scenario's own problem, naming the
    /// field and the rule, or an exercise's lock. Null when it may run.
    pub problem: Option<String>,
    /// The whole of the scenario's own problem, when it says more than `problem`.
    pub in_full: Option<String>,
    /// The cells of its largest shape when it is too large to check here (the worker checks it as
    /// it opens it; it becomes the scenario in view once the worker ran it); 0 when checked here.
    pub large_cells: f64,
}

/// A scenario's comparison (its `compare` section), as the page opens it.
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Comparison {
    /// The scenario compares nothing.
    None,
    /// The second run's scenario (indented JSON: this one with the one setting changed) and the
    /// two runs' names in words, the first run's first.
    Pair { second: String, labels: [String; 2] },
    /// The scenario is too large to check on the page's thread, and is not run twice: the
    /// second run would double the memory the page asked about.
    TooLarge,
}

/// The scenario in view, held between edits.
#[derive(Clone, Debug)]
pub struct Draft {
    /// Scenarios whose shapes span more cells than this are not checked here.
    check_up_to: u64,
    /// Read and checked; `None` before the first scenario opens.
    current: Option<Box<Scenario>>,
}

impl Draft {
    /// A draft with nothing in view, which checks scenarios whose shapes span up to `check_up_to`
    /// cells and leaves larger ones to the worker.
    pub fn new(check_up_to: u64) -> Draft {
        Draft {
            check_up_to,
            current: None,
        }
    }

    /// Opens scenario JSON text in place of the one in view: read once and, unless too large,
    /// checked once. `keep_locks`: an edit of the scenario in view (the JSON editor's), which an
    /// exercise's locks hold back; an opening (a link, the gallery, undo) is not held back.
    pub fn open(&mut self, text: &str, keep_locks: bool) -> Proposal {
        let doc = match json::parse(text) {
            Ok(doc) => doc,
            Err(e) => return refused(Error::json(&e)),
        };
        let current = match self.current.is_some() && keep_locks {
            true => match self.document() {
                Ok(current) => Some(current),
                Err(e) => return refused(e),
            },
            false => None,
        };
        self.propose(doc, current, keep_locks)
    }

    /// Changes dotted paths of the scenario in view (`stages.0.target`), all at once: the result
    /// is checked once, as a whole, and held to the exercise's locks.
    pub fn edit(&mut self, changes: &[(String, Value)]) -> Proposal {
        let current = match self.document() {
            Ok(doc) => doc,
            Err(e) => return refused(e),
        };
        let mut doc = current.clone();
        for (path, value) in changes {
            if let Err(e) = set_path(&mut doc, path, value.clone()) {
                return refused(e);
            }
        }
        self.propose(doc, Some(current), true)
    }

    /// The run of the scenario in view, built from the checked scenario held: what checking it
    /// learnt goes into the model, nothing is read or checked again, and the draft holds the
    /// scenario the run keeps.
    pub fn start(&mut self) -> Result<Run> {
        let scenario = self
            .current
            .take()
            .ok_or_else(|| Error::field("", "no scenario is open"))?;
        let run = Run::new(*scenario)?;
        self.ran(run.scenario().clone());
        Ok(run)
    }

    /// The run in view runs `scenario`: one too large to check at once, which its run checked as
    /// it opened, or the one in view with a click recorded.
    pub fn ran(&mut self, scenario: Scenario) {
        self.current = Some(Box::new(scenario));
    }

    /// The share-link payload of the scenario in view, or of it named `name` (a student's
    /// hand-in).
    pub fn link(&self, name: Option<&str>) -> Result<String> {
        let scenario = self.held()?;
        match name {
            None => Ok(link::encode(scenario)),
            Some(name) => Ok(link::encode(&scenario.with_override("name", name.into())?)),
        }
    }

    /// The hand-in link of the scenario in view: named `name`, with the hand-in's record
    /// (`record`: when, how many checks and hints, the answer to the exercise's question), checked
    /// as the scenario's `handin` section. The page gives the time: the core has no clock.
    pub fn handin(&self, name: &str, record: Value) -> Result<String> {
        let mut doc = self.document()?;
        if doc.get("exercise").is_none() {
            return Err(Error::field(
                "exercise",
                "the scenario in view is no exercise: there is nothing to hand in",
            ));
        }
        crate::handin::Handin::from_value(record.clone()).map_err(|e| e.within("handin"))?;
        set_path(&mut doc, "name", name.into())?;
        set_path(&mut doc, "handin", record)?;
        Ok(link::encode(&Scenario::from_value(doc)?))
    }

    /// Why a click of the tool `label`, whose action is of `kind`, may not be made on the
    /// scenario in view (its exercise allows no more of that kind), in words the page shows
    /// where the click is made; `None` when it may (or when no exercise is in view). The
    /// simulation worker refuses such a click anyway (`Playback::apply`); this lets the page show
    /// the tool as locked before it is used.
    pub fn click_problem(&self, kind: &str, label: &str) -> Option<String> {
        let doc = self.document().ok()?;
        let exercise: crate::exercise::Exercise =
            serde_json::from_value(doc.get("exercise")?.clone()).ok()?;
        exercise.click_problem(kind, label, crate::exercise::listed(&doc))
    }

    /// How many more disturbances of `kind` the exercise in view lets a student add (its
    /// allowance less those the scenario already adds), for the page to count down beside the
    /// tool; `None` when no exercise is in view (clicks are not counted).
    pub fn clicks_left(&self, kind: &str) -> Option<u32> {
        let doc = self.document().ok()?;
        let exercise: crate::exercise::Exercise =
            serde_json::from_value(doc.get("exercise")?.clone()).ok()?;
        let added = exercise.added(kind, crate::exercise::listed(&doc));
        Some(exercise.allowed(kind).saturating_sub(added))
    }

    /// The scenario in view's comparison. Its `compare` section was checked with the scenario, so
    /// nothing is checked again here: the second run's worker checks the second scenario as it
    /// opens it. A scenario too large to check at once is not run twice.
    pub fn comparison(&self) -> Result<Comparison> {
        let doc = self.document()?;
        let Some(section) = doc.get("compare").cloned() else {
            return Ok(Comparison::None);
        };
        if shape::estimate_cells(&doc) > self.check_up_to {
            return Ok(Comparison::TooLarge);
        }
        let compare = crate::compare::Compare::from_value(section, &doc)?;
        let (first, second_label) = compare.labels(&doc);
        let mut second = doc;
        if let Value::Object(map) = &mut second {
            map.remove("compare");
            map.remove("exercise");
        }
        set_path(&mut second, &compare.path, compare.value)?;
        Ok(Comparison::Pair {
            second: json::pretty(&second).map_err(|e| Error::json(&e))?,
            labels: [first, second_label],
        })
    }

    /// What is wrong with an exercise goal written for the scenario in view, whose model reports
    /// `metrics`; `None` when it reads well.
    pub fn goal_problem(&self, goal: &str, metrics: &[String]) -> Option<String> {
        match Goal::parse(goal) {
            Err(e) => Some(e.to_string()),
            Ok(goal) => {
                let doc = self.document().unwrap_or(Value::Null);
                grading::unknown_name(&goal, metrics, &doc)
            }
        }
    }

    /// The scenario in view.
    fn held(&self) -> Result<&Scenario> {
        self.current
            .as_deref()
            .ok_or_else(|| Error::field("", "no scenario is open"))
    }

    /// The scenario in view as a JSON document.
    fn document(&self) -> Result<Value> {
        self.held().map(Scenario::to_value)
    }

    /// Reads and checks `doc` (unless too large) and holds it to the locks of the exercise in
    /// `current` when `keep_locks`. Checked here, it becomes the scenario in view; too large, it
    /// does once its worker ran it ([`Draft::ran`]).
    fn propose(&mut self, doc: Value, current: Option<Value>, keep_locks: bool) -> Proposal {
        let cells = shape::estimate_cells(&doc);
        // Read and checked, unless too large: then left as it is, for its run to check.
        let (checked, unchecked) = match cells > self.check_up_to {
            true => (None, Some(doc)),
            false => match Scenario::from_value(doc) {
                Ok(scenario) => (Some(scenario), None),
                Err(e) => return refused(e),
            },
        };
        if let Some(current) = current.as_ref().filter(|_| keep_locks) {
            let next = match (&checked, &unchecked) {
                (Some(scenario), _) => scenario.to_value(),
                (None, doc) => doc.clone().unwrap_or(Value::Null),
            };
            if let Some(problem) = grading::locked_problem(current, &next) {
                return Proposal {
                    problem: Some(problem),
                    ..Proposal::default()
                };
            }
        }
        let (text, large_cells) = match (checked, unchecked) {
            (Some(scenario), _) => {
                let text = scenario.to_json_pretty();
                self.current = Some(Box::new(scenario));
                (text, 0)
            }
            (None, doc) => match json::pretty(&doc.unwrap_or(Value::Null)) {
                Ok(text) => (text, cells),
                Err(e) => return refused(Error::json(&e)),
            },
        };
        Proposal {
            text,
            problem: None,
            in_full: None,
            large_cells: large_cells as f64,
        }
    }
}

/// A proposal refused for the scenario's own problem: brief, and whole when that says more.
fn refused(e: Error) -> Proposal {
    let problem = e.to_string();
    let whole = format!("{e:#}");
    Proposal {
        in_full: (whole != problem).then_some(whole),
        problem: Some(problem),
        ..Proposal::default()
    }
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;
    use crate::{counts, lessons, presets};

    const PAGE: u64 = 1 << 18;

    fn opened(name: &str) -> Draft {
        let mut draft = Draft::new(PAGE);
        let text = presets::scenario(name)
            .or_else(|_| lessons::scenario(name))
            .unwrap()
            .to_json_pretty();
        assert_eq!(draft.open(&text, false).problem, None);
        draft
    }

    fn edit(draft: &mut Draft, path: &str, value: Value) -> Proposal {
        draft.edit(&[(path.to_string(), value)])
    }

    /// One edit of the page's form reads no scenario text and checks the result once, and the
    /// run is built from the scenario checked, reading and checking nothing again. (The string
    /// relay before the draft read the scenario's text 9 times and checked it 4 times on the page's
    /// thread, and 1 and 2 times in the worker; the draft on the page's thread, with the worker
    /// reading its text again, read it once and checked it twice.)
    #[test]
    fn an_edit_reads_no_text_and_checks_once() {
        for name in presets::names() {
            let mut draft = opened(name);
            let scenario = presets::scenario(name).unwrap();
            let (parses, checks, builds) = (counts::parses(), counts::checks(), counts::builds());
            let proposal = edit(&mut draft, "seed", json!(7));
            assert_eq!(proposal.problem, None, "{name}");
            assert_eq!(counts::parses() - parses, 0, "{name}: the edit read text");
            assert_eq!(counts::checks() - checks, 1, "{name}: checks per edit");
            assert_eq!(counts::builds(), builds, "{name}: the edit built the model");
            let expected = scenario.with_override("seed", json!(7)).unwrap();
            assert_eq!(proposal.text, expected.to_json_pretty(), "{name}");
            // The run: no read, no check, one build.
            let (parses, checks) = (counts::parses(), counts::checks());
            let run = draft.start().unwrap();
            assert_eq!(counts::parses() - parses, 0, "{name}: the run read text");
            assert_eq!(counts::checks(), checks, "{name}: the run checked again");
            assert_eq!(counts::builds() - builds, 1, "{name}");
            assert_eq!(run.scenario().seed, 7);
            assert_eq!(run.scenario().to_json_pretty(), proposal.text, "{name}");
            // The draft holds the scenario the run keeps: the next edit starts from it.
            assert_eq!(
                draft.link(None).unwrap(),
                link::encode(run.scenario()),
                "{name}"
            );
        }
    }

    /// The page asks before a click whether the exercise in view allows it, and hands in a link
    /// that carries the hand-in's record.
    #[test]
    fn a_locked_click_is_known_before_it_is_made_and_a_hand_in_carries_its_record() {
        let mut draft = opened("lesson-amas-heatmap");
        assert_eq!(
            draft.click_problem("dismantle", "Mark to be removed (6.2)").unwrap(),
            "Mark to be removed (6.2) is locked by the exercise: it allows no 'dismantle' disturbance"
        );
        assert_eq!(draft.clicks_left("dismantle"), Some(0));
        let record =
            json!({"made": "2026-11-28T10:15:00Z", "checks": 2, "hints": 1, "answer": "A T."});
        let link = draft.handin("Ada", record).unwrap();
        let handin = crate::link::decode(&link).unwrap();
        assert_eq!(handin.name, "Ada");
        assert_eq!(handin.handin.unwrap().answer, "A T.");
        assert!(draft
            .handin("Ada", json!({"made": "now"}))
            .unwrap_err()
            .to_string()
            .starts_with("handin.made:"));
        draft = opened("amas-L");
        assert_eq!(draft.click_problem("remove", "Remove module"), None);
        assert_eq!(
            draft.clicks_left("remove"),
            None,
            "no exercise: not counted"
        );
        assert!(
            draft.handin("Ada", json!({})).is_err(),
            "no exercise in view"
        );
    }

    /// A refused edit says why, by field, and leaves the scenario in view as it was.
    #[test]
    fn a_refused_edit_keeps_the_scenario_in_view() {
        let mut draft = opened("amas-L");
        let refused = edit(&mut draft, "robots", json!(0));
        assert_eq!(
            refused.problem.as_deref(),
            Some("robots: at least one robot is needed")
        );
        assert!(refused.text.is_empty());
        let unknown = edit(&mut draft, "robot", json!(3));
        assert!(unknown.problem.unwrap().starts_with("robot: "));
        let next = edit(&mut draft, "robots", json!(3));
        assert_eq!(next.problem, None);
        let doc: Value = serde_json::from_str(&next.text).unwrap();
        assert_eq!((doc["robots"].clone(), doc.get("robot")), (json!(3), None));
        // Several changes at once are checked together: each alone would be refused.
        let both = draft.edit(&[
            ("robots".into(), json!(30)),
            ("supply_rows".into(), json!(3)),
        ]);
        assert_eq!(both.problem, None);
    }

    /// An exercise's locked fields keep the teacher's values through edits (the JSON editor's
    /// included); opening another scenario is not an edit.
    #[test]
    fn locked_fields_refuse_edits_but_not_openings() {
        let mut draft = opened("lesson-amas-robots");
        let free = edit(&mut draft, "robots", json!(4));
        assert_eq!(free.problem, None);
        let locked = edit(&mut draft, "collision", json!("relay"));
        assert!(
            locked
                .problem
                .unwrap()
                .starts_with("locked by the exercise"),
            "a locked field changed"
        );
        assert_eq!(locked.in_full, None);
        let mut doc: Value = serde_json::from_str(&free.text).unwrap();
        doc["collision"] = json!("relay");
        let text = doc.to_string();
        assert!(draft.open(&text, true).problem.is_some());
        assert_eq!(draft.open(&text, false).problem, None);
    }

    /// A scenario too large to check here is held as written for the worker, and becomes the one
    /// in view once its worker ran it; its edits are not checked here either.
    #[test]
    fn a_large_scenario_is_left_to_the_worker() {
        let mut draft = opened("amas-L");
        let mut large = presets::scenario("amas-L").unwrap().to_value();
        large["target"] = json!({"rect": [1024, 1024]});
        let checks = counts::checks();
        let proposal = draft.open(&large.to_string(), false);
        assert_eq!((proposal.problem, proposal.large_cells), (None, 1048576.0));
        assert_eq!(counts::checks(), checks, "checked on the page's thread");
        // Until the worker ran it, the scenario in view is the one before.
        let before = edit(&mut draft, "seed", json!(3));
        assert_eq!(
            serde_json::from_str::<Value>(&before.text).unwrap()["target"],
            presets::scenario("amas-L").unwrap().to_value()["target"]
        );
        draft.ran(Scenario::from_json(&proposal.text).unwrap());
        let checks = counts::checks();
        let edited = edit(&mut draft, "seed", json!(5));
        assert_eq!((edited.problem, edited.large_cells), (None, 1048576.0));
        assert_eq!(counts::checks(), checks);
        assert_eq!(
            serde_json::from_str::<Value>(&edited.text).unwrap()["seed"],
            json!(5)
        );
    }

    /// A comparison's second scenario is the one the core derives, made without checking again;
    /// a scenario too large to check here is not run twice.
    #[test]
    fn a_comparison_is_derived_without_checking_again() {
        let draft = opened("lesson-amas-compare");
        let scenario = lessons::scenario("lesson-amas-compare").unwrap();
        let checks = counts::checks();
        let Comparison::Pair { second, labels } = draft.comparison().unwrap() else {
            panic!("the lesson compares two runs")
        };
        assert_eq!(counts::checks(), checks);
        let second = Scenario::from_json(&second).unwrap();
        assert_eq!(second, scenario.compared().unwrap().unwrap());
        assert_eq!(
            labels,
            ["collision relay".to_string(), "tokens only".to_string()]
        );
        assert_eq!(opened("amas-L").comparison().unwrap(), Comparison::None);
        let mut large = Draft::new(100);
        assert!(large.open(&scenario.to_json_pretty(), false).large_cells > 0.0);
        large.ran(scenario.clone());
        assert_eq!(large.comparison().unwrap(), Comparison::TooLarge);
    }

    /// The link of the scenario in view is the core's link of it, named as a hand-in when asked.
    #[test]
    fn links_are_made_from_the_scenario_held() {
        let draft = opened("amas-L");
        let scenario = presets::scenario("amas-L").unwrap();
        assert_eq!(draft.link(None).unwrap(), link::encode(&scenario));
        let handin = link::open(&draft.link(Some("Ada")).unwrap())
            .unwrap()
            .scenario;
        assert_eq!(handin.name, "Ada");
        assert_eq!(
            handin.with_override("name", json!("amas-L")).unwrap(),
            scenario
        );
        assert!(draft.link(Some(&"n".repeat(101))).is_err());
        assert!(Draft::new(PAGE).link(None).is_err());
    }

    /// Text that is no scenario is refused briefly, with the whole message when it says more.
    #[test]
    fn problems_are_brief_with_the_whole_message_beside() {
        let mut draft = Draft::new(PAGE);
        let broken = draft.open("{\"model\": ", false);
        assert!(broken.problem.is_some() && broken.text.is_empty());
        let mut doc = presets::scenario("amas-L").unwrap().to_value();
        doc["robots"] = json!("many");
        let refused = draft.open(&doc.to_string(), false);
        let (problem, whole) = (refused.problem.unwrap(), refused.in_full);
        assert!(problem.starts_with("robots: "), "{problem}");
        assert!(problem.len() < 200);
        if let Some(whole) = whole {
            assert!(whole.len() > problem.len());
        }
    }

    /// A teacher's goal is checked against the scenario in view and its model's metrics.
    #[test]
    fn goals_are_checked_against_the_scenario_held() {
        let draft = opened("amas-L");
        let metrics = ["steps".to_string(), "collisions".to_string()];
        assert_eq!(
            draft.goal_problem("completed and scenario.robots <= 6", &metrics),
            None
        );
        let unknown = draft
            .goal_problem("metrics.colisions < 3", &metrics)
            .unwrap();
        assert!(unknown.contains("collisions"), "{unknown}");
        let field = draft.goal_problem("scenario.robot <= 6", &metrics).unwrap();
        assert!(field.contains("robot"), "{field}");
        assert!(draft.goal_problem("completed and", &metrics).is_some());
    }
}
