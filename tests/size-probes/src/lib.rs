//! The runtime the size probes share: a reset handler (FPU on, `.data` copied, `.bss` zeroed),
//! a panic handler, and the probe loop. Without the `qemu` feature the loop reads an index from a
//! volatile location and writes the results to another, forever, so that nothing is optimised
//! away and nothing but the call is measured; with it, the loop runs over
//! [`probe_index`]`(0 .. PROBE_POINTS)` and prints each result as eight hex digits per line over
//! ARM semihosting, then exits.
#![no_std]

use core::panic::PanicInfo;

include!("indices.rs");

#[cfg(target_arch = "arm")]
core::arch::global_asm!(
    ".section .text.Reset, \"ax\"",
    ".global Reset",
    ".type Reset, %function",
    ".thumb_func",
    "Reset:",
    // CPACR: full access to CP10 and CP11, the FPU (hard-float code faults without it).
    "    ldr r0, =0xE000ED88",
    "    ldr r1, [r0]",
    "    orr r1, r1, #0xF00000",
    "    str r1, [r0]",
    "    dsb",
    "    isb",
    "    ldr r0, =__sdata",
    "    ldr r1, =__edata",
    "    ldr r2, =__sidata",
    "1:  cmp r0, r1",
    "    bhs 2f",
    "    ldr r3, [r2], #4",
    "    str r3, [r0], #4",
    "    b 1b",
    "2:  ldr r0, =__sbss",
    "    ldr r1, =__ebss",
    "    movs r2, #0",
    "3:  cmp r0, r1",
    "    bhs 4f",
    "    str r2, [r0], #4",
    "    b 3b",
    "4:  bl probe_main",
    "5:  b 5b",
);

#[cfg(not(test))]
#[panic_handler]
fn panic(_: &PanicInfo<'_>) -> ! {
    #[cfg(feature = "qemu")]
    {
        semihosting::write(b"PANIC\n\0");
        semihosting::exit(1);
    }
    #[allow(unreachable_code)]
    loop {}
}

#[cfg(not(feature = "qemu"))]
static mut INPUT: u64 = 0;
#[cfg(not(feature = "qemu"))]
static mut OUTPUT: u32 = 0;

/// Calls `f` with one index after another: read from a volatile location (size mode), or the
/// [`probe_index`] run (with `qemu`, which then exits).
pub fn run(mut f: impl FnMut(u64)) -> ! {
    #[cfg(not(feature = "qemu"))]
    loop {
        f(unsafe { core::ptr::read_volatile(&raw const INPUT) });
    }
    #[cfg(feature = "qemu")]
    {
        for k in 0..PROBE_POINTS {
            f(probe_index(k));
        }
        semihosting::write(b"END\n\0");
        semihosting::exit(0)
    }
}

/// Hands one result word out: a volatile store (size mode) or a line of eight hex digits.
#[inline(always)]
pub fn emit(x: u32) {
    #[cfg(not(feature = "qemu"))]
    unsafe {
        core::ptr::write_volatile(&raw mut OUTPUT, x);
    }
    #[cfg(feature = "qemu")]
    {
        let mut line = [0u8; 10];
        for (k, c) in line[..8].iter_mut().enumerate() {
            let nibble = (x >> (28 - 4 * k)) & 15;
            *c = b"0123456789abcdef"[nibble as usize];
        }
        line[8] = b'\n';
        semihosting::write(&line);
    }
}

#[cfg(feature = "qemu")]
mod semihosting {
    /// One semihosting call: operation `op`, argument `arg`.
    fn call(op: u32, arg: usize) -> u32 {
        #[cfg(target_arch = "arm")]
        unsafe {
            let r: u32;
            core::arch::asm!("bkpt 0xab", inout("r0") op => r, in("r1") arg);
            r
        }
        #[cfg(not(target_arch = "arm"))]
        {
            let _ = (op, arg);
            0
        }
    }

    /// Writes a NUL-terminated string to the host's console (SYS_WRITE0).
    pub fn write(s: &[u8]) {
        debug_assert_eq!(s.last(), Some(&0));
        call(0x04, s.as_ptr() as usize);
    }

    /// Ends the emulation (SYS_EXIT with ADP_Stopped_ApplicationExit, or RunTimeErrorUnknown).
    pub fn exit(status: u32) -> ! {
        call(0x18, if status == 0 { 0x20026 } else { 0x20024 });
        loop {
            core::hint::spin_loop();
        }
    }
}

/// One step of a camera-sample loop: the camera sample of a pixel and sample index taken from
/// `i` (pixel `(i mod 64, ⌊i/64⌋ mod 64)`, sample `⌊i/4096⌋` cut to 32 bits), then one `get_1d`
/// and one `get_2d` (dimensions 5 to 7); emits the eight values. `host/` runs the same steps.
#[inline(always)]
pub fn camera_loop<S: nyquist::sampler::Sampler>(s: &mut S, i: u64) {
    let c = s.camera_sample([(i & 63) as u32, (i >> 6 & 63) as u32], (i >> 12) as u32);
    let t = s.get_1d();
    let [u, v] = s.get_2d();
    for x in [
        c.p_film[0],
        c.p_film[1],
        c.lens[0],
        c.lens[1],
        c.time,
        t,
        u,
        v,
    ] {
        emit(x.to_bits());
    }
}
