/*
 * A test stand-in for the Control Panel's Screen Saver dialog, run under
 * Wine by tests/platforms/wine.rs.
 *
 *   preview_host.exe SAVER.EXE SECONDS unaware|per-monitor
 *
 * The host's window is DPI-unaware, as an old dialog is, or per-monitor
 * aware (v2, else v1: Wine 8 has no v2), as a modern Settings app is. Set
 * for the thread that makes the window: Wine 8 has already made the process
 * per-monitor aware, and a process's awareness is set only once.
 * Makes a top-level window titled "preview-host" with a 152x112 black
 * client area (the dialog's little monitor), starts `SAVER.EXE /p <HWND>`
 * with that window's handle in decimal, as Windows does, pumps messages
 * until the saver's child window shows up in it (up to 10 s) and then for
 * SECONDS more, half-way resizing its window to 200x150 and waiting (up to
 * 10 s) for the child to follow, destroys the window, then waits up to 10 s
 * for the saver to end. Prints on stdout, one fact a line:
 *   hwnd=<decimal>
 *   child_after_ms=<ms from the start>   (or: no_child)
 *   dpi_awareness host=<n> child=<n>     (DPI_AWARENESS of each window:
 *                                         0 unaware, 1 system, 2 per monitor)
 *   child_size=<w>x<h> after_ms=<ms>     (the child's client area, once it
 *                                         fills the host, or after 10 s)
 *   resized_child=<w>x<h> after_ms=<ms since the resize>
 *   destroyed
 *   exit_code=<code> ended_after_ms=<ms since the destroy>
 * or, instead of the last two, `ended_early exit_code=<code>` (the saver was
 * gone before the destroy) or `not_ended after_ms=<ms>` (still running 10 s
 * after it; then it is terminated).
 * Exits 0 if the saver ended after the destroy, 1 if not, 2 on a setup error.
 */
/* Windows 10 1607: the DPI awareness context functions. */
#define WINVER 0x0A00
#define _WIN32_WINNT 0x0A00
#include <windows.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CLIENT_W 152
#define CLIENT_H 112
#define RESIZED_W 200
#define RESIZED_H 150
#define FOLLOW_WAIT_MS 10000
#define END_WAIT_MS 10000
#define CHILD_WAIT_MS 10000

static LRESULT CALLBACK host_proc(HWND w, UINT msg, WPARAM wp, LPARAM lp) {
    return DefWindowProcW(w, msg, wp, lp);
}

/* The host window, shown at (40, 40); NULL on failure. */
static HWND make_window(void) {
    WNDCLASSW wc = {0};
    wc.lpfnWndProc = host_proc;
    wc.hInstance = GetModuleHandleW(NULL);
    wc.lpszClassName = L"preview-host";
    /* Black, so that an undrawn preview does not look like a mountain. */
    wc.hbrBackground = (HBRUSH)GetStockObject(BLACK_BRUSH);
    if (!RegisterClassW(&wc)) return NULL;
    /* A frameless popup: its window rectangle is its client area, so the
     * test finds it by size among the X windows. WS_CLIPCHILDREN as the
     * dialog's preview control has it: the host never paints over the saver. */
    DWORD style = WS_POPUP | WS_VISIBLE | WS_CLIPCHILDREN;
    HWND w = CreateWindowExW(0, wc.lpszClassName, L"preview-host", style, 40, 40,
                             CLIENT_W, CLIENT_H, NULL, NULL, wc.hInstance, NULL);
    if (w) UpdateWindow(w);
    return w;
}

/* Starts `saver /p <hwnd>`; the process handle, or NULL. */
static HANDLE start_saver(const char *saver, HWND w) {
    char cmd[MAX_PATH + 64];
    snprintf(cmd, sizeof cmd, "\"%s\" /p %llu", saver, (unsigned long long)(UINT_PTR)w);
    STARTUPINFOA si = {sizeof si};
    PROCESS_INFORMATION pi;
    if (!CreateProcessA(NULL, cmd, NULL, NULL, FALSE, 0, NULL, NULL, &si, &pi)) return NULL;
    CloseHandle(pi.hThread);
    return pi.hProcess;
}

/* Dispatches this thread's messages until `ms` have passed, or until `w`
 * has a child window if `w` is not NULL; TRUE if it has one. */
static BOOL pump(DWORD ms, HWND w) {
    ULONGLONG end = GetTickCount64() + ms;
    for (ULONGLONG now; (now = GetTickCount64()) < end;) {
        if (w && GetWindow(w, GW_CHILD)) return TRUE;
        /* Wake at least every 20 ms to look for the child. */
        DWORD wait = (DWORD)(end - now) < 20 ? (DWORD)(end - now) : 20;
        MsgWaitForMultipleObjects(0, NULL, FALSE, w ? wait : (DWORD)(end - now), QS_ALLINPUT);
        MSG msg;
        while (PeekMessageW(&msg, NULL, 0, 0, PM_REMOVE)) {
            TranslateMessage(&msg);
            DispatchMessageW(&msg);
        }
    }
    return w && GetWindow(w, GW_CHILD);
}

