//! The metrics fracta reports (see its `each_metric` in `mod.rs`): unit and meaning of each.

use kumiki_model::model::MetricInfo;

pub const METRICS: &[MetricInfo] = &[
    MetricInfo::new("completed", "flag", "True when every working unit matches a goal statement."),
    MetricInfo::new("steps", "steps", "Time steps taken so far."),
    MetricInfo::new("mean_difference", "difference", "Mean over working units of the difference between a unit's connection state and its closest goal statement.").key(),
    MetricInfo::new("moves", "count", "Rolls made by units so far.").key(),
    MetricInfo::new("conflicts", "count", "Rolls cancelled because two units would collide.").key(),
    MetricInfo::new("irritations", "count", "Times a unit's irritation passed the threshold and made it move whatever the difference (condition 5)."),
    MetricInfo::new("units", "units", "Working units in the system."),
    MetricInfo::new("faults", "count", "Units whose power was cut (a fault injected)."),
    MetricInfo::new("cut_off", "units", "Faulty units cut off by their neighbours and gone."),
    MetricInfo::new("stranded", "units", "Units left behind when a cut split the system (the largest part carries on)."),
    MetricInfo::new("holes", "cells", "Empty cells enclosed by units, which no rule can open."),
    MetricInfo::new("convergence_steps", "steps", "Steps to reach the goal in a run without faults; empty otherwise or until reached."),
    MetricInfo::new("repair_steps", "steps", "Steps from the last fault to the goal; empty until reached."),
];
