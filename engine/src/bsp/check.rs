//! Checks of a compiled map: the structural ones that loading a compiled file
//! needs before anything may index with its numbers, and the geometric
//! invariants that the compiler promises (run by the tests).

use std::collections::HashMap;

use super::build::ON_EPSILON;
use super::{Bsp, Child, LineSide};
use crate::geom::front_distance;
use crate::map::Map;

/// Every index in range, every coordinate finite, nodes and leaves forming one
/// tree. After this passes, walking the tree cannot index out of bounds or loop.
pub fn check_structure(map: &Map, bsp: &Bsp) -> Result<(), String> {
    let finite = |p: glam::DVec2| p.x.is_finite() && p.y.is_finite();
    for (i, s) in bsp.segs.iter().enumerate() {
        let sectors_ok = s.front_sector < map.sectors.len() && s.back_sector.is_none_or(|b| b < map.sectors.len());
        if s.line >= map.lines.len() || !sectors_ok || !finite(s.v1) || !finite(s.v2) || !s.offset.is_finite() {
            return Err(format!("seg {i} refers to a missing line or sector, or is not finite"));
        }
    }
    let mut referenced_nodes = vec![false; bsp.nodes.len()];
    let mut referenced_leaves = vec![false; bsp.leaves.len()];
    let mut mark = |child: Child, what: &str| -> Result<(), String> {
        let seen = match child {
            Child::Node(i) => referenced_nodes.get_mut(i),
            Child::Leaf(i) => referenced_leaves.get_mut(i),
        };
        match seen {
            None => Err(format!("{what} refers to {child:?}, which does not exist")),
            Some(true) => Err(format!("{what}: {child:?} is referenced twice (not a tree)")),
            Some(seen) => {
                *seen = true;
                Ok(())
            }
        }
    };
    mark(bsp.root, "the root")?;
    for (i, node) in bsp.nodes.iter().enumerate() {
        if !finite(node.a) || !finite(node.b) || node.a == node.b {
            return Err(format!("node {i} has a degenerate partition line"));
        }
        for child in node.children {
            mark(child, &format!("node {i}"))?;
        }
    }
    if referenced_nodes.iter().chain(&referenced_leaves).any(|seen| !seen) {
        return Err("some nodes or leaves are not reachable from the root".into());
    }
    // The leaves' seg ranges must partition `segs`: each seg in exactly one leaf.
    let mut owned = vec![false; bsp.segs.len()];
    for (i, leaf) in bsp.leaves.iter().enumerate() {
        let end = leaf.first.checked_add(leaf.count).filter(|&e| e <= bsp.segs.len());
        let Some(end) = end.filter(|_| leaf.count > 0 && leaf.sector < map.sectors.len()) else {
            return Err(format!("leaf {i} has a bad seg range or sector"));
        };
        for seen in &mut owned[leaf.first..end] {
            if std::mem::replace(seen, true) {
                return Err(format!("leaf {i} shares segs with another leaf"));
            }
        }
    }
    if owned.iter().any(|seen| !seen) {
        return Err("some segs belong to no leaf".into());
    }
    Ok(())
}

/// The compiler's geometric promises; returns the first broken one.
pub fn check_invariants(map: &Map, bsp: &Bsp) -> Result<(), String> {
    check_structure(map, bsp)?;
    check_sides_covered(map, bsp)?;
    check_sides_of_ancestors(bsp)?;
    check_leaves_convex(bsp)
}

/// Tolerance for the geometric checks: a few compiler epsilons, scaled up for
/// far-out coordinates where the split points carry more rounding.
fn tolerance(p: glam::DVec2) -> f64 {
    ON_EPSILON * 4.0 + p.abs().max_element() * 1e-12
}

