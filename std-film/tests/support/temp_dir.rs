//! A test's scratch folder that cannot outlive the test. Shared by the film's and the CLI's
//! tests (`#[path]`-included).

use std::path::{Path, PathBuf};

/// A fresh empty folder under the system temp folder, removed with everything in it when
/// dropped, so a test leaves nothing behind whether it passes or panics. Derefs to its path.
pub struct TempDir(PathBuf);

impl TempDir {
    /// `<temp>/<name>-<process id>`, emptied if a killed run left it behind.
    pub fn new(name: &str) -> TempDir {
        let d = std::env::temp_dir().join(format!("{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        TempDir(d)
    }
}

impl std::ops::Deref for TempDir {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for TempDir {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
