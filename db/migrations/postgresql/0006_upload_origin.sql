-- Schema v6 on PostgreSQL: ../0006_upload_origin.sql in PostgreSQL's dialect.
CREATE TABLE upload_spool (
    spool_id TEXT NOT NULL
);

CREATE TABLE upload_origin (
    spool_id TEXT NOT NULL,
    kind TEXT NOT NULL CHECK (kind IN ('campaign', 'run')),
    spool_row_id BIGINT NOT NULL,
    row_id BIGINT NOT NULL,
    PRIMARY KEY (spool_id, kind, spool_row_id)
);