/// Each input side is the union of its pieces: they lie on the line, point the
/// side's way, and tile it from end to end without gaps or overlaps.
fn check_sides_covered(map: &Map, bsp: &Bsp) -> Result<(), String> {
    let mut pieces: HashMap<(usize, bool), Vec<usize>> = HashMap::new();
    for (i, s) in bsp.segs.iter().enumerate() {
        pieces.entry((s.line, s.side == LineSide::Back)).or_default().push(i);
    }
    for (l, line) in map.lines.iter().enumerate() {
        for back in [false, true] {
            let list = pieces.remove(&(l, back)).unwrap_or_default();
            if back && line.back.is_none() {
                if !list.is_empty() {
                    return Err(format!("line {l} is one-sided but has back segs"));
                }
                continue;
            }
            let (mut start, mut end) = map.line_points(line);
            if back {
                std::mem::swap(&mut start, &mut end);
            }
            let length = start.distance(end);
            let mut list: Vec<_> = list.into_iter().map(|i| &bsp.segs[i]).collect();
            list.sort_by(|a, b| a.offset.total_cmp(&b.offset));
            let mut reached = start;
            let mut covered = 0.0;
            for s in &list {
                let tol = tolerance(s.v1);
                if s.v1.distance(reached) > tol {
                    return Err(format!("line {l} side {back}: gap or overlap before offset {}", s.offset));
                }
                if (s.offset - covered).abs() > tol {
                    return Err(format!("line {l} side {back}: piece offset {} should be {covered}", s.offset));
                }
                for p in [s.v1, s.v2] {
                    if front_distance(start, end, p).abs() > tol {
                        return Err(format!("line {l}: a piece leaves the line"));
                    }
                }
                if (s.v2 - s.v1).dot(end - start) <= 0.0 {
                    return Err(format!("line {l}: a piece points the wrong way"));
                }
                covered += s.v1.distance(s.v2);
                reached = s.v2;
            }
            if list.is_empty() || reached.distance(end) > tolerance(end) || (covered - length).abs() > tolerance(end) {
                return Err(format!("line {l} side {back}: pieces do not cover it"));
            }
        }
    }
    Ok(())
}

/// Every seg is on the side of each ancestor partition that leads to its leaf.
fn check_sides_of_ancestors(bsp: &Bsp) -> Result<(), String> {
    let mut stack = vec![(bsp.root, Vec::<(usize, bool)>::new())];
    while let Some((child, path)) = stack.pop() {
        match child {
            Child::Node(i) => {
                for (k, c) in bsp.nodes[i].children.iter().enumerate() {
                    let mut p = path.clone();
                    p.push((i, k == 1));
                    stack.push((*c, p));
                }
            }
            Child::Leaf(l) => {
                for s in bsp.leaf_segs(&bsp.leaves[l]) {
                    for &(n, behind) in &path {
                        let node = &bsp.nodes[n];
                        for p in [s.v1, s.v2] {
                            let d = front_distance(node.a, node.b, p);
                            let ok = if behind { d < tolerance(p) } else { d > -tolerance(p) };
                            if !ok {
                                return Err(format!(
                                    "leaf {l}: a seg of line {} is on the wrong side of node {n}",
                                    s.line
                                ));
                            }
                        }
                    }
                }
            }
        }
    }
    Ok(())
}

/// Each leaf's segs face into one convex cell of the leaf's sector.
fn check_leaves_convex(bsp: &Bsp) -> Result<(), String> {
    for (l, leaf) in bsp.leaves.iter().enumerate() {
        let segs = bsp.leaf_segs(leaf);
        for s in segs {
            if s.front_sector != leaf.sector {
                return Err(format!("leaf {l}: seg of line {} is not of sector {}", s.line, leaf.sector));
            }
            for t in segs {
                for p in [t.v1, t.v2] {
                    if front_distance(s.v1, s.v2, p) < -tolerance(p) {
                        return Err(format!("leaf {l} is not convex: line {} is behind line {}", t.line, s.line));
                    }
                }
            }
        }
    }
    Ok(())
}
