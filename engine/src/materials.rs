//! Materials: every texture name a map uses, resolved once when the level is
//! opened (a PNG beside the map or a built-in texture) into ids the renderer
//! indexes directly. A name that resolves to nothing is an error naming the
//! element that uses it.

use std::collections::{BTreeSet, HashMap};
use std::path::PathBuf;

use crate::actors::ActorTable;
use crate::map::{Map, Side, PLAYER_START, SKY};
use crate::texture::animdefs::AnimDefs;
use crate::texture::{Library, TextureError, TextureId, TextureKind, TextureSet};

/// The textures of one side of a line.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct SideTextures {
    pub upper: Option<TextureId>,
    pub middle: Option<TextureId>,
    pub lower: Option<TextureId>,
}

/// A sector's plane textures; `None` for untextured or sky.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct SectorTextures {
    pub floor: Option<TextureId>,
    pub ceiling: Option<TextureId>,
}

#[derive(Clone, Default)]
pub struct Materials {
    pub textures: TextureSet,
    /// Per line: `[front, back]` (the back is empty on one-sided lines).
    pub sides: Vec<[SideTextures; 2]>,
    pub sectors: Vec<SectorTextures>,
    /// Per thing: its sprite (`None` for things that are not drawn, such as
    /// the player start).
    pub sprites: Vec<Option<TextureId>>,
    /// Per actor sprite and frame ([`Materials::view_index`]), the textures
    /// it shows from Doom's eight directions (index 0 is direction 1, the
    /// front), for every actor the map's things can bring into play; `None`
    /// where the art has no such frame. Mirrored views are textures of
    /// their own (see `wad::import::sprite_view`).
    pub sprite_views: Vec<Option<[TextureId; 8]>>,
    /// Per sprite frame (indexed as `sprite_views`), the screen picture of
    /// a weapon's frame (the weapons' states only).
    pub screen_views: Vec<Option<TextureId>>,
    /// The panorama shown by `"SKY"` ceilings and floors, if any sector has one.
    pub sky: Option<TextureId>,
    /// Some two-sided line has a see-through middle texture.
    pub masked: bool,
    /// Per texture id, the texture drawn in its place now: itself, or the
    /// current frame of its animation ([`Self::side`] and [`Self::plane`]
    /// apply it; `play::world::animation` advances it).
    pub translation: Vec<TextureId>,
    /// The animations whose textures the map uses, with every frame resolved.
    pub animations: Vec<Animated>,
    /// Switch textures the map uses: each with its partner and its place in
    /// the switch list (Doom swaps the first part of a side that matches,
    /// in list order).
    pub switches: HashMap<TextureId, (TextureId, usize)>,
    /// Per texture and player colour, the texture redrawn in that colour
    /// (or itself, where it has no green to redraw), made when a body in
    /// that colour is first drawn ([`Materials::in_colour`]).
    pub coloured: HashMap<(TextureId, u8), TextureId>,
}

/// Frames a sprite may have: `A` to `]` (Doom's 29).
const SPRITE_FRAMES: usize = 29;

/// An animation's frames, as texture ids.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Animated {
    pub frames: Vec<TextureId>,
    pub tics: u32,
}

#[derive(Debug, thiserror::Error)]
#[error("{path}: {element}: {error}")]
pub struct MaterialError {
    pub path: String,
    /// Which element uses the name, e.g. `line 6 front side upper texture`.
    pub element: String,
    pub error: TextureError,
}

impl Materials {
    /// Sets every animated texture's current frame for tick `time` (Doom's
    /// `P_UpdateSpecials`): a texture that is frame `k` of an animation of
    /// `n` shows frame `(k + time / tics) mod n`, so all run in step. The
    /// renderers apply [`Materials::translation`] where they look a
    /// texture up: only what is drawn pays for it.
    pub fn animate(&mut self, time: u64) {
        for anim in &self.animations {
            let n = anim.frames.len();
            let step = (time / u64::from(anim.tics)) as usize % n;
            for (k, &frame) in anim.frames.iter().enumerate() {
                if let Some(slot) = self.translation.get_mut(frame.0 as usize) {
                    *slot = anim.frames[(k + step) % n];
                }
            }
        }
    }

