//! An actor's state text, parsed line by line into entries (`load.rs` then
//! resolves them into [`State`](super::State)s). The syntax is DECORATE's,
//! which Doom modders know:
//!
//! ```text
//! Spawn:                      a label (a name and a colon; text may follow it)
//!     POSS AB 10 A_Look       sprite, frames (one state each), tics, action
//!     loop                    back to the label's first state
//! Missile:
//!     POSS E 10 A_FaceTarget
//!     POSS F 8 bright A_PosAttack
//!     goto See                or See+2: the third state after See
//! Death:
//!     POSS L -1               -1 tics: stays for ever
//!     stop                    removes the actor when reached
//! ```
//!
//! `bright` draws the frame at full brightness; `fast` halves its tics on
//! fast skills; `wait` repeats the last state for ever. An action may take
//! arguments: `A_Explode(64, 128)`, `A_PlaySound("slop")`. `//` starts a
//! comment. Keywords are case-insensitive.

/// One parsed line (or part of a line: a label may share its line).
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// The line within the state text, from 1.
    pub line: usize,
    /// The line as written, trimmed, for errors.
    pub text: String,
    pub kind: EntryKind,
}

#[derive(Clone, Debug, PartialEq)]
pub enum EntryKind {
    Label(String),
    /// One line of states: one state per frame letter.
    States(StateLine),
    Loop,
    Stop,
    Wait,
    Goto {
        label: String,
        offset: u32,
    },
}

#[derive(Clone, Debug, PartialEq)]
pub struct StateLine {
    pub sprite: String,
    /// Frame numbers, 0 for `A`.
    pub frames: Vec<u8>,
    pub tics: i32,
    pub bright: bool,
    pub fast: bool,
    /// The action's name and its arguments as written.
    pub action: Option<(String, Vec<RawArg>)>,
}

/// An action argument before it is checked against the action's signature.
#[derive(Clone, Debug, PartialEq)]
pub enum RawArg {
    Int(i64),
    Number(f64),
    /// A quoted string: an actor or a sound.
    Str(String),
    /// A bare word: a label.
    Word(String),
}

/// A line that could not be read.
#[derive(Clone, Debug, PartialEq)]
pub struct SyntaxError {
    pub line: usize,
    pub text: String,
    pub message: String,
}

/// Parses the state text.
pub fn parse(text: &str) -> Result<Vec<Entry>, SyntaxError> {
    let mut entries = Vec::new();
    for (n, raw) in text.lines().enumerate() {
        let line = n + 1;
        let code = raw.split("//").next().unwrap_or("").trim();
        if code.is_empty() {
            continue;
        }
        let fail = |message: String| SyntaxError { line, text: code.to_string(), message };
        let mut rest = code;
        // Labels first: `Spawn:` or `Spawn: POSS AB 10 A_Look`.
        while let Some((head, tail)) = rest.split_once(':') {
            let label = head.trim();
            if label.is_empty() || !label.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.') {
                break;
            }
            entries.push(Entry { line, text: code.to_string(), kind: EntryKind::Label(label.to_string()) });
            rest = tail.trim();
        }
        if rest.is_empty() {
            continue;
        }
        let kind = parse_body(rest).map_err(fail)?;
        entries.push(Entry { line, text: code.to_string(), kind });
    }
    Ok(entries)
}

/// A line after its labels: a flow keyword or a line of states.
fn parse_body(text: &str) -> Result<EntryKind, String> {
    let mut words = text.split_whitespace();
    let first = words.next().unwrap_or("");
    match first.to_ascii_lowercase().as_str() {
        "loop" | "stop" | "wait" => {
            if let Some(extra) = words.next() {
                return Err(format!("`{first}` takes nothing after it, found `{extra}`"));
            }
            return Ok(match first.to_ascii_lowercase().as_str() {
                "loop" => EntryKind::Loop,
                "stop" => EntryKind::Stop,
                _ => EntryKind::Wait,
            });
        }
        "goto" => {
            let target: String = words.collect::<Vec<_>>().join("");
            let (label, offset) = match target.split_once('+') {
                Some((l, o)) => (
                    l.to_string(),
                    o.parse::<u32>().map_err(|_| format!("`{o}` is not a state offset (goto Label+N)"))?,
                ),
                None => (target, 0),
            };
            if label.is_empty() {
                return Err("goto needs a label".into());
            }
            return Ok(EntryKind::Goto { label, offset });
        }
        _ => {}
    }
    parse_states(text).map(EntryKind::States)
}

