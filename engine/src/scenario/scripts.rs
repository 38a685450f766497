//! A map's ACS scripts running on its game: [`Scripts`] holds the map's
//! BEHAVIOR module in a VM ([`crate::acs::Vm`]), the scripts' own random
//! generator, and what they printed; each tic of the simulation is
//! followed by [`Scripts::tick`].
//!
//! Where scripts sit in the tic: ZDoom runs its scripts' thinker
//! (`DACSThinker`, `STAT_SCRIPTS`) after the players and every actor and
//! mover, so a script sees the tic's moves, kills and pickups. Here the
//! simulation's tic runs whole, then the thing specials it set off
//! (`Sim::zdoom`'s `fired`: a monster's death, an item taken) start their
//! scripts, then every script runs in ZDoom's list order. The one
//! difference from ZDoom: Doom's end-of-tic work (texture animation, the
//! item respawn queue) has already run when the scripts do; no scenario
//! reads either.

use rand::rngs::ChaCha8Rng;
use rand::SeedableRng;

use super::host::SimHost;
use crate::acs::{behavior_for_map, default_level_number, Activator, HostCx, Module, ScriptKind, Strings, Vm};
use crate::sim::zdoom::Fired;
use crate::sim::{MobjId, Sim, MAXPLAYERS};
use crate::wad::Wad;

/// ZDoom's ACS line specials that start scripts.
const ACS_EXECUTE: i32 = 80;
const ACS_SUSPEND: i32 = 81;
const ACS_TERMINATE: i32 = 82;
const ACS_EXECUTE_ALWAYS: i32 = 226;

/// A map's scripts.
pub struct Scripts {
    pub vm: Vm,
    rng: ChaCha8Rng,
    /// What scripts printed or logged, oldest first.
    pub printed: Vec<String>,
    /// What scripts asked that this game does not do, once each.
    pub unsupported: Vec<String>,
}

/// A copy that goes on exactly as the original: the generator copied by
/// its seed, stream and position.
impl Clone for Scripts {
    fn clone(&self) -> Scripts {
        let mut rng = ChaCha8Rng::from_seed(self.rng.get_seed());
        rng.set_stream(self.rng.get_stream());
        rng.set_word_pos(self.rng.get_word_pos());
        Scripts { vm: self.vm.clone(), rng, printed: self.printed.clone(), unsupported: self.unsupported.clone() }
    }
}

impl Scripts {
    /// The scripts of `map` in `wad`, or `None` when it has no BEHAVIOR.
    /// The VM's random generator is seeded with `seed`. A module this VM or
    /// this game cannot run is refused here, naming the lump and the pcode
    /// or function.
    pub fn load(wad: &Wad, map: &str, seed: u64) -> Result<Option<Scripts>, String> {
        let Some(index) = behavior_for_map(wad, map) else { return Ok(None) };
        let label = format!("{}: {}/BEHAVIOR", wad.path, map.to_ascii_uppercase());
        let module = Module::load(wad.bytes(index), &label).map_err(|e| e.to_string())?;
        let probe = ProbeHost;
        let mut vm = Vm::new(module, &probe).map_err(|e| e.to_string())?;
        vm.level_number = default_level_number(map);
        let rng = ChaCha8Rng::seed_from_u64(seed);
        Ok(Some(Scripts { vm, rng, printed: Vec::new(), unsupported: Vec::new() }))
    }

    /// The VM's random generator seeded anew with `seed` (a game set up
    /// once and copied for each episode: see `SimGame::reseeded`).
    pub fn reseed(&mut self, seed: u64) {
        self.rng = ChaCha8Rng::seed_from_u64(seed);
    }

    /// The level begins: its OPEN scripts with the world as activator, then
    /// each player's ENTER scripts with the player's body (ZDoom's
    /// `P_SetupLevel` and `G_DoLoadLevel`). They first run on the first tic.
    pub fn begin(&mut self, sim: &Sim) {
        self.vm.start_typed(ScriptKind::Open, Activator::World, false, 0);
        for n in 0..MAXPLAYERS {
            if let Some(p) = sim.player(n) {
                self.vm.start_typed(ScriptKind::Enter, Activator::Thing(u64::from(p.mo.0)), true, 0);
            }
        }
    }

