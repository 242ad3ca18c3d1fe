/*
 * A test stand-in for the Control Panel's Screen Saver dialog, run under
 * Wine by tests/saver_wine.rs.
 *
 *   preview_host.exe SAVER.EXE SECONDS
 *
 * Makes a top-level window titled "preview-host" with a 152x112 black
 * client area (the dialog's little monitor), starts `SAVER.EXE /p <HWND>`
 * with that window's handle in decimal, as Windows does, pumps messages
 * until the saver's child window shows up in it (up to 10 s) and then for
 * SECONDS more, destroys the window, then waits up to 10 s for the saver to
 * end. Prints on stdout, one fact a line:
 *   hwnd=<decimal>
 *   child_after_ms=<ms from the start>   (or: no_child)
 *   destroyed
 *   exit_code=<code> ended_after_ms=<ms since the destroy>
 * or, instead of the last two, `ended_early exit_code=<code>` (the saver was
 * gone before the destroy) or `not_ended after_ms=<ms>` (still running 10 s
 * after it; then it is terminated).
 * Exits 0 if the saver ended after the destroy, 1 if not, 2 on a setup error.
 */
#include <windows.h>
#include <stdio.h>
#include <stdlib.h>

#define CLIENT_W 152
#define CLIENT_H 112
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

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: preview_host SAVER.EXE SECONDS\n");
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
    if (pump(CHILD_WAIT_MS, w))
        printf("child_after_ms=%llu\n", GetTickCount64() - started);
    else
        printf("no_child\n");
    fflush(stdout);
    pump((DWORD)(atof(argv[2]) * 1000), NULL);
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