/// `SPRT FRAMES TICS [bright] [fast] [Action[(args)]]`.
fn parse_states(text: &str) -> Result<StateLine, String> {
    let mut parts = text.splitn(4, char::is_whitespace).filter(|s| !s.is_empty());
    let sprite = parts.next().unwrap_or("");
    if sprite.len() != 4 || !sprite.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(format!(
            "`{sprite}` is not a sprite name (four letters or digits); a state is `SPRT FRAMES TICS [bright] [fast] [action]`"
        ));
    }
    let letters = parts.next().ok_or("a state needs frames and tics after its sprite")?;
    let frames = letters
        .chars()
        .map(|c| match c.to_ascii_uppercase() {
            c @ ('A'..='Z' | '[' | '\\' | ']') => Ok(c as u8 - b'A'),
            c => Err(format!("frame `{c}` is not a letter from A to ]")),
        })
        .collect::<Result<Vec<u8>, String>>()?;
    let tics_text = parts.next().ok_or("a state needs tics after its frames")?;
    let tics: i32 = tics_text.parse().map_err(|_| format!("`{tics_text}` is not a number of tics"))?;
    if tics < -1 {
        return Err(format!("tics {tics}: a state lasts 0 or more tics, or -1 for ever"));
    }
    let mut state =
        StateLine { sprite: sprite.to_ascii_uppercase(), frames, tics, bright: false, fast: false, action: None };
    let mut rest = parts.next().unwrap_or("").trim();
    loop {
        let word = rest.split(|c: char| c.is_whitespace() || c == '(').next().unwrap_or("");
        match word.to_ascii_lowercase().as_str() {
            "" => break,
            "bright" => state.bright = true,
            "fast" => state.fast = true,
            _ => {
                state.action = Some(parse_action(rest)?);
                break;
            }
        }
        rest = rest[word.len()..].trim_start();
    }
    Ok(state)
}

/// `Name` or `Name(arg, arg, ...)`, and nothing after it.
fn parse_action(text: &str) -> Result<(String, Vec<RawArg>), String> {
    let (name, args) = match text.split_once('(') {
        None => (text.trim(), ""),
        Some((name, tail)) => {
            let tail = tail.trim_end();
            let inner = tail.strip_suffix(')').ok_or_else(|| format!("`{text}`: an argument list ends with `)`"))?;
            (name.trim(), inner)
        }
    };
    if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(format!("`{text}`: expected `bright`, `fast` or an action name"));
    }
    let args = if args.trim().is_empty() {
        Vec::new()
    } else {
        split_args(args)?.iter().map(|a| parse_arg(a)).collect::<Result<_, _>>()?
    };
    Ok((name.to_string(), args))
}

/// Splits on commas outside quotes.
fn split_args(text: &str) -> Result<Vec<String>, String> {
    let (mut args, mut current, mut quoted) = (Vec::new(), String::new(), false);
    for c in text.chars() {
        match c {
            '"' => {
                quoted = !quoted;
                current.push(c);
            }
            ',' if !quoted => args.push(std::mem::take(&mut current)),
            _ => current.push(c),
        }
    }
    if quoted {
        return Err(format!("`{text}`: a string is not closed"));
    }
    args.push(current);
    Ok(args)
}

fn parse_arg(text: &str) -> Result<RawArg, String> {
    let t = text.trim();
    if let Some(inner) = t.strip_prefix('"').and_then(|s| s.strip_suffix('"')) {
        return Ok(RawArg::Str(inner.to_string()));
    }
    if let Ok(i) = t.parse::<i64>() {
        return Ok(RawArg::Int(i));
    }
    if let Ok(x) = t.parse::<f64>() {
        if x.is_finite() {
            return Ok(RawArg::Number(x));
        }
    }
    if !t.is_empty() && t.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '+' || c == '.') {
        return Ok(RawArg::Word(t.to_string()));
    }
    Err(format!("`{t}` is not an argument (a number, a \"string\" or a label)"))
}
