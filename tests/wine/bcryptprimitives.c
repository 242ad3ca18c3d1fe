/*
 * A stand-in for Windows' bcryptprimitives.dll, for running mountains.exe
 * under Wine 8 in the tests only (never shipped).
 *
 * Why: Rust's std on Windows takes its random bytes (HashMap seeds) from
 * ProcessPrng in bcryptprimitives.dll, which Wine 8.0 does not have: the
 * exe then fails to load with c0000135 (DLL not found). Placed next to the
 * exe, this DLL answers ProcessPrng with RtlGenRandom (advapi32's
 * SystemFunction036), which Wine has. Built by tests/platforms/wine.rs with
 *   x86_64-w64-mingw32-gcc -O2 -shared -o bcryptprimitives.dll \
 *     bcryptprimitives.c bcryptprimitives.def -ladvapi32
 */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

/* Fills `len` bytes at `data` with random bytes; TRUE on success. */
BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T len) {
    while (len > 0) {
        /* RtlGenRandom takes a ULONG length: feed it in chunks. */
        ULONG chunk = len > 0x10000000 ? 0x10000000 : (ULONG)len;
        if (!SystemFunction036(data, chunk)) return FALSE;
        data += chunk;
        len -= chunk;
    }
    return TRUE;
}
