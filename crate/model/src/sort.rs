//! One stable sort for the paths that run once per scenario, edit or frame rather than per unit.
//!
//! The standard library's sorts are generic over the element and the comparison, so each call
//! site with its own closure compiles a sort of its own (a stable one is about 7 KB of wasm). The
//! functions here put every call through one instantiation: the sort orders the elements'
//! indices with a comparison behind a `dyn` reference, then moves the elements into that order.
//! The result is what `slice::sort_by` gives: stable, equal elements in their first order.
//! The steps' own sorts, which run per unit, keep the standard library's.

use std::cmp::Ordering;

/// Sorts `items` by `cmp`, stably, as `items.sort_by(cmp)` does.
pub fn sort_by<T>(items: &mut [T], mut cmp: impl FnMut(&T, &T) -> Ordering) {
    let order = sorted_indices(items.len(), &mut |a, b| cmp(&items[a], &items[b]));
    permute(items, order);
}

/// Sorts `items` by the key `key` gives, stably, as `items.sort_by_key(key)` does.
pub fn sort_by_key<T, K: Ord>(items: &mut [T], mut key: impl FnMut(&T) -> K) {
    sort_by(items, |a, b| key(a).cmp(&key(b)));
}

/// Sorts `items` in their own order, stably, as `items.sort()` does.
pub fn sort<T: Ord>(items: &mut [T]) {
    sort_by(items, T::cmp);
}

/// The indices `0..n` ordered by `cmp` on them, equal ones in increasing order: the one sort
/// every function here compiles to.
#[inline(never)]
fn sorted_indices(n: usize, cmp: &mut dyn FnMut(usize, usize) -> Ordering) -> Vec<usize> {
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| cmp(a, b));
    order
}

/// Moves `items` so that the item at `i` is the one that was at `order[i]`, following each cycle
/// of the permutation once.
fn permute<T>(items: &mut [T], mut order: Vec<usize>) {
    for start in 0..items.len() {
        let mut at = start;
        loop {
            let from = order[at];
            order[at] = at;
            if from == start {
                break;
            }
            items.swap(at, from);
            at = from;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    #[test]
    fn sorts_as_the_standard_library_does_and_keeps_equal_items_in_order() {
        let mut rng = Rng::new(7);
        for n in [0usize, 1, 2, 3, 8, 21, 64, 300] {
            let items: Vec<(u32, usize)> = (0..n).map(|i| (rng.below(5), i)).collect();
            let mut ours = items.clone();
            let mut std = items.clone();
            sort_by_key(&mut ours, |&(k, _)| k);
            std.sort_by_key(|&(k, _)| k);
            assert_eq!(ours, std, "n = {n}");
            let mut ours = items.clone();
            let mut std = items;
            sort_by(&mut ours, |a, b| b.cmp(a));
            std.sort_by(|a, b| b.cmp(a));
            assert_eq!(ours, std, "n = {n}, descending");
        }
    }

    #[test]
    fn sorts_owned_items_without_copying_them() {
        let mut words: Vec<String> = ["pear", "fig", "apple", "fig", "kiwi"]
            .map(String::from)
            .to_vec();
        sort(&mut words);
        assert_eq!(words, ["apple", "fig", "fig", "kiwi", "pear"]);
    }
}