    /// Resolves every texture `map` names, looking for PNGs under each of `dirs`
    /// (`textures/` and `sprites/` inside them) before the built-in textures.
    /// `label` names the map in errors.
    pub fn resolve(map: &Map, dirs: &[PathBuf], label: &str) -> Result<Materials, MaterialError> {
        Materials::resolve_in(map, &Library::dirs(dirs), label)
    }

    /// [`Materials::resolve`] in a library: PNG folders, then a WAD, then
    /// the built-in set.
    pub fn resolve_in(map: &Map, library: &Library, label: &str) -> Result<Materials, MaterialError> {
        let mut m = Materials::default();
        // A name may be a texture of the other kind (a STONE floor): walls and
        // flats are both just images. Report the lookup of the expected kind.
        let mut get = |name: &str, kind: TextureKind, element: String| {
            let other = match kind {
                TextureKind::Wall => Some(TextureKind::Flat),
                TextureKind::Flat => Some(TextureKind::Wall),
                TextureKind::Sprite | TextureKind::Screen => None,
            };
            m.textures
                .resolve_in(name, kind, library)
                .or_else(|error| match other {
                    Some(o) if matches!(error, TextureError::Missing { .. }) => {
                        m.textures.resolve_in(name, o, library).map_err(|_| error)
                    }
                    _ => Err(error),
                })
                .map_err(|error| MaterialError { path: label.to_string(), element, error })
        };
        let mut sides = Vec::with_capacity(map.lines.len());
        for (i, line) in map.lines.iter().enumerate() {
            let mut pair = [SideTextures::default(); 2];
            for (k, (which, side)) in
                [("front", Some(&line.front)), ("back", line.back.as_ref())].into_iter().enumerate()
            {
                if let Some(side) = side {
                    pair[k] = side_textures(side, &mut |name, part| {
                        get(name, TextureKind::Wall, format!("line {i} {which} side {part} texture"))
                    })?;
                }
            }
            sides.push(pair);
        }
        let mut sectors = Vec::with_capacity(map.sectors.len());
        let mut uses_sky = false;
        for (i, s) in map.sectors.iter().enumerate() {
            let mut plane = |name: &Option<String>, which: &str| -> Result<Option<TextureId>, MaterialError> {
                match name.as_deref() {
                    None => Ok(None),
                    Some(n) if n.eq_ignore_ascii_case(SKY) => {
                        uses_sky = true;
                        Ok(None)
                    }
                    Some(n) => get(n, TextureKind::Flat, format!("sector {i} {which} texture")).map(Some),
                }
            };
            let floor = plane(&s.floor_texture, "floor")?;
            let ceiling = plane(&s.ceiling_texture, "ceiling")?;
            sectors.push(SectorTextures { floor, ceiling });
        }
        let mut sprites = Vec::with_capacity(map.things.len());
        for (i, t) in map.things.iter().enumerate() {
            let element = format!("thing {i} (kind {:?}) sprite", t.kind);
            let sprite = if t.kind == PLAYER_START {
                None
            } else if map.version >= 2 {
                // A thing type names its first frame; its front view is
                // rotation 0 (all sides alike) or 1 (facing the viewer).
                match ActorTable::active().get(&t.kind).and_then(|ty| ActorTable::active().first_frame(ty)) {
                    None => None,
                    Some(stem) => {
                        let all_sides = format!("{stem}0");
                        match get(&all_sides, TextureKind::Sprite, element.clone()) {
                            Ok(id) => Some(id),
                            Err(_) => Some(get(&format!("{stem}1"), TextureKind::Sprite, element)?),
                        }
                    }
                }
            } else {
                Some(get(&t.kind.to_ascii_uppercase(), TextureKind::Sprite, element)?)
            };
            sprites.push(sprite);
        }
        let sky = match (&map.sky, uses_sky) {
            (_, false) => None,
            (Some(name), true) => Some(get(name, TextureKind::Wall, format!("the sky ({name})"))?),
            (None, true) => Some(get(SKY, TextureKind::Wall, "the sky".into())?),
        };
        let masked =
            sides.iter().zip(&map.lines).any(|(s, l)| l.back.is_some() && s.iter().any(|s| s.middle.is_some()));
        let mut m = Materials { sides, sectors, sprites, sky, masked, ..m };
        let own = own_animations(map, library).map_err(|error| MaterialError {
            path: label.to_string(),
            element: "the animations file".into(),
            error,
        })?;
        m.add_animations(map, library, own.as_ref().unwrap_or(AnimDefs::doom()));
        if map.version >= 2 {
            m.add_sprite_views(map, library);
        }
        Ok(m)
    }

