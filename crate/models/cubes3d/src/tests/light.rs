//! Section 6: the light's priority on each unit's positions, each unit's clock, the ladder that
//! forms with the lit units held, and links of earlier versions replaying as they did.

use super::runs::check_invariants;
use super::*;
use kumiki_core::{hash, link};

fn light(over: &[(&str, Value)], seed: u64) -> Cubes {
    let mut s = presets::scenario("cubes-light").unwrap();
    for (k, v) in over {
        s = s.with_override(k, v.clone()).unwrap();
    }
    s.seed = seed;
    Cubes::new(&s).unwrap()
}

/// Whether the unit at `p` has a reachable position nearer the light.
fn can_approach(m: &Cubes, p: usize) -> bool {
    let here = m.along_light(p);
    m.reach_report(p)
        .iter()
        .any(|&(dest, _)| m.along_light(dest as usize) > here)
}

#[test]
fn with_the_priority_on_positions_a_unit_that_can_approach_the_light_does() {
    let (mut toward, mut otherwise) = (0, 0);
    for seed in 1..=3 {
        let mut m = light(&[], seed);
        for _ in 0..400 {
            let could: Vec<usize> = m
                .movable
                .iter()
                .map(|&c| c as usize)
                .filter(|&c| can_approach(&m, c))
                .collect();
            let moves = m.moves;
            m.step();
            if m.moves == moves {
                continue;
            }
            let from = m.events.iter().find(|e| e.kind == LEFT).unwrap().cell as usize;
            let to = m.events.iter().find(|e| e.kind == ARRIVED).unwrap().cell as usize;
            if could.contains(&from) {
                assert!(
                    m.along_light(to) > m.along_light(from),
                    "seed {seed} step {}: a unit that could approach the light moved otherwise",
                    m.steps
                );
                toward += 1;
            } else {
                otherwise += 1;
            }
        }
        check_invariants(&m);
    }
    // Both kinds of unit move: the rule is tested, not vacuous.
    assert!(toward > 50 && otherwise > 50, "{toward} {otherwise}");
}

#[test]
fn each_units_clock_restarts_when_it_switches_target() {
    let mut m = light(&[], 2);
    while m.switches == 0 {
        m.step();
    }
    let switched: Vec<usize> = m
        .units
        .iter()
        .map(|&c| c as usize)
        .filter(|&c| m.took[m.upos[c] as usize] == m.steps)
        .collect();
    assert!(!switched.is_empty());
    m.run_temperature = m.temperature_at(m.steps + 1);
    for &c in &m.units {
        let c = c as usize;
        let want = match switched.contains(&c) {
            // The first step on its new target is its step 1: T = C / ln 2.
            true => m.temperature_at(1),
            false => m.run_temperature,
        };
        assert_eq!(m.temperature(c), want, "cell {c}");
    }
    // On the run's clock every unit has the run's temperature.
    let mut m = light(&[("clock", json!("run"))], 2);
    for _ in 0..200 {
        m.step();
    }
    assert!(m.switches > 0);
    m.run_temperature = m.temperature_at(m.steps + 1);
    assert!(m
        .units
        .iter()
        .all(|&c| m.temperature(c as usize) == m.run_temperature));
    // With a single target nobody switches, and the two clocks are the same run.
    let runs = |clock: &str| {
        let mut s = presets::scenario("cubes-box12-ladder")
            .unwrap()
            .with_override("clock", json!(clock))
            .unwrap();
        s.seed = 5;
        let mut run = Run::new(s).unwrap();
        run.advance(300);
        hash::hex(run.state_hash())
    };
    assert_eq!(runs("target"), runs("run"));
}

#[test]
fn the_ladder_that_forms_with_the_lit_units_held_is_a_plank_facing_the_light() {
    // With the four lit units of the cube's front face held, a 2×4 ladder that holds them lies in
    // their plane: every complete ladder is a vertical plank facing the light, never flat.
    let mut formed = 0;
    for seed in 1..=10 {
        let mut m = light(&[], seed);
        for _ in 0..1000 {
            m.step();
            let all_ladder = m.units.iter().all(|&c| m.target[c as usize] == 1);
            if !all_ladder || m.zero != m.units.len() {
                continue;
            }
            formed += 1;
            let held: Vec<usize> = m
                .units
                .iter()
                .map(|&c| c as usize)
                .filter(|&c| m.flags[c] & HELD_LIT != 0)
                .collect();
            assert_eq!(held.len(), 4, "seed {seed}");
            let x = m.along_light(held[0]);
            assert!(
                m.units.iter().all(|&c| m.along_light(c as usize) == x),
                "seed {seed} step {}: a complete ladder off the lit face's plane",
                m.steps
            );
        }
    }
    assert!(formed > 0, "no complete ladder formed in ten runs");
}

