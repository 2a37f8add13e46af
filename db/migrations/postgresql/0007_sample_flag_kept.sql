-- Schema v7 on PostgreSQL: ../0007_sample_flag_kept.sql in PostgreSQL's dialect.
ALTER TABLE sample_flag ADD COLUMN kept INTEGER NOT NULL DEFAULT 0 CHECK (kept IN (0, 1));
