//! Footnote 3: the direction the module under a robot displays, and what the robot is shown.
//! "Every module holds the values of the gradient field its neighbors have. The discretized
//! direction (N, S, E, W) calculated by these values is displayed to the robot. When these values
//! do not differ (i.e. difference between the maximum and minimum values is less than threshold),
//! the module displays 'no effective gradient' to the robot and the robot randomly decides its
//! direction." One pure function of typed inputs ([`shown`]); planning (`plan.rs`) reads the
//! neighbours into a [`Reading`] and acts on what is [`Shown`].

use super::spec::Direction;

/// The neighbour slots, in footnote 3's order.
pub const N: usize = 0;
pub const S: usize = 1;
pub const E: usize = 2;
pub const W: usize = 3;

/// The slots in the order Kumiki listed a cell's neighbours before model version 3 (right, up,
/// left, down). A robot that chooses at random draws in this order, so that runs of the
/// per-robot reading replay as they did.
pub const LISTED: [usize; 4] = [E, N, W, S];

/// What the module under a robot holds about its four neighbouring sites, by slot (N, S, E, W).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reading {
    /// The value each neighbouring module last sent, as a cost for this robot (lower is nearer
    /// its destination); `None` where no module is.
    pub cost: [Option<f32>; 4],
    /// Whether the robot may step onto that module (a blackboard closes the modules other
    /// robots' plans engage; giving way closes those a robot stands on).
    pub open: [bool; 4],
}

/// What the robot is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shown {
    /// The module displays this direction (a slot).
    Toward(usize),
    /// The best open neighbours, equally good, as a set of slots (bit `1 << slot`): the robot
    /// draws one (the per-robot reading).
    Among(u8),
    /// There is a gradient but no open module to step onto: the robot waits.
    Nowhere,
    /// No effective gradient: the spread of the neighbours' values is below the threshold (or
    /// no neighbour is a module). The robot picks its way at random.
    NoGradient,
}

/// What the module shows a robot whose neighbours read `reading`. The gradient is judged on
/// every neighbouring module's value, open or not; the direction is the open module of lowest
/// cost. With [`Direction::Module`] the module shows one, the first in the order N, S, E, W
/// among equally good ones, a rule it applies alone, so every robot reading it gets the same;
/// with [`Direction::Robot`] it shows them all and the robot draws.
pub fn shown(reading: &Reading, threshold: f32, rule: Direction) -> Shown {
    let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
    for &c in reading.cost.iter().flatten() {
        lo = lo.min(c);
        hi = hi.max(c);
    }
    if !(hi - lo >= threshold && hi >= lo) {
        return Shown::NoGradient;
    }
    let open = |slot: usize| match reading.open[slot] {
        true => reading.cost[slot],
        false => None,
    };
    let best = (0..4).filter_map(open).fold(f32::INFINITY, f32::min);
    let among = (0..4)
        .filter(|&slot| open(slot) == Some(best))
        .fold(0u8, |set, slot| set | 1 << slot);
    match (among, rule) {
        (0, _) => Shown::Nowhere,
        (set, Direction::Module) => Shown::Toward(set.trailing_zeros() as usize),
        (set, Direction::Robot) => Shown::Among(set),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reading(cost: [Option<f32>; 4]) -> Reading {
        Reading {
            cost,
            open: cost.map(|c| c.is_some()),
        }
    }

    #[test]
    fn the_module_shows_the_first_best_in_footnote_3s_order() {
        // West and south equally good: the module shows south (N, S, E, W), whoever reads it.
        let r = reading([Some(5.0), Some(3.0), None, Some(3.0)]);
        assert_eq!(shown(&r, 1.0, Direction::Module), Shown::Toward(S));
        assert_eq!(
            shown(&r, 1.0, Direction::Robot),
            Shown::Among(1 << S | 1 << W)
        );
        // A closed best module leaves the best open one.
        let mut closed = r;
        closed.open[S] = false;
        assert_eq!(shown(&closed, 1.0, Direction::Module), Shown::Toward(W));
        closed.open[W] = false;
        assert_eq!(shown(&closed, 1.0, Direction::Module), Shown::Toward(N));
        closed.open[N] = false;
        assert_eq!(shown(&closed, 1.0, Direction::Module), Shown::Nowhere);
    }

    #[test]
    fn values_that_do_not_differ_show_no_gradient() {
        let flat = reading([Some(2.0), Some(2.0), Some(2.0), None]);
        assert_eq!(shown(&flat, 1.0, Direction::Module), Shown::NoGradient);
        assert_eq!(shown(&flat, 0.0, Direction::Module), Shown::Toward(N));
        // The spread counts closed modules too: the module holds every neighbour's value.
        let mut r = reading([Some(1.0), Some(2.0), None, None]);
        r.open[N] = false;
        assert_eq!(shown(&r, 1.0, Direction::Robot), Shown::Among(1 << S));
        assert_eq!(
            shown(&reading([None; 4]), 0.0, Direction::Module),
            Shown::NoGradient
        );
    }
}
