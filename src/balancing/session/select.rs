//! Which rows and planes a solve uses, and with what row weights: the
//! `speeds_rpm`, `sensors`, `planes` and `row_weights` options, checked against the session.

use crate::balancing::error::InputError;
use crate::balancing::model::SolveOptions;
use crate::balancing::validate::Checked;

const MAX_ROW_WEIGHT: f64 = 1e6;
/// Smallest non-zero row weight (0 leaves the rows out). Weights of 1e-300
/// made the correction's covariance infinite (its squares underflow; found by
/// fuzzing in session 15).
const MIN_ROW_WEIGHT: f64 = 1e-6;
/// Bound on the product of the weights that match one row, either way: two
/// weights in range multiply to at most 1e12, while 26 weights of 1e6 on one
/// sensor overflowed the SVD's squares and made it panic (session 15).
const MAX_ROW_PRODUCT: f64 = 1e12;

/// The rows and planes of one solve.
#[derive(Debug, Clone, PartialEq)]
pub struct Selection {
    /// Indices into `Checked::rows` that enter the fit (selected, weight > 0).
    pub rows: Vec<usize>,
    /// Row weight `G_aa` (method 3.3) of each entry of `rows`.
    pub weights: Vec<f64>,
    /// Indices into `session.planes` to correct in, in session order.
    pub planes: Vec<usize>,
}

fn ids_to_indices<'a>(
    field: &str,
    wanted: &[String],
    ids: impl Iterator<Item = &'a str> + Clone,
    what: &str,
) -> Result<Vec<usize>, InputError> {
    let mut out = Vec::with_capacity(wanted.len());
    for (i, id) in wanted.iter().enumerate() {
        let f = format!("{field}[{i}]");
        let k = ids.clone().position(|x| x == id).ok_or_else(|| {
            let code = if what == "plane" {
                "unknown_plane"
            } else {
                "unknown_sensor"
            };
            InputError::invalid(code, f.clone(), format!("the session has no {what} '{id}'"))
        })?;
        if out.contains(&k) {
            return Err(InputError::invalid(
                "duplicate_id",
                f,
                format!("{what} '{id}' is listed twice"),
            ));
        }
        out.push(k);
    }
    Ok(out)
}

fn speed_point(checked: &Checked, field: String, speed: f64) -> Result<usize, InputError> {
    if !(speed.is_finite() && speed > 0.0) {
        return Err(InputError::invalid(
            "invalid_value",
            field,
            "a speed must be a finite number greater than 0",
        ));
    }
    checked.point_of(speed).ok_or_else(|| {
        InputError::invalid(
            "unknown_speed",
            field,
            format!(
                "the reference run has no readings within 1 % of {} rpm",
                crate::balancing::error::shown(speed)
            ),
        )
    })
}

/// `n` flags, set at `on`.
fn mask(n: usize, on: Vec<usize>) -> Vec<bool> {
    let mut m = vec![false; n];
    for i in on {
        m[i] = true;
    }
    m
}

