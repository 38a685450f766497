//! The masked pass: things (billboard sprites) and see-through middle
//! textures, drawn after the opaque walk, far to near, each clipped to what
//! the walls in front of it left open (Doom's drawsegs idea, kept per column
//! as clip events; see [`super::frame::ClipEvent`]).
//!
//! A sprite faces the viewer: at depth `d` it spans sideways `[s - w/2, s + w/2)`
//! and stands on its sector's floor, one map unit per texel. Column `x` shows
//! texel column `u = t_x * d - (s - w/2)` when `0 <= u < w`; the reference
//! renderer uses the same predicates, so `ids` frames agree.

use super::columns::ColumnWriter;
use super::frame::{ClipEvent, Scene, StripFrame, NONE};
use super::shade::{colour, ids_colour, masked_top, Shade, Surface};
use super::view::{hides_sprite, Camera, NEAR};
use crate::level::Level;
use crate::texture::{Texture, TextureId};

/// A thing in view.
#[derive(Clone, Copy, Debug)]
pub(crate) struct VisSprite {
    pub thing: usize,
    pub depth: f64,
    /// Sideways position of its left edge, camera space.
    pub left: f64,
    /// Floor height it stands on, and its sector's light.
    pub floor: f64,
    pub light: u8,
    pub texture: TextureId,
    pub fuzz: bool,
    /// Columns it may cover (the predicate decides each).
    pub x0: usize,
    pub x1: usize,
}

/// Finds the things in view and sorts them far to near, into `sprites`.
pub(crate) fn collect(level: &Level, cam: &Camera, slopes: &[f64], sprites: &mut Vec<VisSprite>) {
    sprites.clear();
    for t in &level.things {
        let q = cam.to_camera(t.pos);
        if q.x < NEAR {
            continue;
        }
        // One column of slack each side: the per-column predicate decides.
        let columns = |w: f64| {
            let left = q.y - w / 2.0;
            let x0 = cam.first_column_in(slopes, glam::DVec2::new(q.x, left)).saturating_sub(1);
            let x1 = (cam.first_column_in(slopes, glam::DVec2::new(q.x, left + w)) + 1).min(cam.width);
            (left, x0, x1)
        };
        let width = |texture| level.materials.textures.get(texture).width as f64;
        // The view after the cheap tests: half the things are behind the
        // eye, and of a thing seen differently from each side (a monster),
        // its widest view tells whether it can be in view before the
        // direction is worked out (`first_column_in` is monotone, so a
        // wider extent covers at least the columns of a narrower one).
        if t.turns() {
            let (_, x0, x1) = columns(t.views.iter().map(|&v| width(v)).fold(0.0, f64::max));
            if x0 >= x1 {
                continue;
            }
        }
        let texture = t.texture_seen_from(cam.eye);
        let (left, x0, x1) = columns(width(texture));
        if x0 >= x1 {
            continue;
        }
        let light = if t.bright { u8::MAX } else { level.map.sectors[t.sector].light };
        sprites.push(VisSprite { thing: t.key, depth: q.x, left, floor: t.z, light, texture, fuzz: t.fuzz, x0, x1 });
    }
    // Far to near. At equal depth the lower-numbered thing is drawn last, on
    // top, and a sprite goes over a masked middle: the reference walks near
    // to far and lets the first it meets win, in that same order.
    // (Keys are unique, so the unstable sort gives the one order.)
    sprites.sort_unstable_by(|a, b| b.depth.total_cmp(&a.depth).then(b.thing.cmp(&a.thing)));
}

/// What every masked column draw needs to know.
struct MaskedPass<'a> {
    scene: &'a Scene<'a>,
    cam: &'a Camera,
    /// The strip's clip events, and each column's deepest.
    events: &'a [ClipEvent],
    last_event: &'a [u32],
}

