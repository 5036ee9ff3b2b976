//! The world text, the parameters and the terrain beyond the right edge.

use super::*;

#[test]
fn world_text_errors_name_the_line() {
    let bad = |w: &str| refusal(w, json!({}));
    assert_eq!(
        bad("....\n.#x.\n===="),
        "world: line 2, column 3: 'x' is not a tile; use '=' for terrain, '#' for a robot and '.' for empty"
    );
    assert!(
        bad("#...\n..#.\n====").starts_with("world: line 2, column 3: this robot is not connected")
    );
    assert!(bad("##..\n....\n====").contains("no robot rests on the terrain"));
    assert!(bad("....\n====").contains("there is no robot"));
    assert!(bad("\n\n").contains("the world is empty"));
}

#[test]
fn parameters_are_checked() {
    let bad = |extra| refusal("#\n=", extra);
    assert!(bad(json!({"board": 0.2})).starts_with("board:"));
    assert!(bad(json!({"safety_factor": 0})).starts_with("safety_factor:"));
    assert!(bad(json!({"method": "guess"})).starts_with("method:"));
    assert!(bad(json!({"goal": 0})).starts_with("goal:"));
    assert!(bad(json!({"colour": 1})).contains("unknown field"));
}

#[test]
fn extend_copies_the_rightmost_terrain_column() {
    let w = spec::parse_world("#.\n==\n", 3, &kumiki_model::Limits::PAGE).unwrap();
    assert_eq!(w.w, 5);
    assert_eq!(w.get(4, 1), spec::Tile::Ground);
    assert_eq!(w.get(4, 0), spec::Tile::Empty);
}
