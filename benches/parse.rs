//! Criterion benchmarks of what `fieldbal solve` and the HTTP API do around
//! the solve of a large job (issue 15): parsing the 1.7 MB session file
//! (16 planes × 32 sensors × 40 speeds, `benches/data/ls-16x32x40.json`) and
//! writing its 3.7 MB solution. The old ways are still in the code (they are
//! the error path), so old and new are measured in the same run.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use fieldbal::balancing::error::from_json_tracked;
use fieldbal::balancing::model::Session;
use fieldbal::balancing::{self, file, from_json};
use serde_json::Value;

const LARGE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/benches/data/ls-16x32x40.json");

fn benches(c: &mut Criterion) {
    let bytes = std::fs::read(LARGE).expect("the large job is in the repository");
    let mut group = c.benchmark_group("parse 16x32x40");
    group.sample_size(10);
    // Before: `fieldbal solve` read the file as a `Value` (cases?), then
    // `parse_session_file` did again (session?), then parsed it typed,
    // tracking the path.
    group.bench_function("session file, old: Value twice, then tracked", |b| {
        b.iter(|| {
            let _cases: Value = from_json_tracked(black_box(&bytes)).unwrap();
            let value: Value = from_json_tracked(&bytes).unwrap();
            file::parse_tracked(&bytes, &value).unwrap()
        })
    });
    group.bench_function("session file, new: one typed pass", |b| {
        b.iter(|| file::parse(black_box(&bytes)).unwrap())
    });
    // A posted body (`POST /api/v1/sessions`): `from_json`.
    group.bench_function("from_json Session, tracked", |b| {
        b.iter(|| from_json_tracked::<Session>(black_box(&bytes)).unwrap())
    });
    group.bench_function("from_json Session", |b| {
        b.iter(|| from_json::<Session>(black_box(&bytes)).unwrap())
    });
    group.finish();

    let (session, options) = balancing::parse_session_file(&bytes).unwrap();
    let solution = balancing::solve(&session, &options).unwrap();
    let mut group = c.benchmark_group("write 16x32x40 solution");
    group.sample_size(10);
    group.bench_function("old: to_value, then to_string_pretty", |b| {
        b.iter(|| {
            let value = serde_json::to_value(black_box(&solution)).unwrap();
            serde_json::to_string_pretty(&value).unwrap().len()
        })
    });
    group.bench_function("new: pretty from the struct", |b| {
        b.iter(|| {
            fieldbal::cli::pretty::to_vec_pretty(black_box(&solution))
                .unwrap()
                .len()
        })
    });
    // The HTTP answer (axum's `Json`): compact, from the struct.
    group.bench_function("compact from the struct (HTTP)", |b| {
        b.iter(|| serde_json::to_vec(black_box(&solution)).unwrap().len())
    });
    group.finish();
}

criterion_group!(parse, benches);
criterion_main!(parse);