/// Resolve the options into a selection, naming the offending option field.
pub fn select(checked: &Checked, options: &SolveOptions) -> Result<Selection, InputError> {
    let session = checked.session;
    let planes = match &options.planes {
        Some(list) => {
            let mut p = ids_to_indices(
                "options.planes",
                list,
                session.planes.iter().map(|p| p.id.as_str()),
                "plane",
            )?;
            if p.is_empty() {
                return Err(InputError::invalid(
                    "no_planes",
                    "options.planes",
                    "every plane is excluded: select at least one plane",
                ));
            }
            p.sort_unstable();
            p
        }
        None => (0..session.planes.len()).collect(),
    };
    // Which sensors and speed points are selected, as masks by index: looked
    // up for every row (a hash set cost ~400 instructions a row: issue 15).
    let sensors: Vec<bool> = match &options.sensors {
        Some(list) => {
            let s = ids_to_indices(
                "options.sensors",
                list,
                session.sensors.iter().map(|s| s.id.as_str()),
                "sensor",
            )?;
            if s.is_empty() {
                return Err(InputError::invalid(
                    "no_rows",
                    "options.sensors",
                    "every sensor is excluded: select at least one sensor",
                ));
            }
            mask(session.sensors.len(), s)
        }
        None => vec![true; session.sensors.len()],
    };
    let points: Vec<bool> = match &options.speeds_rpm {
        Some(list) => {
            if list.is_empty() {
                return Err(InputError::invalid(
                    "no_rows",
                    "options.speeds_rpm",
                    "every speed is excluded: select at least one speed",
                ));
            }
            let p = list
                .iter()
                .enumerate()
                .map(|(i, &s)| speed_point(checked, format!("options.speeds_rpm[{i}]"), s))
                .collect::<Result<Vec<_>, _>>()?;
            mask(checked.points.len(), p)
        }
        None => vec![true; checked.points.len()],
    };

    // Row weights multiply the rows they match (contract); checked first, applied below.
    let mut matchers = Vec::new();
    for (i, rw) in options.row_weights.iter().flatten().enumerate() {
        let f = format!("options.row_weights[{i}]");
        let w = rw.weight;
        if !(w == 0.0 || (w.is_finite() && (MIN_ROW_WEIGHT..=MAX_ROW_WEIGHT).contains(&w))) {
            return Err(InputError::invalid(
                "invalid_value",
                format!("{f}.weight"),
                format!("a row weight is 0 (the rows are left out) or a finite number from {MIN_ROW_WEIGHT:e} to {MAX_ROW_WEIGHT:e}, got {}", crate::balancing::error::shown(w)),
            ));
        }
        let sensor = match &rw.sensor {
            Some(id) => Some(
                session
                    .sensors
                    .iter()
                    .position(|s| &s.id == id)
                    .ok_or_else(|| {
                        InputError::invalid(
                            "unknown_sensor",
                            format!("{f}.sensor"),
                            format!("the session has no sensor '{id}'"),
                        )
                    })?,
            ),
            None => None,
        };
        let point = match rw.speed_rpm {
            Some(s) => Some(speed_point(checked, format!("{f}.speed_rpm"), s)?),
            None => None,
        };
        if sensor.is_none() && point.is_none() {
            return Err(InputError::invalid(
                "invalid_value",
                f,
                "a row weight names a sensor, a speed, or both",
            ));
        }
        matchers.push((sensor, point, rw.weight));
    }

    let mut rows = Vec::new();
    let mut weights = Vec::new();
    for (a, row) in checked.rows.iter().enumerate() {
        if !sensors[row.sensor] || !points[row.point] {
            continue;
        }
        let g: f64 = matchers
            .iter()
            .filter(|(s, p, _)| {
                s.is_none_or(|s| s == row.sensor) && p.is_none_or(|p| p == row.point)
            })
            .map(|(_, _, w)| w)
            .product();
        if g > 0.0 && !(1.0 / MAX_ROW_PRODUCT..=MAX_ROW_PRODUCT).contains(&g) {
            let sensor = &session.sensors[row.sensor].id;
            return Err(InputError::invalid(
                "invalid_value",
                "options.row_weights",
                format!(
                    "the row weights that match sensor '{sensor}' at {} rpm multiply to {g:e}: the product on one row must lie from {:e} to {MAX_ROW_PRODUCT:e} (or be 0)",
                    row.speed_rpm,
                    1.0 / MAX_ROW_PRODUCT
                ),
            ));
        }
        if g > 0.0 {
            rows.push(a);
            weights.push(g);
        }
    }
    if rows.is_empty() {
        return Err(InputError::unsolvable("no_rows", "no reading is left to balance on: the selected sensors and speeds have no readings with a weight above 0"));
    }
    Ok(Selection {
        rows,
        weights,
        planes,
    })
}
