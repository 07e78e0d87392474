//! Measurement: every contender of a workload in rotation within each sample round, timed by
//! the thread's CPU time, and the table of peer ÷ nyquist ratios.

use std::hint::black_box;

/// One call of a contender: the whole batch of a workload (its outputs go to a buffer the
/// closure owns and hands to `black_box`).
pub type Job<'a> = Box<dyn FnMut() + 'a>;

/// A peer's entry in a workload: its job, or why there is none (not built, or its check
/// against nyquist failed).
pub struct Entry<'a> {
    pub peer: String,
    pub job: Result<Job<'a>, String>,
}

impl<'a> Entry<'a> {
    pub fn ready(peer: &str, job: Job<'a>) -> Self {
        Entry {
            peer: peer.to_owned(),
            job: Ok(job),
        }
    }

    pub fn skipped(peer: &str, why: impl Into<String>) -> Self {
        Entry {
            peer: peer.to_owned(),
            job: Err(why.into()),
        }
    }

    /// `job` if `check` passed, otherwise the row says which check failed.
    pub fn checked(peer: &str, check: Result<(), String>, job: Job<'a>) -> Self {
        match check {
            Ok(()) => Entry::ready(peer, job),
            Err(e) => Entry::skipped(peer, format!("CHECK FAILED: {e}")),
        }
    }
}

/// A workload: nyquist's job and the peers doing the same computation.
pub struct Workload<'a> {
    pub name: String,
    /// Elements per call (values, samples, weights…) and their name, for the per-element times.
    pub elements: u64,
    pub unit: &'static str,
    pub nyquist: Job<'a>,
    pub peers: Vec<Entry<'a>>,
}

#[derive(Clone, Copy, Debug)]
pub struct Settings {
    pub samples: usize,
    pub runs: usize,
    /// Target CPU time of one timed sample of one contender.
    pub sample_ns: u64,
}

/// One row of the table.
pub struct Row {
    pub workload: String,
    pub peer: String,
    pub unit: &'static str,
    pub outcome: Result<Measured, String>,
}

pub struct Measured {
    /// Peer ÷ nyquist of each run's median times.
    pub ratios: Vec<f64>,
    /// Median over all runs of the per-element times, nyquist's and the peer's.
    pub nyquist_ns: f64,
    pub peer_ns: f64,
}

/// The calling thread's CPU time in nanoseconds (`CLOCK_THREAD_CPUTIME_ID`).
pub fn thread_cpu_ns() -> u64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid, writable timespec; the clock id is a constant Linux defines.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    assert_eq!(rc, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
    t.tv_sec as u64 * 1_000_000_000 + t.tv_nsec as u64
}

/// Calls per timed sample so that one sample takes about `target_ns` of CPU time.
fn calibrate(job: &mut Job<'_>, target_ns: u64) -> u64 {
    job(); // warm caches and lazily built tables
    let mut reps = 1u64;
    loop {
        let t0 = thread_cpu_ns();
        for _ in 0..reps {
            job();
        }
        let t = thread_cpu_ns() - t0;
        if t >= target_ns / 4 || reps >= 1 << 24 {
            return (reps * target_ns / t.max(1)).max(1);
        }
        reps *= 4;
    }
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    }
}