/* The DPI awareness of a window (of any process); -1 if unknown. */
static int awareness(HWND w) {
    return (int)GetAwarenessFromDpiAwarenessContext(GetWindowDpiAwarenessContext(w));
}

/* The client size of `w`'s first child; FALSE if it has none. */
static BOOL child_size(HWND w, LONG *cw, LONG *ch) {
    HWND c = GetWindow(w, GW_CHILD);
    RECT r;
    if (!c || !GetClientRect(c, &r)) return FALSE;
    *cw = r.right - r.left;
    *ch = r.bottom - r.top;
    return TRUE;
}

/* Waits (up to FOLLOW_WAIT_MS) for `w`'s child to have a `tw` x `th`
 * client area; prints `label=<w>x<h> after_ms=<ms>` with what it had last. */
static void wait_child_size(HWND w, LONG tw, LONG th, const char *label) {
    ULONGLONG since = GetTickCount64();
    LONG cw = 0, ch = 0;
    while (GetTickCount64() - since < FOLLOW_WAIT_MS) {
        if (child_size(w, &cw, &ch) && cw == tw && ch == th) break;
        pump(20, NULL);
    }
    child_size(w, &cw, &ch);
    printf("%s=%ldx%ld after_ms=%llu\n", label, cw, ch, GetTickCount64() - since);
    fflush(stdout);
}

int main(int argc, char **argv) {
    BOOL unaware = argc == 4 && strcmp(argv[3], "unaware") == 0;
    BOOL per_monitor = argc == 4 && strcmp(argv[3], "per-monitor") == 0;
    if (!unaware && !per_monitor) {
        fprintf(stderr, "usage: preview_host SAVER.EXE SECONDS unaware|per-monitor\n");
        return 2;
    }
    BOOL set = unaware ? SetThreadDpiAwarenessContext(DPI_AWARENESS_CONTEXT_UNAWARE) != NULL
                       : SetThreadDpiAwarenessContext(DPI_AWARENESS_CONTEXT_PER_MONITOR_AWARE_V2) ||
                             SetThreadDpiAwarenessContext(DPI_AWARENESS_CONTEXT_PER_MONITOR_AWARE);
    if (!set) {
        fprintf(stderr, "preview_host: cannot set DPI awareness %s (error %lu)\n", argv[3],
                GetLastError());
        return 2;
    }
    HWND w = make_window();
    if (!w) {
        fprintf(stderr, "preview_host: no window (error %lu)\n", GetLastError());
        return 2;
    }
    printf("hwnd=%llu\n", (unsigned long long)(UINT_PTR)w);
    fflush(stdout);
    HANDLE saver = start_saver(argv[1], w);
    if (!saver) {
        fprintf(stderr, "preview_host: cannot start %s (error %lu)\n", argv[1], GetLastError());
        return 2;
    }
    ULONGLONG started = GetTickCount64();
    if (pump(CHILD_WAIT_MS, w)) {
        printf("child_after_ms=%llu\n", GetTickCount64() - started);
        printf("dpi_awareness host=%d child=%d\n", awareness(w), awareness(GetWindow(w, GW_CHILD)));
    } else {
        printf("no_child\n");
    }
    wait_child_size(w, CLIENT_W, CLIENT_H, "child_size");
    DWORD half = (DWORD)(atof(argv[2]) * 500);
    pump(half, NULL);
    /* As a user resizing the dialog would; the child must follow. */
    SetWindowPos(w, NULL, 0, 0, RESIZED_W, RESIZED_H, SWP_NOMOVE | SWP_NOZORDER | SWP_NOACTIVATE);
    wait_child_size(w, RESIZED_W, RESIZED_H, "resized_child");
    pump(half, NULL);
    DWORD code = 0;
    if (WaitForSingleObject(saver, 0) == WAIT_OBJECT_0) {
        /* A preview must live as long as its window: ending before is a failure. */
        GetExitCodeProcess(saver, &code);
        printf("ended_early exit_code=%lu\n", code);
        return 1;
    }
    DestroyWindow(w);
    ULONGLONG destroyed = GetTickCount64();
    printf("destroyed\n");
    fflush(stdout);
    /* The dialog goes on living; the saver must notice on its own. */
    DWORD waited = WaitForSingleObject(saver, END_WAIT_MS);
    ULONGLONG took = GetTickCount64() - destroyed;
    if (waited != WAIT_OBJECT_0) {
        printf("not_ended after_ms=%llu\n", took);
        TerminateProcess(saver, 1);
        return 1;
    }
    GetExitCodeProcess(saver, &code);
    printf("exit_code=%lu ended_after_ms=%llu\n", code, took);
    return 0;
}
