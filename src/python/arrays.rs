//! Arrays at the boundary: borrowing what the package's intake (`glshade._intake`) prepared, and
//! allocating results so that a failed allocation is a `MemoryError`, not an abort.

use std::mem::MaybeUninit;

use numpy::npyffi::{self, npy_intp, PY_ARRAY_API};
use numpy::{
    Element, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods, PyReadonlyArray2, PyReadonlyArrayDyn,
    PyReadwriteArrayDyn, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::gl::vertex_colors::VertexColors;
use crate::memory::recycle::Recycled;

/// The computation type an input array selects.
pub enum Float {
    /// `float32`.
    F32,
    /// `float64`.
    F64,
}

/// The float type of `array`, which the intake made float32 or float64.
pub fn float_of(array: &Bound<'_, PyUntypedArray>, name: &str) -> PyResult<Float> {
    let py = array.py();
    let dtype = array.dtype();
    if dtype.is_equiv_to(&numpy::dtype::<f32>(py)) {
        Ok(Float::F32)
    } else if dtype.is_equiv_to(&numpy::dtype::<f64>(py)) {
        Ok(Float::F64)
    } else {
        Err(PyTypeError::new_err(format!(
            "{name} must be float32 or float64, got {dtype}"
        )))
    }
}

/// The float type a `describe` call names ("float32" or "float64").
///
/// # Errors
/// A `ValueError` for another name.
pub fn float_named(dtype: &str) -> PyResult<Float> {
    match dtype {
        "float32" => Ok(Float::F32),
        "float64" => Ok(Float::F64),
        _ => Err(PyValueError::new_err(format!(
            "dtype must be 'float32' or 'float64', got '{dtype}'"
        ))),
    }
}

/// A read borrow of `array` as `T`; a conflict with a write borrow (the same memory passed as
/// `out=` to a call running in another thread) is a `ValueError` naming `name`.
pub fn read<'py, T: Element>(
    array: &Bound<'py, PyUntypedArray>,
    name: &str,
) -> PyResult<PyReadonlyArrayDyn<'py, T>> {
    let typed = array.cast::<PyArrayDyn<T>>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{name} must be an array of {}, got {}",
            numpy::dtype::<T>(array.py()),
            array.dtype()
        ))
    })?;
    typed.try_readonly().map_err(|_| {
        PyValueError::new_err(format!(
            "{name} is being written by another call (it is that call's out=)"
        ))
    })
}

/// The rows of a C-contiguous array whose last axis has length `K`, without copying.
pub fn rows<'a, T: Element, const K: usize>(
    array: &'a PyReadonlyArrayDyn<'_, T>,
    name: &str,
) -> PyResult<&'a [[T; K]]> {
    let shape = array.shape();
    if shape.last() != Some(&K) {
        return Err(PyValueError::new_err(format!(
            "{name} must have shape (..., {K}), got {}",
            shape_text(shape)
        )));
    }
    // as_slice also takes Fortran order, which would read the values scrambled.
    let data = array
        .as_slice()
        .ok()
        .filter(|_| array.is_c_contiguous())
        .ok_or_else(|| PyValueError::new_err(format!("{name} must be C-contiguous and aligned")))?;
    Ok(data.as_chunks::<K>().0)
}

/// Per-vertex colours of width 3 or 4 for `GL_COLOR_MATERIAL`.
pub fn vertex_colors<'a, T: Element>(
    colors: &'a PyReadonlyArrayDyn<'_, T>,
) -> PyResult<VertexColors<'a, T>> {
    let width = colors.shape().last().copied().unwrap_or(0);
    let data = match width {
        3 => rows::<T, 3>(colors, "colors")?.as_flattened(),
        4 => rows::<T, 4>(colors, "colors")?.as_flattened(),
        _ => {
            return Err(PyValueError::new_err(format!(
                "colors must have shape (..., 3) or (..., 4), got {}",
                shape_text(colors.shape())
            )))
        }
    };
    Ok(VertexColors { data, width })
}

