//! The points of a sweep: named dimensions, the keywords' values along them, and the parallel
//! loop over the points that validates first, polls [`crate::control`] and names the point of
//! any error.

use rayon::prelude::*;
use std::sync::Arc;

use crate::control;
use crate::error::{Error, Result};
use crate::limits;

/// One dimension of a sweep, or of a block of it (a chunk computed on its own).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Dim<'a> {
    /// Its name: the keyword it sweeps (`"theta"`), `"sample"` for a random sample, or the
    /// name given to keywords paired along one dimension.
    pub name: &'a str,
    /// Its length in this block (≥ 1).
    pub len: usize,
    /// The index, in the whole sweep, of this block's first element along it (0 for a whole
    /// sweep): error messages give indices into the user's arrays.
    pub offset: usize,
    /// The caller's argument that makes it, named by the errors about the dimension (its
    /// length, the memory budget): the keyword itself, `"samples"` for a random sample, the
    /// first keyword of a paired dimension.
    pub argument: &'a str,
}

/// A keyword's values: `width` numbers per entry (1 for a number, 3 for a vector, 4 for a
/// quaternion), one entry per index along dimension `dim`, or one entry for every point when
/// `dim` is `None`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Column<'a> {
    /// The keyword, as the model spells it (`"theta"`, `"omega0"`).
    pub keyword: &'a str,
    /// The entries, row-major: `width` × (the dimension's length, or 1).
    pub values: &'a [f64],
    /// The index of its dimension in the grid's dimensions, or `None` for a constant.
    pub dim: Option<usize>,
}

/// A keyword's values ready to be read at any point of a [`Grid`] (see [`Grid::param`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Param<'a> {
    values: &'a [f64],
    width: usize,
    /// The point's index is divided by `stride` and taken modulo `len` (1 for a constant).
    stride: usize,
    len: usize,
}

impl<'a> Param<'a> {
    /// A constant parameter (a model's default), `values.len()` numbers wide.
    pub fn constant(values: &'a [f64]) -> Self {
        Self {
            values,
            width: values.len(),
            stride: 1,
            len: 1,
        }
    }

    /// The entry at `point` (`width` numbers).
    #[inline]
    pub fn at(&self, point: usize) -> &'a [f64] {
        let i = (point / self.stride) % self.len;
        &self.values[i * self.width..(i + 1) * self.width]
    }

    /// The single number at `point` (for a parameter one number wide).
    #[inline]
    pub fn scalar(&self, point: usize) -> f64 {
        self.at(point)[0]
    }

    /// The three numbers at `point`.
    #[inline]
    pub fn vec3(&self, point: usize) -> [f64; 3] {
        let v = self.at(point);
        [v[0], v[1], v[2]]
    }

    /// The four numbers at `point`.
    #[inline]
    pub fn vec4(&self, point: usize) -> [f64; 4] {
        let v = self.at(point);
        [v[0], v[1], v[2], v[3]]
    }
}

/// The points of a sweep (or of a block of it): the row-major product of its dimensions, and
/// the keywords' values along them.
#[derive(Debug, Clone)]
pub struct Grid<'a> {
    dims: Vec<Dim<'a>>,
    columns: Vec<Column<'a>>,
    /// Row-major strides of the dimensions (in points).
    strides: Vec<usize>,
    len: usize,
}

