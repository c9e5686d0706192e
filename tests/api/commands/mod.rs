//! The offline commands beside the service.

mod refusals;
