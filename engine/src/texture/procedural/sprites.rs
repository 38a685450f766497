//! Sprites: things standing in the map, drawn as flat billboards. The
//! background is transparent (alpha 0), the figure opaque (alpha 255, never in
//! between, so the renderer's mask test is one compare), and every figure stands
//! on the bottom row with a transparent column at each side.
//!
//! Each is painted as a stack of shapes: a shape says, for a point, whether it
//! covers it and in what colour; later shapes cover earlier ones.

use super::paint::{cylinder, hex, mix, opaque, rand01, scale, smoothstep, Rgb, TileNoise, CLEAR};
use crate::texture::Texture;

/// A shape: the colour it paints at texel centre `(x, y)`, if it covers it.
type Shape<'a> = Box<dyn Fn(f32, f32) -> Option<Rgb> + 'a>;

fn paint(w: usize, h: usize, shapes: Vec<Shape>) -> Texture {
    Texture::from_fn(w, h, |u, v| {
        let (x, y) = (u as f32 + 0.5, v as f32 + 0.5);
        // Keep the outer columns clear so bilinear or clamped sampling at the
        // sprite's edge never smears the figure.
        if u == 0 || u == w - 1 {
            return CLEAR;
        }
        shapes.iter().rev().find_map(|s| s(x, y)).map_or(CLEAR, opaque)
    })
}

fn inside_box(x: f32, y: f32, x0: f32, x1: f32, y0: f32, y1: f32) -> bool {
    (x0..x1).contains(&x) && (y0..y1).contains(&y)
}

/// A metal drum with ribs and a lid of glowing green slime. 32x48.
pub fn barrel(seed: u32) -> Texture {
    let (w, h) = (32, 48);
    let grime = &TileNoise::new(seed, (w, h), (4, 6), 3);
    let cx = 16.0;
    // Half-width bulges a little at mid-height, like a real drum.
    let radius = |y: f32| 12.0 + 1.5 * (std::f32::consts::PI * ((y - 6.0) / 42.0).clamp(0.0, 1.0)).sin();
    let body: Shape = Box::new(move |x, y| {
        let r = radius(y);
        if y < 6.0 || (x - cx).abs() > r {
            return None;
        }
        let t = (y - 6.0) / 42.0;
        let rib = [0.08, 0.5, 0.92].iter().any(|&rt| (t - rt).abs() < 0.035);
        let base = if rib { hex(0x7c8a5a) } else { hex(0x4f6236) };
        let dirty = mix(base, hex(0x4a3a28), 0.45 * smoothstep(0.55, 0.8, grime.at(x, y)));
        let lit = cylinder(x, cx, r) * if rib { 1.15 } else { 1.0 };
        Some(scale(dirty, lit))
    });
    // The lid seen slightly from above: an ellipse with a steel rim.
    let lid: Shape = Box::new(move |x, y| {
        let (dx, dy) = ((x - cx) / 12.8, (y - 6.0) / 4.2);
        let d = dx * dx + dy * dy;
        if d > 1.0 {
            return None;
        }
        if d > 0.62 {
            return Some(scale(hex(0x8c9478), 0.8 + 0.4 * (1.0 - dy)));
        }
        let swirl = rand01(seed, x as i32 / 2, y as i32);
        Some(mix(hex(0x5fd02c), hex(0xb8ff6a), swirl * 0.6 + 0.4 * (1.0 - d)))
    });
    paint(w, h, vec![body, lid])
}

/// A brass floor lamp with a glowing shade. 24x64.
pub fn lamp(_seed: u32) -> Texture {
    let (w, h) = (24, 64);
    let brass = hex(0xb08d3c);
    let base: Shape = Box::new(move |x, y| {
        let half = 8.0 + 0.4 * (y - 58.0); // widening to the floor
        (y >= 58.0 && (x - 12.0).abs() < half)
            .then(|| scale(brass, cylinder(x, 12.0, half) * (0.8 + 0.05 * (y - 58.0))))
    });
    let pole: Shape =
        Box::new(move |x, y| (y >= 18.0 && (x - 12.0).abs() < 1.5).then(|| scale(brass, cylinder(x, 12.0, 1.5))));
    // Fabric shade lit from inside: brightest at the middle and the bottom.
    let shade: Shape = Box::new(|x, y| {
        if !(3.0..20.0).contains(&y) {
            return None;
        }
        let t = (y - 3.0) / 17.0;
        let half = 4.5 + 6.0 * t;
        if (x - 12.0).abs() > half {
            return None;
        }
        let glow = 1.0 - ((x - 12.0) / half).powi(2);
        let c = mix(hex(0xc06a24), hex(0xffe28a), glow * (0.5 + 0.5 * t));
        Some(if !(4.0..19.0).contains(&y) { hex(0x8a5a20) } else { c })
    });
    let finial: Shape =
        Box::new(move |x, y| (((x - 12.0).powi(2) + (y - 2.0).powi(2)).sqrt() < 1.6).then(|| scale(brass, 1.2)));
    paint(w, h, vec![base, pole, shade, finial])
}

