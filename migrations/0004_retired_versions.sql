-- The last coefficient version of each machine id whose machine was deleted,
-- so that a machine created again under that id numbers its versions on from
-- there: a `{machine, version}` kept by a script never names other
-- coefficients. Rows stay when the machine is created again.
-- Append-only: never edit this file once applied; add a new migration instead.

CREATE TABLE machine_versions_retired (
    machine_id   TEXT    PRIMARY KEY,                -- machines.id of the deleted machine
    last_version INTEGER NOT NULL                    -- its highest coefficient version
);
