//! The text inside BEHAVIOR lumps: acc's escape sequences, and STRE's
//! scrambled string tables.

use super::load::u32_at;

/// ZDoom's `strbin`: the escapes acc leaves in strings (\n, \t, \c, \xHH,
/// octal, ...); bytes become chars one for one (Latin-1).
pub(super) fn unescape(s: &[u8]) -> String {
    let mut out = String::with_capacity(s.len());
    let mut i = 0;
    while i < s.len() {
        let c = s[i];
        i += 1;
        if c != b'\\' || i >= s.len() {
            out.push(char::from(c));
            continue;
        }
        let e = s[i];
        i += 1;
        let digits = |i: &mut usize, radix: u32, max: usize| {
            let mut v = 0u32;
            for _ in 0..max {
                match s.get(*i).and_then(|&d| char::from(d).to_digit(radix)) {
                    Some(d) => {
                        v = v * radix + d;
                        *i += 1;
                    }
                    None => break,
                }
            }
            v
        };
        match e {
            b'a' => out.push('\x07'),
            b'b' => out.push('\x08'),
            b'c' => out.push('\x1c'),
            b'f' => out.push('\x0c'),
            b'n' => out.push('\n'),
            b't' => out.push('\t'),
            b'r' => out.push('\r'),
            b'v' => out.push('\x0b'),
            b'\n' => {}
            b'x' | b'X' => out.push(char::from((digits(&mut i, 16, 2) & 0xff) as u8)),
            b'0'..=b'7' => {
                i -= 1;
                out.push(char::from((digits(&mut i, 8, 3) & 0xff) as u8));
            }
            other => out.push(char::from(other)),
        }
    }
    out
}

/// STRE: a STRL whose strings are scrambled with a key from each string's
/// offset (ZDoom's `UnencryptStrings`): byte i is XORed with
/// `(offset * 157135 + i / 2) mod 256` up to and including the terminator.
pub(super) fn decrypt(chunk: &[u8]) -> Vec<u8> {
    let mut data = chunk.to_vec();
    let count = u32_at(&data, 4).unwrap_or(0) as usize;
    for s in 0..count {
        let Some(ofs) = u32_at(chunk, 12 + s * 4) else { break };
        let key = (ofs as usize).wrapping_mul(157135) as u8;
        let mut i = 0usize;
        while let Some(byte) = data.get_mut(ofs as usize + i) {
            *byte ^= key.wrapping_add((i / 2) as u8);
            i += 1;
            if *byte == 0 {
                break;
            }
        }
    }
    data
}