/// A short fluted marble pillar on a plinth. 32x48.
pub fn column(seed: u32) -> Texture {
    let (w, h) = (32, 48);
    let vein = &TileNoise::new(seed, (w, h), (3, 5), 4);
    let marble = move |x: f32, y: f32| {
        let n = vein.at(x, y);
        let line = 1.0 - ((n - 0.5).abs() * 25.0).min(1.0);
        mix(hex(0xd8d2c6), hex(0x8c8478), 0.15 * n + 0.5 * line)
    };
    let slab = move |y0: f32, y1: f32, half: f32| -> Shape {
        Box::new(move |x, y| {
            if !inside_box(x, y, 16.0 - half, 16.0 + half, y0, y1) {
                return None;
            }
            let top_lit = if y < y0 + 1.0 { 1.25 } else { 1.0 };
            Some(scale(marble(x, y), cylinder(x, 16.0, half * 1.4) * top_lit))
        })
    };
    let shaft: Shape = Box::new(move |x, y| {
        let half = 9.5 - 0.5 * ((y - 9.0) / 31.0);
        if !inside_box(x, y, 16.0 - half, 16.0 + half, 9.0, 41.0) {
            return None;
        }
        // Flutes: grooves evenly spaced around the shaft, seen foreshortened.
        let angle = ((x - 16.0) / half).clamp(-1.0, 1.0).asin();
        let flute = (angle * 6.0).cos() * 0.5 + 0.5;
        Some(scale(marble(x, y), cylinder(x, 16.0, half) * (0.68 + 0.4 * flute)))
    });
    paint(w, h, vec![shaft, slab(41.0, 44.0, 13.0), slab(44.0, 48.0, 14.5), slab(6.0, 9.0, 12.5), slab(3.0, 6.0, 14.0)])
}

/// A fern in a terracotta pot. 32x56.
pub fn plant(seed: u32) -> Texture {
    let (w, h) = (32, 56);
    let pot: Shape = Box::new(|x, y| {
        if (40.0..44.0).contains(&y) && (x - 16.0).abs() < 11.0 {
            return Some(scale(hex(0xb8643a), cylinder(x, 16.0, 11.0) * if y < 41.0 { 1.2 } else { 1.0 }));
        }
        let t = (y - 44.0) / 12.0;
        let half = 10.0 - 3.0 * t;
        ((0.0..=1.0).contains(&t) && (x - 16.0).abs() < half)
            .then(|| scale(hex(0xa55834), cylinder(x, 16.0, half) * (1.0 - 0.2 * t)))
    });
    // Fronds radiate from the pot's mouth; drawn back (dark) to front (light).
    let mut leaves: Vec<Shape> = vec![pot];
    for i in 0..9 {
        let a = -2.6 + 2.2 * (i as f32 / 8.0) + 0.25 * (rand01(seed, i, 0) - 0.5);
        let a = if i % 2 == 0 { a } else { -std::f32::consts::PI - a };
        let len = 18.0 + 14.0 * rand01(seed, i, 1);
        let (dx, dy) = (a.cos(), a.sin());
        let tone = 0.75 + 0.35 * (i as f32 / 8.0);
        leaves.push(Box::new(move |x, y| {
            let (px, py) = (x - 16.0, y - 41.0);
            let along = px * dx + py * dy;
            let across = -px * dy + py * dx;
            // Fronds droop: bend the leaf's axis downwards with distance.
            let across = across - 0.012 * along * along * dx.signum();
            if !(0.0..len).contains(&along) {
                return None;
            }
            let t = along / len;
            let half = 3.2 * (std::f32::consts::PI * t).sin().powf(0.7);
            if across.abs() > half {
                return None;
            }
            let serrated = ((along * 1.6).sin() * 0.5 + 0.5) * 0.8;
            if across.abs() > half - serrated {
                return None;
            }
            let midrib = across.abs() < 0.5;
            let c = mix(hex(0x1f5a1c), hex(0x5aa03a), t * 0.6 + 0.2);
            Some(scale(if midrib { hex(0x8cc460) } else { c }, tone))
        }));
    }
    // Leaves first in the list are drawn first, so put the pot in front.
    let pot_front = leaves.remove(0);
    leaves.push(pot_front);
    paint(w, h, leaves)
}

