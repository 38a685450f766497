//! F12: the frame on screen (HUD and automap included) to a numbered PNG in
//! the current directory.

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use sightline::level::write_atomic;
use sightline::Framebuffer;

/// Writes `fb` to the first free `sightline-NNNN.png` in `dir` and returns
/// its path.
pub fn save(fb: &Framebuffer, dir: &Path) -> Result<PathBuf> {
    let Some(path) = (1..=9999).map(|n| dir.join(format!("sightline-{n:04}.png"))).find(|p| !p.exists()) else {
        bail!("{}: sightline-0001.png to sightline-9999.png all exist; move some away", dir.display());
    };
    write_atomic(&path, &fb.to_png())?;
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_count_up() {
        let dir = tempfile::tempdir().unwrap();
        let fb = Framebuffer::new(4, 3);
        let first = save(&fb, dir.path()).unwrap();
        let second = save(&fb, dir.path()).unwrap();
        assert!(first.ends_with("sightline-0001.png") && second.ends_with("sightline-0002.png"));
        assert_eq!(Framebuffer::read_png(&second).unwrap(), fb);
    }
}
