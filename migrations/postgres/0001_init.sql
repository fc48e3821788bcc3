-- The scene store's tables (src/store/postgres.rs), the same as SQLite's (src/store/sqlite.rs).
-- Scenes and patches are TEXT, not JSONB: the edit log's scene_hash is blake3 of the exact
-- text, which JSONB would reformat.
CREATE TABLE worlds (
    id TEXT PRIMARY KEY,
    seed BIGINT NOT NULL,
    public BOOLEAN NOT NULL,
    version BIGINT NOT NULL,
    scene TEXT NOT NULL,
    created_at BIGINT NOT NULL,
    updated_at BIGINT NOT NULL
);
CREATE TABLE edits (
    world_id TEXT NOT NULL REFERENCES worlds(id),
    version BIGINT NOT NULL,
    patch TEXT NOT NULL,
    scene_hash BYTEA NOT NULL,
    created_at BIGINT NOT NULL,
    PRIMARY KEY (world_id, version)
);
CREATE TABLE snapshots (
    world_id TEXT NOT NULL REFERENCES worlds(id),
    version BIGINT NOT NULL,
    scene TEXT NOT NULL,
    PRIMARY KEY (world_id, version)
);
CREATE TABLE tokens (
    hash BYTEA PRIMARY KEY,
    world_id TEXT NOT NULL REFERENCES worlds(id),
    role TEXT NOT NULL CHECK (role IN ('read', 'edit', 'admin')),
    created_at BIGINT NOT NULL
);
CREATE INDEX worlds_created ON worlds (created_at, id);