/// Draws sprites and masked middles over columns `[x0, x1)`, far to near per
/// column.
///
/// Sprite by sprite, far to near (Doom's R_DrawMasked order): before a
/// sprite's column, the column's masked middles at or beyond its depth are
/// drawn, so each column still receives its sprites and middles merged far to
/// near; the middles nearer than every sprite come last. At equal depth the
/// sprite goes last, on top (see `collect`). Walking each column's list of
/// sprites instead cost a test of every sprite in the strip per column: 16%
/// of an E1M4 frame at 320x200 (288 things).
pub(crate) fn draw(scene: &Scene, frame: &mut StripFrame, out: &mut ColumnWriter, (x0, x1): (usize, usize)) {
    // Each column's next masked middle to draw, deepest first: the walk's
    // list heads, consumed in place (the next strip resets them).
    let StripFrame { last_masked: next, masked, events, last_event, sprite_rows, .. } = frame;
    let pass = MaskedPass { scene, cam: scene.cam, events, last_event };
    let mut drain = |out: &mut ColumnWriter, x: usize, depth: f64| {
        while let Some(m) =
            (next[x] != NONE).then(|| &masked[next[x] as usize]).filter(|m| !hides_sprite(m.depth, depth))
        {
            pass.masked_column(out, m, x);
            next[x] = m.prev;
        }
    };
    for s in scene.sprites.iter().filter(|s| s.x0 < x1 && s.x1 > x0) {
        // Only the columns from the first to the last that a wall nearer
        // did not close: a sprite behind a wall costs a look at its
        // columns, not its set-up and a draw of each (the middles of the
        // columns passed over are drained by a later sprite or the end,
        // still far to near).
        let (from, to) = (s.x0.max(x0), s.x1.min(x1));
        let Some(first) = (from..to).find(|&x| !pass.closed_before(x, s.depth)) else { continue };
        let last = (first..to).rev().find(|&x| !pass.closed_before(x, s.depth)).unwrap_or(first);
        let sprite = pass.sprite(s, sprite_rows);
        for x in first..=last {
            drain(out, x, s.depth);
            pass.sprite_column(out, s, &sprite, x);
        }
    }
    for x in x0..x1 {
        drain(out, x, f64::NEG_INFINITY);
    }
}

/// What is the same in every column of one sprite.
struct SpriteColumns<'a> {
    texture: &'a Texture,
    rows: (i32, i32),
    paint: Texels,
    /// The texel row each screen row of `rows` shows: a sprite is at one
    /// depth, so every column of it shares them.
    texel_rows: &'a [u32],
}

