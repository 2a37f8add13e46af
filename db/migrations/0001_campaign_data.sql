-- Schema v1: campaigns as imported from bundles (docs/bundles.md and docs/store.md).
CREATE TABLE campaign (
    id INTEGER PRIMARY KEY,
    name TEXT NOT NULL,
    nut_length_mm REAL,
    travel_from_mm REAL,
    travel_to_mm REAL,
    extra_json TEXT NOT NULL DEFAULT '{}',
    imported_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE TABLE machine (
    campaign_id INTEGER PRIMARY KEY REFERENCES campaign(id) ON DELETE CASCADE,
    name TEXT NOT NULL,
    axis TEXT NOT NULL DEFAULT '',
    controller TEXT NOT NULL DEFAULT '',
    extra_json TEXT NOT NULL DEFAULT '{}'
);

CREATE TABLE screw (
    campaign_id INTEGER PRIMARY KEY REFERENCES campaign(id) ON DELETE CASCADE,
    length_mm REAL NOT NULL CHECK (length_mm > 0),
    diameter_mm REAL NOT NULL CHECK (diameter_mm > 0),
    lead_mm REAL NOT NULL CHECK (lead_mm > 0),
    fixed_end_mm REAL NOT NULL,
    mounting TEXT NOT NULL,
    alpha_per_K REAL NOT NULL,
    density_kg_m3 REAL NOT NULL,
    specific_heat_J_kgK REAL NOT NULL,
    conductivity_W_mK REAL NOT NULL,
    extra_json TEXT NOT NULL DEFAULT '{}'
);

CREATE TABLE interferometer (
    campaign_id INTEGER PRIMARY KEY REFERENCES campaign(id) ON DELETE CASCADE,
    dead_path_mm REAL NOT NULL,
    environment_compensation INTEGER NOT NULL,
    extra_json TEXT NOT NULL DEFAULT '{}'
);

-- Declared sensor channels and the axis columns of samples.csv (position_mm,
-- feed_mm_min, torque_Nm), which have quantity 'axis' and no declared_ordinal.
CREATE TABLE channel (
    id INTEGER PRIMARY KEY,
    campaign_id INTEGER NOT NULL REFERENCES campaign(id) ON DELETE CASCADE,
    name TEXT NOT NULL,
    quantity TEXT NOT NULL,
    role TEXT,
    location TEXT NOT NULL DEFAULT '',
    position_mm REAL,
    declared_ordinal INTEGER,
    column_ordinal INTEGER,
    extra_json TEXT NOT NULL DEFAULT '{}',
    UNIQUE (campaign_id, name)
);

CREATE TABLE run (
    id INTEGER PRIMARY KEY,
    campaign_id INTEGER NOT NULL REFERENCES campaign(id) ON DELETE CASCADE,
    name TEXT NOT NULL,
    ordinal INTEGER NOT NULL,
    kind TEXT NOT NULL CHECK (kind IN ('moving', 'spindle', 'etve', 'positioning')),
    feed_mm_min REAL,
    range_from_mm REAL,
    range_to_mm REAL,
    description TEXT NOT NULL DEFAULT '',
    extra_json TEXT NOT NULL DEFAULT '{}',
    UNIQUE (campaign_id, name)
);

-- One present sample value; a missing sample has no row. Keyed by (run, time,
-- channel), the order in which samples are logged, so inserting is an append
-- and reading a run in time order needs no sort. channel_id has no foreign key:
-- channels are only deleted with their campaign, whose runs take the samples
-- with them, and a key on it would scan the whole table per deleted channel.
CREATE TABLE sample (
    run_id INTEGER NOT NULL REFERENCES run(id) ON DELETE CASCADE,
    t REAL NOT NULL,
    channel_id INTEGER NOT NULL,
    value REAL NOT NULL,
    PRIMARY KEY (run_id, t, channel_id)
) WITHOUT ROWID;

CREATE TABLE motion_segment (
    run_id INTEGER NOT NULL REFERENCES run(id) ON DELETE CASCADE,
    start_s REAL NOT NULL,
    end_s REAL NOT NULL,
    from_mm REAL NOT NULL,
    to_mm REAL NOT NULL,
    feed_mm_min REAL NOT NULL
);
CREATE INDEX motion_by_run ON motion_segment (run_id);

CREATE TABLE positioning (
    run_id INTEGER NOT NULL REFERENCES run(id) ON DELETE CASCADE,
    time_s REAL NOT NULL,
    cycle INTEGER NOT NULL,
    target_mm REAL NOT NULL,
    direction TEXT NOT NULL CHECK (direction IN ('+', '-')),
    deviation_um REAL NOT NULL
);
CREATE INDEX positioning_by_run ON positioning (run_id);
