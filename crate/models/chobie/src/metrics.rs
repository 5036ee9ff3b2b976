//! The metrics CHOBIE II reports (see its `each_metric` in `view.rs`): unit and meaning of each.

use kumiki_model::model::MetricInfo;

pub const METRICS: &[MetricInfo] = &[
    MetricInfo::new("adaptations", "cycles", "Transformation cycles that moved robots while the group was in adaptation mode."),
    MetricInfo::new("beam_theory_stress", "MPa", "Root stress of a straight single-tier cantilever of the present span, by beam theory, for comparison."),
    MetricInfo::new("distance", "cells", "How far the group's centre of mass has moved along x since the start.").key(),
    MetricInfo::new("election_failures", "count", "Leader elections in which the algorithm tried found no leader."),
    MetricInfo::new("energy", "robot cells", "Sum over moves of the robots driven in each: the work spent moving."),
    MetricInfo::new("failed", "code", "Whether the structure has failed: 0 standing, 1 broken (a robot's stress passed the strength of ABS), 2 tipped over the cliff edge."),
    MetricInfo::new("leaders", "count", "Temporary leaders elected in the last cycle."),
    MetricInfo::new("max_peak_stress", "MPa", "The highest stress any robot has carried so far in the run."),
    MetricInfo::new("messages", "count", "Signals that crossed a face between two robots, over the whole run."),
    MetricInfo::new("messages_per_robot", "messages per cycle per robot", "Messages per transformation cycle and per robot."),
    MetricInfo::new("messages_per_transformation", "messages per cycle", "Messages per transformation cycle, whether the cycle moved or not."),
    MetricInfo::new("mode", "code", "What the group is doing: 0 crawl, 1 construction, 2 adaptation."),
    MetricInfo::new("overloads", "robots", "Robots whose stress is above the threshold now."),
    MetricInfo::new("overturning", "N·m", "Moment of the robots' weights and loads about the cliff edge; positive turns the structure over it (it tips when the base does not hold it)."),
    MetricInfo::new("peak_stress", "MPa", "The highest stress any robot carries now.").key(),
    MetricInfo::new("reinforcements", "cycles", "Transformation cycles in which a leader 1 moved (section 3.4, step 7): its column down under the overloaded place, its right neighbour's up where it can."),
    MetricInfo::new("refused", "cycles", "Cycles whose commands could not be carried out."),
    MetricInfo::new("reserves", "robots", "Robots above the row of those resting on the terrain: the bridge's reserves on the upper tier (the crawl's upper tier)."),
    MetricInfo::new("resumed", "count", "Times the group went back from load adaptation to construction because its overload cleared."),
    MetricInfo::new("robots", "robots", "The number of robots in the group."),
    MetricInfo::new("slot_us", "µs", "The communication slot length the structure needs: twice its diameter in hops times the hop time."),
    MetricInfo::new("slots", "slots", "Communication slots used so far."),
    MetricInfo::new("slots_per_transformation", "slots per cycle", "Communication slots per transformation cycle, whether the cycle moved or not."),
    MetricInfo::new("span", "cells", "How far the structure reaches beyond the cliff edge.").key(),
    MetricInfo::new("stalled", "flag", "True when the last cycle moved nothing."),
    MetricInfo::new("strength", "MPa", "The stress at which a robot breaks: the tensile strength taken for ABS."),
    MetricInfo::new("threshold", "MPa", "The stress threshold above which a robot counts as overloaded (σ_th)."),
    MetricInfo::new("transformations", "cycles", "Transformation cycles (election, command, move) that moved robots.").key(),
];
