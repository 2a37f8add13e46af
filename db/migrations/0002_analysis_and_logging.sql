-- Schema v2: what DriftLab derives from campaigns (fits, diagnoses,
-- compensation tables and their pushes), the event log, and run status for
-- live logging (an interrupted run is marked so and can be resumed).
ALTER TABLE run ADD COLUMN status TEXT NOT NULL DEFAULT 'complete'
    CHECK (status IN ('complete', 'logging', 'interrupted'));

CREATE TABLE model_fit (
    id INTEGER PRIMARY KEY,
    campaign_id INTEGER NOT NULL REFERENCES campaign(id) ON DELETE CASCADE,
    model TEXT NOT NULL,
    target TEXT NOT NULL DEFAULT 'positioning',
    train_runs_json TEXT NOT NULL,
    test_runs_json TEXT NOT NULL,
    parameters_json TEXT NOT NULL,
    metrics_json TEXT NOT NULL,
    created_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE TABLE diagnosis (
    id INTEGER PRIMARY KEY,
    campaign_id INTEGER NOT NULL REFERENCES campaign(id) ON DELETE CASCADE,
    base_model TEXT NOT NULL,
    verdict TEXT NOT NULL,
    adopted_fit_id INTEGER REFERENCES model_fit(id) ON DELETE SET NULL,
    result_json TEXT NOT NULL,
    created_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE TABLE compensation_table (
    id INTEGER PRIMARY KEY,
    campaign_id INTEGER NOT NULL REFERENCES campaign(id) ON DELETE CASCADE,
    model_fit_id INTEGER REFERENCES model_fit(id) ON DELETE SET NULL,
    axis TEXT NOT NULL,
    start_mm REAL NOT NULL,
    spacing_mm REAL NOT NULL CHECK (spacing_mm > 0),
    values_um_json TEXT NOT NULL,
    created_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE TABLE compensation_push (
    id INTEGER PRIMARY KEY,
    table_id INTEGER NOT NULL REFERENCES compensation_table(id) ON DELETE CASCADE,
    target TEXT NOT NULL,
    outcome TEXT NOT NULL CHECK (outcome IN ('applied', 'rolled_back', 'refused', 'failed')),
    message TEXT NOT NULL DEFAULT '',
    pushed_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE TABLE event_log (
    id INTEGER PRIMARY KEY,
    campaign_id INTEGER REFERENCES campaign(id) ON DELETE CASCADE,
    run_id INTEGER REFERENCES run(id) ON DELETE CASCADE,
    logged_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
    level TEXT NOT NULL CHECK (level IN ('info', 'warning', 'error')),
    source TEXT NOT NULL,
    message TEXT NOT NULL
);
