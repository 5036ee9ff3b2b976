//! The state byte of a lattice cell and the codes of the cell buffer the page draws.

/// A module is here: supply, built, or to be removed.
pub const MODULE: u8 = 1;
/// A cell of the current target that has no module yet.
pub const VACANT: u8 = 2;
/// A module of the supply area (the conveyor): never removed, always offers modules.
pub const CONVEYOR: u8 = 4;
/// A module outside the current target: to be removed (section 6.2).
pub const REMOVE: u8 = 8;
/// A module next to a vacant target cell: the growth front. The supply takes modules back
/// when the target is full and modules are still to be removed.
pub const FRONT: u8 = 16;
/// A module of the module supply area: the conveyor, or next to a module to be removed.
pub const SOURCE: u8 = 32;
/// Communication breakdown (section 5.5): no field value, nothing said to robots.
pub const BROKEN: u8 = 64;
/// Transient, within a step: a robot has claimed this cell.
pub const CLAIMED: u8 = 128;

/// `s & ACTIVE_MASK == MODULE`: a communicating module, part of the field.
pub const ACTIVE_MASK: u8 = MODULE | BROKEN;

/// Codes of the cell buffer.
pub mod code {
    pub const NOTHING: u8 = 0;
    pub const VACANT: u8 = 1;
    pub const SUPPLY: u8 = 2;
    pub const SUPPLY_FRONT: u8 = 3;
    pub const MODULE: u8 = 4;
    pub const FRONT: u8 = 5;
    pub const DISASSEMBLY_SUPPLY: u8 = 6;
    pub const TO_REMOVE: u8 = 7;
    pub const BROKEN: u8 = 8;
}

/// The drawn code of a state byte: breakdown first, then "to be removed", growth front, supply.
pub const fn display(s: u8) -> u8 {
    if s & MODULE == 0 {
        if s & VACANT != 0 {
            code::VACANT
        } else {
            code::NOTHING
        }
    } else if s & BROKEN != 0 {
        code::BROKEN
    } else if s & REMOVE != 0 {
        code::TO_REMOVE
    } else if s & CONVEYOR != 0 {
        if s & FRONT != 0 {
            code::SUPPLY_FRONT
        } else {
            code::SUPPLY
        }
    } else if s & FRONT != 0 {
        code::FRONT
    } else if s & SOURCE != 0 {
        code::DISASSEMBLY_SUPPLY
    } else {
        code::MODULE
    }
}

/// Words for the inspector.
pub fn describe(s: u8) -> String {
    if s & MODULE == 0 {
        return if s & VACANT != 0 {
            "vacant target site".into()
        } else {
            "empty".into()
        };
    }
    let mut words = vec![if s & CONVEYOR != 0 {
        "supply module"
    } else if s & REMOVE != 0 {
        "module to be removed"
    } else {
        "module"
    }];
    if s & FRONT != 0 {
        words.push("growth front");
    }
    if s & SOURCE != 0 && s & CONVEYOR == 0 {
        words.push("supply area");
    }
    if s & BROKEN != 0 {
        words.push("communication broken");
    }
    words.join(", ")
}
