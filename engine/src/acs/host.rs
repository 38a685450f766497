//! The boundary between the VM and the game: what a script asks of the
//! world goes through [`Host`], which the simulation implements. Arguments
//! are ACS values (integers, 16.16 fixed point, or string ids resolved
//! through [`Strings`]); the VM never sees an actor, only [`Activator`]s.

use std::collections::HashMap;

/// Who a script runs for (ZDoom's `activator`): nobody (the world, as for
/// OPEN scripts) or an actor the host named when it started the script.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Activator {
    #[default]
    World,
    Thing(u64),
}

/// How printed text is to be shown.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PrintKind {
    /// `Print`: to the activator's screen (everyone's when the world runs it).
    Print,
    /// `PrintBold`: to every player.
    Bold,
    /// `Log`: to the console.
    Log,
    /// `HudMessage`/`HudMessageBold`: the six parameters (type, id, colour,
    /// x, y, hold time) and the optional ones after them, as pushed.
    HudMessage { bold: bool, params: Vec<i32> },
}

/// What a host call can see besides its arguments.
pub struct HostCx<'a> {
    pub activator: Activator,
    /// The calling script's number (negative for a named one).
    pub script: i32,
    /// To read string arguments and to return new strings.
    pub strings: &'a mut Strings,
}

/// The game side of ACS. Each method names the ACS functions it serves.
/// Calls happen inside [`super::Vm::tick`] (or the `execute` that ran a
/// script at once), in script order.
pub trait Host {
    /// `Random(min, max)`: an integer in `min..=max` (`min <= max` is
    /// guaranteed; ZDoom draws it from its `pr_acs` generator).
    fn random(&mut self, min: i32, max: i32) -> i32;

    /// A line special by number with its five arguments (`Thing_Remove`,
    /// `Exit_Normal`, `Thing_Hate`, ...; the `LSPEC` pcodes). The ACS
    /// specials (80-85, 226) on the current map are the VM's own and never
    /// come here. Returns the special's result (`LSPEC5RESULT`).
    fn line_special(&mut self, special: i32, args: [i32; 5], cx: &mut HostCx) -> i32;

    /// A game pcode (`pcodes::game_op`: `Spawn`, `CheckInventory`,
    /// `SetActorProperty`, `GetActorX`, `SetThingSpecial`, ...), by its stack
    /// form's number, with the arguments in source order. The result is
    /// pushed only for pcodes that leave a value.
    fn game(&mut self, pcode: u16, args: &[i32], cx: &mut HostCx) -> i32;

    /// Whether [`Host::function`] serves the extended function `id`
    /// (`ACSF_*`); asked once per function when the VM is built, so a module
    /// calling one the game lacks is refused before it runs.
    fn supports_function(&self, id: u16) -> bool;

    /// An extended function (`PCD_CALLFUNC`: `PlaySound`, `SetActorVelocity`,
    /// `CheckActorClass`, ...), its arguments in source order.
    fn function(&mut self, id: u16, args: &[i32], cx: &mut HostCx) -> i32;

    /// Text a script finished (`Print`, `PrintBold`, `Log`, `HudMessage`).
    fn print(&mut self, kind: PrintKind, text: &str, activator: Activator);

    /// `TagWait(tag)`: whether any sector with this tag still has a floor or
    /// ceiling mover.
    fn sectors_busy(&mut self, tag: i32) -> bool;

    /// `PolyWait(po)`: whether the polyobject still moves.
    fn polyobj_busy(&mut self, po: i32) -> bool;

    /// `ACS_LockedExecute`'s key check: whether the activator holds `lock`.
    fn has_lock(&mut self, lock: i32, activator: Activator) -> bool;
}

/// String ids: the module's string table from 0, strings made while running
/// (`StrParam`, `StrLeft`, host results) from [`Strings::POOL`] up, as in
/// ZDoom's global string pool. Equal made strings share an id.
#[derive(Clone, Debug, Default)]
pub struct Strings {
    module: Vec<String>,
    pool: Vec<String>,
    ids: HashMap<String, i32>,
}

impl Strings {
    /// First id of made strings (ZDoom's `STRPOOL_LIBRARYID_OR`).
    pub const POOL: i32 = 0x7ff0_0000;

    pub fn new(module: Vec<String>) -> Strings {
        Strings { module, pool: Vec::new(), ids: HashMap::new() }
    }

    pub fn get(&self, id: i32) -> Option<&str> {
        if id >= Strings::POOL {
            self.pool.get((id - Strings::POOL) as usize).map(String::as_str)
        } else {
            usize::try_from(id).ok().and_then(|i| self.module.get(i)).map(String::as_str)
        }
    }

    /// The id of `text`, adding it to the pool if it is new.
    pub fn add(&mut self, text: &str) -> i32 {
        if let Some(&id) = self.ids.get(text) {
            return id;
        }
        let id = Strings::POOL.saturating_add(self.pool.len() as i32);
        self.pool.push(text.to_string());
        self.ids.insert(text.to_string(), id);
        id
    }
}