/// Links made with model version 4, before the priority on positions, the clock restarting at a
/// switch and "no motion" for random selection: cubes-light as it was then, and the ladder with
/// random selection (seed 3).
const LIGHT_V4: &str = "k1.jVTRbtswDPwVQn1YizqGk7TrkGJP3b5gA4ahLQLFpmNhimRIcp2i6L_vaCVpi73swbFEinenI50XpdVqUVaFqtXqWt4NxzqYPhnv1Er94FpW9Jl8S7997EyjiRNpW9J5a7ZD4EjzBSVP86uLFWlaPAxV1dwcX1QPGyYgaOqtdkw7_4SS5EcdGgSt2XYC592WLve0eaY4mlR3BvsNp5HZURo9JR22nGJBqeOMqZ3Ut1anI-cVWd00HEr6ruuOBmfSAQ2MJkXyozsA0dgBWGKNaVsO7Gqmb-uKOh0pJv3MDeqBNfHlmk-Q3eG-nbcNnc_LatJR0BesMvEFtT7QsgIC9_EW8iYNqdPvhMAqwcwV0GEskwhlyUlickRIRImx9la8l4yAxYxWd95HFizxs4DBDCgJyZ503wevM90JcuuxbU2IqaSfiOZ-ZKJ38H7I7kOTNX-ARRvvmmLyW47FFIY6ofGTT4K4h1lQgoLzbfCwDXPgoDBclPSLvlJVXqMci0VBd3hdZ_4wuMlu5yFNW4Go_a63nHiFy8gtAQZJJutrTITkmnfs0nGATrcrVaEyOaY2syMypRC43GOzQxcNhnq-kPV-PTUJ26rC2O98wxYnpaVx2chx_6Q3ltXqXt3Nsb9bTL_LuXqckhzWUJTAhTM3h5DgFcrpHR-xZllDodDgZspGtvmrwpFdaCXV6V4Kzs4enDyz2Swv5JF8EiVHwUvIPXwOEPeipINra3DPVtvIH-j_A_w00xAnfwDpuWfARUGX697jQd8OP4-oeS3ek2Ic3jjzVH9gzVT_kuGzeYWTYtrkBZwZ1UpmJTdjfcpcvf4F";
const RANDOM_LADDER_V4: &str = "k1.dVJdS8MwFP0rl_jioC3tOp0W9jTYmy--iGwy0uZuDWRJTdJNGf537-06QcQ85H7m5NyTnIUUVZHliWjI5uwoDI3XXdTOikqs9L73GGAO0ip4BLeDVxdarSRgBGkyuOVCwIYPwB03xBYpYXapx05qD53s0E8qiCc0R4Te6hhAW5CwMzLCdNPnuZrfg5FKoYe610ZRccyPpoTafSRwYVejgvoTlmWxXs6KhJ1hextYUmpM_67d4nsvB5rlJIOn5xWzHImfdGzhBRZQJnT1AvgMmzwTidh711tFalhnkeKD9HtN6jyw-7ENEbsgqrs8J_kOTqGh1qavMZSKu91R1gZFtRbLguLldNjLQrwNRfRbpUOUtqGe-ZgivCIRVh7wipXS_MU0vYhEAAGRKJXsjENQp6f53YGrLYlOiZthbezVcikynSvrkjhHmgcjBeuzaJ1RW6OjqHbSBPzhQLf_gmXIjU3T9OL8Cag5tvRzGE9Uw8-Knx0SdOCbxN-329h_Ho7AvkgqVmWYkoQ5EfHsqvb2pzL7-gY";

#[test]
fn links_made_before_version_5_replay_as_they_did() {
    // The state hashes those links gave with model version 4 (the golden fixture of cubes-light
    // then, and the ladder's run by that program).
    for (text, seed, steps, want) in [
        (LIGHT_V4, None, 150, "bdc05c4b9d86462e"),
        (LIGHT_V4, Some(7), 400, "eba29c1bc515bc6f"),
        (RANDOM_LADDER_V4, None, 300, "9b2e74199ab27094"),
    ] {
        let opened = link::open(text).unwrap();
        assert_eq!((opened.made_with, opened.current), (4, ENTRY.model_version));
        let mut scenario = opened.scenario;
        if let Some(seed) = seed {
            scenario.seed = seed;
        }
        let mut run = Run::new(scenario).unwrap();
        run.advance(steps);
        assert_eq!(hash::hex(run.state_hash()), want);
    }
}
