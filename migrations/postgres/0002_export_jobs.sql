-- Export jobs (src/store/jobs.rs), so that any replica answers for a job and takes over one
-- whose owner stopped renewing its lease. The same table as SQLite's (src/store/sqlite.rs).
CREATE TABLE export_jobs (
    id TEXT PRIMARY KEY,
    world_id TEXT NOT NULL REFERENCES worlds(id),
    version BIGINT NOT NULL,
    spec TEXT NOT NULL,
    status TEXT NOT NULL CHECK (status IN ('queued', 'running', 'done', 'failed', 'expired')),
    done BIGINT NOT NULL,
    total BIGINT NOT NULL,
    error TEXT,
    reserved BIGINT NOT NULL,
    bytes BIGINT NOT NULL,
    owner TEXT NOT NULL,
    lease_until_ms BIGINT NOT NULL,
    created_at BIGINT NOT NULL,
    finished_at BIGINT
);
-- What claim_job scans: the unfinished jobs by lease.
CREATE INDEX export_jobs_unfinished ON export_jobs (lease_until_ms, created_at, id)
    WHERE status IN ('queued', 'running');
