-- Schema v3: samples in blocks (db/SampleBlocks.h) instead of a row per value,
-- and the content hash of an imported bundle, so a second import of the same
-- bundle is noticed. The rows of the old sample table are moved into blocks
-- by the migration's C++ step (SchemaMigrations.cpp), which then drops it.
CREATE TABLE sample_block (
    run_id INTEGER NOT NULL REFERENCES run(id) ON DELETE CASCADE,
    first_t REAL NOT NULL,
    last_t REAL NOT NULL,
    row_count INTEGER NOT NULL CHECK (row_count > 0),
    column_count INTEGER NOT NULL,
    present_count INTEGER NOT NULL,
    data BLOB NOT NULL,
    PRIMARY KEY (run_id, first_t)
);

ALTER TABLE campaign ADD COLUMN content_sha256 TEXT;
CREATE INDEX campaign_by_content ON campaign (content_sha256);
