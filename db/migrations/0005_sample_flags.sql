-- Schema v5: sensor flags (docs/sensor-health.md, "Flags in the store").
-- What `health --store` found in a run's samples: per channel and kind (the
-- SensorFault ids), time ranges of consecutive flagged samples, both ends
-- inclusive. The samples themselves are never changed; the models leave
-- these out unless told otherwise. Flags go with their run.
CREATE TABLE sample_flag (
    id INTEGER PRIMARY KEY,
    run_id INTEGER NOT NULL REFERENCES run(id) ON DELETE CASCADE,
    channel TEXT NOT NULL,
    kind TEXT NOT NULL CHECK (kind IN ('out_of_range', 'frozen', 'spike', 'rate_of_change',
                                       'redundant_drift')),
    from_t REAL NOT NULL,
    to_t REAL NOT NULL CHECK (to_t >= from_t)
);
CREATE INDEX sample_flag_by_run ON sample_flag (run_id);
