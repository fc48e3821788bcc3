-- Uploaded images (PNG) of a world, for image materials and decals (src/ptex/spec.rs), stored
-- under the blake3 of their bytes and never changed or removed, so a scene version that names
-- one pins its bytes. The same table as SQLite's (src/store/sqlite.rs).
CREATE TABLE images (
    world_id TEXT NOT NULL REFERENCES worlds(id),
    hash BYTEA NOT NULL,
    png BYTEA NOT NULL,
    created_at BIGINT NOT NULL,
    PRIMARY KEY (world_id, hash)
);