/// A tall iron torch stand with a flame. 16x64.
pub fn torch(seed: u32) -> Texture {
    let (w, h) = (16, 64);
    let iron = hex(0x4a4440);
    let stand: Shape = Box::new(move |x, y| {
        let foot = y >= 60.0 && (x - 8.0).abs() < 6.0 - (63.9 - y) * 0.5;
        let pole = y >= 20.0 && (x - 8.0).abs() < 1.5;
        let cup = (16.0..21.0).contains(&y) && (x - 8.0).abs() < 2.0 + (21.0 - y) * 0.8;
        (foot || pole || cup).then(|| scale(iron, cylinder(x, 8.0, if cup { 6.0 } else { 2.0 })))
    });
    let flicker = &TileNoise::new(seed, (w, h), (2, 8), 3);
    let flame: Shape = Box::new(move |x, y| {
        if !(1.0..17.0).contains(&y) {
            return None;
        }
        let t = (y - 1.0) / 16.0; // 0 at the tip, 1 at the cup
        let sway = (flicker.at(x, y) - 0.5) * 2.5 * (1.0 - t);
        let half = 5.5 * t.powf(0.6) * (1.0 - 0.3 * t * t);
        let d = (x - 8.0 - sway).abs() / half.max(0.01);
        if d > 1.0 {
            return None;
        }
        let heat = (1.0 - d) * (0.4 + 0.6 * t);
        let c = mix(hex(0xc0301a), hex(0xffa020), smoothstep(0.0, 0.4, heat));
        Some(mix(c, hex(0xfff6c0), smoothstep(0.4, 0.8, heat)))
    });
    paint(w, h, vec![stand, flame])
}

/// A wooden crate: a frame of boards with a diagonal brace, seen head on with
/// a sliver of lid. 48x48.
pub fn crate_(seed: u32) -> Texture {
    let (w, h) = (48, 48);
    let grain = &TileNoise::new(seed, (w, h), (12, 3), 3);
    let wood = move |x: f32, y: f32, tone: f32, along_x: bool| {
        let g = if along_x { grain.at(x, y * 3.0) } else { grain.at(y, x * 3.0) };
        scale(mix(hex(0x9c7040), hex(0x6a4422), g * 0.8), tone)
    };
    let lid: Shape =
        Box::new(move |x, y| inside_box(x, y, 3.0, 45.0, 1.0, 6.0).then(|| scale(wood(x, y, 1.0, true), 1.25)));
    let front: Shape = Box::new(move |x, y| {
        if !inside_box(x, y, 2.0, 46.0, 6.0, 48.0) {
            return None;
        }
        let (fx, fy) = (x - 2.0, y - 6.0); // 0..44, 0..42
        let upright = !(5.0..=39.0).contains(&fx);
        let rail = !(5.0..=37.0).contains(&fy);
        let frame = upright || rail;
        if frame {
            let corner = upright && rail;
            let nail = corner && ((fx % 39.0 - 2.5).powi(2) + (fy % 37.0 - 2.5).powi(2)) < 1.2;
            let edge = fx.min(44.0 - fx).min(fy).min(42.0 - fy);
            let lit = if edge < 1.0 { 1.2 } else { 1.0 };
            let c = wood(x, y, lit, !upright);
            return Some(if nail { hex(0x303030) } else { c });
        }
        // The brace runs from bottom left to top right across the panel.
        let brace = (fy - (42.0 - fx * 42.0 / 44.0)).abs() < 3.5;
        if brace {
            return Some(wood(x + 7.0, y, 1.05, true));
        }
        // Recessed planks behind, in the frame's shadow near its top and left.
        let plank = ((fy - 5.0) / 8.0).floor();
        let gap = (fy - 5.0) % 8.0 < 1.0;
        let shadow = smoothstep(5.0, 8.0, fx).min(smoothstep(5.0, 8.0, fy));
        let tone = (0.7 + 0.12 * rand01(seed, plank as i32, 0)) * (0.7 + 0.3 * shadow);
        Some(if gap { hex(0x2a1a0e) } else { wood(x, y + plank * 11.0, tone, true) })
    });
    paint(w, h, vec![lid, front])
}

