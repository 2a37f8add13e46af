-- Schema v3 on PostgreSQL: ../0003_sample_blocks.sql in PostgreSQL's dialect;
-- a block's data is BYTEA (db/SampleBlocks.h gives its layout). No PostgreSQL
-- store predates blocks (the server back end came with schema v5), so the
-- row-per-value table is empty here and simply dropped: SQLite's C++ step
-- that moves rows into blocks is not needed.
CREATE TABLE sample_block (
    run_id BIGINT NOT NULL REFERENCES run(id) ON DELETE CASCADE,
    first_t DOUBLE PRECISION NOT NULL,
    last_t DOUBLE PRECISION NOT NULL,
    row_count INTEGER NOT NULL CHECK (row_count > 0),
    column_count INTEGER NOT NULL,
    present_count BIGINT NOT NULL,
    data BYTEA NOT NULL,
    PRIMARY KEY (run_id, first_t)
);

DROP TABLE sample;

ALTER TABLE campaign ADD COLUMN content_sha256 TEXT;
CREATE INDEX campaign_by_content ON campaign (content_sha256);
