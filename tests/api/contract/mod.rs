//! The contract against what the service serves: every endpoint in the
//! OpenAPI document, every field it names in docs/session-format.md.

mod fields;
mod openapi;
