//! The HTTP service.

use crate::cli::ServeArgs;

/// Runs the server until Ctrl-C.
pub async fn serve(_args: ServeArgs) -> anyhow::Result<()> {
    anyhow::bail!("not yet")
}
