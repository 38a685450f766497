//! Sightline's engine: everything from a RON level file to a finished frame, with
//! no windowing dependency.
//!
//! The data flow, one module per stage:
//!
//! ```text
//! RON text --map::load--> MapSource --map::validate--> Map
//!     --bsp::build--> CompiledMap (Map + wall-segment BSP) --bsp::file--> .slbsp
//!     --render::render_frame(View)--> Framebuffer --framebuffer::write_png--> PNG
//! ```
//!
//! `level` ties the first steps together: it opens either a source or a compiled
//! map and hands back a [`CompiledMap`](bsp::CompiledMap) ready to render.
//!
//! `acs` loads and runs ZDoom's map scripts (BEHAVIOR lumps) behind a `Host`
//! trait the simulation will implement.
//!
//! `decorate` reads ZDoom's actor definitions (DECORATE lumps) into a syntax
//! tree; nothing maps it onto the actor table yet.
//!
//! `play` runs a level as a game: a fixed 35 Hz simulation (movement,
//! collision, doors) from per-tick inputs, which demos record and replay.

pub mod acs;
pub mod actors;
pub mod autopilot;
pub mod bsp;
pub mod campaign;
pub mod decorate;
pub mod envelope;
pub mod fixed;
pub mod framebuffer;
pub mod geom;
pub mod grid;
pub mod level;
pub mod map;
pub mod materials;
pub mod play;
pub mod render;
pub mod scenario;
pub mod screen;
pub mod sim;
pub mod sound;
pub mod study;
pub mod text_cursor;
pub mod texture;
pub mod tour;
pub mod wad;

pub use bsp::CompiledMap;
pub use framebuffer::Framebuffer;
pub use map::Map;
pub use render::{render_frame, Frame, RenderOptions, Renderer, Shade, View};
