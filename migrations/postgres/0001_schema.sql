-- The whole schema on PostgreSQL: the same tables as migrations/0001-0003
-- (SQLite), in PostgreSQL's types. Integers are BIGINT so that every number
-- reads back as the same 64-bit integer on both engines; timestamps are
-- TEXT in the same RFC 3339 form (UTC, milliseconds) as SQLite's strftime.
-- Append-only: never edit this file once applied; add a new migration instead.

CREATE TABLE sessions (
    seq        BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,  -- creation order, for paging
    id         TEXT   NOT NULL UNIQUE,                           -- public id (uuid v4)
    name       TEXT   NOT NULL,
    machine    TEXT,
    setup      TEXT   NOT NULL,                                  -- the session JSON without `runs`
    created_at TEXT   NOT NULL
        DEFAULT to_char(clock_timestamp() AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"')
);

CREATE TABLE runs (
    session_seq BIGINT NOT NULL REFERENCES sessions(seq) ON DELETE CASCADE,
    run_id      TEXT   NOT NULL,
    position    BIGINT NOT NULL,                                 -- order of the run in the session
    version     BIGINT NOT NULL,                                 -- current version in run_versions
    PRIMARY KEY (session_seq, run_id),
    UNIQUE (session_seq, position)
);

CREATE TABLE run_versions (
    session_seq BIGINT NOT NULL,
    run_id      TEXT   NOT NULL,
    version     BIGINT NOT NULL,                                 -- 1, 2, … per run
    body        TEXT   NOT NULL,                                 -- the run JSON as it would be posted
    created_at  TEXT   NOT NULL
        DEFAULT to_char(clock_timestamp() AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"'),
    PRIMARY KEY (session_seq, run_id, version),
    FOREIGN KEY (session_seq, run_id) REFERENCES runs(session_seq, run_id) ON DELETE CASCADE
);

CREATE TABLE solutions (
    seq              BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
    session_seq      BIGINT NOT NULL REFERENCES sessions(seq) ON DELETE CASCADE,
    options          TEXT   NOT NULL,                            -- the solve options as posted
    run_versions     TEXT   NOT NULL,                            -- [{"run_id","version"}] the solve used
    solution         TEXT   NOT NULL,                            -- the solution JSON as answered
    fieldbal_version TEXT   NOT NULL,
    created_at       TEXT   NOT NULL
        DEFAULT to_char(clock_timestamp() AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"')
);

CREATE INDEX solutions_by_session ON solutions (session_seq, seq);

-- /healthz writes (and rolls back) a row here, keyed by the backend's pid.
CREATE TABLE health_probe (
    id     BIGINT PRIMARY KEY,
    filler BYTEA  NOT NULL
);

-- Answers kept for `Idempotency-Key` replays (see migrations/0002_hardening.sql).
CREATE TABLE idempotency (
    key         TEXT   PRIMARY KEY,
    fingerprint TEXT   NOT NULL,                                 -- SHA-256 of method, path and parsed body
    status      BIGINT NOT NULL,
    location    TEXT,
    body        TEXT   NOT NULL,                                 -- the JSON answered
    created_at  TEXT   NOT NULL
        DEFAULT to_char(clock_timestamp() AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"')
);

-- Machines and their influence-coefficient versions (see migrations/0003_machines.sql).
CREATE TABLE machines (
    seq        BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,  -- creation order, for paging
    id         TEXT   NOT NULL UNIQUE,                           -- public id, chosen by the client
    name       TEXT   NOT NULL,
    rotor      TEXT,                                             -- the rotor JSON, if given
    notes      TEXT,
    created_at TEXT   NOT NULL
        DEFAULT to_char(clock_timestamp() AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"')
);

CREATE TABLE machine_coefficients (
    machine_seq BIGINT NOT NULL REFERENCES machines(seq) ON DELETE CASCADE,
    version     BIGINT NOT NULL,                                 -- 1, 2, … per machine, allocated under the machine's row lock
    sessions    TEXT   NOT NULL,                                 -- JSON list of the session ids pooled
    body        TEXT   NOT NULL,                                 -- the pooled coefficients JSON
    created_at  TEXT   NOT NULL
        DEFAULT to_char(clock_timestamp() AT TIME ZONE 'UTC', 'YYYY-MM-DD"T"HH24:MI:SS.MS"Z"'),
    UNIQUE (machine_seq, version)
);

CREATE INDEX sessions_by_machine ON sessions (machine, seq);
