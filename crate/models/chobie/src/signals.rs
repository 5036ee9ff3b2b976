//! Slot-based signalling (section 3.2): all robots share synchronous time slots, a robot sends or
//! does not send an ON signal in a slot, and the slot gives the signal its meaning. A message is
//! one signal crossing one face between neighbours. Signals that spread through the whole
//! structure (the leader's announcement, the completion signal, an overload) are relayed within
//! one slot, which is why a slot must outlast a round trip across the structure.

use std::collections::VecDeque;

use super::motion::{Body, NONE};
use kumiki_model::model::Event;

/// Event kinds, one per kind of slot, drawn on the robots that sent in it.
pub mod kind {
    pub const ELECTION: u8 = 0;
    pub const ANNOUNCE: u8 = 1;
    pub const COMMAND: u8 = 2;
    pub const OVERLOAD: u8 = 3;
    pub const CHAIN: u8 = 4;
    pub const GATHER: u8 = 5;
}

/// One entry of a transformation's slot trace: what the slot means and who sent in it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Slot {
    /// The slot's meaning, as the page shows it.
    pub meaning: &'static str,
    /// How many time slots this entry stands for (the baseline's bit-serial transfers take many).
    pub count: u64,
    /// Per sender: its cell and the faces it lit, bit `d` for lattice direction `d` (right, up,
    /// left, down); no bit when the signal's way is not modelled face by face.
    pub senders: Vec<(u32, u8)>,
}

/// The slots and messages of one transformation, and who sent what.
#[derive(Clone, Debug, Default)]
pub struct Comm {
    pub slots: u64,
    pub messages: u64,
    /// One event per robot that sent in a slot, for the page.
    pub signals: Vec<Event>,
    /// Slot by slot, in order.
    pub trace: Vec<Slot>,
}

impl Comm {
    /// Opens a slot with the given meaning.
    pub fn slot(&mut self, meaning: &'static str) {
        self.open(1, meaning);
    }

    /// Opens `count` consecutive slots that share one meaning (one trace entry).
    pub fn open(&mut self, count: u64, meaning: &'static str) {
        self.slots += count;
        self.trace.push(Slot {
            meaning,
            count,
            senders: Vec::new(),
        });
    }

    /// Records that robot `r` sent `messages` signals in the current slot, on every face it
    /// shares with a neighbour.
    pub fn send(&mut self, body: &Body, r: u32, messages: u64, kind: u8) {
        let faces = (0..4)
            .filter(|&d| body.has(r, d))
            .fold(0, |m, d| m | 1 << d);
        self.record(body, r, messages, faces, kind);
    }

    /// Records that robot `r` sent one signal through each face in `faces` (a direction mask).
    pub fn send_toward(&mut self, body: &Body, r: u32, faces: u8, kind: u8) {
        self.record(body, r, faces.count_ones() as u64, faces, kind);
    }

    /// Records that robot `r` sent `messages` signals along a path (a route or a line) rather
    /// than through chosen faces.
    pub fn send_along(&mut self, body: &Body, r: u32, messages: u64, kind: u8) {
        self.record(body, r, messages, 0, kind);
    }

    fn record(&mut self, body: &Body, r: u32, messages: u64, faces: u8, kind: u8) {
        if messages == 0 {
            return;
        }
        self.messages += messages;
        let (x, y) = body.pos[r as usize];
        if let Some(i) = body.index(x, y) {
            self.signals.push(Event {
                cell: i as u32,
                kind,
            });
            if let Some(slot) = self.trace.last_mut() {
                slot.senders.push((i as u32, faces));
            }
        }
    }

    /// One slot in which a signal from `origins` is relayed to every robot: each robot, on first
    /// hearing it, lights all its faces once.
    pub fn flood(&mut self, body: &Body, origins: &[u32], kind: u8, meaning: &'static str) {
        self.slot(meaning);
        if origins.is_empty() {
            return;
        }
        for r in 0..body.len() as u32 {
            self.send(body, r, body.degree(r) as u64, kind);
        }
    }
}

/// Hops from `from` to every robot (breadth-first over faces).
pub fn hops(body: &Body, from: u32) -> Vec<u32> {
    let mut dist = vec![u32::MAX; body.len()];
    let mut queue = VecDeque::from([from]);
    dist[from as usize] = 0;
    while let Some(r) = queue.pop_front() {
        for d in 0..4 {
            let n = body.nbr(r, d);
            if n != NONE && dist[n as usize] == u32::MAX {
                dist[n as usize] = dist[r as usize] + 1;
                queue.push_back(n);
            }
        }
    }
    dist
}

/// The structure's diameter in hops, by a double sweep (exact on trees and on the forms used
/// here, a lower bound in general).
pub fn diameter(body: &Body) -> u32 {
    if body.is_empty() {
        return 0;
    }
    let first = hops(body, 0);
    let far = (0..body.len())
        .max_by_key(|&r| (first[r], std::cmp::Reverse(r)))
        .unwrap_or(0);
    hops(body, far as u32).into_iter().max().unwrap_or(0)
}