/// A shape as Python prints it: `(3,)`, `(2, 4)`, `()`.
pub fn shape_text(shape: &[usize]) -> String {
    match shape {
        [d] => format!("({d},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// The bytes an array's data spans.
fn span(start: *const u8, bytes: usize) -> std::ops::Range<usize> {
    let start = start as usize;
    start..start + bytes
}

/// A write borrow of `out`, checked to be exactly the result's array: `T` in native byte order,
/// `shape`, C-contiguous, aligned, writeable, and sharing no memory with any of `inputs`
/// (named C-contiguous slices, so the overlap test is exact). Errors name `out`; a borrow
/// conflict left after those checks is the same memory in use by a call in another thread.
pub fn write<'py, T: Element>(
    out: &Bound<'py, PyUntypedArray>,
    shape: &[usize],
    inputs: &[(&str, &[T])],
) -> PyResult<PyReadwriteArrayDyn<'py, T>> {
    let array = out.cast::<PyArrayDyn<T>>().map_err(|_| {
        PyTypeError::new_err(format!(
            "out must have dtype {} (native byte order), got {}",
            numpy::dtype::<T>(out.py()),
            out.dtype()
        ))
    })?;
    let found = array.shape();
    if found != shape {
        let text = |s: &[usize]| match s {
            [d] => format!("({d},)"),
            _ => format!(
                "({})",
                s.iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        return Err(PyValueError::new_err(format!(
            "out must have shape {}, got {}",
            text(shape),
            text(found)
        )));
    }
    if !array.is_c_contiguous() {
        return Err(PyValueError::new_err(
            "out must be C-contiguous, got an array that is not",
        ));
    }
    let data = array.data().cast::<u8>().cast_const();
    if data.align_offset(std::mem::align_of::<T>()) != 0 {
        return Err(PyValueError::new_err(
            "out must be aligned, got an array that is not",
        ));
    }
    let out_span = span(data, array.len() * std::mem::size_of::<T>());
    for (name, input) in inputs {
        let input_span = span(input.as_ptr().cast(), std::mem::size_of_val(*input));
        if out_span.start < input_span.end && input_span.start < out_span.end {
            return Err(PyValueError::new_err(format!(
                "out and {name} share memory: the result would overwrite {name} while it is \
                 read; pass a separate out"
            )));
        }
    }
    array.try_readwrite().map_err(|e| match e {
        numpy::BorrowError::NotWriteable => {
            PyValueError::new_err("out must be writeable, got an array that is not")
        }
        _ => PyValueError::new_err("out is in use by another call in another thread"),
    })
}

/// A new C-contiguous array of `shape`, filled by `write` before Python sees it; it starts
/// uninitialised, as numpy's own ufunc results do (clearing it would cost a pass over memory as
/// long as shading one light), and a failed allocation is numpy's `MemoryError`. Results of at
/// least [`crate::memory::recycle::RECYCLED_BYTES`] take a pooled buffer ([`Recycled`]), which
/// a [`ResultMemory`] holds as the array's base; smaller ones numpy's allocator.
#[allow(unsafe_code)]
pub fn filled<'py, T: Element>(
    py: Python<'py>,
    shape: &[usize],
    write: impl FnOnce(&mut [MaybeUninit<T>]) -> PyResult<()>,
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    let mut dims = dims(shape)?;
    let bytes = shape
        .iter()
        .try_fold(std::mem::size_of::<T>(), |b, &d| b.checked_mul(d));
    let owner = match bytes.and_then(Recycled::take) {
        Some(mut buffer) => {
            let data = buffer.as_mut_ptr();
            Some((data, Bound::new(py, ResultMemory { _buffer: buffer })?))
        }
        None => None,
    };
    let (data, flags) = match &owner {
        Some((data, _)) => (data.cast(), npyffi::NPY_ARRAY_CARRAY),
        None => (std::ptr::null_mut(), 0),
    };
    // SAFETY: as rust-numpy's own `PyArray::new`: a C-ordered array of T's descriptor (whose
    // reference PyArray_NewFromDescr steals), in numpy's allocator (null data) or over a pooled
    // buffer, page-aligned and at least as long as the array (`Recycled::take`), which its
    // owner keeps alive as the array's base (PyArray_SetBaseObject steals the reference it is
    // given); a null result is numpy's error, which `from_owned_ptr_or_err` takes.
    let array: Bound<'py, PyArrayDyn<T>> = unsafe {
        let ptr = PY_ARRAY_API.PyArray_NewFromDescr(
            py,
            npyffi::get_type_object(py, npyffi::NpyTypes::PyArray_Type),
            T::get_dtype(py).into_dtype_ptr(),
            rank(&dims)?,
            dims.as_mut_ptr(),
            std::ptr::null_mut(),
            data,
            flags,
            std::ptr::null_mut(),
        );
        let array = Bound::from_owned_ptr_or_err(py, ptr)?;
        if let Some((_, owner)) = owner {
            let base = owner.into_ptr();
            if PY_ARRAY_API.PyArray_SetBaseObject(py, array.as_ptr().cast(), base) != 0 {
                return Err(PyErr::fetch(py));
            }
        }
        array.cast_into_unchecked()
    };
    // SAFETY: the array is C-contiguous and nothing else refers to its memory yet; MaybeUninit<T>
    // has T's layout and may hold anything. The array reaches Python only when `write` returned
    // Ok, which means it wrote every element; on an error it is dropped unread.
    let data = unsafe { std::slice::from_raw_parts_mut(array.data().cast(), array.len()) };
    write(data)?;
    Ok(array)
}

/// The owner of a pooled result's memory: the array's base object, which hands the buffer back
/// to the pool ([`Recycled`]) when the last array viewing it is gone.
#[pyclass(frozen, module = "glshade._glshade")]
pub struct ResultMemory {
    _buffer: Recycled,
}

/// A new C-contiguous array of `shape` filled with zeros (numpy's `calloc`: fresh pages cost
/// no pass over memory), or `MemoryError`.
#[allow(unsafe_code)]
pub fn zeros<'py, T: Element>(
    py: Python<'py>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    let mut dims = dims(shape)?;
    // SAFETY: as rust-numpy's `PyArray::zeros`, with numpy's null result taken as its error.
    unsafe {
        let ptr = PY_ARRAY_API.PyArray_Zeros(
            py,
            rank(&dims)?,
            dims.as_mut_ptr(),
            T::get_dtype(py).into_dtype_ptr(),
            0,
        );
        Ok(Bound::from_owned_ptr_or_err(py, ptr)?.cast_into_unchecked())
    }
}

