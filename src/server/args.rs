//! `strata serve` options.

use crate::gpu::BackendChoice;
use std::net::SocketAddr;
use std::path::PathBuf;

/// `strata serve` options.
#[derive(Debug, clap::Args)]
pub struct ServeArgs {
    /// Address to listen on.
    #[arg(long, default_value = "127.0.0.1:8080")]
    pub addr: SocketAddr,
    /// Data directory (scene store, caches).
    #[arg(long, default_value = "data")]
    pub data: PathBuf,
    /// Compute backend.
    #[arg(long, value_enum, default_value_t = BackendChoice::Auto)]
    pub backend: BackendChoice,
    /// Directory of the browser viewer served at `/`.
    #[arg(long, default_value = "web/dist")]
    pub web: PathBuf,
    /// Server admin token: may create worlds and acts as admin of every world. Read from
    /// `STRATA_ADMIN_TOKEN` when not given. Without one, anyone may create worlds.
    #[arg(long)]
    pub admin_token: Option<super::access::Secret>,
    /// An origin (`https://maps.example.org`) whose pages may call every route from a browser,
    /// worlds included; repeat it for several. Read from `STRATA_CORS_ORIGINS` (comma-separated)
    /// when not given. Without one, only the server's own origin may, besides the bare seeds'
    /// routes, which every origin may read.
    #[arg(long, value_name = "ORIGIN", value_parser = check_origin)]
    pub cors_origin: Vec<String>,
    /// Directory of the disk tier of the stage cache (finished tiles by input hash); memory
    /// only without it.
    #[arg(long)]
    pub cache_dir: Option<PathBuf>,
}

fn check_origin(s: &str) -> Result<String, String> {
    super::cors::parse_origin(s).map(|_| s.to_owned())
}