/// Distance from `(x, y)` to the segment `a`-`b`.
fn to_segment(x: f32, y: f32, a: (f32, f32), b: (f32, f32)) -> f32 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let t = (((x - a.0) * dx + (y - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    ((x - a.0 - t * dx).powi(2) + (y - a.1 - t * dy).powi(2)).sqrt()
}

/// A bronze robed figure holding a staff, on a stone pedestal. 32x64.
pub fn statue(seed: u32) -> Texture {
    let (w, h) = (32, 64);
    const CX: f32 = 15.0;
    let patina = &TileNoise::new(seed, (w, h), (4, 8), 4);
    // Verdigris runs down from where rain collects: more of it lower down.
    let bronze = move |x: f32, y: f32, lit: f32| {
        let p = smoothstep(0.42, 0.68, patina.at(x, y) + 0.1 * (y / 48.0));
        scale(mix(hex(0x9a6e38), hex(0x4f8f78), p), lit)
    };
    let pedestal: Shape = Box::new(|x, y| {
        let cornice = inside_box(x, y, 2.0, 30.0, 48.0, 51.0);
        let block = inside_box(x, y, 4.0, 28.0, 51.0, 60.0);
        let plinth = inside_box(x, y, 2.0, 30.0, 60.0, 64.0);
        (cornice || block || plinth).then(|| {
            let edge = if cornice && y < 49.0 || plinth && y < 61.0 { 1.3 } else { 1.0 };
            scale(hex(0x8e8a84), cylinder(x, 16.0, 20.0) * edge)
        })
    });
    // The body's half-width by row: shoulders, narrowing to a belted waist,
    // then a robe flaring to the hem.
    let half = |y: f32| match y {
        _ if y < 17.0 => 4.0 + 4.0 * smoothstep(14.0, 17.0, y),
        _ if y < 28.0 => 8.0 - 3.0 * (y - 17.0) / 11.0,
        _ => 5.0 + 4.5 * (y - 28.0) / 20.0,
    };
    let body: Shape = Box::new(move |x, y| {
        let hw = half(y);
        if !(14.0..48.0).contains(&y) || (x - CX).abs() > hw {
            return None;
        }
        let belt = (27.0..29.0).contains(&y);
        // Folds below the belt: ridges that fan out towards the hem.
        let t = ((y - 28.0) / 20.0).max(0.0);
        let fold = ((x - CX) / (1.0 + t) * 1.6).cos() * 0.15 * t;
        let lit = cylinder(x, CX, hw) + fold - if belt { 0.25 } else { 0.0 };
        Some(bronze(x, y, lit))
    });
    let head: Shape = Box::new(move |x, y| {
        let d = ((x - CX).powi(2) + ((y - 9.0) * 1.1).powi(2)).sqrt();
        let neck = (11.0..15.0).contains(&y) && (x - CX).abs() < 1.8;
        (d < 3.8 || neck).then(|| bronze(x, y, cylinder(x, CX, 3.8)))
    });
    // The left arm hangs at the side; the right is raised to the staff.
    let arms: Shape = Box::new(move |x, y| {
        let left = to_segment(x, y, (8.0, 17.0), (7.0, 31.0));
        let right = to_segment(x, y, (21.5, 17.0), (25.5, 14.0));
        let d = left.min(right);
        (d < 1.9).then(|| bronze(x, y, 1.1 - 0.3 * d))
    });
    let staff: Shape = Box::new(move |x, y| {
        ((2.0..48.0).contains(&y) && (x - 25.5).abs() < 1.0).then(|| bronze(x, y, cylinder(x, 25.5, 1.0)))
    });
    paint(w, h, vec![pedestal, staff, body, arms, head])
}

/// A trooper in the zombieman's frames, by Doom's sprite naming (`POSSA1`:
/// frame A seen from direction 1, the front; `POSSH0`: a death frame seen
/// alike from every side), so that a test level plays with a monster and
/// no art files. 32x56: helmet, face or back of the head by direction, a
/// rifle on the side the figure turns to, legs that stride in frames A-D,
/// a raised rifle in E and its flash in F, a flinch in G; H-L fall and
/// M-U burst into a heap. `None` for other names.
pub fn trooper(name: &str) -> Option<Texture> {
    let b = name.as_bytes();
    if b.len() != 6 || &name[..4] != "POSS" {
        return None;
    }
    let (frame, view) = (b[4], b[5].wrapping_sub(b'0'));
    let standing = (b'A'..=b'G').contains(&frame) && (1..=8).contains(&view);
    let down = (b'H'..=b'U').contains(&frame) && view == 0;
    if !standing && !down {
        return None;
    }
    let (w, h) = (32usize, 56usize);
    let cx = 16.0f32;
    let khaki = hex(0x6b6a3a);
    let boots = hex(0x3a2a1c);
    let skin = hex(0xc08a68);
    let helmet = hex(0x4a5a32);
    let red = hex(0x9a1010);
    if down {
        // Falling, then a body on the floor; from M on, a bloody heap.
        let k = f32::from(frame - b'H');
        let height = if frame <= b'L' { 56.0 - k * 11.0 } else { 12.0 - (k - 5.0).min(6.0) };
        let shapes: Vec<Shape> = vec![Box::new(move |x, y| {
            let top = h as f32 - height;
            let half = if frame <= b'L' { 6.0 + k * 2.5 } else { 12.0 };
            if y < top || (x - cx).abs() > half {
                return None;
            }
            let gore = frame > b'L' || (y - top) < 3.0;
            Some(scale(if gore { red } else { khaki }, cylinder(x, cx, half)))
        })];
        return Some(paint(w, h, shapes));
    }
    // Directions 1 (front) round to 5 (back): how far the figure has turned
    // and to which side (3 and 7 are its profiles).
    let turn = match view {
        1 => 0.0,
        2 => -0.5,
        3 => -1.0,
        4 => -0.5,
        5 => 0.0,
        6 => 0.5,
        7 => 1.0,
        _ => 0.5,
    };
    let back = (4..=6).contains(&view);
    let half = 8.0 - 3.0 * f32::abs(turn);
    let stride = match frame {
        b'A' | b'C' => 3.0,
        _ => 0.0,
    };
    let aiming = frame == b'E' || frame == b'F';
    let flinch = if frame == b'G' { 1.0 } else { 0.0 };
    let torso: Shape = Box::new(move |x, y| {
        ((16.0..36.0).contains(&y) && (x - cx - flinch).abs() < half)
            .then(|| scale(khaki, cylinder(x, cx, half) * if back { 0.8 } else { 1.0 }))
    });
    let legs: Shape = Box::new(move |x, y| {
        let left = (x - (cx - 3.0 - stride)).abs() < 2.5;
        let right = (x - (cx + 3.0 + stride * 0.5)).abs() < 2.5;
        ((36.0..56.0).contains(&y) && (left || right)).then(|| if y > 50.0 { boots } else { scale(khaki, 0.8) })
    });
    let head: Shape = Box::new(move |x, y| {
        let d = ((x - cx - flinch).powi(2) + (y - 10.0).powi(2)).sqrt();
        (d < 5.5).then(|| {
            let face = !back && y > 9.0 && (x - cx - turn * 3.0 - flinch).abs() < 3.0;
            if face {
                skin
            } else {
                scale(helmet, cylinder(x, cx, 5.5))
            }
        })
    });
    // The rifle: across the body, towards the side the figure turns to,
    // raised when aiming.
    let gun_y = if aiming { 20.0 } else { 26.0 };
    let side = if turn == 0.0 { 1.0 } else { turn.signum() };
    let reach = 6.0 + 8.0 * f32::abs(turn);
    let gun: Shape = Box::new(move |x, y| {
        let along = (x - cx) * side;
        ((gun_y..gun_y + 3.0).contains(&y) && (-2.0..reach).contains(&along)).then(|| hex(0x202020))
    });
    let mut shapes = vec![legs, torso, head, gun];
    if frame == b'F' {
        let tip = cx + side * (reach + 2.0);
        shapes.push(Box::new(move |x, y| {
            (((x - tip).powi(2) + (y - gun_y - 1.5).powi(2)).sqrt() < 3.0).then(|| hex(0xffe070))
        }));
    }
    Some(paint(w, h, shapes))
}
