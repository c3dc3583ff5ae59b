//! How a native call runs: without the GIL, on a thread pool that survives `fork()`, answering
//! Ctrl-C between slabs of work, and with every failure of the core turned into a Python
//! exception (a panic included, so none crosses into Python).

use std::borrow::Cow;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicU32, AtomicU8, Ordering};
use std::sync::{Arc, Mutex, TryLockError};
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
        ErrorKind::Value => PyValueError::new_err(e.message.into_owned()),
        ErrorKind::Index => PyIndexError::new_err(e.message.into_owned()),
        // A static message stays static: a memory error must not need memory to be raised.
        ErrorKind::Memory => match e.message {
            Cow::Borrowed(message) => PyMemoryError::new_err(message),
            Cow::Owned(message) => PyMemoryError::new_err(message),
        },
        ErrorKind::Interrupted => PyRuntimeError::new_err("glshade: the call was interrupted"),
    }
}

/// The process that claimed the start of rayon's global pool (0: none yet). A `fork()`ed child
/// inherits its parent's claim, and so never waits on a start that was running in the parent.
static STARTER: AtomicU32 = AtomicU32::new(0);

/// How the claimed start went: [`PENDING`], [`STARTED`] or [`FAILED`]; read only by the claimer.
static START: AtomicU8 = AtomicU8::new(PENDING);
const PENDING: u8 = 0;
const STARTED: u8 = 1;
const FAILED: u8 = 2;

/// The threads a call runs on.
enum Threads {
    /// rayon's global pool, which this process started: the work runs on the calling thread,
    /// and its parallel loops on the pool.
    Global,
    /// A pool of this process's own, which the work is installed in.
    Own(Arc<rayon::ThreadPool>),
}

/// rayon's global pool where this process started it, else a pool of its own ([`pool`]).
///
/// The global pool is started here, fallibly, on the first call: rayon would start it on first
/// use and panic if it cannot, and a failed start cannot be retried (every later use panics),
/// so a process whose start failed (as under a tight address-space limit) uses its own pool.
/// A `fork()`ed child inherits the global pool without its threads, so it uses its own too.
fn threads() -> Result<Threads, Error> {
    let pid = std::process::id();
    match STARTER.compare_exchange(0, pid, Ordering::AcqRel, Ordering::Acquire) {
        Ok(_) => {
            let started = rayon::ThreadPoolBuilder::new().build_global().is_ok();
            START.store(if started { STARTED } else { FAILED }, Ordering::Release);
        }
        // Another thread of this process is starting it: a few milliseconds.
        Err(claimer) if claimer == pid => {
            while START.load(Ordering::Acquire) == PENDING {
                std::thread::yield_now();
            }
        }
        Err(_) => return pool().map(Threads::Own), // the parent's pool: its threads are gone
    }
    if START.load(Ordering::Acquire) == STARTED {
        return Ok(Threads::Global);
    }
    pool().map(Threads::Own)
}

/// This process's own pool of threads, started fallibly (a failure is a `MemoryError` and the
/// next call tries again), and again in a `fork()`ed child, whose parent's threads are gone.
fn pool() -> Result<Arc<rayon::ThreadPool>, Error> {
    static POOLS: Mutex<Option<(u32, Arc<rayon::ThreadPool>)>> = Mutex::new(None);
    let pid = std::process::id();
    let build = || {
        rayon::ThreadPoolBuilder::new()
            .thread_name(|i| format!("glshade-{i}"))
            .build()
            .map(Arc::new)
            .map_err(|_| Error::memory("cannot start glshade's threads"))
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
            Err(TryLockError::WouldBlock) => return build(),
        }
    };
    if let Some((owner, pool)) = slot.as_ref() {
        if *owner == pid {
            return Ok(Arc::clone(pool));
        }
    }
    let pool = build()?;
    // An inherited pool's threads are gone: dropping it would signal threads that do not exist.
    if let Some(old) = slot.replace((pid, Arc::clone(&pool))) {
        std::mem::forget(old);
    }
    Ok(pool)
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
            // Builder's spawn, not scope.spawn: a thread that cannot start is an error, not a
            // panic (whose message would need the memory that is missing).
            let worker = std::thread::Builder::new().spawn_scoped(scope, move || {
                let result = guarded(work, stop);
                caller.unpark();
                result
            });
            let Ok(worker) = worker else {
                return (
                    Err(PyMemoryError::new_err(
                        "cannot start glshade's worker thread",
                    )),
                    None,
                );
            };
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
    let call = || catch_unwind(AssertUnwindSafe(|| work(stop)));
    let outcome = match threads().map_err(to_pyerr)? {
        Threads::Global => call(),
        Threads::Own(pool) => pool.install(call),
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
