-- Machines and their influence-coefficient versions (v2 "Machines").
-- A session belongs to a machine through its `machine` field (sessions.machine),
-- so deleting a machine never deletes sessions.
-- Append-only: never edit this file once applied; add a new migration instead.

CREATE TABLE machines (
    seq        INTEGER PRIMARY KEY AUTOINCREMENT,   -- creation order, for paging
    id         TEXT    NOT NULL UNIQUE,             -- public id, chosen by the client
    name       TEXT    NOT NULL,
    rotor      TEXT,                                -- the rotor JSON, if given
    notes      TEXT,
    created_at TEXT    NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE TABLE machine_coefficients (
    machine_seq INTEGER NOT NULL REFERENCES machines(seq) ON DELETE CASCADE,
    version     INTEGER NOT NULL,                   -- 1, 2, … per machine, allocated in the insert
    sessions    TEXT    NOT NULL,                   -- JSON list of the session ids pooled
    body        TEXT    NOT NULL,                   -- the pooled coefficients JSON
    created_at  TEXT    NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
    UNIQUE (machine_seq, version)
);

CREATE INDEX sessions_by_machine ON sessions (machine, seq);
