//! What a request may send: bad requests and their error bodies, texts,
//! solve options, query parameters and the conditional and idempotent
//! writes' headers.

mod headers;
mod options;
mod queries;
mod table;
mod texts;
