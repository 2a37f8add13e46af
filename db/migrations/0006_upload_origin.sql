-- Schema v6: store-and-forward into a server store (docs/lab-store.md, "The
-- spool and the upload"). A rig logs into a local SQLite store, its spool,
-- which names itself once (upload_spool, a random id); the uploader copies
-- the spool's campaigns and runs to the server and records there, in the same
-- transaction, which spool row each came from (upload_origin). An upload that
-- is repeated after an outage or a crash finds them and adds nothing twice.
CREATE TABLE upload_spool (
    spool_id TEXT NOT NULL
);

CREATE TABLE upload_origin (
    spool_id TEXT NOT NULL,
    kind TEXT NOT NULL CHECK (kind IN ('campaign', 'run')),
    spool_row_id INTEGER NOT NULL,
    row_id INTEGER NOT NULL,
    PRIMARY KEY (spool_id, kind, spool_row_id)
);
