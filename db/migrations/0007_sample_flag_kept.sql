-- Schema v7: a flagged stretch the user keeps (docs/sensor-health.md, "Flags
-- in the store"). A flag whose `kept` is 1 stays stored and shown, but its
-- samples go into the models as logged; 0 (every flag of an older store) leaves
-- them out, as before. Re-checking a run keeps the choice for a stretch found again.
ALTER TABLE sample_flag ADD COLUMN kept INTEGER NOT NULL DEFAULT 0 CHECK (kept IN (0, 1));
