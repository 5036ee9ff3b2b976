//! The sandbox: what a script may do, and hostile scripts stopped by name, line and cap.

use kumiki_model::rng::Rng;
use kumiki_model::slot::{SlotInfo, MAX_SOURCE_BYTES};
use serde_json::{json, Value};

use crate::caps;

const SLOT: SlotInfo = SlotInfo {
    name: "decide",
    title: "A test slot",
    about: "Answers whatever its script computes.",
    input: &[],
    output: "anything",
    paper: "fn decide(input) { input }",
    random: true,
};

fn run(source: &str, input: Value) -> Result<Value, String> {
    let script = crate::compile(SLOT, source).map_err(|e| format!("compile: {e}"))?;
    script.call(input, None).map_err(|s| s.0)
}

fn refused(source: &str) -> String {
    match crate::check(SLOT, source) {
        Ok(()) => panic!("accepted: {source}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn a_rule_reads_its_input_and_answers() {
    let source = "fn decide(unit) {\n  if unit.near.len() > 1 { unit.near[1] * 2 } else { () }\n}";
    assert_eq!(run(source, json!({"near": [1, 5]})), Ok(json!(10)));
    assert_eq!(run(source, json!({"near": [1]})), Ok(Value::Null));
    // Helper functions, loops, maps and strings are the language's own.
    let source = r#"
        fn double(x) { x * 2 }
        fn decide(unit) {
            let total = 0;
            for v in unit.values { total += double(v); }
            #{ total: total, name: "n" + total }
        }"#;
    assert_eq!(
        run(source, json!({"values": [1, 2, 3]})),
        Ok(json!({"total": 12, "name": "n12"}))
    );
}

#[test]
fn maths_are_the_models_portable_functions_and_floats_print_the_same_everywhere() {
    let source = r#"fn decide(x) {
        [exp(x), ln(x), pow(x, 0.5), sqrt(2), floor(-x), round(x), to_int(x * 10.0),
         `${0.1 + 0.2} ${exp(1.0)} ${1.0e-9} ${1e300 * 10.0}`]
    }"#;
    let answer = run(source, json!(2.5)).unwrap();
    assert_eq!(answer[0], json!(kumiki_model::math::exp(2.5)));
    assert_eq!(answer[1], json!(kumiki_model::math::ln(2.5)));
    assert_eq!(answer[2], json!(kumiki_model::math::pow(2.5, 0.5)));
    assert_eq!(answer[3], json!(2f64.sqrt()));
    assert_eq!(
        answer.as_array().unwrap()[4..7],
        [json!(-3.0), json!(3.0), json!(25)]
    );
    // The same text in the wasm suite (tests/wasm/rules.rs).
    assert_eq!(
        answer[7],
        json!("0.30000000000000004 2.7182818284590455 0.000000001 1e301")
    );
}

#[test]
fn randomness_is_the_models_generator_lent_for_the_call() {
    let script = crate::compile(
        SLOT,
        "fn decide(n) { [random_int(n), random(), random_int(n)] }",
    )
    .unwrap();
    let mut rng = Rng::new(7);
    let mut same = Rng::new(7);
    let answer = script.call(json!(1000), Some(&mut rng)).unwrap();
    let expected = json!([same.below(1000), same.unit(), same.below(1000)]);
    assert_eq!(answer, expected);
    // The generator moved on by the script's draws, as if the model had drawn them.
    assert_eq!(rng.next_u64(), same.next_u64());
    let err = script.call(json!(1000), None).unwrap_err().0;
    assert!(err.contains("draws no random numbers"), "{err}");
    let err = script.call(json!(0), Some(&mut rng)).unwrap_err().0;
    assert_eq!(
        err,
        "rule 'decide' stopped at line 1, column 17: random_int(0): n must be from 1 to 4294967295"
    );
}

#[test]
fn an_endless_loop_stops_at_the_cap_per_call_naming_the_rule_and_the_line() {
    let err = run(
        "fn decide(x) {\n  let n = 0;\n  loop {\n    n += 1;\n  }\n}",
        json!(0),
    )
    .unwrap_err();
    assert!(err.starts_with("rule 'decide' stopped at line 4"), "{err}");
    assert!(
        err.ends_with(&format!(
            "more than {} operations in one call (the cap per call)",
            caps::OPERATIONS_PER_CALL
        )),
        "{err}"
    );
}

#[test]
fn calls_just_under_the_cap_stop_at_the_cap_per_step_until_the_next_step() {
    let script = crate::compile(
        SLOT,
        "fn decide(n) { let i = 0; while i < n { i += 1; } i }",
    )
    .unwrap();
    let calls = |script: &std::rc::Rc<dyn kumiki_model::slot::Script>| {
        (0..100)
            .map(|_| script.call(json!(10_000), None))
            .position(|r| r.is_err())
    };
    // Each call takes 60 006 operations: 2 000 000 a step last 33 calls.
    let stopped = calls(&script).expect("the step's budget runs out");
    assert_eq!(stopped, 33);
    let err = script.call(json!(10_000), None).unwrap_err().0;
    assert!(err.contains("(the cap per step)"), "{err}");
    script.begin_step();
    assert_eq!(calls(&script), Some(stopped));
}

#[test]
fn deep_recursion_stops_at_the_cap_on_call_depth() {
    let err = run(
        "fn down(n) { down(n + 1) }\nfn decide(x) { down(0) }",
        json!(0),
    )
    .unwrap_err();
    assert!(
        err.starts_with("rule 'decide' stopped at line 1, column"),
        "{err}"
    );
    assert!(
        err.ends_with(&format!(
            "calls nested more than {} deep (the cap on call depth)",
            caps::CALL_DEPTH
        )),
        "{err}"
    );
    // Recursion within the cap is the language's own.
    let source =
        "fn fact(n) { if n <= 1 { 1 } else { n * fact(n - 1) } }\nfn decide(n) { fact(n) }";
    assert_eq!(run(source, json!(15)), Ok(json!(1_307_674_368_000_i64)));
}

#[test]
fn huge_arrays_strings_maps_and_variables_stop_at_their_caps() {
    let cases = [
        ("fn decide(x) { let a = []; loop { a.push(1); } }", "the cap on array size"),
        ("fn decide(x) { let a = [[1, 2], [3]]; loop { a = [a, a]; } }", "the cap on array size"),
        ("fn decide(x) { let s = \"x\"; loop { s += s; } }", "the cap on string size"),
        ("fn decide(x) { let m = #{}; let i = 0; loop { let n = #{}; n[`k${i}`] = i; m += n; i += 1; } }", "the cap on map size"),
        ("fn decide(x) { let m = #{}; let i = 0; loop { m[`k${i}`] = i; m.last = i; i += 1; } }", "the cap on map size"),
    ];
    let many: String = (0..40).map(|i| format!("let v{i} = {i}; ")).collect();
    let many = format!("fn decide(x) {{ {many} }}");
    for (source, cap) in cases
        .into_iter()
        .chain([(many.as_str(), "the cap on variables")])
    {
        let err = run(source, json!(0)).unwrap_err();
        assert!(
            err.starts_with("rule 'decide' stopped at line"),
            "{source}: {err}"
        );
        assert!(err.ends_with(&format!("({cap})")), "{source}: {err}");
    }
    let err = run("fn decide(x) { \"y\".pad(100000, \"z\") }", json!(0)).unwrap_err();
    assert!(err.ends_with("(the cap on string size)"), "{err}");
}

#[test]
fn a_source_over_the_limit_is_refused_before_it_is_read() {
    let huge = format!("fn decide(x) {{ x }}\n//{}", "a".repeat(1 << 20));
    assert_eq!(
        refused(&huge),
        format!(
            "rules.decide: {} bytes is too long; a rule's script holds at most {MAX_SOURCE_BYTES}",
            huge.len()
        )
    );
}

#[test]
fn no_eval_no_io_no_clock_no_modules_and_no_platform_maths() {
    assert_eq!(
        refused("fn decide(x) { eval(\"1\") }"),
        "rules.decide: line 1, column 16: eval is not available to a rule: a rule's code is its script"
    );
    assert!(refused("fn decide(x) { x ** 0.5 }").contains("line 1, column 18"));
    assert!(refused("import \"a\" as a;\nfn decide(x) { x }").starts_with("rules.decide: line 1"));
    for missing in [
        "sleep(1)",
        "timestamp()",
        "sin(1.0)",
        "exit()",
        "parse_json(\"1\")",
    ] {
        let err = run(&format!("fn decide(x) {{ {missing} }}"), json!(0)).unwrap_err();
        assert!(err.contains("Function not found"), "{missing}: {err}");
    }
    // print and debug go nowhere.
    assert_eq!(
        run("fn decide(x) { print(x); debug(x); x }", json!(3)),
        Ok(json!(3))
    );
}

#[test]
fn a_script_is_its_functions_and_defines_the_slots_own() {
    assert_eq!(
        refused("let a = 1;\nfn decide(x) { x }"),
        "rules.decide: line 1, column 1: a rule's script holds only functions; this statement outside them would never run"
    );
    assert_eq!(
        refused("fn choose(x) { x }"),
        "rules.decide: the script defines no function decide(input) of one parameter, which the slot calls"
    );
    assert!(refused("fn decide(x) { y }").contains("line 1, column 16"));
    assert!(refused("fn decide(x) {\n  x +\n}").starts_with("rules.decide: line 3"));
    let deep = format!("fn decide(x) {{ {}x{} }}", "(".repeat(80), ")".repeat(80));
    assert!(refused(&deep).ends_with("(the cap on expression depth)"));
}

#[test]
fn a_runtime_error_or_a_throw_stops_the_run_with_its_line() {
    assert_eq!(
        run("fn decide(x) {\n  throw \"no\";\n}", json!(0)),
        Err("rule 'decide' stopped at line 2, column 3: no".into())
    );
    let err = run("fn decide(x) {\n  x[5]\n}", json!([1])).unwrap_err();
    assert!(err.starts_with("rule 'decide' stopped at line 2"), "{err}");
    let err = run("fn decide(x) { 9223372036854775807 + x }", json!(1)).unwrap_err();
    assert!(err.contains("overflow"), "{err}");
    let err = run("fn decide(x) { || x }", json!(1)).unwrap_err();
    assert_eq!(
        err,
        "rule 'decide' answered a value of type Fn; it must answer anything"
    );
}
