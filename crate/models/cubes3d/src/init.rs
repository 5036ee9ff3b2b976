//! Building the model from its checked description: the space, the units, the targets and the per-cell books.

use super::connect::Scratch;
use super::motion::{Structure, PAD};
use super::spec::{Checked, Ground};
use super::state::whole_diffs;
use super::typelist::{self, TypeList};
use super::{Cubes, Target};
use kumiki_model::rng::Rng;
use kumiki_model::shape::Grid3;

impl Cubes {
    /// The model at step 0, from its checked description.
    pub fn from_checked(checked: Checked, seed: u64) -> Cubes {
        let Checked {
            spec,
            movable_types,
            light,
            shape,
            target_lists,
            target_shapes,
            dims,
            below,
            max_units,
        } = checked;
        let m = spec.margin;
        let off = [PAD + m, PAD + m, PAD + below];
        let mut st = Structure::new(
            dims,
            [PAD; 3],
            [dims[0] - PAD, dims[1] - PAD, dims[2] - PAD],
        );
        if matches!(spec.ground, Ground::Fixed | Ground::Anchor) {
            st.hold_on_plane(PAD as i32);
        }
        let place = |st: &Structure, g: &Grid3| -> Vec<usize> {
            typelist::grid_units(g)
                .into_iter()
                .filter_map(|(x, y, z)| {
                    st.index([x + off[0] as i32, y + off[1] as i32, z + off[2] as i32])
                })
                .collect()
        };
        let start = place(&st, &shape);
        st.place(&start);
        let targets = spec
            .targets
            .iter()
            .zip(target_lists)
            .zip(&target_shapes)
            .map(|((t, lists), g)| Target {
                name: t.name.clone(),
                lists: lists.iter().map(TypeList::padded).collect(),
                ghost: g
                    .as_ref()
                    .map(|g| place(&st, g).into_iter().map(|c| c as u32).collect())
                    .unwrap_or_default(),
                threshold: t.threshold,
                hold_lit: t.hold_lit,
            })
            .collect();

        let mut near2 = Vec::new();
        let [w, h, _] = dims;
        for dz in -2i32..=2 {
            for dy in -2i32..=2 {
                for dx in -2i32..=2 {
                    if dx.abs() + dy.abs() + dz.abs() <= 2 {
                        near2.push(
                            dx as isize + (dy as isize + dz as isize * h as isize) * w as isize,
                        );
                    }
                }
            }
        }
        let len = st.len();
        let table = typelist::diff_table(spec.a);
        let mut model = Cubes {
            flags: vec![0; len],
            units: Vec::with_capacity(start.len()),
            upos: vec![u32::MAX; len],
            movable: Vec::new(),
            mpos: vec![u32::MAX; len],
            movable_types,
            targets,
            target: vec![0; len],
            diff: Vec::with_capacity(start.len()),
            stable: Vec::with_capacity(start.len()),
            took: Vec::with_capacity(start.len()),
            whole_diffs: whole_diffs(&table, spec.w),
            table,
            w: spec.w,
            c: spec.c,
            log: spec.log,
            clock: spec.clock,
            run_temperature: f64::NAN,
            selection: spec.selection,
            random_stays: spec.random_stays,
            priority: spec.priority,
            movers: spec.movers,
            mover_distance: spec.mover_distance,
            ground: spec.ground,
            floor_z: PAD as i32,
            light,
            stable_steps: spec.stable_steps,
            stop_at_goal: spec.stop_at_goal,
            reached: None,
            max_units,
            switches: 0,
            near2,
            rng: Rng::stream(seed, 1),
            steps: 0,
            moves: 0,
            moves_toward: 0,
            moves_away: 0,
            zero: 0,
            start_light: 0.0,
            scratch: Scratch::default(),
            order: Vec::new(),
            deferred: Vec::new(),
            arrived: Vec::new(),
            senses: Default::default(),
            select: Default::default(),
            stopped: None,
            events: Vec::new(),
            st,
        };
        for &c in &start {
            model.upos[c] = model.units.len() as u32;
            model.units.push(c as u32);
            model.diff.push(f64::NAN);
            model.stable.push(0);
            model.took.push(0);
        }
        model.recompute_all();
        if model.targets.len() == 1 && model.zero == model.units.len() {
            model.reached = Some(0);
        }
        model.start_light = model.light_position();
        model
    }
}
