//! The pairing with Doom's numbering, parsing, applying, and Freedoom's
//! own patches.

mod apply;
mod freedoom;
mod mapping;
mod parse;

use super::*;
use crate::actors::{ActorDef, ActorFlag, AmmoKind, Give, State, StateId};