/// The number of dimensions, as numpy's C API takes it.
fn rank(dims: &[npy_intp]) -> PyResult<std::ffi::c_int> {
    std::ffi::c_int::try_from(dims.len())
        .map_err(|_| PyValueError::new_err(format!("{} dimensions are too many", dims.len())))
}

/// `shape` as numpy's dimensions.
fn dims(shape: &[usize]) -> PyResult<Vec<npy_intp>> {
    shape
        .iter()
        .map(|&d| npy_intp::try_from(d))
        .collect::<Result<_, _>>()
        .map_err(|_| PyValueError::new_err(format!("array shape {shape:?} is too large")))
}

/// A row-major (4, 4) array (as numpy prints matrices) as a column-major `DMat4`.
pub fn matrix(m: &PyReadonlyArray2<'_, f64>, name: &str) -> PyResult<glam::DMat4> {
    let values: &[f64] = m
        .as_slice()
        .ok()
        .filter(|_| m.is_c_contiguous())
        .unwrap_or(&[]);
    let rows: [f64; 16] = values
        .try_into()
        .ok()
        .filter(|_| m.shape() == [4, 4])
        .ok_or_else(|| {
            PyValueError::new_err(format!(
                "{name} must be a C-contiguous (4, 4) array, got shape {}",
                shape_text(m.shape())
            ))
        })?;
    Ok(glam::DMat4::from_cols_array(&rows).transpose())
}
