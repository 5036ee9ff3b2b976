//! The metrics the 3-D units report (see `each_metric_value` in `view.rs`): unit and meaning of
//! each.

use kumiki_model::model::MetricInfo;

pub const METRICS: &[MetricInfo] = &[
    MetricInfo::new("steps", "steps", "Time steps taken so far; in each, the units that may move choose a motion."),
    MetricInfo::new("moves", "count", "Unit motions made so far.").key(),
    MetricInfo::new("units", "units", "Units in the structure."),
    MetricInfo::new("mean_difference", "difference", "Mean over units of the difference D_0 between a unit's type-list and its target (0 when matched).").key(),
    MetricInfo::new("matched", "fraction", "Share of units whose difference D_0 is 0, from 0 to 1.").key(),
    MetricInfo::new("completed", "flag", "1 when every unit matches its target type-list, else 0."),
    MetricInfo::new("reached", "steps", "The first step at which every unit matched its target; missing until then (a run may go on past it)."),
    MetricInfo::new("movable", "units", "Units that may move in the present configuration."),
    MetricInfo::new("connectivity_checks", "count", "Connectivity checks made (rule 4: a motion must not split the structure).").internal(),
    MetricInfo::new("connectivity_searches", "count", "Connectivity checks that needed a search beyond the local box around the unit.").internal(),
    MetricInfo::new("connectivity_search_cells", "cells", "Cells visited by those wider searches, all together.").internal(),
    MetricInfo::new("target", "index", "With two or more targets: the one most units hold, counting from 0."),
    MetricInfo::new("switches", "count", "With two or more targets: target switches made by units, all together."),
    MetricInfo::new("displacement", "cells", "With a light: how far the centre of mass has moved toward the light since the start."),
    MetricInfo::new("moves_toward", "count", "With a light: unit motions that ended nearer the light than they began."),
    MetricInfo::new("moves_away", "count", "With a light: unit motions that ended farther from the light than they began; the rest went across it."),
];
