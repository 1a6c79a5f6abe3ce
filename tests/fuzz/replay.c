/* SPDX-License-Identifier: MIT */
/* replay.c - run the fuzz harness over files without libFuzzer, so the
 * committed regression corpus also runs under the ordinary compiler ($(CC),
 * sanitised with SANITIZE=1).  Each file runs in its own child process: a
 * property violation aborts the child and is counted, not fatal.
 * Usage: replay FILE...   Prints "fuzz-replay: N passed, N failed". */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include "harness.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path)
{
    static uint8_t buf[1 << 16];
    size_t n;
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        perror(path);
        return 1;
    }
    n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    (void)LLVMFuzzerTestOneInput(buf, n);
    return 0;
}

int main(int argc, char **argv)
{
    c2d_tally tally = {0, 0};
    int i;
    for (i = 1; i < argc; i++) {
        int st = 0;
        pid_t pid = fork();
        if (pid == 0) _exit(run_file(argv[i]));
        if (!c2d_tally_add(&tally, pid > 0 && waitpid(pid, &st, 0) == pid && WIFEXITED(st) && WEXITSTATUS(st) == 0))
            fprintf(stderr, "fuzz-replay: FAILED %s\n", argv[i]);
    }
    c2d_put_tally("fuzz-replay", &tally);
    return c2d_tally_status(&tally);
}
