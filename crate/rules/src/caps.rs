//! The sandbox's caps: what a rule script may spend. Each is counted by the engine in the same way
//! on every target (operations, nesting, items), never by a clock or an allocator, so a script
//! that goes past one stops at the same place natively and in wasm, and the run's hash is the
//! same.

/// Operations one call of a rule may take (Rhai counts one for each statement, expression and
/// function call it evaluates). The paper's CHOBIE II rule takes about 30.
pub const OPERATIONS_PER_CALL: u64 = 100_000;
/// Operations the calls of one step may take together: a step asks a rule once a unit, and a
/// rule just under the cap per call on thousands of units must not hold a step for minutes.
pub const OPERATIONS_PER_STEP: u64 = 2_000_000;
/// Function calls nested in one another (a call of the rule itself is the first).
pub const CALL_DEPTH: usize = 16;
/// Expressions nested in one another, at the top level and inside functions (checked when the
/// script is read).
pub const EXPRESSION_DEPTH: usize = 32;
pub const FUNCTION_EXPRESSION_DEPTH: usize = 24;
/// Bytes of one string, counted with the strings inside an array or map (map keys are strings
/// too, but the engine does not count them: they are at most this long each).
pub const STRING_BYTES: usize = 128;
/// Items of one array, counted with the items of the arrays inside it.
pub const ARRAY_ITEMS: usize = 512;
/// Entries of one map, counted with the entries of the maps inside it.
pub const MAP_ENTRIES: usize = 128;
/// Variables alive at once in one call, its arguments included (each call has its own).
pub const VARIABLES: usize = 32;
/// Functions a script may define.
pub const FUNCTIONS: usize = 64;

/// What the caps above bound a call's memory to, in bytes: about 33 MiB. Each of the calls
/// nested at once (at most [`CALL_DEPTH`]) has at most [`VARIABLES`] variables and one temporary
/// value a level of expression ([`FUNCTION_EXPRESSION_DEPTH`]), and each may hold the largest
/// value the size caps allow: an array of 512 items (16 bytes each), a map of 128 entries whose
/// keys are strings of at most 128 bytes, and 128 bytes of strings. The engine checks a map's size
/// when it is built, added to or given a property, but not when an entry is added by index
/// (`m[key] = v`): such entries cost at least three operations each, so the cap per call bounds
/// them too. A script cannot hold more than this at once; its memory is freed when the call
/// returns.
pub const MEMORY_BYTES: usize = CALL_DEPTH
    * (VARIABLES + FUNCTION_EXPRESSION_DEPTH)
    * (ARRAY_ITEMS * 16 + MAP_ENTRIES * (STRING_BYTES + 48) + STRING_BYTES)
    + (OPERATIONS_PER_CALL as usize / 3) * (STRING_BYTES + 48);

/// The names the stop messages give the caps that tokens of the progress callback stand for.
pub(crate) const PER_CALL: &str = "call";
pub(crate) const PER_STEP: &str = "step";
