//! Doom's own arithmetic, exact to the bit: the foundation of a simulation
//! that plays vanilla Doom demos in sync. It hands the play code numbers,
//! angles, tables, geometry predicates and random draws that give the same
//! bits as Doom v1.9 (as Chocolate Doom reproduces it), overflow and quirks
//! included; nothing here uses a float except the conversions for tools.
//!
//! - [`number`]: [`Fixed`], 16.16 fixed point, `FixedMul` and `FixedDiv`
//!   (`m_fixed.c`);
//! - [`angle`]: [`Angle`], the 32-bit binary angle (`tables.h`);
//! - [`tables`]: `finesine`, `finecosine`, `finetangent`, `tantoangle`
//!   (`tables.c`), stored as data (`tables_data.rs`) because no formula
//!   reproduces them;
//! - [`direction`]: `SlopeDiv` and `R_PointToAngle2`;
//! - [`lines`]: `P_AproxDistance`, the three side tests, `divline_t` and
//!   `P_InterceptVector` (`p_maputl.c`, `r_main.c`);
//! - [`random`]: `P_Random`, `M_Random` and their table (`m_random.c`).
//!
//! Besides hand-worked cases, `vectors` checks 2,400 cases against the
//! results of Chocolate Doom's own C functions.
//!
//! Doom's C relies on the x86's two's-complement wrapping for `int`
//! overflow and on its compiler's left-to-right evaluation; each place that
//! does says so where it is reproduced. Doom's code is the specification,
//! rewritten here in Rust; its constants and tables carry over as facts.

pub mod angle;
pub mod direction;
pub mod lines;
pub mod number;
pub mod random;
pub mod tables;
mod tables_data;
#[cfg(test)]
mod vectors;

pub use angle::{Angle, ANG1, ANG180, ANG270, ANG45, ANG90, ANGLETOFINESHIFT, ANG_MAX};
pub use direction::{point_to_angle, point_to_angle2, slope_div};
pub use lines::{
    approx_distance, intercept_vector, point_on_divline_side, point_on_line_side, point_on_node_side, Divline, Side,
};
pub use number::{Fixed, FRACBITS, FRACUNIT};
pub use random::{DoomRandom, RNDTABLE};
pub use tables::{finecosine, finesine, finetangent, tantoangle, FINEANGLES, FINEMASK, SLOPERANGE};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_and_angle_serialise_as_their_bits() {
        let text = ron::to_string(&Fixed(-98304)).expect("a Fixed serialises");
        assert_eq!(text, "-98304");
        let back: Fixed = ron::from_str(&text).expect("and reads back");
        assert_eq!(back, Fixed(-98304));
        let angle: Angle = ron::from_str("1073741824").expect("an Angle reads from its bits");
        assert_eq!(angle, ANG90);
        assert_eq!(ron::to_string(&ANG_MAX).expect("an Angle serialises"), "4294967295");
    }
}
