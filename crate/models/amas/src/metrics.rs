//! The metrics AMAS reports (see [`super::Amas`]'s `each_metric`): unit and meaning of each.

use kumiki_model::model::MetricInfo;

pub const METRICS: &[MetricInfo] = &[
    MetricInfo::new(
        "steps",
        "steps",
        "Time steps taken so far; every robot acts once a step.",
    ),
    MetricInfo::new(
        "total_steps",
        "robot steps",
        "Steps times the number of robots: the work the paper's figures count (figure 23).",
    )
    .key(),
    MetricInfo::new(
        "collisions",
        "count",
        "Times a robot was blocked by another robot in its way.",
    )
    .key(),
    MetricInfo::new(
        "corner_collisions",
        "count",
        "Collisions at the corner rows: the row where the shape changes width and the row below it.",
    ),
    MetricInfo::new(
        "above_corner_collisions",
        "count",
        "Collisions above the corner rows, in the part of the shape past the corner.",
    ),
    MetricInfo::new(
        "supply_collisions",
        "count",
        "Collisions on the supply rows, where robots pick up their modules.",
    ),
    MetricInfo::new(
        "mixed_collisions",
        "count",
        "Collisions between a loaded and an unloaded robot, the kind appendix A.1 finds most common and module relay solves.",
    ),
    MetricInfo::new(
        "loaded_collisions",
        "count",
        "Collisions between two robots carrying modules.",
    ),
    MetricInfo::new(
        "unloaded_collisions",
        "count",
        "Collisions between two robots carrying nothing.",
    ),
    MetricInfo::new(
        "wandering",
        "robot steps",
        "Times a robot found no effective gradient (or stood on a broken module) and chose its way at random (sections 5.4, 5.5).",
    ),
    MetricInfo::new(
        "relays",
        "count",
        "Modules handed from one robot to another instead of carried all the way (section 5.2).",
    )
    .key(),
    MetricInfo::new(
        "corner_relays",
        "count",
        "Relays where the handing robot stood on the corner row or the row below it (figure 24).",
    ),
    MetricInfo::new(
        "lower_bound",
        "robot steps",
        "The paper's lower bound on total steps for this target (footnote 2, Manhattan distances).",
    ),
    MetricInfo::new(
        "path_bound",
        "robot steps",
        "The same bound with distances measured along paths through the target shape; never lower.",
    ),
    MetricInfo::new(
        "built",
        "fraction",
        "Share of the current target's cells that hold a module, from 0 to 1.",
    )
    .key(),
    MetricInfo::new(
        "placed",
        "count",
        "Modules placed into the structure by robots.",
    ),
    MetricInfo::new(
        "picked",
        "count",
        "Modules picked up from the supply conveyor.",
    ),
    MetricInfo::new(
        "dismantled",
        "count",
        "Modules taken out of the structure by robots during disassembly (section 6.2).",
    ),
    MetricInfo::new(
        "returned",
        "count",
        "Dismantled modules handed back to the supply.",
    ),
    MetricInfo::new(
        "removed",
        "count",
        "Built modules that disappeared through a 'remove' disturbance (section 5.4).",
    ),
    MetricInfo::new(
        "broken",
        "count",
        "Built modules that lost their communication through a 'break' disturbance (section 5.5).",
    ),
    MetricInfo::new(
        "stage",
        "index",
        "Which target of a staged scenario is being built, counting from 1 (section 6.4).",
    ),
    MetricInfo::new(
        "never_past_corner",
        "fraction",
        "Share of robots that never stood on the corner row or above it (figure 24).",
    ),
    MetricInfo::new(
        "corner_assemblers",
        "fraction",
        "Share of robots that placed a module on the corner row or above it (figure 24).",
    ),
];
