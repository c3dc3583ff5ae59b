//! Fallible allocation of the buffers whose size grows with the input: a request the allocator
//! cannot meet (or whose size overflows) is a [`ErrorKind::Memory`](crate::ErrorKind) error for
//! the caller, where `vec!`, `Vec::with_capacity` and `collect` would abort the process.

use rayon::prelude::*;

use crate::errors::error::Error;

/// The memory error of `len` elements of `T` for `what`.
fn failed<T>(len: usize, what: &str) -> Error {
    // u128: the byte count of a request that overflows usize is still printed exactly.
    let bytes = len as u128 * size_of::<T>() as u128;
    Error::memory_fmt(
        format_args!("cannot allocate {bytes} bytes for {what}"),
        "cannot allocate memory",
    )
}

/// The product of `factors`, the element count of a buffer for `what`.
///
/// # Errors
/// A memory error when the product overflows `usize`.
pub(crate) fn count(factors: &[usize], what: &str) -> Result<usize, Error> {
    factors
        .iter()
        .try_fold(1_usize, |n, &f| n.checked_mul(f))
        .ok_or_else(|| {
            Error::memory_fmt(
                format_args!("the size of {what} overflows, {factors:?}"),
                "a buffer's size overflows",
            )
        })
}

/// An empty vector with room for exactly `len` elements.
///
/// # Errors
/// A memory error naming `what` when the allocation fails.
pub(crate) fn try_with_capacity<T>(len: usize, what: &str) -> Result<Vec<T>, Error> {
    let mut v = Vec::new();
    v.try_reserve_exact(len)
        .map_err(|_| failed::<T>(len, what))?;
    Ok(v)
}

/// Room for `additional` more elements in `v`, as `v.reserve(additional)`.
///
/// # Errors
/// A memory error naming `what` when the allocation fails.
pub(crate) fn try_reserve<T>(v: &mut Vec<T>, additional: usize, what: &str) -> Result<(), Error> {
    v.try_reserve(additional)
        .map_err(|_| failed::<T>(v.len().saturating_add(additional), what))
}

/// `len` copies of `value`, as `vec![value; len]`.
///
/// # Errors
/// A memory error naming `what` when the allocation fails.
pub(crate) fn try_filled<T: Clone>(len: usize, value: T, what: &str) -> Result<Vec<T>, Error> {
    let mut v = try_with_capacity(len, what)?;
    v.resize(len, value);
    Ok(v)
}

/// The items of `iter` in a vector allocated once, to their exact count.
///
/// # Errors
/// A memory error naming `what` when the allocation fails.
pub(crate) fn try_collect<I: ExactSizeIterator>(
    iter: I,
    what: &str,
) -> Result<Vec<I::Item>, Error> {
    let mut v = try_with_capacity(iter.len(), what)?;
    // Within the capacity: extend does not allocate again.
    v.extend(iter);
    Ok(v)
}

/// The items of a parallel `iter`, in order, in a vector allocated once.
///
/// # Errors
/// A memory error naming `what` when the allocation fails.
pub(crate) fn try_par_collect<I>(iter: I, what: &str) -> Result<Vec<I::Item>, Error>
where
    I: IndexedParallelIterator,
{
    let mut v = try_with_capacity(iter.len(), what)?;
    // rayon reserves `len` more, which the capacity already holds, and writes in place.
    v.par_extend(iter);
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn absurd_sizes_are_memory_errors() {
        let err = try_filled(usize::MAX / 16, 0.0_f64, "the test").unwrap_err();
        assert_eq!(err.kind, crate::errors::error::ErrorKind::Memory);
        assert!(err.message.contains("for the test"), "{}", err.message);
        let err = try_with_capacity::<[f64; 3]>(1 << 58, "rows").unwrap_err();
        assert_eq!(err.kind, crate::errors::error::ErrorKind::Memory);
        assert_eq!(
            count(&[usize::MAX / 2, 3], "out").unwrap_err().kind,
            crate::errors::error::ErrorKind::Memory
        );
    }

    #[test]
    fn the_helpers_build_what_vec_and_collect_do() {
        assert_eq!(try_filled(3, 7_u8, "x").unwrap(), vec![7; 3]);
        assert_eq!(try_collect(0..4, "x").unwrap(), vec![0, 1, 2, 3]);
        let v = try_par_collect((0..10_000).into_par_iter().map(|i| i * 2), "x").unwrap();
        assert_eq!(v, (0..10_000).map(|i| i * 2).collect::<Vec<_>>());
        assert_eq!(count(&[2, 3, 4], "x").unwrap(), 24);
    }
}
