-- Schema v4: the push history (docs/compensation.md, "Push history"). v2's
-- compensation_push hung every push on a stored compensation_table row; a
-- push also comes from a bundle, with no campaign in the store, and must say
-- what it sent to which controller. Old rows are carried over with what they
-- knew (the table's values as JSON, their campaign through the table).
CREATE TABLE compensation_push_v4 (
    id INTEGER PRIMARY KEY,
    pushed_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
    campaign_id INTEGER REFERENCES campaign(id) ON DELETE SET NULL,
    table_id INTEGER REFERENCES compensation_table(id) ON DELETE SET NULL,
    run TEXT NOT NULL DEFAULT '',
    controller_url TEXT NOT NULL,
    table_version INTEGER NOT NULL DEFAULT 0,
    points INTEGER NOT NULL DEFAULT 0,
    table_checksum INTEGER NOT NULL DEFAULT 0,
    table_json TEXT NOT NULL DEFAULT '{}',
    result TEXT NOT NULL CHECK (result IN ('applied', 'rolled_back', 'refused', 'failed')),
    message TEXT NOT NULL DEFAULT '',
    steps_json TEXT NOT NULL DEFAULT '[]'
);

INSERT INTO compensation_push_v4 (id, pushed_at, campaign_id, table_id, controller_url, points,
                                  table_json, result, message)
SELECT p.id, p.pushed_at, t.campaign_id, p.table_id, p.target, json_array_length(t.values_um_json),
       json_object('start_mm', t.start_mm, 'spacing_mm', t.spacing_mm, 'axis', t.axis,
                   'correction_um', json(t.values_um_json)),
       p.outcome, p.message
FROM compensation_push p LEFT JOIN compensation_table t ON t.id = p.table_id;

DROP TABLE compensation_push;
ALTER TABLE compensation_push_v4 RENAME TO compensation_push;
CREATE INDEX compensation_push_by_campaign ON compensation_push (campaign_id, id);