impl<'a> Grid<'a> {
    /// The grid of `dims` (row-major: the last varies fastest) carrying `columns`.
    ///
    /// Errors name the keyword: a column on a dimension that does not exist, or whose values do
    /// not hold a whole number of entries for its dimension's length; a keyword given twice;
    /// a dimension of length 0 (`"theta: must not be empty"`), or a product of lengths beyond
    /// the address space.
    pub fn new(dims: Vec<Dim<'a>>, columns: Vec<Column<'a>>) -> Result<Self> {
        for d in &dims {
            if d.len == 0 {
                return Err(Error::invalid(
                    d.argument,
                    "must not be empty: a dimension of a sweep needs at least one value",
                ));
            }
        }
        for (i, c) in columns.iter().enumerate() {
            if columns[..i].iter().any(|o| o.keyword == c.keyword) {
                return Err(Error::invalid(c.keyword, "is given twice"));
            }
            if let Some(d) = c.dim {
                if d >= dims.len() {
                    return Err(Error::invalid(
                        c.keyword,
                        format!(
                            "lies along dimension {d}, but the sweep has {} dimensions",
                            dims.len()
                        ),
                    ));
                }
            }
        }
        let mut strides = vec![1usize; dims.len()];
        let mut len = 1usize;
        for k in (0..dims.len()).rev() {
            strides[k] = len;
            len = len.checked_mul(dims[k].len).ok_or_else(|| {
                Error::invalid(
                    dims[k].argument,
                    format!(
                        "the sweep's {} dimensions ({}) hold more points than can be counted",
                        dims.len(),
                        describe_dims(&dims)
                    ),
                )
            })?;
        }
        Ok(Self {
            dims,
            columns,
            strides,
            len,
        })
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the grid has no points (never: dimensions are not empty; for clippy).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The dimensions.
    pub fn dims(&self) -> &[Dim<'a>] {
        &self.dims
    }

    /// Refuses a column whose keyword is not one of `known` (the keywords of `model`).
    pub fn check_keywords(&self, model: &str, known: &[&str]) -> Result<()> {
        for c in &self.columns {
            if !known.contains(&c.keyword) {
                return Err(Error::invalid(
                    c.keyword,
                    format!(
                        "is not a keyword of {model}; its keywords are {}",
                        known.join(", ")
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Whether `keyword` was given.
    pub fn has(&self, keyword: &str) -> bool {
        self.columns.iter().any(|c| c.keyword == keyword)
    }

    /// The values of `keyword`, `width` numbers per entry, or `None` if it was not given. The
    /// error names the keyword when its values do not fill its dimension.
    pub fn param(&self, keyword: &str, width: usize) -> Result<Option<Param<'a>>> {
        let Some(c) = self.columns.iter().find(|c| c.keyword == keyword) else {
            return Ok(None);
        };
        let (stride, len) = match c.dim {
            Some(d) => (self.strides[d], self.dims[d].len),
            None => (1, 1),
        };
        if c.values.len() != width * len {
            let shape = if width == 1 {
                format!("({len},)")
            } else {
                format!("({len}, {width})")
            };
            return Err(Error::invalid(
                keyword,
                format!(
                    "must hold {shape} numbers for its dimension, got {}",
                    c.values.len()
                ),
            ));
        }
        Ok(Some(Param {
            values: c.values,
            width,
            stride,
            len,
        }))
    }

    /// The values of a keyword the model needs; the error says it is missing.
    pub fn required(&self, keyword: &str, width: usize) -> Result<Param<'a>> {
        self.param(keyword, width)?
            .ok_or_else(|| Error::invalid(keyword, "must be given"))
    }

    /// The values of `keyword`, or the constant `default` (the model's own default).
    pub fn or_default(&self, keyword: &str, default: &'a [f64]) -> Result<Param<'a>> {
        Ok(self
            .param(keyword, default.len())?
            .unwrap_or(Param::constant(default)))
    }

    /// Where `point` lies, in the user's indices: `"theta[3], psi_dot[17]"` (the dimensions
    /// of the sweep, each with the index of the point along it in the whole sweep).
    pub fn locate(&self, point: usize) -> String {
        if self.dims.is_empty() {
            return "the single point".into();
        }
        self.dims
            .iter()
            .zip(&self.strides)
            .map(|(d, &s)| format!("{}[{}]", d.name, d.offset + (point / s) % d.len))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// `e` with the point it happened at appended to its message (same kind and argument).
    pub fn at_point(&self, e: Error, point: usize) -> Error {
        let message = format!("{} (at {})", e.message, self.locate(point));
        Error::new(e.kind, e.argument, message)
    }

    /// Checks that `bytes_each` bytes per point fit in the memory budget
    /// ([`crate::limits`]); the error names the longest dimension.
    pub fn check_memory(&self, bytes_each: usize) -> Result<()> {
        let argument = self
            .dims
            .iter()
            .max_by_key(|d| d.len)
            .map_or("sweep", |d| d.argument);
        limits::check_bytes(
            argument,
            &format!(
                "a sweep of {} points ({})",
                self.len,
                describe_dims(&self.dims)
            ),
            self.len as f64 * bytes_each as f64,
        )
    }

    /// Runs `check` at every point (in parallel) and returns the error of the first point, in
    /// row-major order, that fails it, with the point located ([`Grid::at_point`]): the same
    /// error whatever the number of threads.
    pub fn validate(&self, check: impl Fn(usize) -> Result<()> + Sync) -> Result<()> {
        let first = control::parallel(self.len as u64, |cancel| {
            Ok((0..self.len)
                .into_par_iter()
                .with_min_len(4096)
                .find_first(|&p| {
                    if p % 4096 == 0 {
                        cancel.advance(4096);
                    }
                    cancel.check().is_err() || check(p).is_err()
                }))
        })?;
        match first {
            None => Ok(()),
            Some(p) => match check(p) {
                Err(e) => Err(self.at_point(e, p)),
                // Only a stop request makes a point "fail" that passes its check.
                Ok(()) => Err(control::interrupted()),
            },
        }
    }

    /// Computes `f` at every point, in parallel across the cores, in row-major order. The loop
    /// polls [`crate::control`] (Ctrl-C and progress: one unit of work per point) and `f`'s own
    /// loops obey a stop request too. A point whose `f` fails stops the run with the error of
    /// the first failing point in row-major order, located ([`Grid::at_point`]): the points
    /// before it are searched again on failure, so that the error does not depend on the
    /// order in which the threads met them.
    pub fn compute<T: Send>(&self, f: impl Fn(usize) -> Result<T> + Sync) -> Result<Vec<T>> {
        let outcome = control::parallel(self.len as u64, |cancel| {
            (0..self.len)
                .into_par_iter()
                .with_min_len(16)
                .map(|p| {
                    cancel.check()?;
                    let (result, _) = control::watched(Arc::clone(cancel), || f(p));
                    cancel.advance(1);
                    result
                })
                .collect::<Result<Vec<T>>>()
        });
        match outcome {
            Ok(out) => Ok(out),
            Err(e) if e.kind == crate::ErrorKind::Interrupted => Err(e),
            Err(e) => {
                // Some point failed: find the first one in row-major order (stoppable too).
                let first = control::parallel(self.len as u64, |cancel| {
                    Ok((0..self.len).into_par_iter().find_first(|&p| {
                        cancel.check().is_err()
                            || control::watched(Arc::clone(cancel), || f(p)).0.is_err()
                    }))
                })?;
                Err(match first.map(|p| (p, f(p))) {
                    Some((p, Err(first_error))) => self.at_point(first_error, p),
                    Some((_, Ok(_))) => control::interrupted(),
                    None => e,
                })
            }
        }
    }
}

/// `"theta: 81 × psi_dot: 200"`.
fn describe_dims(dims: &[Dim<'_>]) -> String {
    if dims.is_empty() {
        return "no dimensions".into();
    }
    dims.iter()
        .map(|d| format!("{}: {}", d.name, d.len))
        .collect::<Vec<_>>()
        .join(" × ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dims<'a>(spec: &[(&'a str, usize, usize)]) -> Vec<Dim<'a>> {
        spec.iter()
            .map(|&(name, len, offset)| Dim {
                name,
                len,
                offset,
                argument: name,
            })
            .collect()
    }

    #[test]
    fn points_are_row_major_and_read_each_keyword_along_its_dimension() {
        let a = [10.0, 20.0];
        let b = [1.0, 2.0, 3.0];
        let v = [0.0, 0.0, 1.0, 0.0, 1.0, 0.0];
        let c = [7.0];
        let g = Grid::new(
            dims(&[("a", 2, 0), ("b", 3, 0), ("v", 2, 0)]),
            vec![
                Column {
                    keyword: "a",
                    values: &a,
                    dim: Some(0),
                },
                Column {
                    keyword: "b",
                    values: &b,
                    dim: Some(1),
                },
                Column {
                    keyword: "v",
                    values: &v,
                    dim: Some(2),
                },
                Column {
                    keyword: "c",
                    values: &c,
                    dim: None,
                },
            ],
        )
        .unwrap();
        assert_eq!(g.len(), 12);
        let (pa, pb, pv, pc) = (
            g.required("a", 1).unwrap(),
            g.required("b", 1).unwrap(),
            g.required("v", 3).unwrap(),
            g.required("c", 1).unwrap(),
        );
        // An independent reference: the nested loops of the row-major order.
        let mut p = 0;
        for (ia, &av) in a.iter().enumerate() {
            for (ib, &bv) in b.iter().enumerate() {
                for iv in 0..2 {
                    assert_eq!(pa.scalar(p), av);
                    assert_eq!(pb.scalar(p), bv);
                    assert_eq!(pv.vec3(p), [v[3 * iv], v[3 * iv + 1], v[3 * iv + 2]]);
                    assert_eq!(pc.scalar(p), 7.0);
                    assert_eq!(g.locate(p), format!("a[{ia}], b[{ib}], v[{iv}]"));
                    p += 1;
                }
            }
        }
        assert!(g.param("missing", 1).unwrap().is_none());
        assert_eq!(g.required("missing", 1).unwrap_err().argument, "missing");
        assert_eq!(
            g.or_default("missing", &[0.5]).unwrap().scalar(11),
            0.5,
            "a default is constant"
        );
    }

    #[test]
    fn a_block_names_the_indices_of_the_whole_sweep() {
        let b = [1.0, 2.0];
        let g = Grid::new(
            dims(&[("theta", 1, 40), ("psi_dot", 2, 100)]),
            vec![Column {
                keyword: "psi_dot",
                values: &b,
                dim: Some(1),
            }],
        )
        .unwrap();
        assert_eq!(g.locate(1), "theta[40], psi_dot[101]");
        let e = g.at_point(Error::invalid("psi_dot", "must be finite, got NaN"), 1);
        assert_eq!(
            e.to_string(),
            "psi_dot: must be finite, got NaN (at theta[40], psi_dot[101])"
        );
    }

    #[test]
    fn malformed_grids_are_refused_by_name() {
        let x = [1.0, 2.0];
        let e = Grid::new(dims(&[("theta", 0, 0)]), vec![]).unwrap_err();
        assert_eq!(e.argument, "theta");
        assert!(e.message.contains("empty"), "{e}");
        let col = |keyword, dim| Column {
            keyword,
            values: &x,
            dim,
        };
        let e = Grid::new(
            dims(&[("a", 2, 0)]),
            vec![col("a", Some(0)), col("a", None)],
        );
        assert!(e.unwrap_err().message.contains("twice"));
        let e = Grid::new(dims(&[("a", 2, 0)]), vec![col("a", Some(1))]).unwrap_err();
        assert_eq!(e.argument, "a");
        // Two values where the dimension has three: refused when read.
        let g = Grid::new(dims(&[("a", 3, 0)]), vec![col("a", Some(0))]).unwrap();
        let e = g.param("a", 1).unwrap_err();
        assert!(e.message.contains("(3,)"), "{e}");
        let e = g.check_keywords("heavy_top", &["b"]).unwrap_err();
        assert!(e
            .to_string()
            .starts_with("a: is not a keyword of heavy_top"));
        let huge = Grid::new(dims(&[("a", usize::MAX, 0), ("b", 3, 0)]), vec![]);
        assert!(huge.unwrap_err().message.contains("more points"));
    }

    #[test]
    fn the_first_failing_point_is_reported_whatever_the_threads() {
        let g = Grid::new(dims(&[("i", 100_000, 0)]), vec![]).unwrap();
        let check = |p: usize| {
            if p % 7919 == 7918 {
                Err(Error::invalid("x", format!("bad {p}")))
            } else {
                Ok(())
            }
        };
        let e = g.validate(check).unwrap_err();
        assert_eq!(e.to_string(), "x: bad 7918 (at i[7918])");
        let e = g.compute(|p| check(p).map(|_| p)).unwrap_err();
        assert_eq!(e.to_string(), "x: bad 7918 (at i[7918])");
        // Negative control: without failures every point is computed once, in order.
        let out = g.compute(|p| Ok(2 * p)).unwrap();
        assert!(out.iter().enumerate().all(|(p, &v)| v == 2 * p));
        assert!(g.validate(|_| Ok(())).is_ok());
    }

    #[test]
    fn the_memory_budget_is_checked_before_work() {
        let g = Grid::new(dims(&[("theta", 1000, 0), ("psi_dot", 1 << 30, 0)]), vec![]).unwrap();
        let e = g.check_memory(100).unwrap_err();
        assert_eq!(e.argument, "psi_dot");
        assert!(
            e.message.contains("theta: 1000 × psi_dot: 1073741824"),
            "{e}"
        );
        assert!(g.check_memory(0).is_ok());
    }

    #[test]
    fn errors_about_a_dimension_name_the_callers_argument() {
        let sample = |len| Dim {
            name: "sample",
            len,
            offset: 0,
            argument: "samples",
        };
        let g = Grid::new(vec![sample(1 << 30)], vec![]).unwrap();
        assert_eq!(g.check_memory(100).unwrap_err().argument, "samples");
        let e = Grid::new(vec![sample(0)], vec![]).unwrap_err();
        assert_eq!(e.argument, "samples");
        let e = Grid::new(vec![sample(1 << 40), sample(1 << 40)], vec![]).unwrap_err();
        assert_eq!(e.argument, "samples");
        // The dimension keeps its name where it locates a point.
        let g = Grid::new(vec![sample(3)], vec![]).unwrap();
        assert_eq!(g.locate(2), "sample[2]");
    }
}