    /// A player respawned in a net game: the RESPAWN scripts start with
    /// its new body.
    pub fn respawned(&mut self, body: MobjId) {
        self.vm.start_typed(ScriptKind::Respawn, Activator::Thing(u64::from(body.0)), true, 0);
    }

    /// After the simulation's tic: the thing specials it set off, then
    /// every script.
    pub fn tick(&mut self, sim: &mut Sim) {
        // A weapon given to an unarmed player last tic came up as the
        // player thought this tic (ZDoom's `P_BringUpWeapon` for a player
        // with no ready weapon): it becomes the ready one, rising.
        for n in 0..MAXPLAYERS {
            let Some(p) = sim.players[n].as_mut() else { continue };
            if let (None, Some(w)) = (p.psprites[0].state, p.pendingweapon) {
                p.readyweapon = w;
                p.pendingweapon = None;
                crate::sim::weapons::bring_up_weapon(sim, n);
            }
        }
        let fired = std::mem::take(&mut sim.zdoom.fired);
        for f in fired {
            self.run_special(sim, f);
        }
        let mut host =
            SimHost { sim, rng: &mut self.rng, printed: &mut self.printed, unsupported: &mut self.unsupported };
        self.vm.tick(&mut host);
    }

    /// A thing's special: a script started, or a line special done at once.
    fn run_special(&mut self, sim: &mut Sim, fired: Fired) {
        let activator = fired.activator.map_or(Activator::World, |MobjId(i)| Activator::Thing(u64::from(i)));
        let [script, map, a, b, c] = fired.args;
        let here = map == 0 || map == self.vm.level_number;
        match fired.special {
            ACS_EXECUTE | ACS_EXECUTE_ALWAYS if here => {
                self.vm.execute(script, &[a, b, c], activator, fired.special == ACS_EXECUTE_ALWAYS);
            }
            ACS_SUSPEND if here => self.vm.suspend(script),
            ACS_TERMINATE if here => self.vm.terminate(script),
            special => {
                let mut host =
                    SimHost { sim, rng: &mut self.rng, printed: &mut self.printed, unsupported: &mut self.unsupported };
                let mut strings = Strings::default();
                let mut cx = HostCx { activator, script: 0, strings: &mut strings };
                crate::acs::Host::line_special(&mut host, special, fired.args, &mut cx);
            }
        }
    }

    /// ACS global variable `i` (ViZDoom's reward is global 0, in 16.16).
    pub fn global(&self, i: usize) -> i32 {
        self.vm.globals.global.get(i).copied().unwrap_or(0)
    }

    /// Run-time warnings: scripts the VM stopped, and calls the game does
    /// not carry out.
    pub fn warnings(&self) -> impl Iterator<Item = &String> {
        self.vm.warnings.iter().chain(&self.unsupported)
    }
}

/// Answers only [`crate::acs::Host::supports_function`] when the VM is
/// built: the extended functions [`SimHost`] serves.
struct ProbeHost;

impl crate::acs::Host for ProbeHost {
    fn random(&mut self, min: i32, _max: i32) -> i32 {
        min
    }
    fn line_special(&mut self, _: i32, _: [i32; 5], _: &mut HostCx) -> i32 {
        0
    }
    fn game(&mut self, _: u16, _: &[i32], _: &mut HostCx) -> i32 {
        0
    }
    fn supports_function(&self, id: u16) -> bool {
        super::host::SUPPORTED_FUNCTIONS.contains(&id)
    }
    fn function(&mut self, _: u16, _: &[i32], _: &mut HostCx) -> i32 {
        0
    }
    fn print(&mut self, _: crate::acs::PrintKind, _: &str, _: Activator) {}
    fn sectors_busy(&mut self, _: i32) -> bool {
        false
    }
    fn polyobj_busy(&mut self, _: i32) -> bool {
        false
    }
    fn has_lock(&mut self, _: i32, _: Activator) -> bool {
        false
    }
}