impl MaskedPass<'_> {
    fn sprite<'t>(&'t self, s: &VisSprite, texel_rows: &'t mut Vec<u32>) -> SpriteColumns<'t> {
        let texture = self.scene.level.materials.textures.get(s.texture);
        let top = s.floor + texture.height as f64;
        let paint = match self.scene.shade {
            Shade::Ids => Texels::Solid(ids_colour(Surface::Thing { thing: s.thing })),
            Shade::Flat => Texels::Solid(colour(Shade::Flat, Surface::Thing { thing: s.thing }, s.light, 1.0)),
            Shade::Textured if s.fuzz => Texels::Fuzz(self.scene.level.time),
            Shade::Textured => Texels::Tinted(self.scene.lighting.tint(s.light, s.depth)),
        };
        // The frame's row table answers as the camera does, without a division per row tried.
        let (rows, scale) = (self.scene.rows, self.cam.focal / s.depth);
        let rows = (rows.first_at_or_below(s.depth, scale, top), rows.first_at_or_below(s.depth, scale, s.floor));
        let texel_row = self.texel_row(texture, s.depth, top);
        texel_rows.clear();
        texel_rows.extend((rows.0..rows.1).map(|y| texel_row(y) as u32));
        SpriteColumns { texture, rows, paint, texel_rows }
    }

    fn sprite_column(&self, out: &mut ColumnWriter, s: &VisSprite, c: &SpriteColumns, x: usize) {
        let u = self.scene.slopes[x] * s.depth - s.left;
        if !(0.0..c.texture.width as f64).contains(&u) {
            return;
        }
        let at = (s.depth, label(s.thing));
        let (y0, y1) = self.open_rows(x, c.rows, |near| hides_sprite(near, s.depth));
        let Texels::Tinted(tint) = c.paint else {
            let texel_row = |y: i32| c.texel_rows[(y - c.rows.0) as usize] as usize;
            return self.put_texels(out, x, at, (y0, y1), (c.texture, u as usize, texel_row), c.paint, false);
        };
        // The common case with the texel rows read as a run of the table,
        // not looked up row by row (a bounds test a texel).
        if y0 < y1 {
            let column = c.texture.column((u as usize).min(c.texture.width - 1));
            let rows = &c.texel_rows[(y0 - c.rows.0) as usize..(y1 - c.rows.0) as usize];
            put_opaque(out, x, y0, rows.iter().map(|&r| column[r as usize]), tint, at);
        }
    }

    fn masked_column(&self, out: &mut ColumnWriter, m: &super::frame::MaskedColumn, x: usize) {
        let level = self.scene.level;
        let map = &level.map;
        let line = &map.lines[m.line];
        let Some(id) = level.materials.side(m.line, m.back_side as usize).middle else { return };
        let texture = level.materials.textures.get(id);
        let top = masked_top(map, line, m.back_side, texture.height as f64, level.time);
        let near = line.side(m.back_side).sector;
        let light = map.sectors[near].light;
        let paint = match self.scene.shade {
            Shade::Textured => {
                let (from, to) = map.line_points(line);
                Texels::Tinted(self.scene.lighting.tint(super::light::fake_contrast(light, to - from), m.depth))
            }
            shade => Texels::Solid(colour(shade, Surface::Wall { line: m.line }, light, 1.0)),
        };
        let u = texture.wrap_column(crate::geom::floor_i64(m.u));
        let bottom = top - texture.height as f64;
        let (rows, scale) = (self.scene.rows, self.cam.focal / m.depth);
        let rows = (rows.first_at_or_below(m.depth, scale, top), rows.first_at_or_below(m.depth, scale, bottom));
        let event = self.events[m.event as usize];
        let rows = (rows.0.max(event.top), rows.1.min(event.bottom));
        // Walls nearer than the middle clip it; its own event, at its depth, does not.
        let rows = self.open_rows(x, rows, |near| near < m.depth);
        // Translucent middles (Boom's 260) blend only when textured, so
        // the flat and ids pictures stay comparable with the reference.
        let translucent = line.flags.translucent && self.scene.shade == Shade::Textured;
        let texels = (texture, u, self.texel_row(texture, m.depth, top));
        self.put_texels(out, x, (m.depth, 0), rows, texels, paint, translucent);
    }

    /// The texel row screen row `y` shows of `texture` standing at `depth`
    /// with texel row 0 at height `top` (texel row `v` is at `top - v`).
    fn texel_row<'t>(&'t self, texture: &'t Texture, depth: f64, top: f64) -> impl Fn(i32) -> usize + 't {
        let (z, slopes) = (self.cam.z, self.scene.rows.slopes);
        move |y| {
            let v = top - (z + depth * slopes[y as usize]);
            (v.max(0.0) as usize).min(texture.height - 1)
        }
    }

    /// Writes the opaque texels of texture column `u` over rows `rows` of
    /// column `x` (already cut to the window left open in front of it); row
    /// `y` shows texel row `texel_row(y)`. Where the frame fills them, those
    /// pixels get `depth` and `label` (a thing's, or 0 for a middle).
    fn put_texels(
        &self,
        out: &mut ColumnWriter,
        x: usize,
        (depth, label): (f64, u32),
        (y0, y1): (i32, i32),
        (texture, u, texel_row): (&Texture, usize, impl Fn(i32) -> usize),
        paint: Texels,
        translucent: bool,
    ) {
        let column = texture.column(u.min(texture.width - 1));
        let texel = |y: i32| column[texel_row(y)];
        match paint {
            // The common case as one run without a branch per texel: a
            // sprite's transparent texels mispredicted at every edge.
            Texels::Tinted(tint) if !translucent => put_opaque(out, x, y0, (y0..y1).map(texel), tint, (depth, label)),
            _ => {
                for y in y0..y1 {
                    let t = texel(y);
                    if t >> 24 == 0 {
                        continue;
                    }
                    out.buffers.pixel(x, y, depth as f32, label);
                    let c = match paint {
                        Texels::Solid(c) => c,
                        Texels::Tinted(tint) => tint.apply(t),
                        Texels::Fuzz(time) => {
                            out.put_fuzz(x, y, fuzz_offset(x, y, time));
                            continue;
                        }
                    };
                    if translucent {
                        out.put_blended(x, y, c);
                    } else {
                        out.put_masked(x, y, c);
                    }
                }
            }
        }
    }
}

