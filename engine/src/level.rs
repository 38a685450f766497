//! Opening a level for rendering: a RON source (validated and compiled on the
//! spot) or a compiled map file (loaded as is), told apart by content.

use std::path::Path;

use crate::bsp::{build, file, BuildOptions, CompileError, CompiledMap};
use crate::map::{load::parse_map_bytes, MapError};

#[derive(Debug, thiserror::Error)]
pub enum LevelError {
    #[error(transparent)]
    Map(#[from] MapError),
    #[error("{path}: cannot compile: {error}")]
    Compile { path: String, error: CompileError },
    #[error("{path}: {message}")]
    Compiled { path: String, message: String },
    #[error("{path}: cannot write: {error}")]
    Write { path: String, error: std::io::Error },
    #[error("{path}: refusing to overwrite the input map")]
    OverwriteInput { path: String },
}

/// Reads `path` and returns a compiled map, compiling a source map with `options`.
pub fn open_level(path: &Path, options: &BuildOptions) -> Result<CompiledMap, LevelError> {
    let label = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|error| MapError::Io {
        path: label.clone(),
        error,
    })?;
    level_from_bytes(&bytes, &label, options)
}

pub fn level_from_bytes(
    bytes: &[u8],
    label: &str,
    options: &BuildOptions,
) -> Result<CompiledMap, LevelError> {
    if file::is_compiled(bytes) {
        return file::from_bytes(bytes).map_err(|message| LevelError::Compiled {
            path: label.to_string(),
            message,
        });
    }
    let map = parse_map_bytes(bytes, label)?;
    build(&map, options).map_err(|error| LevelError::Compile {
        path: label.to_string(),
        error,
    })
}

/// Writes `bytes` to `path` atomically: a temporary file beside it, then a
/// rename. A failure leaves any existing file at `path` untouched.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), LevelError> {
    use std::io::Write;
    let err = |error| LevelError::Write {
        path: path.display().to_string(),
        error,
    };
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .ok_or_else(|| err(std::io::Error::other("not a file name")))?;
    let tmp = dir.join(format!(
        ".{}.tmp{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result.map_err(err)
}

/// Refuses an output path that names the same file as the input.
pub fn check_not_input(input: &Path, output: &Path) -> Result<(), LevelError> {
    let same = match (input.canonicalize(), output.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    if same {
        return Err(LevelError::OverwriteInput {
            path: output.display().to_string(),
        });
    }
    Ok(())
}
