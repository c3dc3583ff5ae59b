//! How a native call runs: without the GIL, on a thread pool that survives `fork()`, answering
//! Ctrl-C between slabs of work, and with every failure of the core turned into a Python
//! exception (a panic included, so none crosses into Python).

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{Arc, Mutex, OnceLock, TryLockError};
use std::time::Duration;

use pyo3::exceptions::{PyIndexError, PyMemoryError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;

use crate::{Error, ErrorKind, Stop};

/// How often a long call looks for a pending signal (Ctrl-C) while the core works.
const SIGNAL_POLL: Duration = Duration::from_millis(20);

/// How long a forked child waits for the lock on its pool before it takes one of its own.
const LOCK_PATIENCE: Duration = Duration::from_secs(1);

/// The core's error as the Python exception its kind names.
pub fn to_pyerr(e: Error) -> PyErr {
    match e.kind {
        ErrorKind::Value => PyValueError::new_err(e.message),
        ErrorKind::Index => PyIndexError::new_err(e.message),
        ErrorKind::Memory => PyMemoryError::new_err(e.message),
        ErrorKind::Interrupted => PyRuntimeError::new_err("glshade: the call was interrupted"),
    }
}

/// The pid the module was loaded in: rayon's global pool belongs to that process.
static LOADED_IN: OnceLock<u32> = OnceLock::new();

/// Remembers the process the module is loaded in; called once from the module's init.
pub fn init() {
    LOADED_IN.get_or_init(std::process::id);
}

/// A pool of this process's own when it is a `fork()`ed child of the one that loaded the module:
/// the parent's pool threads do not exist in the child, so work sent to them would never end.
fn child_pool() -> Result<Option<Arc<rayon::ThreadPool>>, Error> {
    static POOLS: Mutex<Option<(u32, Arc<rayon::ThreadPool>)>> = Mutex::new(None);
    let pid = std::process::id();
    if LOADED_IN.get().is_none_or(|&p| p == pid) {
        return Ok(None);
    }
    let build = || {
        rayon::ThreadPoolBuilder::new()
            .thread_name(|i| format!("glshade-{i}"))
            .build()
            .map(Arc::new)
            .map_err(|e| Error::memory(format!("cannot start glshade's threads: {e}")))
    };
    // A fork taken while a thread of the forking process held the lock leaves it held for
    // ever in the child (that thread is gone): after a while, the call gets a pool of its own.
    let mut waited = Duration::ZERO;
    let mut slot = loop {
        match POOLS.try_lock() {
            Ok(slot) => break slot,
            Err(TryLockError::Poisoned(poisoned)) => break poisoned.into_inner(),
            Err(TryLockError::WouldBlock) if waited < LOCK_PATIENCE => {
                std::thread::sleep(Duration::from_millis(1));
                waited += Duration::from_millis(1);
            }
            Err(TryLockError::WouldBlock) => return build().map(Some),
        }
    };
    if let Some((owner, pool)) = slot.as_ref() {
        if *owner == pid {
            return Ok(Some(Arc::clone(pool)));
        }
    }
    let pool = build()?;
    // The inherited pool's threads are gone: dropping it would signal threads that do not exist.
    if let Some(old) = slot.replace((pid, Arc::clone(&pool))) {
        std::mem::forget(old);
    }
    Ok(Some(pool))
}

/// Runs `work` with the GIL released and returns its result or the exception it maps to.
///
/// `long` work runs on a helper thread while the calling thread takes the GIL every
/// [`SIGNAL_POLL`] to run Python's signal handlers: when one raises (Ctrl-C's
/// `KeyboardInterrupt`), the work's [`Stop`] is requested, the work ends at its next slab and
/// that exception is returned. Short work runs on the calling thread.
pub fn run<R: Send>(
    py: Python<'_>,
    long: bool,
    work: impl FnOnce(&Stop) -> Result<R, Error> + Send,
) -> PyResult<R> {
    let stop = Stop::new();
    if !long {
        return py.detach(|| guarded(work, &stop));
    }
    let stop = &stop;
    let (result, signal) = py.detach(|| {
        std::thread::scope(|scope| {
            let caller = std::thread::current();
            let worker = scope.spawn(move || {
                let result = guarded(work, stop);
                caller.unpark();
                result
            });
            let mut signal = None;
            while !worker.is_finished() {
                std::thread::park_timeout(SIGNAL_POLL);
                if signal.is_none() && !worker.is_finished() {
                    signal = Python::attach(|py| py.check_signals().err());
                    if signal.is_some() {
                        stop.request();
                    }
                }
            }
            let result = worker
                .join()
                .unwrap_or_else(|panic| Err(internal(panic.as_ref())));
            (result, signal)
        })
    });
    match signal {
        Some(err) => Err(err),
        None => result,
    }
}

/// `work` on this process's pool, its error or panic as a Python exception.
fn guarded<R: Send>(
    work: impl FnOnce(&Stop) -> Result<R, Error> + Send,
    stop: &Stop,
) -> PyResult<R> {
    let pool = child_pool().map_err(to_pyerr)?;
    let call = || catch_unwind(AssertUnwindSafe(|| work(stop)));
    let outcome = match pool {
        Some(pool) => pool.install(call),
        None => call(),
    };
    match outcome {
        Ok(result) => result.map_err(to_pyerr),
        Err(panic) => Err(internal(panic.as_ref())),
    }
}

/// A panic as the `RuntimeError` that reports it.
fn internal(panic: &(dyn std::any::Any + Send)) -> PyErr {
    PyRuntimeError::new_err(format!("glshade: internal error: {}", panic_message(panic)))
}

/// The text a panic was raised with.
fn panic_message(panic: &(dyn std::any::Any + Send)) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".to_owned())
}
