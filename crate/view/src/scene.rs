//! What a renderer draws in one frame: the layout of the run, the model's buffers as they stand
//! (borrowed, never copied), the camera and the page's marks.

use crate::camera::Camera;
use crate::geometry::Grid;
use kumiki_model::model::{Agent, Event, Layout, Scene};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// A field drawn as a heat map, with its finite range.
#[derive(Clone, Copy, Debug)]
pub struct Overlay<'a> {
    pub name: &'a str,
    pub data: &'a [f32],
    pub min: f32,
    pub max: f32,
}

/// The model's state as the view reads it, in place.
#[derive(Clone, Copy, Debug)]
pub struct State<'a> {
    /// One code per cell; 0 is empty.
    pub cells: &'a [u8],
    pub agents: &'a [Agent],
    /// What happened during the last step.
    pub events: &'a [Event],
    /// One bond mask per cell (bit d: bonded in direction d); empty when the model has none.
    pub bonds: &'a [u8],
    pub overlay: Option<Overlay<'a>>,
    /// Ghost, light and ground of a 3-D view.
    pub world: &'a Scene,
}

/// What kind of editing cursor a 3-D view shows, or the keyboard cursor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum CursorKind {
    Add,
    Remove,
    Cursor,
}

/// An editing cursor in 3-D (where a unit would be added or removed), or the keyboard cursor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, JsonSchema)]
pub struct Cursor {
    pub cell: u32,
    pub kind: CursorKind,
}

/// The page's marks over the lattice (its hover, selection, cursor and view options).
#[derive(Clone, Debug, PartialEq, Deserialize, JsonSchema)]
#[serde(default, rename_all = "camelCase")]
pub struct Marks {
    /// Gradient arrows over a field that has them.
    pub arrows: bool,
    /// Cell labels when cells are large enough.
    pub labels: bool,
    pub hover: Option<u32>,
    /// Highlighted cells (reachable positions).
    pub highlight: Vec<u32>,
    /// A value per highlighted cell (a difference), labelled in 3-D.
    pub highlight_values: Vec<f64>,
    /// The cell picked with the inspector, outlined.
    pub selected: Option<u32>,
    pub cursor: Option<Cursor>,
    /// One slot's signals: pairs (cell, lit faces as a mask of lattice directions); a sender
    /// with no face bit is ringed.
    pub signals: Vec<u32>,
    /// Units drawn displaced: triples (cell, dx, dy) in cells, y down.
    pub displaced: Vec<f64>,
    /// 3-D view options.
    pub ghost: bool,
    pub bonds: bool,
}

impl Default for Marks {
    fn default() -> Self {
        Marks {
            arrows: true,
            labels: true,
            hover: None,
            highlight: Vec::new(),
            highlight_values: Vec::new(),
            selected: None,
            cursor: None,
            signals: Vec::new(),
            displaced: Vec::new(),
            ghost: true,
            bonds: true,
        }
    }
}

/// Everything one frame draws.
#[derive(Clone, Copy, Debug)]
pub struct SceneRef<'a> {
    pub layout: &'a Layout,
    pub grid: Grid,
    pub state: State<'a>,
    pub camera: &'a Camera,
    pub marks: &'a Marks,
}

/// What a 3-D frame drew, for the page (and its tests) to read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, JsonSchema)]
pub struct RenderStats {
    pub units: u32,
    pub bonds: u32,
    pub ghost: u32,
    pub highlight: u32,
    pub light: bool,
    pub ground: bool,
}
