//! CPU-time clocks for the timings the benchmarks and the volume pipeline report. Unlike wall
//! time, a thread's CPU time leaves out the time it waited for a core, so it stays meaningful on
//! a shared machine (it still includes the slowdown from cache and memory contention).

/// The reading of the CPU-time clock `clock` (`CLOCK_PROCESS_CPUTIME_ID` or
/// `CLOCK_THREAD_CPUTIME_ID`), milliseconds; NaN when the clock cannot be read.
fn clock_ms(clock: libc::clockid_t) -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec; the call only writes it.
    let rc = unsafe { libc::clock_gettime(clock, &mut ts) };
    if rc != 0 {
        return f64::NAN;
    }
    ts.tv_sec as f64 * 1e3 + ts.tv_nsec as f64 * 1e-6
}

/// CPU time of the whole process (every thread), milliseconds.
pub fn process_ms() -> f64 {
    clock_ms(libc::CLOCK_PROCESS_CPUTIME_ID)
}

/// CPU time of the calling thread, milliseconds.
pub fn thread_ms() -> f64 {
    clock_ms(libc::CLOCK_THREAD_CPUTIME_ID)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cpu_clocks_advance_with_work() {
        let (p0, t0) = (process_ms(), thread_ms());
        let mut x = 0u64;
        for i in 0..20_000_000u64 {
            x = std::hint::black_box(x.wrapping_mul(6364136223846793005).wrapping_add(i));
        }
        assert!(x != 1);
        let (p1, t1) = (process_ms(), thread_ms());
        assert!(
            t1 > t0 && p1 > p0,
            "thread {t0} → {t1}, process {p0} → {p1}"
        );
        assert!(
            p1 - p0 >= 0.5 * (t1 - t0),
            "the process includes this thread"
        );
    }
}