    /// Texture `id` in player colour `colour` (Doom's translation bits: the
    /// player's number less one; 0 is the art's own green), made the first
    /// time it is asked for ([`crate::texture::colours`]).
    pub fn in_colour(&mut self, id: TextureId, colour: u8) -> TextureId {
        if colour == 0 {
            return id;
        }
        if let Some(&made) = self.coloured.get(&(id, colour)) {
            return made;
        }
        let made = match crate::texture::colours::in_colour(self.textures.get(id), usize::from(colour)) {
            Some(texture) => {
                let name = format!("{}@colour{colour}", self.textures.name(id));
                self.textures.add(name, texture)
            }
            None => id,
        };
        self.coloured.insert((id, colour), made);
        made
    }

    /// The index of sprite `sprite`'s frame `frame` in [`Self::sprite_views`].
    pub fn view_index(sprite: u16, frame: u8) -> usize {
        usize::from(sprite) * SPRITE_FRAMES + usize::from(frame)
    }

    /// Resolves every view of every frame of the actors the map's things
    /// can bring into play (the effects every game makes included). A view
    /// the art lacks takes the frame's first view; a frame with none stays
    /// `None`, and the actor keeps the last frame it could show.
    fn add_sprite_views(&mut self, map: &Map, library: &Library) {
        let table = ActorTable::active();
        let roots: Vec<usize> = map.things.iter().filter_map(|t| table.index(&t.kind)).collect();
        self.add_actor_views(table, roots, library);
    }

    /// Resolves the views of `actors` of `table` and of what they bring
    /// into play, with the effects every game makes and every weapon (a
    /// game whose scripts spawn actors by name, or whose table is a mod's
    /// with sprites of its own, adds its actors this way; the table's
    /// sprites must extend the active table's, as a layered table's do).
    pub fn add_actor_views(&mut self, table: &ActorTable, actors: Vec<usize>, library: &Library) {
        let effects = ["bullet_puff", "blood", "teleport_fog", "item_fog"].into_iter().filter_map(|n| table.index(n));
        let weapons: Vec<usize> = (0..table.actors.len()).filter(|&i| table.actors[i].weapon.is_some()).collect();
        let slots = table.sprites.len() * SPRITE_FRAMES;
        if self.sprite_views.len() < slots {
            self.sprite_views.resize(slots, None);
            self.screen_views.resize(slots, None);
        }
        let roots = actors.into_iter();
        for &w in &weapons {
            for label in ["Ready", "Deselect", "Select", "Fire", "Flash"] {
                let Some(start) = table.actors[w].label(label) else { continue };
                // A label's sequence, up to the next label of the actor or a loop back.
                let mut at = Some(start);
                for _ in 0..64 {
                    let Some(id) = at else { break };
                    let state = table.state(id);
                    let slot = Materials::view_index(state.sprite, state.frame);
                    if self.screen_views[slot].is_none() {
                        let name =
                            format!("{}{}0", table.sprites[usize::from(state.sprite)], char::from(b'A' + state.frame));
                        self.screen_views[slot] = self.textures.resolve_in(&name, TextureKind::Screen, library).ok();
                    }
                    at = state.next.filter(|n| n.0 > id.0);
                }
            }
        }
        for actor in table.closure(roots.chain(effects).chain(weapons.iter().copied())) {
            for id in table.states_of(&table.actors[actor]) {
                let state = table.state(id);
                let slot = Materials::view_index(state.sprite, state.frame);
                if self.sprite_views[slot].is_some() {
                    continue;
                }
                let stem = format!("{}{}", table.sprites[usize::from(state.sprite)], char::from(b'A' + state.frame));
                let mut find =
                    |view: char| self.textures.resolve_in(&format!("{stem}{view}"), TextureKind::Sprite, library).ok();
                self.sprite_views[slot] = match find('0') {
                    Some(all) => Some([all; 8]),
                    None => {
                        let views: Vec<Option<TextureId>> = ('1'..='8').map(&mut find).collect();
                        views.iter().flatten().next().map(|&first| std::array::from_fn(|k| views[k].unwrap_or(first)))
                    }
                };
            }
        }
    }

