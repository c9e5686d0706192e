-- Balancing sessions: the set-up once, each run as a list of versions so a
-- corrected run keeps its earlier readings, and the solutions computed.
-- Append-only: never edit this file once applied; add a new migration instead.

CREATE TABLE sessions (
    seq        INTEGER PRIMARY KEY AUTOINCREMENT,   -- creation order, for paging
    id         TEXT    NOT NULL UNIQUE,             -- public id (uuid v4)
    name       TEXT    NOT NULL,
    machine    TEXT,
    setup      TEXT    NOT NULL,                    -- the session JSON without `runs`
    created_at TEXT    NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE TABLE runs (
    session_seq INTEGER NOT NULL REFERENCES sessions(seq) ON DELETE CASCADE,
    run_id      TEXT    NOT NULL,
    position    INTEGER NOT NULL,                   -- order of the run in the session
    version     INTEGER NOT NULL,                   -- current version in run_versions
    PRIMARY KEY (session_seq, run_id),
    UNIQUE (session_seq, position)
);

CREATE TABLE run_versions (
    session_seq INTEGER NOT NULL,
    run_id      TEXT    NOT NULL,
    version     INTEGER NOT NULL,                   -- 1, 2, … per run
    body        TEXT    NOT NULL,                   -- the run JSON as it would be posted
    created_at  TEXT    NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
    PRIMARY KEY (session_seq, run_id, version),
    FOREIGN KEY (session_seq, run_id) REFERENCES runs(session_seq, run_id) ON DELETE CASCADE
);

CREATE TABLE solutions (
    seq              INTEGER PRIMARY KEY AUTOINCREMENT,
    session_seq      INTEGER NOT NULL REFERENCES sessions(seq) ON DELETE CASCADE,
    options          TEXT    NOT NULL,              -- the solve options as posted
    run_versions     TEXT    NOT NULL,              -- [{"run_id","version"}] the solve used
    solution         TEXT    NOT NULL,              -- the solution JSON as answered
    fieldbal_version TEXT    NOT NULL,
    created_at       TEXT    NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))
);

CREATE INDEX solutions_by_session ON solutions (session_seq, seq);
