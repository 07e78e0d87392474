//! Speed tables stored in the binary, or built in zeroed memory at first use.
//!
//! The samplers read about 2.7 MiB of tables that are functions of a few constants (the Sobol
//! matrices, Sobol byte and nibble products, radical-inverse constants and digit reversals, the
//! baked PMJ(0,2) sequence). By default they are evaluated at compile time and stored in the binary's read-only
//! data, which costs nothing at run time and suits firmware, where flash is cheaper than RAM.
//!
//! With the `lazy-tables` feature each table is instead a zero-initialised static (`.bss`, which
//! takes no room in an executable or a WebAssembly module) that the same `const fn` fills the
//! first time any thread reads it. The values are the same bit for bit (each table has a test that
//! compares the two); the module shrinks by the tables' size and the first read of each table
//! pays its construction once. The best-candidate table is generated the same way by its own
//! fill (`sampler/best_candidate/generate.rs`), and so is the dither mask. What each first read
//! costs: `docs/performance.md` (`core/examples/first_use.rs` measures it). The browser explorer
//! (`web/`) builds this way.
//!
//! [`baked_table!`] declares one table either way, so the code that reads it (indexing, `iter`)
//! is the same in both builds.

/// Declares a static table filled by a `const fn(&mut T)`:
///
/// ```ignore
/// baked_table! {
///     /// Docs of the table.
///     static NAME: Type = zero_value, fill_fn, test_name;
/// }
/// ```
///
/// Without the `lazy-tables` feature, `NAME` is a plain static evaluated at compile time from
/// `zero_value` and `fill_fn`. With it, `NAME` is a [`LazyTable`] that runs `fill_fn` on the
/// all-zero `zero_value` at first use. `test_name` is a test, in both builds, that the two
/// agree, so `cargo test` checks every lazily built table without the feature. A trailing
/// `, stored STATIC` makes `NAME` an alias of that existing static in the default build.
macro_rules! baked_table {
    // A table whose stored form is the public static `$stored`: without the feature `NAME` is
    // that static, so a program that names both carries it once.
    ($(#[$doc:meta])* $vis:vis static $name:ident: $ty:ty = $zero:expr, $fill:path, $test:ident,
        stored $stored:ident;) => {
        #[cfg(not(feature = "lazy-tables"))]
        $vis use $stored as $name;
        $crate::lazy_table::baked_table!(@at_first_use $(#[$doc])* $vis $name $ty, $zero, $fill, $test);
    };
    ($(#[$doc:meta])* $vis:vis static $name:ident: $ty:ty = $zero:expr, $fill:path, $test:ident;) => {
        $(#[$doc])*
        #[cfg(not(feature = "lazy-tables"))]
        $vis static $name: $ty = {
            let mut t = $zero;
            $fill(&mut t);
            t
        };
        $crate::lazy_table::baked_table!(@at_first_use $(#[$doc])* $vis $name $ty, $zero, $fill, $test);
    };
    // The `lazy-tables` form, and the test that the two forms agree.
    (@at_first_use $(#[$doc:meta])* $vis:vis $name:ident $ty:ty, $zero:expr, $fill:path, $test:ident) => {
        // The table's fill, as a type (a function pointer stored in the static would make it
        // non-zero and move it out of `.bss`). Types and statics have separate namespaces.
        #[cfg(feature = "lazy-tables")]
        #[allow(non_camel_case_types, clippy::upper_case_acronyms)]
        $vis struct $name {}

        #[cfg(feature = "lazy-tables")]
        impl $crate::lazy_table::Fill for $name {
            type Table = $ty;
            fn fill(t: &mut $ty) {
                $fill(t)
            }
        }

        $(#[$doc])*
        #[cfg(feature = "lazy-tables")]
        $vis static $name: $crate::lazy_table::LazyTable<$name> = $crate::lazy_table::LazyTable::new($zero);

        // The table built at first use equals its compile-time value, in either build.
        #[cfg(test)]
        #[test]
        fn $test() {
            #[cfg(not(feature = "lazy-tables"))]
            {
                struct Fill;
                impl $crate::lazy_table::Fill for Fill {
                    type Table = $ty;
                    fn fill(t: &mut $ty) {
                        $fill(t)
                    }
                }
                static AT_FIRST_USE: $crate::lazy_table::LazyTable<Fill> =
                    $crate::lazy_table::LazyTable::new($zero);
                assert!(*AT_FIRST_USE == $name, "{} differs when built at first use", stringify!($name));
            }
            #[cfg(feature = "lazy-tables")]
            {
                static BAKED: $ty = {
                    let mut t = $zero;
                    $fill(&mut t);
                    t
                };
                assert!(*$name == BAKED, "{} differs when built at first use", stringify!($name));
            }
        }
    };
}
pub(crate) use baked_table;

/// Declares a `const fn` that is a plain `fn` when the Sobol matrices are built at first use
/// (`lazy-tables`, outside tests): the fills of the tables derived from them read them at run
/// time then, which a `const fn` cannot. Tests always compile the stored matrices, so there the
/// fills stay `const` and each lazily built table is compared with its compile-time value.
macro_rules! const_unless_lazy {
    ($(#[$attr:meta])* $vis:vis fn $($rest:tt)*) => {
        $(#[$attr])*
        #[cfg(any(not(feature = "lazy-tables"), test))]
        $vis const fn $($rest)*

        $(#[$attr])*
        #[cfg(all(feature = "lazy-tables", not(test)))]
        $vis fn $($rest)*
    };
}
pub(crate) use const_unless_lazy;

#[cfg(any(feature = "lazy-tables", test))]
pub(crate) use lazy::{Fill, LazyTable};

#[cfg(any(feature = "lazy-tables", test))]
mod lazy {
    #![allow(unsafe_code)]
    // `unsafe` here: handing out `&T` into a static that was written once through `&mut T`.
    // Safe alternatives cost more than they save: an atomic per word would change every table's
    // element type and every reader; `spin::Once` and friends build the value on the stack and
    // move it (half a MiB for the largest table, a stack overflow in WebAssembly's 1 MiB stack).
    // Miri runs the tests below (`.ci/run`), including two threads racing for the first read.

    use core::cell::UnsafeCell;
    use core::marker::PhantomData;
    use core::ops::Deref;
    use core::sync::atomic::{AtomicU8, Ordering};

    const EMPTY: u8 = 0;
    const FILLING: u8 = 1;
    const READY: u8 = 2;

    /// How a [`LazyTable`] is filled: `fill` writes every entry of a table that starts all zero.
    pub(crate) trait Fill {
        /// The table's type.
        type Table;
        /// Writes the table's values over its all-zero start.
        fn fill(t: &mut Self::Table);
    }

    /// A table that `F::fill` writes in place, once, at its first read. Its initial value must be
    /// all zero bytes so that the static lands in `.bss` (the filled values need not be): the
    /// fill is a type parameter rather than a stored function pointer for that reason.
    ///
    /// Every thread that reads it before it is ready waits (spinning) for the one thread that
    /// fills it; the fill must not read the same table (it would wait for itself). The fills used
    /// here read only other tables and constants, and never panic.
    pub(crate) struct LazyTable<F: Fill> {
        state: AtomicU8,
        value: UnsafeCell<F::Table>,
        fill: PhantomData<F>,
    }

    // SAFETY: the contents are written only by the one thread that moved `state` from EMPTY to
    // FILLING, through the only `&mut` ever made, and read (as `&`) only after `state` is READY,
    // which that thread stores with Release after its last write and which readers load with
    // Acquire. So a reader never sees a write in progress; sharing `&F::Table` across threads
    // needs `F::Table: Sync`.
    unsafe impl<F: Fill> Sync for LazyTable<F> where F::Table: Sync {}

    impl<F: Fill> LazyTable<F> {
        /// A table that starts as `zero` and is filled by `F::fill` at first use.
        pub(crate) const fn new(zero: F::Table) -> Self {
            LazyTable {
                state: AtomicU8::new(EMPTY),
                value: UnsafeCell::new(zero),
                fill: PhantomData,
            }
        }

        #[cold]
        #[inline(never)]
        fn fill_once(&self) {
            match self
                .state
                .compare_exchange(EMPTY, FILLING, Ordering::Acquire, Ordering::Acquire)
            {
                Ok(_) => {
                    // SAFETY: only the thread whose compare-exchange moved EMPTY to FILLING gets
                    // here, once; no `&` to the contents exists before READY, so this `&mut` is
                    // the only reference.
                    let value = unsafe { &mut *self.value.get() };
                    F::fill(value);
                    self.state.store(READY, Ordering::Release);
                }
                Err(_) => {
                    while self.state.load(Ordering::Acquire) != READY {
                        core::hint::spin_loop();
                    }
                }
            }
        }
    }

    impl<F: Fill> Deref for LazyTable<F> {
        type Target = F::Table;

        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn deref(&self) -> &F::Table {
            if self.state.load(Ordering::Acquire) != READY {
                self.fill_once();
            }
            // SAFETY: `state` is READY (this thread's Acquire load saw the filling thread's
            // Release store, or this thread filled it), so every write happened before and no
            // `&mut` exists any more; READY is never left.
            unsafe { &*self.value.get() }
        }
    }

    #[cfg(test)]
    mod tests {
        use super::{Fill, LazyTable};
        use core::sync::atomic::{AtomicU32, Ordering};
        use std::vec::Vec;

        /// `t[i] = i² + 1`.
        fn squares(t: &mut [u32; 64]) {
            for (i, v) in t.iter_mut().enumerate() {
                *v = (i * i) as u32 + 1;
            }
        }

        struct Squares;
        impl Fill for Squares {
            type Table = [u32; 64];
            fn fill(t: &mut [u32; 64]) {
                squares(t)
            }
        }

        /// [`Squares`] that counts its fills.
        struct CountedSquares;
        static FILLS: AtomicU32 = AtomicU32::new(0);
        impl Fill for CountedSquares {
            type Table = [u32; 64];
            fn fill(t: &mut [u32; 64]) {
                FILLS.fetch_add(1, Ordering::Relaxed);
                squares(t)
            }
        }

        #[test]
        fn filled_at_first_read_and_kept() {
            static T: LazyTable<Squares> = LazyTable::new([0; 64]);
            assert_eq!(T[7], 50);
            let sum: u64 = T.iter().map(|&v| v as u64).sum();
            assert_eq!(sum, 64 + 63 * 64 * 127 / 6);
            // Every entry was written by the fill; none is still the zero it started as.
            assert!(T.iter().all(|&v| v != 0));
        }

        /// Threads racing for the first read all see the filled table, and it is filled once.
        #[test]
        fn racing_first_reads_see_one_fill() {
            static T: LazyTable<CountedSquares> = LazyTable::new([0; 64]);
            let seen: Vec<u32> = std::thread::scope(|s| {
                let handles: Vec<_> = (0..4).map(|k| s.spawn(move || T[k * 9])).collect();
                handles.into_iter().map(|h| h.join().unwrap()).collect()
            });
            assert_eq!(seen, [1, 82, 325, 730]);
            assert_eq!(FILLS.load(Ordering::Relaxed), 1);
        }
    }
}