    /// Resolves the frames of every animation, and the partner of every
    /// switch, whose textures the map uses. An animation with a frame that
    /// resolves to nothing, or a switch without its partner, is left still
    /// (as Doom leaves out an animation whose textures a WAD lacks).
    fn add_animations(&mut self, map: &Map, library: &Library, defs: &AnimDefs) {
        let mut walls = BTreeSet::new();
        let mut flats = BTreeSet::new();
        for line in &map.lines {
            for side in std::iter::once(&line.front).chain(&line.back) {
                walls.extend(
                    [&side.upper, &side.middle, &side.lower].into_iter().flatten().map(|n| n.to_ascii_uppercase()),
                );
            }
        }
        for s in &map.sectors {
            flats.extend([&s.floor_texture, &s.ceiling_texture].into_iter().flatten().map(|n| n.to_ascii_uppercase()));
        }
        for (list, kind, used) in
            [(&defs.flats, TextureKind::Flat, &flats), (&defs.textures, TextureKind::Wall, &walls)]
        {
            for anim in list {
                if !anim.frames.iter().any(|f| used.contains(&f.to_ascii_uppercase())) {
                    continue;
                }
                let frames: Result<Vec<TextureId>, _> =
                    anim.frames.iter().map(|f| self.textures.resolve_in(f, kind, library)).collect();
                if let Ok(frames) = frames {
                    self.animations.push(Animated { frames, tics: anim.tics });
                }
            }
        }
        for (k, s) in defs.switches.iter().enumerate() {
            if !walls.contains(&s.off.to_ascii_uppercase()) && !walls.contains(&s.on.to_ascii_uppercase()) {
                continue;
            }
            let (Ok(off), Ok(on)) = (
                self.textures.resolve_in(&s.off, TextureKind::Wall, library),
                self.textures.resolve_in(&s.on, TextureKind::Wall, library),
            ) else {
                continue;
            };
            self.switches.insert(off, (on, k));
            self.switches.insert(on, (off, k));
        }
        self.translation = (0..self.textures.len() as u32).map(TextureId).collect();
    }

    /// What is drawn for `id` now (its animation's current frame).
    #[inline]
    pub fn current(&self, id: TextureId) -> TextureId {
        self.translation.get(id.0 as usize).copied().unwrap_or(id)
    }

    /// The textures side `k` (0 front, 1 back) of `line` shows now.
    #[inline]
    pub fn side(&self, line: usize, k: usize) -> SideTextures {
        let s = self.sides[line][k];
        let t = |id: Option<TextureId>| id.map(|id| self.current(id));
        SideTextures { upper: t(s.upper), middle: t(s.middle), lower: t(s.lower) }
    }

    /// The floor and ceiling textures `sector` shows now.
    #[inline]
    pub fn plane(&self, sector: usize) -> SectorTextures {
        let s = self.sectors[sector];
        SectorTextures { floor: s.floor.map(|id| self.current(id)), ceiling: s.ceiling.map(|id| self.current(id)) }
    }
}

/// The animations file a map names, read from its folder (the library's
/// first); `None` when it names none (the shipped list applies).
fn own_animations(map: &Map, library: &Library) -> Result<Option<AnimDefs>, TextureError> {
    let Some(name) = &map.animations else { return Ok(None) };
    let plain = !name.is_empty() && !name.starts_with('.') && !name.contains(['/', '\\', '\0', ':']);
    if !plain {
        return Err(TextureError::Animations(format!("{name:?} is not a plain file name beside the map")));
    }
    let path = library.dirs.first().map_or_else(|| PathBuf::from(name), |d| d.join(name));
    let text = std::fs::read_to_string(&path)
        .map_err(|e| TextureError::Animations(format!("{}: cannot read: {e}", path.display())))?;
    AnimDefs::parse(&text, &path.display().to_string()).map(Some).map_err(|e| TextureError::Animations(e.to_string()))
}

fn side_textures(
    side: &Side,
    get: &mut impl FnMut(&str, &str) -> Result<TextureId, MaterialError>,
) -> Result<SideTextures, MaterialError> {
    let mut one = |name: &Option<String>, part: &str| name.as_deref().map(|n| get(n, part)).transpose();
    Ok(SideTextures {
        upper: one(&side.upper, "upper")?,
        middle: one(&side.middle, "middle")?,
        lower: one(&side.lower, "lower")?,
    })
}
