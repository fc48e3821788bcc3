//! The PostgreSQL schema's migrations: the files of `migrations/postgres/`, applied in order
//! once each and recorded in `schema_migrations`, under an advisory lock so that replicas
//! starting together apply each one once.

use super::super::shared::{backend, now};
use super::super::StoreError;

/// Every migration, `(version, SQL)`, in order; a database that records a later version than
/// the last is refused (it was migrated by a newer build).
const MIGRATIONS: &[(i64, &str)] = &[
    (
        1,
        include_str!("../../../migrations/postgres/0001_init.sql"),
    ),
    (
        2,
        include_str!("../../../migrations/postgres/0002_export_jobs.sql"),
    ),
    (
        3,
        include_str!("../../../migrations/postgres/0003_images.sql"),
    ),
];

/// The key of the transaction-level advisory lock taken while migrating (`"strata"` in ASCII).
const LOCK_KEY: i64 = 0x7374_7261_7461;

/// Applies the migrations `client`'s database lacks, in one transaction.
///
/// # Errors
/// [`StoreError::Backend`] when the database fails or was migrated by a newer build.
pub(super) async fn migrate(client: &mut tokio_postgres::Client) -> Result<(), StoreError> {
    let tx = client.transaction().await.map_err(backend)?;
    tx.execute("SELECT pg_advisory_xact_lock($1)", &[&LOCK_KEY])
        .await
        .map_err(backend)?;
    tx.batch_execute(
        "CREATE TABLE IF NOT EXISTS schema_migrations (
             version BIGINT PRIMARY KEY,
             applied_at BIGINT NOT NULL
         )",
    )
    .await
    .map_err(backend)?;
    let applied: i64 = tx
        .query_one(
            "SELECT COALESCE(MAX(version), 0) FROM schema_migrations",
            &[],
        )
        .await
        .map_err(backend)?
        .get(0);
    let known = MIGRATIONS.last().map_or(0, |m| m.0);
    if applied > known {
        return Err(StoreError::Backend(format!(
            "the database has schema version {applied}; this build knows {known}"
        )));
    }
    for (version, sql) in MIGRATIONS.iter().filter(|m| m.0 > applied) {
        tx.batch_execute(sql).await.map_err(|e| {
            StoreError::Backend(format!("migration {version} failed: {}", pg_message(&e)))
        })?;
        tx.execute(
            "INSERT INTO schema_migrations (version, applied_at) VALUES ($1, $2)",
            &[version, &now()],
        )
        .await
        .map_err(backend)?;
    }
    tx.commit().await.map_err(backend)
}

/// The server's message of a database error, or the client's when there is none.
pub(super) fn pg_message(e: &tokio_postgres::Error) -> String {
    match e.as_db_error() {
        Some(db) => format!("{}: {}", db.code().code(), db.message()),
        None => e.to_string(),
    }
}
