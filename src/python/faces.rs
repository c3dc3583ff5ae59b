//! Face indices at the boundary: copied while the GIL is held, so that another thread changing
//! the caller's array while the core works cannot make an index checked valid invalid.

use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArray};
use pyo3::exceptions::{PyMemoryError, PyTypeError, PyValueError};
use pyo3::prelude::*;

/// The (m, 3) int64 array `faces` as owned rows.
pub fn copy(faces: &Bound<'_, PyUntypedArray>) -> PyResult<Vec<[i64; 3]>> {
    let array = faces.cast::<PyArrayDyn<i64>>().map_err(|_| {
        PyTypeError::new_err("faces must be an int64 array (the package's intake makes it one)")
    })?;
    let borrow = array.try_readonly().map_err(|_| {
        PyValueError::new_err("faces is being written by another call (it is that call's out=)")
    })?;
    let rows = super::arrays::rows::<i64, 3>(&borrow, "faces")?;
    let mut owned = Vec::new();
    owned.try_reserve_exact(rows.len()).map_err(|_| {
        PyMemoryError::new_err(format!("cannot allocate a copy of {} faces", rows.len()))
    })?;
    owned.extend_from_slice(rows);
    Ok(owned)
}
