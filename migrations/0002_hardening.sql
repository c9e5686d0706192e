-- Hardening (issue 9): the write probe of /healthz, and the answers kept for
-- `Idempotency-Key` replays. Append-only: never edit once applied.

-- /healthz writes (and rolls back) a row here to see that the database can be written.
CREATE TABLE health_probe (
    id     INTEGER PRIMARY KEY,
    filler BLOB NOT NULL
);

-- One row per Idempotency-Key of a POST that stored something, written in the
-- same transaction as what it stored; a repeat with the same fingerprint gets
-- `status` and `body` (and `location`) again.
CREATE TABLE idempotency (
    key         TEXT    PRIMARY KEY,
    fingerprint TEXT    NOT NULL,                    -- SHA-256 of method, path and parsed body
    status      INTEGER NOT NULL,
    location    TEXT,
    body        TEXT    NOT NULL,                    -- the JSON answered
    created_at  TEXT    NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);