impl MaskedPass<'_> {
    /// Whether column `x` was closed by a wall in front of a sprite at
    /// `depth` ([`hides_sprite`]), so that the sprite does not show there: a
    /// closed column's last clip event is the one that closed it, its window
    /// empty (what [`Self::window`] would find).
    fn closed_before(&self, x: usize, depth: f64) -> bool {
        let e = self.last_event[x];
        e != NONE && {
            let event = &self.events[e as usize];
            event.top >= event.bottom && hides_sprite(event.depth, depth)
        }
    }

    /// Rows `rows` of column `x` cut to the window through which something
    /// can be seen there (empty when the window misses them); `hides` says
    /// whether a wall at a depth is in front of it.
    fn open_rows(&self, x: usize, rows: (i32, i32), hides: impl Fn(f64) -> bool) -> (i32, i32) {
        let (top, bottom) = self.window(x, self.cam.height as i32, hides);
        (rows.0.max(top), rows.1.min(bottom))
    }

    /// Rows `[top, bottom)` of column `x` through which something can be
    /// seen: the window of the last clip event that `hides` it.
    fn window(&self, x: usize, height: i32, hides: impl Fn(f64) -> bool) -> (i32, i32) {
        let mut e = self.last_event[x];
        while e != NONE {
            let event = &self.events[e as usize];
            if hides(event.depth) {
                return (event.top, event.bottom);
            }
            e = event.prev;
        }
        (0, height)
    }
}

/// Writes `texels` down column `x` from row `y0`, lit by `tint`, where they
/// are opaque: the texels first, a load each, then light and select in one
/// vectorised loop, a stack buffer's worth at a time. Where the frame fills
/// them, those pixels get `depth` and `label`.
#[inline]
fn put_opaque(
    out: &mut ColumnWriter,
    x: usize,
    y0: i32,
    mut texels: impl Iterator<Item = u32>,
    tint: super::light::Tint,
    (depth, label): (f64, u32),
) {
    let mut run = [0u32; 64];
    let mut y = y0;
    loop {
        let mut n = 0;
        for (t, texel) in run.iter_mut().zip(&mut texels) {
            *t = texel;
            n += 1;
        }
        if n == 0 {
            return;
        }
        out.tint_opaque(x, y, &run[..n], tint);
        out.buffers.opaque(x, y, &run[..n], depth, label);
        y += n as i32;
    }
}

/// The label buffer's value for the thing keyed `key`: `key + 1`, so that 0
/// is no thing (saturating, for keys no simulation hands out).
pub(crate) fn label(key: usize) -> u32 {
    u32::try_from(key.saturating_add(1)).unwrap_or(u32::MAX)
}

/// How opaque texels become pixels.
#[derive(Clone, Copy)]
enum Texels {
    Solid(u32),
    Tinted(super::light::Tint),
    /// The spectre's fuzz at this tick.
    Fuzz(u64),
}

/// The row the fuzz copies into pixel `(x, y)` at tick `time`: the one
/// above or below, in a pattern that crawls a row a tick (a hash, so any
/// strip computes the same pixel alike; Doom walks a fixed table of 50).
fn fuzz_offset(x: usize, y: i32, time: u64) -> i32 {
    let h = (x as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ (y as u64 + time).wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
    if (h >> 29) & 1 == 0 {
        -1
    } else {
        1
    }
}
