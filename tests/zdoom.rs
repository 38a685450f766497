//! ZDoom-format levels: ViZDoom's scenario WADs (UDMF maps) read.

#[path = "vizdoom.rs"]
mod vizdoom;

use sightline::wad::udmf::Namespace;
use sightline::wad::Wad;

/// Every map of the 18 scenario WADs is a UDMF map in the zdoom namespace
/// that reads without an error, every reference checked.
#[test]
fn every_scenario_map_reads() {
    let Some(dir) = vizdoom::scenarios_or_skip("every_scenario_map_reads") else { return };
    let mut maps = 0;
    for name in vizdoom::WADS {
        let wad = Wad::open(&dir.join(format!("{name}.wad"))).unwrap();
        let names = wad.map_names();
        assert!(!names.is_empty(), "{name}.wad has no map");
        for map in names {
            assert!(wad.is_udmf(&map), "{name}.wad {map} is not a UDMF map");
            let udmf = wad.udmf(&map).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(udmf.namespace, Namespace::ZDoom, "{name}.wad {map}");
            assert!(!udmf.lines.is_empty() && !udmf.sectors.is_empty() && !udmf.things.is_empty(), "{name}.wad {map}");
            eprintln!(
                "{name}.wad {map}: {} vertices, {} lines, {} sides, {} sectors, {} things; not read: {:?}",
                udmf.vertices.len(),
                udmf.lines.len(),
                udmf.sides.len(),
                udmf.sectors.len(),
                udmf.things.len(),
                udmf.ignored
            );
            maps += 1;
        }
    }
    // cig.wad has two maps, cig_with_unknown.wad five.
    assert_eq!(maps, 16 + 2 + 5);
}

/// basic.wad's room as its TEXTMAP says: a 512 by 448 box, the player at
/// (-384, 32) in every skill and mode.
#[test]
fn basic_wad_is_the_room_vizdoom_describes() {
    let Some(dir) = vizdoom::scenarios_or_skip("basic_wad_is_the_room_vizdoom_describes") else { return };
    let map = Wad::open(&dir.join("basic.wad")).unwrap().udmf("map01").unwrap();
    assert_eq!((map.vertices.len(), map.lines.len(), map.sides.len(), map.sectors.len()), (4, 4, 4, 1));
    let xs: Vec<f64> = map.vertices.iter().map(|v| v.x).collect();
    assert_eq!(xs, [-448.0, 64.0, 64.0, -448.0]);
    let player = &map.things[0];
    assert_eq!((player.kind, player.x, player.y, player.id), (1, -384.0, 32.0, 1));
    assert!(player.flags.skills.iter().all(|&s| s) && player.flags.single);
    assert_eq!((map.sectors[0].ceiling, map.sectors[0].light), (104, 210));
    assert!(map.lines.iter().all(|l| l.flags.blocking && l.back.is_none()));
}

/// A UDMF map asked for as Doom-format records, and a Doom-format map asked
/// for as UDMF, say so.
#[test]
fn the_wrong_reader_says_which_format_the_map_is() {
    let Some(dir) = vizdoom::scenarios_or_skip("the_wrong_reader_says_which_format_the_map_is") else { return };
    let path = dir.join("basic.wad");
    let err = Wad::open(&path).unwrap().map("MAP01").unwrap_err().to_string();
    assert!(
        err.ends_with(
            "lump MAP01/TEXTMAP: a UDMF map, with no Doom-format records (UDMF maps can be drawn, imported and checked; the game does not play them yet)"
        ),
        "{err}"
    );
}

#[path = "freedoom_wads.rs"]
#[allow(dead_code)]
mod freedoom_wads;

/// The scenario maps on freedoom2.wad (ViZDoom's art) open as the same map
/// model as Doom's, compile and draw from their player start, every
/// texture found; the ZDoom specials they carry are listed as not read
/// yet. cig.wad's MAP02 has two one-sided lines over each other facing
/// opposite ways into sector 10 (ZDoom never minds): the import keeps the
/// one that closes the sector and says so.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn every_scenario_map_opens_on_freedoom2_and_draws() {
    use sightline::bsp::BuildOptions;
    use sightline::campaign::{open, MapRef};
    use sightline::render::{render_frame, Frame, RenderOptions, View};
    use sightline::Framebuffer;
    let Some(dir) = vizdoom::scenarios_or_skip("every_scenario_map_opens_on_freedoom2_and_draws") else { return };
    let iwad = freedoom_wads::path("freedoom2.wad");
    let mut drawn = 0;
    for name in vizdoom::WADS {
        let path = dir.join(format!("{name}.wad"));
        for map in Wad::open(&path).unwrap().map_names() {
            let what = format!("{name}.wad {map}");
            let opened = open(
                &MapRef::Wad { wads: vec![iwad.clone(), path.clone()], map: Some(map.clone()) },
                &BuildOptions::default(),
            );
            let opened = opened.unwrap_or_else(|e| panic!("{what}: {e}"));
            if name.starts_with("cig") && map == "MAP02" {
                let kept =
                    "kept linedef 95 instead of linedef 91: it has the same end points and closes sector 10's outline";
                assert!(opened.repairs.iter().any(|r| r == kept), "{what}: {:?}", opened.repairs);
            }
            let report = opened.report.expect("a WAD map has a report");
            assert!(
                report.unsupported_specials.iter().all(|s| s.contains("not translated yet")),
                "{what}: {:?}",
                report.unsupported_specials
            );
            let view = View::at_start(&opened.level).unwrap_or_else(|e| panic!("{what}: {e}"));
            let mut fb = Framebuffer::new(160, 100);
            render_frame(&opened.level, &view, &RenderOptions::default(), &mut Frame::new(), &mut fb);
            let colours = fb.pixels.iter().collect::<std::collections::BTreeSet<_>>().len();
            assert!(colours > 40, "{what}: a flat frame ({colours} colours)");
            drawn += 1;
        }
    }
    assert_eq!(drawn, 23);
}
