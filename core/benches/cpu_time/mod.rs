//! The benches' clock: the bench thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`), so time the
//! hypervisor or other processes take from the thread is not counted — on a shared 2-core VM
//! wall-clock medians swing by 1.5–2× from run to run while CPU-time medians hold. Set
//! `NYQUIST_BENCH_CLOCK=wall` to measure wall-clock time (`CLOCK_MONOTONIC`) instead. Either way
//! the unit is nanoseconds.
#![allow(dead_code)]

use criterion::Criterion;
use criterion::measurement::{Measurement, ValueFormatter, WallTime};
use rustix::time::{ClockId, clock_gettime};
use std::sync::OnceLock;

/// The measurement: thread CPU time by default, wall-clock time on request.
pub struct BenchClock;

fn clock() -> ClockId {
    static CLOCK: OnceLock<ClockId> = OnceLock::new();
    *CLOCK.get_or_init(|| match std::env::var("NYQUIST_BENCH_CLOCK").as_deref() {
        Ok("wall") => ClockId::Monotonic,
        _ => ClockId::ThreadCPUTime,
    })
}

fn now_ns() -> u64 {
    let t = clock_gettime(clock());
    t.tv_sec as u64 * 1_000_000_000 + t.tv_nsec as u64
}

impl Measurement for BenchClock {
    type Intermediate = u64;
    type Value = u64;
    fn start(&self) -> u64 {
        now_ns()
    }
    fn end(&self, start: u64) -> u64 {
        now_ns().saturating_sub(start)
    }
    fn add(&self, a: &u64, b: &u64) -> u64 {
        a + b
    }
    fn zero(&self) -> u64 {
        0
    }
    fn to_f64(&self, v: &u64) -> f64 {
        *v as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        WallTime.formatter()
    }
}

/// Criterion configured with [`BenchClock`].
pub fn config() -> Criterion<BenchClock> {
    Criterion::default().with_measurement(BenchClock)
}