/// Measures a workload: per run, `samples` rounds; in round `s` the contenders (nyquist first in
/// the list, then each live peer) are timed one after the other starting at contender
/// `s mod n`, so no contender always runs first or right after the same one.
pub fn measure(w: Workload<'_>, settings: Settings) -> Vec<Row> {
    let Workload {
        name,
        elements,
        unit,
        nyquist,
        peers,
    } = w;
    let mut jobs: Vec<Job<'_>> = vec![nyquist];
    let mut labels = Vec::new();
    let mut rows = Vec::new();
    for e in peers {
        match e.job {
            Ok(j) => {
                labels.push((e.peer, rows.len()));
                jobs.push(j);
                rows.push(None);
            }
            Err(why) => rows.push(Some(Row {
                workload: name.clone(),
                peer: e.peer,
                unit,
                outcome: Err(why),
            })),
        }
    }
    if jobs.len() > 1 {
        let reps: Vec<u64> = jobs
            .iter_mut()
            .map(|j| calibrate(j, settings.sample_ns))
            .collect();
        let n = jobs.len();
        // times[run][contender] = per-call ns of every sample.
        let mut times = vec![vec![Vec::with_capacity(settings.samples); n]; settings.runs];
        for run in times.iter_mut() {
            for s in 0..settings.samples {
                for k in 0..n {
                    let c = (s + k) % n;
                    let job = &mut jobs[c];
                    let t0 = thread_cpu_ns();
                    for _ in 0..reps[c] {
                        job();
                    }
                    let t = thread_cpu_ns() - t0;
                    run[c].push(black_box(t) as f64 / reps[c] as f64);
                }
            }
        }
        let per_element = |v: &mut Vec<f64>| median(v) / elements as f64;
        let mut all: Vec<Vec<f64>> = vec![Vec::new(); n];
        for run in &times {
            for (c, t) in run.iter().enumerate() {
                all[c].extend_from_slice(t);
            }
        }
        let nyquist_ns = per_element(&mut all[0]);
        for (k, (peer, slot)) in labels.into_iter().enumerate() {
            let c = k + 1;
            let ratios = times
                .iter_mut()
                .map(|run| {
                    let ours = median(&mut run[0]);
                    median(&mut run[c]) / ours
                })
                .collect();
            rows[slot] = Some(Row {
                workload: name.clone(),
                peer,
                unit,
                outcome: Ok(Measured {
                    ratios,
                    nyquist_ns,
                    peer_ns: per_element(&mut all[c]),
                }),
            });
        }
    }
    rows.into_iter().flatten().collect()
}

/// Prints the table: one row per (workload, peer); skipped peers say why.
pub fn print_table(rows: &mut [Row], settings: Settings) {
    let runs = settings.runs;
    let mut head = String::from("| workload | peer |");
    let mut rule = String::from("|---|---|");
    for r in 1..=runs {
        head += &format!(" run {r} |");
        rule += "---|";
    }
    head += " median | nyquist | peer |";
    rule += "---|---|---|";
    println!("{head}\n{rule}");
    for row in rows.iter_mut() {
        let mut line = format!("| {} | {} |", row.workload, row.peer);
        match &mut row.outcome {
            Ok(m) => {
                for r in &m.ratios {
                    line += &format!(" {r:.2}× |");
                }
                let med = median(&mut m.ratios.clone());
                line += &format!(
                    " **{med:.2}×** | {} | {} |",
                    ns(m.nyquist_ns, row.unit),
                    ns(m.peer_ns, row.unit)
                );
            }
            Err(why) => {
                line += &" — |".repeat(runs);
                line += &format!(" skipped: {why} | | |");
            }
        }
        println!("{line}");
    }
}

fn ns(t: f64, unit: &str) -> String {
    if t >= 100.0 {
        format!("{t:.0} ns/{unit}")
    } else if t >= 10.0 {
        format!("{t:.1} ns/{unit}")
    } else {
        format!("{t:.2} ns/{unit}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spin(n: u64) -> Job<'static> {
        Box::new(move || {
            let mut x = 0u64;
            for i in 0..n {
                x = black_box(x.wrapping_mul(31).wrapping_add(i));
            }
            black_box(x);
        })
    }

    #[test]
    fn a_slower_peer_has_a_ratio_above_one_and_a_skipped_peer_says_why() {
        let w = Workload {
            name: "spin".into(),
            elements: 1000,
            unit: "step",
            nyquist: spin(1000),
            peers: vec![
                Entry::ready("four times the work", spin(4000)),
                Entry::skipped("absent", "not built"),
            ],
        };
        let settings = Settings {
            samples: 5,
            runs: 2,
            sample_ns: 200_000,
        };
        let rows = measure(w, settings);
        assert_eq!(rows.len(), 2);
        let m = rows[0].outcome.as_ref().unwrap();
        assert_eq!(m.ratios.len(), 2);
        assert!(m.ratios.iter().all(|&r| r > 2.0), "{:?}", m.ratios);
        assert_eq!(rows[1].outcome.as_ref().err().unwrap(), "not built");
    }

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 2.0, 3.0]), 2.5);
    }
}
