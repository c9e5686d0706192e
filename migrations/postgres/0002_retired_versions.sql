-- The last coefficient version of each deleted machine id (see
-- migrations/0004_retired_versions.sql), in PostgreSQL's types.
-- Append-only: never edit this file once applied; add a new migration instead.

CREATE TABLE machine_versions_retired (
    machine_id   TEXT   PRIMARY KEY,                               -- machines.id of the deleted machine
    last_version BIGINT NOT NULL                                   -- its highest coefficient version
);
