//! One work queue for the studies and the sheets: independent tasks handed out in a chosen
//! order to a few scoped threads, results kept by task index, so an outcome never depends on
//! the thread count.
//!
//! ```
//! use nyquist_lab::parallel::map_tasks;
//! let squares = map_tasks(&[3, 2, 1, 0], 2, |i| Ok::<_, String>(i * i)).unwrap();
//! assert_eq!(squares, [0, 1, 4, 9]);
//! ```

use nyquist_film::CAN_START_THREADS;
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// Runs `task(i)` for every index `i` of `order` on up to `threads` threads and returns the
/// results in index order (`result[i] = task(i)`); `order` is a permutation of `0..n` and says
/// which tasks are handed out first (long tasks first balance the threads best).
///
/// With `threads ≤ 1`, or where no thread can be started (WebAssembly), the tasks run on the
/// calling thread in `order`. After a task fails no new task starts, and the error of the
/// failed task with the smallest index is returned (the same for every thread count when one
/// task fails). A task that panics ends the run, and its panic resumes on the calling thread
/// with the task's own payload (its message, not "a scoped thread panicked").
///
/// # Errors
/// The first failed task's error, as above.
///
/// # Panics
/// When a task panics (re-raised, as above), or when `order` is not a permutation of `0..n`.
///
/// ```
/// use nyquist_lab::parallel::map_tasks;
/// let r = map_tasks(&[0, 1, 2], 2, |i| if i == 1 { Err(format!("task {i}")) } else { Ok(i) });
/// assert_eq!(r, Err("task 1".to_owned()));
/// let caught = std::panic::catch_unwind(|| {
///     map_tasks(&[0, 1], 2, |i| -> Result<(), ()> { panic!("task {i} broke") })
/// });
/// let message = caught.unwrap_err().downcast::<String>().unwrap();
/// assert!(message.starts_with("task ") && message.ends_with(" broke"), "{message}");
/// ```
pub fn map_tasks<T: Send, E: Send>(
    order: &[usize],
    threads: usize,
    task: impl Fn(usize) -> Result<T, E> + Sync,
) -> Result<Vec<T>, E> {
    let n = order.len();
    let slots: Vec<Mutex<Option<Result<T, E>>>> = (0..n).map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    let failed = AtomicBool::new(false);
    let work = || {
        while !failed.load(Ordering::Relaxed) {
            let Some(&i) = order.get(next.fetch_add(1, Ordering::Relaxed)) else {
                break;
            };
            let r = task(i);
            if r.is_err() {
                failed.store(true, Ordering::Relaxed);
            }
            *slots[i].lock().unwrap_or_else(|e| e.into_inner()) = Some(r);
        }
    };
    if threads <= 1 || !CAN_START_THREADS || n <= 1 {
        work();
    } else {
        std::thread::scope(|scope| {
            let handles: Vec<_> = (0..threads.min(n)).map(|_| scope.spawn(work)).collect();
            for h in handles {
                if let Err(payload) = h.join() {
                    std::panic::resume_unwind(payload);
                }
            }
        });
    }
    let mut out = Vec::with_capacity(n);
    let mut first_error = None;
    for slot in slots {
        match slot.into_inner().unwrap_or_else(|e| e.into_inner()) {
            Some(Ok(v)) if first_error.is_none() => out.push(v),
            Some(Err(e)) if first_error.is_none() => first_error = Some(e),
            Some(_) => {}
            None => assert!(
                failed.load(Ordering::Relaxed) || first_error.is_some(),
                "order is not a permutation of 0..{n}"
            ),
        }
    }
    match first_error {
        Some(e) => Err(e),
        None => Ok(out),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_do_not_depend_on_threads_or_order() {
        let order: Vec<usize> = (0..100).rev().collect();
        let one = map_tasks(&order, 1, |i| Ok::<_, ()>(i * 3)).unwrap();
        let two = map_tasks(&(0..100).collect::<Vec<_>>(), 2, |i| Ok::<_, ()>(i * 3)).unwrap();
        assert_eq!(one, two);
        assert_eq!(one, (0..100).map(|i| i * 3).collect::<Vec<_>>());
    }

    #[test]
    fn the_failed_task_with_the_smallest_index_is_reported() {
        // On one thread in this order, task 5 runs (and fails) first, then nothing else starts.
        let order = [5, 2, 0, 1, 3, 4];
        let r = map_tasks(&order, 1, |i| if i >= 2 { Err(i) } else { Ok(i) });
        assert_eq!(r, Err(5));
        // Both failures recorded: the smaller index wins.
        let order = [0, 1, 2, 3];
        let r = map_tasks(&order, 1, |i| if i == 3 { Err(i) } else { Ok(i) });
        assert_eq!(r, Err(3));
    }

    #[test]
    fn a_panic_keeps_its_message_on_one_thread_too() {
        let caught = std::panic::catch_unwind(|| {
            map_tasks(&[0], 1, |_| -> Result<(), ()> { panic!("alone") })
        });
        assert_eq!(*caught.unwrap_err().downcast::<&str>().unwrap(), "alone");
    }
}
